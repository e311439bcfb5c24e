//===- Schedule.cpp - order components and classify reads -----------------===//
//
// Runs the scheduling analysis and records its result on the IR, so that
// later passes (interpolation insertion, memory planning) and FileCheck tests
// read the decisions instead of re-deriving them: the full order and the hip
// step bounds on sim.schedule, and a role on every view read of a component.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/IR/Builders.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMSCHEDULE
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

ArrayAttr getSymbolArray(Builder &builder, ArrayRef<ComponentOp> components) {
  return builder.getArrayAttr(
      llvm::map_to_vector(components, [](ComponentOp component) -> Attribute {
        return FlatSymbolRefAttr::get(component.getSymNameAttr());
      }));
}

struct SchedulePass : public sim::impl::SimScheduleBase<SchedulePass> {
  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    if (failed(checkBeforeInterpolation(simulation, getArgument(),
                                        "its schedule and read roles are")))
      return signalPassFailure();
    auto &analysis = getAnalysis<DependencyAnalysis>();
    FailureOr<Schedule> schedule =
        computeSchedule(analysis, getUserOrder(simulation));
    if (failed(schedule))
      return signalPassFailure();
    if (schedule->getOrder().empty())
      return markAllAnalysesPreserved();

    OpBuilder builder(&getContext());
    ScheduleOp scheduleOp = simulation.getScheduleOp();
    if (!scheduleOp) {
      builder.setInsertionPointToEnd(&simulation.getBody().front());
      scheduleOp = ScheduleOp::create(builder, simulation.getLoc(),
                                      builder.getArrayAttr({}), ArrayAttr());
    }
    scheduleOp.setOrderAttr(getSymbolArray(builder, schedule->getOrder()));
    SmallVector<ComponentOp> bounds = schedule->getHipStepBounds(analysis);
    if (bounds.empty())
      scheduleOp.removeBoundedByAttr();
    else
      scheduleOp.setBoundedByAttr(getSymbolArray(builder, bounds));

    for (const ReadInfo &read : analysis.getReads()) {
      if (!read.component)
        continue;
      ReadRole role =
          schedule->getRole(read.component, analysis.getWriter(read.buffer));
      read.read.setRoleAttr(ReadRoleAttr::get(&getContext(), role));
    }
    // Only attributes changed: reads, writes and patterns are as analysed.
    markAnalysesPreserved<DependencyAnalysis>();
  }
};

} // namespace
