//===- CPUKernels.h - CPU kernels to a shared object ------------*- C++ -*-===//
//
// Compiles the CPU kernels of a lowered simulation (the nested module that
// --sim-lower-to-cpu produces) into an ELF shared object that the runtime
// loads with dlopen (docs/Bundle.md, "CPU shared object").
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_CPUKERNELS_H
#define SIM_TARGET_CPUKERNELS_H

#include "mlir/IR/BuiltinOps.h"

#include <string>

namespace mlir::sim {

/// Options of the CPU code generation.
struct CPUKernelOptions {
  /// LLVM optimisation level (0 to 3).
  unsigned optLevel = 3;
  /// The instruction-set level the code is for: an LLVM CPU name of the
  /// host's architecture (`x86-64`, `x86-64-v2`, `x86-64-v3`, `x86-64-v4`).
  /// The code runs on every CPU of that level, not only on this one.
  std::string isa = "x86-64";
  /// Compile for a runtime that flushes subnormals to zero (--sim-ftz): the
  /// functions' denormal modes say so, so that LLVM folds as the CPU will
  /// compute with MXCSR's FTZ and DAZ set.
  bool flushSubnormals = false;
  /// The linker; found next to the LLVM tools when empty.
  std::string linker;
};

/// Compiles `kernels` (a module of func.func kernels taking the plan's
/// arguments and the three group arguments) into the bytes of a shared
/// object that exports `sim_cpu_<kernel>(void **params, int64_t first_group,
/// int64_t end_group, int64_t group_size)` for every kernel. Emits an error
/// at `kernels` and fails when a step fails.
FailureOr<std::string> compileCPUKernels(ModuleOp kernels,
                                         const CPUKernelOptions &options = {});

/// As above, once per instruction-set level of `isas` (options.isa is not
/// used): the kernels are lowered to LLVM IR once, then optimised and
/// compiled for each level. Returns the objects in the order of `isas`.
FailureOr<SmallVector<std::string>>
compileCPUKernels(ModuleOp kernels, ArrayRef<std::string> isas,
                  const CPUKernelOptions &options = {});

/// As above for several modules at once: every pair of a module and a level
/// compiles side by side on the modules' context's threads. Returns the
/// objects of each module in the order of `isas`.
FailureOr<SmallVector<SmallVector<std::string>>>
compileCPUKernels(ArrayRef<ModuleOp> modules, ArrayRef<std::string> isas,
                  const CPUKernelOptions &options = {});

/// Compiles the body functions of a reference module (what
/// --sim-lower-to-reference makes of a simulation) into the bytes of a shared
/// object that exports them with the C signatures of docs/Reference.md.
FailureOr<std::string>
compileReferenceFunctions(ModuleOp reference,
                          const CPUKernelOptions &options = {});

/// The instruction-set levels the CPU kernels can be compiled for on this
/// host's architecture, most portable first (`x86-64` ... `x86-64-v4`).
ArrayRef<StringRef> getCPUIsaLevels();

/// The levels a bundle's CPU kernels are compiled for by default: the
/// portable `x86-64` (scalar lanes, libm's fmaf where the scene fuses),
/// `x86-64-v3` (AVX2 and FMA, 8 lanes at once) and `x86-64-v4` (AVX-512, 16
/// lanes). Not the compiling CPU's own level: a bundle is the same wherever
/// it is compiled (getHostCPUIsa() is --sim-cpu-isas=host's).
SmallVector<std::string, 3> getDefaultCPUIsas();

/// The highest level of getCPUIsaLevels() that this machine's CPU runs, as
/// the runtime chooses it here: at most $SIM_CPU_ISA when that names a level
/// (the runtime's cap; a name it does not know is the runtime's error, and
/// leaves the CPU's own level here). `x86-64` on a CPU the checks do not
/// know.
std::string getHostCPUIsa();

/// Registers the dialect translations the CPU compilation needs.
void registerCPUKernelDialects(DialectRegistry &registry);

} // namespace mlir::sim

#endif // SIM_TARGET_CPUKERNELS_H
