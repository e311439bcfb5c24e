//===- Stages.cpp - what the front-end stages may run on ------------------===//
//
// Each front-end pass records decisions that later passes and the lowerings
// trust. Once --sim-insert-interpolation has turned view reads into explicit
// loads, the analyses no longer see the reads those decisions were made
// from: rerunning an earlier stage would re-decide from nothing (no reads,
// so no snapshot, no role, no dependency) while the loads still rely on the
// old decisions. Those stages refuse such a simulation instead.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/Transforms/Passes.h"

using namespace mlir;
using namespace mlir::sim;

LogicalResult mlir::sim::checkBeforeInterpolation(SimulationOp simulation,
                                                  StringRef passArgument,
                                                  StringRef decisions) {
  Operation *access = simulation.findExplicitAccess();
  if (!access)
    return success();
  InFlightDiagnostic diag = simulation.emitOpError()
                            << "has explicit loads, so " << decisions
                            << " fixed; run --" << passArgument
                            << " before --sim-insert-interpolation";
  diag.attachNote(access->getLoc())
      << "the first explicit access is this '" << access->getName() << "'";
  return diag;
}
