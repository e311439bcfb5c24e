//===- Stages.cpp - what the front-end stages may run on ------------------===//
//
// Checks that more than one front-end pass makes, with one message each.
//
// Each front-end pass records decisions that later passes and the lowerings
// trust. Once --sim-insert-interpolation has turned view reads into explicit
// loads, the analyses no longer see the reads those decisions were made
// from: rerunning an earlier stage would re-decide from nothing (no reads,
// so no snapshot, no role, no dependency) while the loads still rely on the
// old decisions. Those stages refuse such a simulation instead.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

using namespace mlir;
using namespace mlir::sim;

LogicalResult mlir::sim::checkBeforeInterpolation(SimulationOp simulation,
                                                  StringRef passArgument,
                                                  StringRef decisions) {
  if (failed(simulation.checkConstantsInlined(passArgument)))
    return failure();
  Operation *access = simulation.findExplicitAccess();
  if (!access)
    return success();
  InFlightDiagnostic diag = simulation.emitOpError()
                            << "has explicit loads, so " << decisions
                            << " fixed; run --" << passArgument
                            << " before --sim-insert-interpolation";
  // The whole front end already ran (sim-translate, --sim-front-end or
  // --sim-lower-to-* given its own output): what to give instead.
  if (StrategyAttr strategy = simulation.getStrategyAttr())
    diag << " (this simulation has been through the front end already, "
            "for strategy '"
         << stringifyStrategy(strategy.getValue())
         << "': give the scene as written, before --sim-front-end)";
  diag.attachNote(access->getLoc())
      << "the first explicit access is this '" << access->getName() << "'";
  return diag;
}

LogicalResult mlir::sim::checkInterpolable(ReadOp read, BufferOp buffer,
                                           ComponentOp component, BodyKind kind,
                                           Strategy strategy) {
  if (buffer.getInterpolation().isInterpolable() ||
      !isSubSteppingStrategy(strategy))
    return success();
  // A component that takes the big step whole (no num_steps, or one that
  // bounds the step) reads the end of the step in evaluate and its start
  // in num_steps: no intermediate time. Its recorded stepping decides, else
  // the one --sim-plan-memory will record.
  bool wholeStep = !component.hasNumSteps();
  if (std::optional<Advance> advance = component.getAdvance()) {
    wholeStep = *advance == Advance::whole_step;
  } else if (component.getSubSteppingAttr()) {
    FailureOr<Stepping> stepping = decideStepping(component, strategy);
    wholeStep = succeeded(stepping) && stepping->advance == Advance::whole_step;
  }
  if (wholeStep)
    return success();
  // The reader of a pair under lts reads its writer's value as it is (the
  // writer evaluated the item when its block started the sub-step): no
  // intermediate time (docs/Model.md, "Item pairs").
  ComponentOp writer =
      component->getParentOfType<SimulationOp>().getWriter(buffer);
  if (strategy == Strategy::lts && kind == BodyKind::Evaluate && writer &&
      writer.getFluxWindowAttr())
    return success();
  InFlightDiagnostic diag =
      read.emitOpError()
      << "reads @" << buffer.getSymName()
      << " at an intermediate time of the big step (@" << component.getSymName()
      << "'s " << stringifyBodyKind(kind)
      << " interpolates buffers advanced earlier in the step under "
      << stringifyStrategy(strategy) << "), but @" << buffer.getSymName()
      << " is declared interp(none)";
  diag.attachNote(buffer.getLoc())
      << "@" << buffer.getSymName()
      << " is declared interp(none) here: its value means nothing between "
         "the ends of a big step; read it through the back edge, or use "
         "strategy simple or traditional";
  return diag;
}
