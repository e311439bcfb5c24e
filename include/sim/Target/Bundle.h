//===- Bundle.h - scenes to .simb bundles -----------------------*- C++ -*-===//
//
// Writes the bundle of a scene (docs/Bundle.md): a 32-byte header and one
// FlatBuffer of the schema runtime/schema/bundle.fbs holding the scene as
// written, for each strategy its plan with the kernels' signatures, the PTX
// and a CPU shared object of the same kernels, and the reference
// executor's model and shared object. The runtime reads it without MLIR.
// `sim-translate scene.mlir --sim-to-bundle -o scene.simb`.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_BUNDLE_H
#define SIM_TARGET_BUNDLE_H

#include "sim/Dialect/Sim/IR/SimAttrs.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Target/CPUKernels.h"

#include "mlir/IR/BuiltinOps.h"
#include "llvm/ADT/SmallVector.h"
#include "llvm/Support/raw_ostream.h"

namespace mlir::sim {

/// What a bundle holds and how its kernels are compiled. The defaults are
/// those of the pipelines (lib/Pipelines) and of sim-translate's options.
struct BundleOptions {
  /// The strategies to compile for, in the order of the bundle's plans; each
  /// at most once.
  SmallVector<Strategy, 5> strategies = {Strategy::simple,
                                         Strategy::traditional, Strategy::hip,
                                         Strategy::hip_cache, Strategy::lts};
  /// Threads per thread group the plans and kernels are made for.
  int64_t groupSize = 256;
  /// The GPU back end's target. Its optimization level applies to the CPU
  /// kernels too. Without libdevice (see GPUTargetOptions::cudaPath), a
  /// strategy whose kernels call math functions gets no PTX (a warning says
  /// so): it still runs on the CPU.
  GPUTargetOptions target;
  /// The instruction-set levels to compile the CPU kernels for, each into
  /// its own shared object (getCPUIsaLevels()); the runtime runs the highest
  /// one the CPU supports.
  SmallVector<std::string, 3> cpuIsas = getDefaultCPUIsas();
  /// Flush subnormals to zero on every backend (--sim-ftz): recorded in the
  /// bundle, compiled into the PTX and the CPU code, and set by the runtime
  /// on the CPU threads. target.flushSubnormals is set from it.
  bool flushSubnormals = false;
  /// Plans for many processes (--sim-distributed, docs/Distributed.md):
  /// the front end records every buffer's ghost items and the kernels
  /// address one rank's block.
  bool distributed = false;
  /// The CPU kernels limit lts levels one lane per block, as the GPU
  /// kernels do (--sim-lower-to-cpu=levels-per-lane), for tests.
  bool cpuLevelsPerLane = false;
};

/// Compiles the one sim.simulation in `module` for every strategy of
/// `options` and writes the bundle to `os`. `module` is not changed: each
/// strategy compiles a clone. Fails with an error at a location, and writes
/// nothing, when the module does not hold exactly one simulation, when the
/// scene cannot be written in the bundle format, or when a strategy fails to
/// compile (diagnostics carry a note naming the strategy).
LogicalResult writeBundle(ModuleOp module, const BundleOptions &options,
                          raw_ostream &os);

/// Registers in `registry` the dialects a scene is written in and what both
/// back ends need (writeBundle also appends them to its module's context).
void registerBundleDependencies(DialectRegistry &registry);

/// Registers `--sim-to-bundle` with sim-translate (options --sim-strategies,
/// --sim-group-size, --sim-chip, --sim-features, --sim-opt-level and
/// --sim-cuda-path).
void registerToBundleTranslation();

} // namespace mlir::sim

#endif // SIM_TARGET_BUNDLE_H
