//===- SubstepLegality.cpp - may sub-steps run inside one kernel? ---------===//
//
// The paper runs all sub-steps of a component inside one kernel and does not
// check that this is safe. It is safe only when each thread owns the state it
// reads between sub-steps, i.e. the component reads the buffers it writes at
// its own item. This pass proves that per component and records the verdict;
// a component that reads its own buffers at other items falls back to a
// grid-wide barrier between sub-steps, and a remark says why.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMSUBSTEPLEGALITY
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

struct SubstepLegalityPass
    : public sim::impl::SimSubstepLegalityBase<SubstepLegalityPass> {
  void runOnOperation() override {
    if (failed(checkBeforeInterpolation(getOperation(), getArgument(),
                                        "its sub-stepping verdicts are")))
      return signalPassFailure();
    auto &analysis = getAnalysis<DependencyAnalysis>();
    for (ComponentOp component : analysis.getComponents()) {
      const BufferAccess *hazard = analysis.findSubStepHazard(component);
      SubStepping verdict =
          hazard ? SubStepping::grid_sync : SubStepping::in_kernel;
      component.setSubSteppingAttr(
          SubSteppingAttr::get(&getContext(), verdict));
      if (!hazard)
        continue;
      InFlightDiagnostic remark =
          component.emitRemark()
          << "@" << component.getSymName()
          << " needs a grid-wide barrier between sub-steps: its "
          << stringifyBodyKind(hazard->body) << " body reads @"
          << hazard->buffer.getSymName() << ", which it writes, at "
          << hazard->pattern.str()
          << ", so a thread could read another item while that item is "
             "between sub-steps";
      ReadOp offending = *llvm::find_if(hazard->reads, [&](ReadOp read) {
        return !analysis.getPattern(read).isOwn();
      });
      remark.attachNote(offending.getLoc())
          << "reads @" << hazard->buffer.getSymName() << " at "
          << analysis.getPattern(offending).str();
    }
    markAllAnalysesPreserved();
  }
};

} // namespace
