//===- Pipelines.cpp - sim pass pipelines ---------------------------------===//
//
// The front end in the order its passes depend on each other: pruning first
// (nothing else should spend effort on what is removed), then the schedule
// (read roles), the sub-stepping verdicts, the memory plan (which needs both)
// and interpolation insertion (which needs the plan). docs/Pipeline.md
// describes each stage.
//
//===----------------------------------------------------------------------===//

#include "sim/Pipelines/Pipelines.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

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

void mlir::sim::registerSimPipelines() {
  PassPipelineRegistration<FrontEndOptions>(
      "sim-front-end",
      "Prune, schedule, check sub-stepping, plan memory and insert "
      "interpolation for one strategy",
      buildFrontEndPipeline);
}
