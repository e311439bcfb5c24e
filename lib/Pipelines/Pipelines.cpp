//===- Pipelines.cpp - sim pass pipelines ---------------------------------===//
//
// The front end in the order its passes depend on each other: pruning first
// (nothing else should spend effort on what is removed), then the schedule
// (read roles), the sub-stepping verdicts, the memory plan (which needs both)
// and interpolation insertion (which needs the plan). docs/Pipeline.md
// describes each stage. Then the whole way to PTX: the front end, the
// lowering to gpu.modules and the GPU back end (GPUToPTX.cpp).
//
//===----------------------------------------------------------------------===//

#include "sim/Pipelines/Pipelines.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "sim/Conversion/Passes.h"

#include "mlir/IR/BuiltinOps.h"
#include "mlir/Pass/PassManager.h"
#include "mlir/Pass/PassRegistry.h"

using namespace mlir;
using namespace mlir::sim;

void mlir::sim::buildFrontEndPipeline(OpPassManager &pm,
                                      const FrontEndOptions &options) {
  OpPassManager &simulation = pm.nest<SimulationOp>();
  simulation.addPass(createSimInlineConstants());
  if (options.prune)
    simulation.addPass(createSimPrune());
  simulation.addPass(createSimDefineEdgeCases());
  simulation.addPass(createSimSchedule());
  // Strategies without sub-steps record the verdicts (the plan checks
  // them) but need no explanation of them.
  SimSubstepLegalityOptions legalityOptions;
  legalityOptions.remarks = options.strategy != Strategy::simple &&
                            options.strategy != Strategy::traditional;
  // Pairs are lts's alone.
  legalityOptions.pairRemarks = options.strategy == Strategy::lts;
  simulation.addPass(createSimSubstepLegality(legalityOptions));
  SimPlanMemoryOptions planOptions;
  planOptions.strategy = options.strategy;
  planOptions.groupSize = options.groupSize;
  simulation.addPass(createSimPlanMemory(planOptions));
  if (options.distributed)
    simulation.addPass(createSimPlanHalos());
  simulation.addPass(createSimInsertInterpolation());
}

void mlir::sim::buildReferencePipeline(OpPassManager &pm,
                                       const ReferenceOptions &options) {
  OpPassManager &simulation = pm.nest<SimulationOp>();
  simulation.addPass(createSimInlineConstants());
  if (options.prune)
    simulation.addPass(createSimPrune());
  simulation.addPass(createSimDefineEdgeCases());
  simulation.addPass(createSimSchedule());
  SimSubstepLegalityOptions legalityOptions;
  legalityOptions.remarks = options.remarks;
  simulation.addPass(createSimSubstepLegality(legalityOptions));
  pm.addPass(createSimLowerToReference());
}

void mlir::sim::buildSimToGPUPipeline(OpPassManager &pm, Strategy strategy,
                                      unsigned groupSize,
                                      const GPUTargetOptions &target) {
  FrontEndOptions frontEnd;
  frontEnd.strategy = strategy;
  frontEnd.groupSize = groupSize;
  buildFrontEndPipeline(pm, frontEnd);

  SimLowerToGPUOptions lowering;
  lowering.groupSize = groupSize;
  pm.addPass(createSimLowerToGPU(lowering));

  buildSimGPUToPTXPipeline(pm, target);
}

/// Registers a pipeline that runs on a builtin.module: it nests its own
/// passes on the simulations and gpu.modules inside. Nested under another
/// op (`sim.simulation(sim-front-end)`), it would nest its passes one
/// level too deep and change nothing, or add a module pass to a nested
/// pass manager, which LLVM aborts on; that is an error instead.
template <typename Options>
static void registerModulePipeline(
    StringRef arg, StringRef description,
    std::function<void(OpPassManager &, const Options &)> builder) {
  registerPassPipeline(
      arg, description,
      [name = arg.str(),
       builder](OpPassManager &pm, StringRef text,
                function_ref<LogicalResult(const Twine &)> errorHandler) {
        StringRef anchor = pm.getOpAnchorName();
        if (anchor != ModuleOp::getOperationName())
          return errorHandler("the " + name +
                              " pipeline runs on a builtin.module, whose "
                              "sim.simulation and gpu.module ops it nests its "
                              "passes on, not on '" +
                              anchor + "': give --" + name +
                              " or --pass-pipeline='builtin.module(" + name +
                              ")'");
        Options options;
        if (failed(options.parseFromString(text)))
          return failure();
        builder(pm, options);
        return success();
      },
      [](function_ref<void(const mlir::detail::PassOptions &)> handler) {
        handler(Options());
      });
}

void mlir::sim::registerSimPipelines() {
  registerModulePipeline<FrontEndOptions>(
      "sim-front-end",
      "Prune, schedule, check sub-stepping, plan memory and insert "
      "interpolation for one strategy",
      buildFrontEndPipeline);
  registerModulePipeline<ReferenceOptions>(
      "sim-reference-pipeline",
      "Prune, schedule, check sub-stepping and lower every sim.simulation "
      "to the per-item body functions of the reference executor",
      buildReferencePipeline);
  registerModulePipeline<SimGPUToPTXOptions>(
      "sim-gpu-to-ptx",
      "Lower gpu.modules to NVVM and serialize each to a gpu.binary holding "
      "PTX text",
      [](OpPassManager &pm, const SimGPUToPTXOptions &options) {
        buildSimGPUToPTXPipeline(pm, options.getTarget());
      });
  registerModulePipeline<SimToGPUOptions>(
      "sim-to-gpu-pipeline",
      "Compile scenes to PTX: the front end, the lowering of every "
      "sim.simulation to GPU kernels and a host plan, and --sim-gpu-to-ptx",
      [](OpPassManager &pm, const SimToGPUOptions &options) {
        buildSimToGPUPipeline(pm, options.strategy, options.groupSize,
                              options.getTarget());
      });
}
