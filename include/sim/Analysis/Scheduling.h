//===- Scheduling.h - the order of components in one step ------*- C++ -*-===//
//
// Computes the per-step order of components (Section 4, Figs. 5 and 6).
//
// The model: a step starts with an entry component, the first of the
// schedule. The entry's reads of other components' buffers cross the back edge
// (they read values at the start T of the big step). Every other read must be
// of a buffer advanced earlier in the same step, so the remaining read->write
// dependencies must form a DAG, and the order is its topological sort. The
// entry is decided by the user (the first element of sim.schedule) unless the
// dependencies have no cycle at all. Where the DAG leaves a choice, the user's
// order (a prefix or the whole list in sim.schedule) decides; where it does
// not, that is an error that lists the candidates, never a guess.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_ANALYSIS_SCHEDULING_H
#define SIM_ANALYSIS_SCHEDULING_H

#include "sim/Analysis/DependencyAnalysis.h"

namespace mlir::sim {

/// The order of one step and the roles it gives to reads.
class Schedule {
public:
  explicit Schedule(SmallVector<ComponentOp> order);

  /// The components in step order; the first starts a step.
  ArrayRef<ComponentOp> getOrder() const { return order; }
  ComponentOp getEntry() const { return order.front(); }
  unsigned getPosition(ComponentOp component) const {
    return position.lookup(component);
  }

  /// The role of `reader`'s reads of a buffer written by `writer`: `own` for
  /// its own buffers, `interpolate` when the writer runs earlier in the step,
  /// `back_edge` when it runs later (only the entry has such reads).
  ReadRole getRole(ComponentOp reader, ComponentOp writer) const;

  /// The components whose num_steps bound the `hip` big step: those that read
  /// through the back edge (Fig. 6) and have a num_steps body. Their inputs
  /// cannot be interpolated; a component without num_steps never bounds a
  /// step.
  SmallVector<ComponentOp>
  getHipStepBounds(const DependencyAnalysis &analysis) const;

  /// The components whose num_steps bound the `traditional` big step: every
  /// component that has a num_steps body.
  SmallVector<ComponentOp> getTraditionalStepBounds() const;

private:
  SmallVector<ComponentOp> order;
  llvm::DenseMap<Operation *, unsigned> position;
};

/// Computes the schedule of the analysed simulation. `userOrder` is the order
/// the user gave (a prefix or the whole list; may be empty). On failure,
/// emits a diagnostic that names the cycle, the candidates or the violated
/// dependency when `emitDiagnostics` is set, and returns failure.
FailureOr<Schedule> computeSchedule(const DependencyAnalysis &analysis,
                                    ArrayRef<ComponentOp> userOrder,
                                    bool emitDiagnostics = true);

/// The user's order from the simulation's sim.schedule (empty without one).
SmallVector<ComponentOp> getUserOrder(SimulationOp simulation);

/// How a component takes a big step under a strategy (docs/Model.md,
/// "Time"). `--sim-plan-memory` records it on the component for its
/// strategy, the reference lowering for every strategy; every later stage
/// reads the record, so this is the one place that decides it.
struct Stepping {
  Advance advance;
  /// The component's num_steps decides the size of the big step.
  bool estimates;
};

/// Whether `component` bounds the hip big step: it has num_steps and
/// sim.schedule's `bounded_by` (recorded by --sim-schedule) names it. False
/// before a schedule is recorded.
bool boundsBigStep(ComponentOp component);

/// Decides `component`'s stepping under `strategy` from what the front end
/// recorded: the step bounds of sim.schedule (`bounded_by`, recorded by
/// --sim-schedule) and, under hip and hip-cache, the component's
/// sub-stepping verdict (--sim-substep-legality). Emits an error at the
/// component and fails when a record it needs is missing.
FailureOr<Stepping> decideStepping(ComponentOp component, Strategy strategy);

/// The largest big step of `strategy`: 1 under simple, max_steps otherwise.
int64_t getStepCap(SimulationOp simulation, Strategy strategy);

} // namespace mlir::sim

#endif // SIM_ANALYSIS_SCHEDULING_H
