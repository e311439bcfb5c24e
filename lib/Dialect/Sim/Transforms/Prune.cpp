//===- Prune.cpp - remove what no observed output needs -------------------===//
//
// "Model only what a scene needs": a buffer is needed when it is observed,
// when a `sim.total` reads it (a total is an output too), or when something
// needed depends on it. The dependencies of a buffer B are
// computed per written buffer, not per component: the buffers its writer
// reads in num_steps (the step size affects everything it writes), the
// buffers read in the backward slice of B's yielded value in evaluate, the
// auxiliary buffers of B's interpolation, and the buffers B's init and exact
// bodies read. So a component kept for one buffer can still drop another
// buffer it writes that nothing needs. The slice is conservative: any read
// inside a region op (a loop, a conditional) on the slice counts, and so
// does the slice of every operation in evaluate that dead-code elimination
// would keep (a store, an op of unknown effects).
//
// A read in the evaluate body of a kept component that is on no slice feeds
// nothing that stays: it is dead code. When its buffer goes, the read goes
// with it (and with the rest of the body's dead code), with a remark, so no
// read is left naming a buffer that is gone.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/IR/PatternMatch.h"
#include "mlir/Interfaces/SideEffectInterfaces.h"
#include "mlir/Transforms/RegionUtils.h"
#include "llvm/ADT/BitVector.h"
#include "llvm/ADT/SetVector.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMPRUNE
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

using SymbolSet = llvm::SetVector<StringAttr>;

/// Adds to `buffers` every buffer read by an operation on the backward slice
/// of `roots` (values, and operations that count whole) inside a component
/// body.
void collectSliceReads(ArrayRef<Value> rootValues,
                       ArrayRef<Operation *> rootOps, SymbolSet &buffers) {
  SmallVector<Value> worklist(rootValues);
  llvm::DenseSet<Value> seenValues;
  llvm::DenseSet<Operation *> seenOps;
  auto visitOp = [&](Operation *op) {
    if (seenOps.contains(op))
      return;
    op->walk([&](Operation *nested) {
      seenOps.insert(nested);
      if (auto read = dyn_cast<ReadOp>(nested))
        buffers.insert(read.getBufferAttr().getAttr());
      if (auto load = dyn_cast<LoadOp>(nested))
        buffers.insert(load.getBufferAttr().getAttr());
      llvm::append_range(worklist, nested->getOperands());
    });
  };
  for (Operation *op : rootOps)
    visitOp(op);
  while (!worklist.empty()) {
    Value value = worklist.pop_back_val();
    if (!seenValues.insert(value).second)
      continue;
    if (Operation *def = value.getDefiningOp()) {
      visitOp(def);
      continue;
    }
    // A block argument of a nested region (a loop's iteration argument)
    // depends on the whole op; the body's own arguments depend on nothing.
    Operation *parent = cast<BlockArgument>(value).getOwner()->getParentOp();
    if (parent && !isa<ComponentOp>(parent))
      visitOp(parent);
  }
}

/// The operations of `body` that stay whatever uses their results: those
/// region dead-code elimination keeps (writes, unknown effects), apart from
/// terminators, whose operands matter only through their parent.
SmallVector<Operation *> collectEffectRoots(Region &body) {
  SmallVector<Operation *> roots;
  body.walk([&](Operation *op) {
    if (!op->hasTrait<OpTrait::IsTerminator>() && !wouldOpBeTriviallyDead(op))
      roots.push_back(op);
  });
  return roots;
}

/// Adds every buffer read anywhere in `region`.
void collectRegionReads(Region &region, SymbolSet &buffers) {
  region.walk([&](Operation *op) {
    if (auto read = dyn_cast<ReadOp>(op))
      buffers.insert(read.getBufferAttr().getAttr());
    if (auto load = dyn_cast<LoadOp>(op))
      buffers.insert(load.getBufferAttr().getAttr());
  });
}

