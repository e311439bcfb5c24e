//===- SubstepLegality.cpp - may sub-steps run inside one kernel? ---------===//
//
// The paper runs all sub-steps of a component inside one kernel and does not
// check that this is safe. It is safe only when each thread owns the state it
// reads between sub-steps, i.e. the component reads the buffers it writes at
// its own item. This pass proves that per component and records the verdict;
// a component that reads its own buffers at other items falls back to a
// grid-wide barrier between sub-steps, and a remark says why.
//
// Such a component can still advance each thread group at its own rate
// under `lts` (docs/Model.md, "Local time stepping") when every read of its
// own buffers at other items is a window (so the groups a group reads are
// known, and their levels can be limited) of a buffer whose value between
// two time levels is an interpolation of the two: the pass records the
// joined window as `local_window`, or says in the remark what prevents it.
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
      component.removeLocalWindowAttr();
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
      recordLocalWindow(analysis, component, offending, remark);
    }
    markAllAnalysesPreserved();
  }

  /// Records `local_window` on a grid_sync component whose reads of its own
  /// buffers allow local time steps, or completes `remark` with what does
  /// not and what to change (with a note at a gather unless it is the
  /// already `noted` read).
  void recordLocalWindow(const DependencyAnalysis &analysis,
                         ComponentOp component, ReadOp noted,
                         InFlightDiagnostic &remark) {
    AccessPattern window = AccessPattern::own();
    for (const BufferAccess &access : analysis.getAccesses(component)) {
      if (analysis.getWriter(access.buffer) != component)
        continue;
      BufferOp buffer = access.buffer;
      StringRef name = buffer.getSymName();
      if (access.pattern.isGather()) {
        ReadOp gather = *llvm::find_if(access.reads, [&](ReadOp read) {
          return analysis.getPattern(read).isGather();
        });
        remark << "; under lts it cannot take local time steps: its "
               << stringifyBodyKind(access.body) << " body reads @" << name
               << " through a gather, so the groups it reads are not known; "
                  "a window (%i plus a bounded offset) lets the levels of "
                  "neighbouring groups be limited";
        if (gather != noted)
          remark.attachNote(gather.getLoc()) << "the gather of @" << name;
        return;
      }
      if (access.pattern.isOwn())
        continue;
      InterpolationAttrInterface interp = buffer.getInterpolation();
      if (!interp.isInterpolable()) {
        remark << "; under lts it cannot take local time steps: @" << name
               << " is interp(none), and a read of a neighbour that is ahead "
                  "in time needs a value between its time levels; give @"
               << name << " an interpolation";
        return;
      }
      if (!interp.getAuxiliaryBuffers().empty()) {
        remark << "; under lts it cannot take local time steps: @" << name
               << "'s interpolation reads other buffers ("
               << interp.getAuxiliaryBufferRole(0)
               << "), which are not kept at every item's two time levels; "
                  "use #sim.linear or #sim.cubic for @"
               << name;
        return;
      }
      window = window.join(access.pattern);
    }
    component.setLocalWindowAttr(DenseI64ArrayAttr::get(
        &getContext(), {window.getMinOffset(), window.getMaxOffset()}));
    remark << "; under lts its thread groups take local time steps (window "
           << window.str() << ")";
  }
};

} // namespace
