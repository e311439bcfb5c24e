//===- TranslationOptions.cpp - options of sim-translate ------------------===//
//
// One set of --sim-* options for every translation of sim-translate, so that
// --sim-to-ptx and --sim-to-bundle compile a scene the same way for the same
// command line.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/TranslationOptions.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"
#include "sim/Pipelines/Pipelines.h"

#include "mlir/Pass/PassManager.h"

using namespace mlir;
using namespace mlir::sim;

namespace {
/// The pipelines' defaults, read once.
const SimToGPUOptions &getDefaults() {
  static const SimToGPUOptions defaults;
  return defaults;
}
const GPUTargetOptions &getTargetDefaults() {
  static const GPUTargetOptions defaults;
  return defaults;
}
} // namespace

bool StrategyParser::parse(llvm::cl::Option &option, llvm::StringRef argName,
                           llvm::StringRef arg, Strategy &value) {
  for (const auto &known : Values)
    if (known.Name == arg) {
      value = known.V.getValue();
      return false;
    }
  std::string names;
  for (const auto &known : Values)
    names += (names.empty() ? "" : ", ") + known.Name.str();
  if (arg.empty())
    return option.error("needs a strategy name (" + names + ")");
  return option.error("'" + arg + "' is not a strategy (" + names + ")");
}

bool OptLevelParser::parse(llvm::cl::Option &option, llvm::StringRef argName,
                           llvm::StringRef arg, unsigned &value) {
  if (llvm::cl::parser<unsigned>::parse(option, argName, arg, value))
    return true;
  if (value > 3)
    return option.error("'" + arg + "' is not an optimization level (0 to 3)");
  return false;
}

TranslationOptions::TranslationOptions()
    : category("Translation options (--sim-to-ptx, --gpu-to-ptx, "
               "--sim-to-bundle)"),
      strategy("sim-strategy",
               llvm::cl::desc("--sim-to-ptx: the strategy to compile for "
                              "(default hip)"),
               llvm::cl::init(getDefaults().strategy.getValue()),
               getStrategyOptionValues(), llvm::cl::cat(category)),
      strategies("sim-strategies",
                 llvm::cl::desc("--sim-to-bundle: the strategies to compile "
                                "for, comma-separated (default: all five)"),
                 llvm::cl::CommaSeparated, getStrategyOptionValues(),
                 llvm::cl::cat(category)),
      groupSize("sim-group-size",
                llvm::cl::desc("Threads per thread group (default 256)"),
                llvm::cl::init(getDefaults().groupSize.getValue()),
                llvm::cl::cat(category)),
      chip("sim-chip",
           llvm::cl::desc("The NVIDIA GPU to compile for (default sm_90)"),
           llvm::cl::init(getTargetDefaults().chip), llvm::cl::cat(category)),
      features("sim-features",
               llvm::cl::desc("NVPTX features, e.g. +ptx80 (default: the "
                              "chip's oldest PTX ISA)"),
               llvm::cl::init(getTargetDefaults().features),
               llvm::cl::cat(category)),
      optLevel("sim-opt-level",
               llvm::cl::desc("LLVM optimization level of the kernels, 0 to 3 "
                              "(default 3)"),
               llvm::cl::init(getTargetDefaults().optLevel),
               llvm::cl::cat(category)),
      cudaPath("sim-cuda-path",
               llvm::cl::desc("Root of the CUDA toolkit that provides "
                              "libdevice (default: $CUDA_ROOT, $CUDA_HOME, "
                              "$CUDA_PATH, then /usr/local/cuda)"),
               llvm::cl::init(getTargetDefaults().cudaPath),
               llvm::cl::cat(category)),
      setParams("sim-set-params",
                llvm::cl::desc("--sim-to-bundle, --sim-to-ptx: name=value "
                               "pairs, comma-separated, set on the scene "
                               "before it is compiled, as --sim-set-params "
                               "does (max_steps, range, dt, parameters)"),
                llvm::cl::CommaSeparated, llvm::cl::cat(category)),
      cpuIsas("sim-cpu-isas",
              llvm::cl::desc("--sim-to-bundle: the x86-64 levels to compile "
                             "the CPU kernels for, comma-separated, each a "
                             "shared object; the runtime runs the highest "
                             "the CPU has (x86-64, x86-64-v2, x86-64-v3, "
                             "x86-64-v4, or host: the one a run on this "
                             "machine takes, which compiles fastest; "
                             "default all but x86-64-v2)"),
              llvm::cl::CommaSeparated, llvm::cl::cat(category)),
      ftz("sim-ftz",
          llvm::cl::desc("Flush subnormal values to zero on every backend "
                         "(PTX .ftz f32 forms and libdevice's FTZ variants; "
                         "FTZ and DAZ on the CPU threads; recorded in the "
                         "bundle). Default: IEEE subnormals"),
          llvm::cl::init(false), llvm::cl::cat(category)),
      gpuNarrowLoops(
          "sim-gpu-narrow-loops",
          llvm::cl::desc("--sim-to-ptx, --sim-to-bundle: count the GPU "
                         "kernels' loops of unknown trip count (a scene's "
                         "load loop) in 32 bits where their bounds allow; "
                         "the same results. Default: off"),
          llvm::cl::init(getTargetDefaults().narrowLoopCounters),
          llvm::cl::cat(category)),
      gpuUnroll("sim-gpu-unroll",
                llvm::cl::desc("--sim-to-ptx, --sim-to-bundle: unroll the "
                               "GPU kernels' innermost loops of unknown trip "
                               "count (a scene's load loop) by this factor, "
                               "1 to 32; the same results. Default 1: left "
                               "to LLVM"),
                llvm::cl::init(getTargetDefaults().unroll),
                llvm::cl::cat(category)),
      distributed(
          "sim-distributed",
          llvm::cl::desc("--sim-to-bundle: plans for many processes "
                         "(sim-run --distributed under mpirun): each rank "
                         "holds a block of the range plus the ghost items "
                         "the scene's read windows reach; a buffer read "
                         "through a gather is copied to every rank "
                         "(docs/Distributed.md)"),
          llvm::cl::init(false), llvm::cl::cat(category)),
      cpuLevelsPerLane(
          "sim-cpu-levels-per-lane",
          llvm::cl::desc("--sim-to-bundle: the CPU kernels limit lts levels "
                         "one lane per block, as the GPU kernels do, "
                         "instead of in one pass (the same results; for "
                         "testing the GPU's algorithm on the CPU)"),
          llvm::cl::init(false), llvm::cl::Hidden, llvm::cl::cat(category)) {}

GPUTargetOptions TranslationOptions::getGPUTarget() const {
  GPUTargetOptions target;
  target.chip = chip.getValue();
  target.features = features.getValue();
  target.optLevel = optLevel.getValue();
  target.cudaPath = cudaPath.getValue();
  target.flushSubnormals = ftz.getValue();
  target.narrowLoopCounters = gpuNarrowLoops.getValue();
  target.unroll = gpuUnroll.getValue();
  return target;
}

void TranslationOptions::addSetParams(OpPassManager &pm) const {
  if (setParams.empty())
    return;
  SimSetParamsOptions options;
  options.values.assign(setParams.begin(), setParams.end());
  pm.addNestedPass<SimulationOp>(createSimSetParams(options));
}

const TranslationOptions &mlir::sim::getTranslationOptions() {
  static const TranslationOptions options;
  return options;
}