struct PrunePass : public sim::impl::SimPruneBase<PrunePass> {
  /// Components whose effect roots are already in `needed`.
  llvm::DenseSet<Operation *> rootsCollected;

  void runOnOperation() override {
    rootsCollected.clear();
    SimulationOp simulation = getOperation();
    if (failed(checkBeforeInterpolation(simulation, getArgument(),
                                        "its components and buffers are")))
      return signalPassFailure();
    ObserveOp observe = simulation.getObserveOp();
    if (!observe) {
      simulation.emitError()
          << "has no 'sim.observe', so nothing is needed; list the observed "
             "output buffers before pruning";
      return signalPassFailure();
    }
    auto &analysis = getAnalysis<DependencyAnalysis>();

    SymbolSet needed;
    for (auto name : observe.getBuffers().getAsRange<FlatSymbolRefAttr>())
      needed.insert(name.getAttr());
    for (TotalOp total : simulation.getTotals())
      collectRegionReads(total.getBody(), needed);
    // `needed` grows while we walk it: it doubles as the worklist.
    for (unsigned index = 0; index < needed.size(); ++index) {
      BufferOp buffer =
          simulation.lookupBuffer(FlatSymbolRefAttr::get(needed[index]));
      addDependencies(analysis, buffer, needed);
    }

    IRRewriter rewriter(&getContext());
    for (ComponentOp component : analysis.getComponents()) {
      SmallVector<BufferOp> written = analysis.getWrittenBuffers(component);
      llvm::BitVector dropped(written.size());
      for (auto [index, buffer] : llvm::enumerate(written))
        if (!needed.contains(buffer.getSymNameAttr()))
          dropped.set(index);
      if (dropped.all()) {
        InFlightDiagnostic remark = component.emitRemark()
                                    << "removed component @"
                                    << component.getSymName()
                                    << ": no observed buffer depends on it";
        // Its values feed no output, but its num_steps may have set the big
        // step of every component: that goes with it.
        if (component.hasNumSteps())
          remark << "; its num_steps, which bounds the big step under "
                    "traditional (and under hip where it reads through the "
                    "back edge), goes with it, so the big steps, and the "
                    "values of outputs that sub-step, can differ from a run "
                    "that observes @"
                 << written.front().getSymName()
                 << " (observe a buffer it writes to keep it)";
        rewriter.eraseOp(component);
        continue;
      }
      bool deadReads = remarkDeadReads(component, needed);
      if (dropped.any())
        dropWrites(rewriter, component, written, dropped);
      if (deadReads && failed(eraseDeadReads(rewriter, component, needed)))
        return signalPassFailure();
    }
    for (BufferOp buffer : analysis.getBuffers()) {
      if (needed.contains(buffer.getSymNameAttr()))
        continue;
      buffer.emitRemark() << "removed buffer @" << buffer.getSymName()
                          << ": no observed buffer depends on it";
      rewriter.eraseOp(buffer);
    }
    pruneSchedule(simulation);
  }

  /// Marks what `buffer` depends on as needed.
  void addDependencies(const DependencyAnalysis &analysis, BufferOp buffer,
                       SymbolSet &needed) {
    ComponentOp writer = analysis.getWriter(buffer);
    if (writer.hasNumSteps())
      collectRegionReads(writer.getNumSteps(), needed);
    auto yield = cast<YieldOp>(writer.getEvaluate().front().getTerminator());
    auto writes = writer.getWrites().getAsRange<FlatSymbolRefAttr>();
    unsigned position = std::distance(
        writes.begin(),
        llvm::find(writes, FlatSymbolRefAttr::get(buffer.getSymNameAttr())));
    collectSliceReads(yield.getValues()[position], {}, needed);
    if (rootsCollected.insert(writer).second)
      collectSliceReads({}, collectEffectRoots(writer.getEvaluate()), needed);
    for (FlatSymbolRefAttr aux :
         buffer.getInterpolation().getAuxiliaryBuffers())
      needed.insert(aux.getAttr());
    collectRegionReads(buffer.getInit(), needed);
    collectRegionReads(buffer.getExact(), needed);
  }

