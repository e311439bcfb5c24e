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

/// Compiles the body functions of a reference module (what
/// --sim-lower-to-reference makes of a simulation) into the bytes of a shared
/// object that exports them with the C signatures of docs/Reference.md.
FailureOr<std::string>
compileReferenceFunctions(ModuleOp reference,
                          const CPUKernelOptions &options = {});

/// Registers the dialect translations the CPU compilation needs.
void registerCPUKernelDialects(DialectRegistry &registry);

} // namespace mlir::sim

#endif // SIM_TARGET_CPUKERNELS_H
