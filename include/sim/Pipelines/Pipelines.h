//===- Pipelines.h - sim pass pipelines -------------------------*- C++ -*-===//
//
// Declares the registered pass pipelines of the sim compiler: the front end,
// the GPU back end (gpu.modules to PTX) and the whole way from a scene to PTX.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_PIPELINES_PIPELINES_H
#define SIM_PIPELINES_PIPELINES_H

#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Pass/PassManager.h"
#include "mlir/Pass/PassOptions.h"

namespace mlir {
class DialectRegistry;
} // namespace mlir

namespace mlir::sim {

/// Options of the front-end pipeline.
struct FrontEndOptions : public PassPipelineOptions<FrontEndOptions> {
  PassOptions::Option<Strategy> strategy{
      *this, "strategy", llvm::cl::desc("The strategy to compile for"),
      llvm::cl::init(Strategy::hip), getStrategyOptionValues()};
  PassOptions::Option<int64_t> groupSize{
      *this, "group-size",
      llvm::cl::desc("Threads per group: hip-cache plans a cache only for a "
                     "window whose halo is smaller"),
      llvm::cl::init(256)};
  PassOptions::Option<bool> prune{
      *this, "prune",
      llvm::cl::desc("Remove what no observed buffer depends on"),
      llvm::cl::init(true)};
  PassOptions::Option<bool> distributed{
      *this, "distributed",
      llvm::cl::desc("Plan for many processes: record the ghost items of "
                     "every buffer (--sim-plan-halos)"),
      llvm::cl::init(false)};
};

/// Adds the front end to `pm` (which runs on the module): prune, schedule,
/// sub-step legality, memory plan and interpolation insertion, nested on
/// every sim.simulation.
void buildFrontEndPipeline(OpPassManager &pm, const FrontEndOptions &options);

struct ReferenceOptions : public PassPipelineOptions<ReferenceOptions> {
  PassOptions::Option<bool> prune{
      *this, "prune",
      llvm::cl::desc("Remove what no observed buffer depends on"),
      llvm::cl::init(true)};
  PassOptions::Option<bool> remarks{
      *this, "remarks",
      llvm::cl::desc("Explain the sub-stepping verdicts in remarks (a "
                     "bundle leaves that to its strategies' front ends)"),
      llvm::cl::init(true)};
};

/// The scheduled IR (prune, schedule, sub-stepping verdicts) lowered to the
/// reference executor's body functions (docs/Reference.md).
void buildReferencePipeline(OpPassManager &pm, const ReferenceOptions &options);

/// The GPU back end's target: which GPU the PTX is for, how the kernels are
/// optimized and where libdevice is. One struct that every user passes
/// along: the pipelines below, sim-translate's flags
/// (sim/Target/TranslationOptions.h) and the bundle writer
/// (sim/Target/Bundle.h).
struct GPUTargetOptions {
  /// The NVIDIA GPU to compile for, as LLVM's NVPTX back end names it (sm_80,
  /// sm_90, sm_90a, ...).
  std::string chip = "sm_90";
  /// NVPTX features, e.g. +ptx80 for PTX ISA 8.0; empty: the oldest PTX ISA
  /// that supports the chip (7.8 for sm_90).
  std::string features;
  /// LLVM optimization level of the kernels (0 to 3).
  unsigned optLevel = 3;
  /// Root of the CUDA toolkit whose nvvm/libdevice/libdevice.10.bc
  /// implements math functions; empty: $CUDA_ROOT, $CUDA_HOME, $CUDA_PATH,
  /// then /usr/local/cuda.
  std::string cudaPath;
  /// Flush subnormal f32 values to zero (`.ftz` instructions, libdevice's
  /// FTZ variants): sim-translate --sim-ftz. PTX has no f64 `.ftz`.
  bool flushSubnormals = false;
  /// Count the kernels' loops of unknown trip count in 32 bits where their
  /// bounds allow (sim-gpu-narrow-loop-counters). Off until a GPU has
  /// measured it: ptxas gives one kernel more registers with it.
  bool narrowLoopCounters = false;
  /// Copies of the body per iteration of the kernels' innermost loops of
  /// unknown trip count (sim-gpu-unroll-loops); 1: LLVM decides.
  unsigned unroll = 1;
};

/// The pipeline options that set a GPUTargetOptions (`chip`, `features`,
/// `opt-level`, `cuda-path`), shared by the pipelines that end in PTX.
template <typename Derived>
struct GPUTargetPipelineOptions : public PassPipelineOptions<Derived> {
  template <typename T> using Option = mlir::detail::PassOptions::Option<T>;