  /// Removes the buffers marked in `dropped` from `component`'s writes and its
  /// evaluate results, then the code that only computed them.
  void dropWrites(IRRewriter &rewriter, ComponentOp component,
                  ArrayRef<BufferOp> written, const llvm::BitVector &dropped) {
    SmallVector<Attribute> kept;
    for (auto [index, writtenBuffer] : llvm::enumerate(written)) {
      BufferOp buffer = writtenBuffer;
      if (!dropped.test(index)) {
        kept.push_back(FlatSymbolRefAttr::get(buffer.getSymNameAttr()));
        continue;
      }
      component.emitRemark()
          << "@" << component.getSymName() << " no longer writes @"
          << buffer.getSymName() << ": no observed buffer depends on it";
    }
    component.setWritesAttr(rewriter.getArrayAttr(kept));
    auto yield = cast<YieldOp>(component.getEvaluate().front().getTerminator());
    yield->eraseOperands(dropped);
    (void)runRegionDCE(rewriter, component.getEvaluate());
  }

  /// Emits a remark at each read in the evaluate body of `component` (which
  /// is kept) of a buffer that is not needed, and says whether there is one.
  /// Such a read is on no slice of what stays, so nothing that stays uses
  /// its value: it goes with the body's dead code (eraseDeadReads).
  bool remarkDeadReads(ComponentOp component, const SymbolSet &needed) {
    bool any = false;
    component.getEvaluate().walk([&](ReadOp read) {
      if (needed.contains(read.getBufferAttr().getAttr()))
        return;
      read.emitRemark() << "removed this read of " << read.getBufferAttr()
                        << " from @" << component.getSymName()
                        << ": no observed buffer depends on its value";
      any = true;
    });
    return any;
  }

  /// Removes the dead code of `component`'s evaluate body, and with it the
  /// reads of buffers that are not needed. Region DCE runs until it changes
  /// nothing: in the round that erases a dead loop, the loop's terminator
  /// still keeps what it yields alive.
  LogicalResult eraseDeadReads(IRRewriter &rewriter, ComponentOp component,
                               const SymbolSet &needed) {
    Region &evaluate = component.getEvaluate();
    while (succeeded(runRegionDCE(rewriter, evaluate)))
      ;
    // Cannot happen while the slices cover what DCE keeps; an error here
    // beats a read of a buffer that is gone.
    WalkResult left = evaluate.walk([&](ReadOp read) {
      if (needed.contains(read.getBufferAttr().getAttr()))
        return WalkResult::advance();
      read.emitOpError() << "reads " << read.getBufferAttr()
                         << ", which no observed buffer depends on, but "
                            "--sim-prune cannot remove the read";
      return WalkResult::interrupt();
    });
    return failure(left.wasInterrupted());
  }

  /// Drops removed components from the schedule (and the schedule when it
  /// becomes empty).
  void pruneSchedule(SimulationOp simulation) {
    ScheduleOp schedule = simulation.getScheduleOp();
    if (!schedule)
      return;
    auto keep = [&](ArrayAttr list) {
      SmallVector<Attribute> kept;
      for (auto name : list.getAsRange<FlatSymbolRefAttr>())
        if (simulation.lookupComponent(name))
          kept.push_back(name);
      return ArrayAttr::get(&getContext(), kept);
    };
    ArrayAttr order = keep(schedule.getOrder());
    if (order.empty()) {
      schedule.erase();
      return;
    }
    schedule.setOrderAttr(order);
    if (ArrayAttr bounds = schedule.getBoundedByAttr()) {
      ArrayAttr keptBounds = keep(bounds);
      if (keptBounds.empty())
        schedule.removeBoundedByAttr();
      else
        schedule.setBoundedByAttr(keptBounds);
    }
  }
};

} // namespace
