//===- Pipelines.h - sim pass pipelines -------------------------*- C++ -*-===//
//
// Declares the registered pass pipelines of the sim compiler.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_PIPELINES_PIPELINES_H
#define SIM_PIPELINES_PIPELINES_H

#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Pass/PassManager.h"
#include "mlir/Pass/PassOptions.h"

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
};

/// Adds the front end to `pm` (which runs on the module): prune, schedule,
/// sub-step legality, memory plan and interpolation insertion, nested on
/// every sim.simulation.
void buildFrontEndPipeline(OpPassManager &pm, const FrontEndOptions &options);

/// Registers `--sim-front-end`.
void registerSimPipelines();

} // namespace mlir::sim

#endif // SIM_PIPELINES_PIPELINES_H
