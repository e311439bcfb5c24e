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

#include "mlir/Pass/PassRegistry.h"

using namespace mlir;
using namespace mlir::sim;

void mlir::sim::buildFrontEndPipeline(OpPassManager &pm,
                                      const FrontEndOptions &options) {
  OpPassManager &simulation = pm.nest<SimulationOp>();
  if (options.prune)
    simulation.addPass(createSimPrune());
  simulation.addPass(createSimSchedule());
  simulation.addPass(createSimSubstepLegality());
  SimPlanMemoryOptions planOptions;
  planOptions.strategy = options.strategy;
  planOptions.groupSize = options.groupSize;
  simulation.addPass(createSimPlanMemory(planOptions));
  simulation.addPass(createSimInsertInterpolation());
}

void mlir::sim::buildReferencePipeline(OpPassManager &pm,
                                       const ReferenceOptions &options) {
  OpPassManager &simulation = pm.nest<SimulationOp>();
  if (options.prune)
    simulation.addPass(createSimPrune());
  simulation.addPass(createSimSchedule());
  simulation.addPass(createSimSubstepLegality());
  pm.addPass(createSimLowerToReference());
}

void mlir::sim::buildSimToGPUPipeline(OpPassManager &pm,
                                      const SimToGPUOptions &options) {
  FrontEndOptions frontEnd;
  frontEnd.strategy = options.strategy;
  frontEnd.groupSize = options.groupSize;
  buildFrontEndPipeline(pm, frontEnd);

  SimLowerToGPUOptions lowering;
  lowering.groupSize = options.groupSize;
  pm.addPass(createSimLowerToGPU(lowering));

  GPUTargetOptions target;
  target.chip = options.chip;
  target.features = options.features;
  target.optLevel = options.optLevel;
  target.cudaPath = options.cudaPath;
  buildSimGPUToPTXPipeline(pm, target);
}

void mlir::sim::registerSimPipelines() {
  PassPipelineRegistration<FrontEndOptions>(
      "sim-front-end",
      "Prune, schedule, check sub-stepping, plan memory and insert "
      "interpolation for one strategy",
      buildFrontEndPipeline);
  PassPipelineRegistration<ReferenceOptions>(
      "sim-reference-pipeline",
      "Prune, schedule, check sub-stepping and lower every sim.simulation "
      "to the per-item body functions of the reference executor",
      buildReferencePipeline);
  PassPipelineRegistration<GPUTargetOptions>(
      "sim-gpu-to-ptx",
      "Lower gpu.modules to NVVM and serialize each to a gpu.binary holding "
      "PTX text",
      buildSimGPUToPTXPipeline);
  PassPipelineRegistration<SimToGPUOptions>(
      "sim-to-gpu-pipeline",
      "Compile scenes to PTX: the front end, the lowering of every "
      "sim.simulation to GPU kernels and a host plan, and --sim-gpu-to-ptx",
      buildSimToGPUPipeline);
}