  Option<std::string> chip{
      *this, "chip",
      llvm::cl::desc("The NVIDIA GPU to compile for, as LLVM's NVPTX back "
                     "end names it (sm_80, sm_90, sm_90a, ...)"),
      llvm::cl::init(GPUTargetOptions().chip)};
  Option<std::string> features{
      *this, "features",
      llvm::cl::desc("NVPTX features, e.g. +ptx80 for PTX ISA 8.0; empty: "
                     "the oldest PTX ISA that supports the chip (7.8 for "
                     "sm_90)"),
      llvm::cl::init(GPUTargetOptions().features)};
  Option<unsigned> optLevel{
      *this, "opt-level",
      llvm::cl::desc("LLVM optimization level of the kernels (0 to 3)"),
      llvm::cl::init(GPUTargetOptions().optLevel)};
  Option<std::string> cudaPath{
      *this, "cuda-path",
      llvm::cl::desc("Root of the CUDA toolkit whose "
                     "nvvm/libdevice/libdevice.10.bc implements math "
                     "functions; empty: $CUDA_ROOT, $CUDA_HOME, $CUDA_PATH, "
                     "then /usr/local/cuda"),
      llvm::cl::init(GPUTargetOptions().cudaPath)};
  Option<bool> ftz{*this, "ftz",
                   llvm::cl::desc("Flush subnormal f32 values to zero (.ftz "
                                  "instructions, libdevice's FTZ variants)"),
                   llvm::cl::init(GPUTargetOptions().flushSubnormals)};
  Option<bool> narrowLoopCounters{
      *this, "narrow-loop-counters",
      llvm::cl::desc("Count the kernels' loops of unknown trip count in 32 "
                     "bits where their bounds allow"),
      llvm::cl::init(GPUTargetOptions().narrowLoopCounters)};
  Option<unsigned> unroll{
      *this, "unroll",
      llvm::cl::desc("Unroll the kernels' innermost loops of unknown trip "
                     "count by this factor (1: leave them to LLVM)"),
      llvm::cl::init(GPUTargetOptions().unroll)};

  /// The target these options describe.
  GPUTargetOptions getTarget() const {
    GPUTargetOptions target;
    target.chip = chip;
    target.features = features;
    target.optLevel = optLevel;
    target.cudaPath = cudaPath;
    target.flushSubnormals = ftz;
    target.narrowLoopCounters = narrowLoopCounters;
    target.unroll = unroll;
    return target;
  }
};

/// Options of `--sim-gpu-to-ptx`: the GPU back end's target.
struct SimGPUToPTXOptions
    : public GPUTargetPipelineOptions<SimGPUToPTXOptions> {};

/// Options of the whole way from a scene to PTX: the front end's strategy,
/// the GPU lowering's thread-group size and the GPU back end's target.
struct SimToGPUOptions : public GPUTargetPipelineOptions<SimToGPUOptions> {
  Option<Strategy> strategy{
      *this, "strategy", llvm::cl::desc("The strategy to compile for"),
      llvm::cl::init(Strategy::hip), getStrategyOptionValues()};
  Option<unsigned> groupSize{
      *this, "group-size",
      llvm::cl::desc("Threads per thread group (block) of the kernels"),
      llvm::cl::init(256)};
};

/// Adds the GPU back end to `pm` (which runs on the module): attaches an
/// `#nvvm.target` to every gpu.module, lowers the kernels to the LLVM and
/// NVVM dialects (dynamic memrefs keep their descriptors: 5 PTX parameters
/// each), checks them and serializes each gpu.module to a gpu.binary whose
/// object is PTX text. Only upstream passes lower; two sim passes fix the
/// dynamic shared memory declaration and check the result. Everything
/// outside the gpu.modules is left alone.
void buildSimGPUToPTXPipeline(OpPassManager &pm,
                              const GPUTargetOptions &target);

/// Adds the whole way from a scene to PTX to `pm`: the front end, the
/// lowering of every sim.simulation to gpu.modules and a host plan, and the
/// GPU back end for `target`.
void buildSimToGPUPipeline(OpPassManager &pm, Strategy strategy,
                           unsigned groupSize, const GPUTargetOptions &target);

/// Returns where buildSimGPUToPTXPipeline looks for libdevice given
/// `cudaPath`: `<root>/nvvm/libdevice/libdevice.10.bc`, the root chosen as
/// GPUTargetOptions::cudaPath says. The file need not exist.
std::string getLibdevicePath(StringRef cudaPath);

/// Registers in `registry` what the GPU back end needs in a context: the
/// dialects it produces, their conversions to LLVM, the NVVM target and the
/// translations to LLVM IR that gpu-module-to-binary uses.
void registerGPUToPTXDependencies(DialectRegistry &registry);

/// Registers the upstream and sim passes the GPU back end is made of, so that
/// each can be run on its own.
void registerGPUToPTXPasses();

/// Registers `--sim-front-end`, `--sim-gpu-to-ptx` and
/// `--sim-to-gpu-pipeline`.
void registerSimPipelines();

} // namespace mlir::sim

#endif // SIM_PIPELINES_PIPELINES_H
