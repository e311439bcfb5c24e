//===- Scheduling.cpp - the order of components in one step ---------------===//
//
// Topological sort of the in-step dependencies with the back edge cut at the
// entry component. Diagnostics name what the user must decide: the cycle
// (with the reads that form it), the components that could go next, or the
// dependency a user-given order violates.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/Scheduling.h"
#include "sim/Support/Cycles.h"

#include "mlir/IR/Diagnostics.h"
#include "llvm/ADT/STLExtras.h"
#include "llvm/ADT/SmallPtrSet.h"

using namespace mlir;
using namespace mlir::sim;

//===----------------------------------------------------------------------===//
// Schedule
//===----------------------------------------------------------------------===//

Schedule::Schedule(SmallVector<ComponentOp> order) : order(std::move(order)) {
  for (auto [index, component] : llvm::enumerate(this->order))
    position[component] = index;
}

ReadRole Schedule::getRole(ComponentOp reader, ComponentOp writer) const {
  if (reader == writer)
    return ReadRole::own;
  return getPosition(writer) < getPosition(reader) ? ReadRole::interpolate
                                                   : ReadRole::back_edge;
}

SmallVector<ComponentOp>
Schedule::getHipStepBounds(const DependencyAnalysis &analysis) const {
  SmallVector<ComponentOp> bounds;
  for (ComponentOp component : order) {
    // Without num_steps a component never limits a step.
    if (!component.hasNumSteps())
      continue;
    bool readsBackEdge = llvm::any_of(
        analysis.getProducers(component), [&](ComponentOp producer) {
          return getRole(component, producer) == ReadRole::back_edge;
        });
    if (readsBackEdge)
      bounds.push_back(component);
  }
  return bounds;
}

SmallVector<ComponentOp> Schedule::getTraditionalStepBounds() const {
  return llvm::filter_to_vector(
      order, [](ComponentOp component) { return component.hasNumSteps(); });
}

SmallVector<ComponentOp> mlir::sim::getUserOrder(SimulationOp simulation) {
  SmallVector<ComponentOp> order;
  if (ScheduleOp schedule = simulation.getScheduleOp())
    for (auto name : schedule.getOrder().getAsRange<FlatSymbolRefAttr>())
      if (ComponentOp component = simulation.lookupComponent(name))
        order.push_back(component);
  return order;
}

//===----------------------------------------------------------------------===//
// computeSchedule
//===----------------------------------------------------------------------===//

namespace {

/// The in-step dependency graph: an edge producer -> consumer for every
/// buffer a consumer reads from another component, except reads by the entry
/// (they cross the back edge).
class StepGraph {
public:
  StepGraph(const DependencyAnalysis &analysis, ComponentOp entry)
      : analysis(analysis), entry(entry) {}

  /// The producers of `component` within the step.
  SmallVector<ComponentOp> getInStepProducers(ComponentOp component) const {
    if (component == entry)
      return {};
    return analysis.getProducers(component);
  }

  /// Returns a dependency cycle: each component reads what the previous one
  /// writes, the first what the last writes.
  SmallVector<ComponentOp> findCycle() const {
    ArrayRef<ComponentOp> components = analysis.getComponents();
    auto consumers = [&](ComponentOp producer) {
      return llvm::filter_to_vector(components, [&](ComponentOp consumer) {
        return llvm::is_contained(getInStepProducers(consumer), producer);
      });
    };
    return sim::findCycle(components, consumers);
  }

private:
  const DependencyAnalysis &analysis;
  ComponentOp entry;
};

/// Builds diagnostics about the schedule of one simulation.
class ScheduleDiagnostics {
public:
  ScheduleDiagnostics(const DependencyAnalysis &analysis, bool enabled)
      : analysis(analysis), enabled(enabled) {}

  /// The operation errors are reported on: the user's schedule if any.
  Operation *getAnchor() const {
    SimulationOp simulation = analysis.getSimulation();
    if (ScheduleOp schedule = simulation.getScheduleOp())
      return schedule;
    return simulation;
  }

  /// Attaches one note per edge of `cycle` at the read that forms it.
  void noteCycleReads(InFlightDiagnostic &diag,
                      ArrayRef<ComponentOp> cycle) const {
    for (auto [index, producer] : llvm::enumerate(cycle)) {
      ComponentOp consumer = cycle[(index + 1) % cycle.size()];
      noteRead(diag, consumer, producer);
    }
  }

  /// Notes where `consumer` reads a buffer of `producer`.
  void noteRead(InFlightDiagnostic &diag, ComponentOp consumer,
                ComponentOp producer) const {
    for (const BufferAccess &access : analysis.getAccesses(consumer)) {
      if (analysis.getWriter(access.buffer) != producer)
        continue;
      diag.attachNote(access.reads.front().getLoc())
          << "@" << consumer.getSymName() << " reads @"
          << access.buffer.getSymName() << ", which @" << producer.getSymName()
          << " writes";
      return;
    }
  }

  static void printCycle(InFlightDiagnostic &diag,
                         ArrayRef<ComponentOp> cycle) {
    for (ComponentOp component : cycle)
      diag << "@" << component.getSymName() << " -> ";
    diag << "@" << ComponentOp(cycle.front()).getSymName();
  }

  static void printList(InFlightDiagnostic &diag,
                        ArrayRef<ComponentOp> components) {
    diag << "[";
    llvm::interleaveComma(components, diag, [&](ComponentOp c) {
      diag << "@" << c.getSymName();
    });
    diag << "]";
  }

  LogicalResult cycleWithoutEntry(ArrayRef<ComponentOp> cycle) const {
    if (!enabled)
      return failure();
    InFlightDiagnostic diag = analysis.getSimulation().emitError()
                              << "the components depend on each other in a "
                                 "cycle (";
    printCycle(diag, cycle);
    diag << "), so a step needs a first component whose reads cross the back "
            "edge; name it with 'sim.schedule [@"
         << ComponentOp(cycle.front()).getSymName() << "]' or similar";
    noteCycleReads(diag, cycle);
    return diag;
  }

  LogicalResult cycleInStep(ComponentOp entry,
                            ArrayRef<ComponentOp> cycle) const {
    if (!enabled)
      return failure();
    InFlightDiagnostic diag = getAnchor()->emitError()
                              << "dependency cycle inside one step: ";
    printCycle(diag, cycle);
    diag << "; only the first component (@" << entry.getSymName()
         << ") reads through the back edge";
    noteCycleReads(diag, cycle);
    return diag;
  }

  LogicalResult ambiguous(ArrayRef<ComponentOp> scheduled,
                          ArrayRef<ComponentOp> candidates) const {
    if (!enabled)
      return failure();
    InFlightDiagnostic diag = getAnchor()->emitError();
    if (scheduled.empty()) {
      diag << "the dependency graph does not decide which component starts a "
              "step: any of ";
    } else {
      diag << "the dependency graph does not decide the order after ";
      printList(diag, scheduled);
      diag << ": any of ";
    }
    printList(diag, candidates);
    diag << " could go next; list the order in 'sim.schedule'";
    for (ComponentOp candidate : candidates)
      diag.attachNote(candidate.getLoc())
          << "@" << candidate.getSymName() << " could go next";
    return diag;
  }

  LogicalResult violation(ComponentOp placed, ComponentOp producer) const {
    if (!enabled)
      return failure();
    InFlightDiagnostic diag = getAnchor()->emitError()
                              << "places @" << placed.getSymName()
                              << " before @" << producer.getSymName()
                              << ", but @" << placed.getSymName()
                              << " reads what @" << producer.getSymName()
                              << " writes in the same step; only the first "
                                 "component reads through the back edge";
    noteRead(diag, placed, producer);
    return diag;
  }

private:
  const DependencyAnalysis &analysis;
  bool enabled;
};

} // namespace

FailureOr<Schedule>
mlir::sim::computeSchedule(const DependencyAnalysis &analysis,
                           ArrayRef<ComponentOp> userOrder,
                           bool emitDiagnostics) {
  ScheduleDiagnostics diagnostics(analysis, emitDiagnostics);
  ArrayRef<ComponentOp> components = analysis.getComponents();
  if (components.empty())
    return Schedule({});

  ComponentOp entry = userOrder.empty() ? nullptr : userOrder.front();
  StepGraph graph(analysis, entry);
  SmallVector<ComponentOp> cycle = graph.findCycle();
  if (!cycle.empty()) {
    if (!entry)
      return diagnostics.cycleWithoutEntry(cycle);
    return diagnostics.cycleInStep(entry, cycle);
  }

  // Kahn's algorithm; candidates in program order keep diagnostics stable.
  SmallVector<ComponentOp> order;
  llvm::SmallPtrSet<Operation *, 16> scheduled;
  while (order.size() < components.size()) {
    auto isReady = [&](ComponentOp component) {
      return !scheduled.contains(component) &&
             llvm::all_of(graph.getInStepProducers(component),
                          [&](ComponentOp p) { return scheduled.contains(p); });
    };
    ComponentOp next;
    if (order.size() < userOrder.size()) {
      next = userOrder[order.size()];
      if (!isReady(next)) {
        for (ComponentOp producer : graph.getInStepProducers(next))
          if (!scheduled.contains(producer))
            return diagnostics.violation(next, producer);
      }
    } else {
      SmallVector<ComponentOp> ready =
          llvm::filter_to_vector(components, isReady);
      assert(!ready.empty() && "an acyclic graph always has a ready node");
      if (ready.size() > 1)
        return diagnostics.ambiguous(order, ready);
      next = ready.front();
    }
    order.push_back(next);
    scheduled.insert(next);
  }
  return Schedule(std::move(order));
}

/// Whether `component` reads a buffer that the writer of a pair (a
/// recorded flux_window) writes: through a view read, or through the
/// explicit load --sim-insert-interpolation made of one (the lowerings
/// check the recorded stepping after it).
static bool readsPairWriter(ComponentOp component) {
  auto simulation = component->getParentOfType<SimulationOp>();
  WalkResult found = component->walk([&](Operation *op) {
    FlatSymbolRefAttr name;
    if (auto read = dyn_cast<ReadOp>(op))
      name = read.getBufferAttr();
    else if (auto load = dyn_cast<LoadOp>(op))
      name = load.getBufferAttr();
    else
      return WalkResult::advance();
    BufferOp buffer = simulation.lookupBuffer(name);
    ComponentOp writer = buffer ? simulation.getWriter(buffer) : ComponentOp();
    return writer && writer != component && writer.getFluxWindowAttr()
               ? WalkResult::interrupt()
               : WalkResult::advance();
  });
  return found.wasInterrupted();
}

bool mlir::sim::boundsBigStep(ComponentOp component) {
  ScheduleOp schedule =
      component->getParentOfType<SimulationOp>().getScheduleOp();
  ArrayAttr bounds = schedule ? schedule.getBoundedByAttr() : ArrayAttr();
  return component.hasNumSteps() && bounds &&
         llvm::is_contained(bounds.getAsRange<FlatSymbolRefAttr>(),
                            FlatSymbolRefAttr::get(component.getSymNameAttr()));
}

FailureOr<Stepping> mlir::sim::decideStepping(ComponentOp component,
                                              Strategy strategy) {
  auto simulation = component->getParentOfType<SimulationOp>();
  ScheduleOp schedule = simulation.getScheduleOp();
  if (!schedule || !simulation.getSchedulePosition(component))
    return component.emitOpError()
           << "is not in a complete schedule; run --sim-schedule before "
              "deciding how it takes a big step";
  bool hasNumSteps = component.hasNumSteps();
  // With max_steps 1 every big step is one base step whatever num_steps
  // says: an estimate cannot lengthen it and a sub-step is the whole step,
  // so every strategy takes it as simple does and pays for neither.
  if (simulation.getMaxSteps() <= 1)
    return Stepping{Advance::whole_step, false};
  switch (strategy) {
  case Strategy::simple:
    return Stepping{Advance::whole_step, false};
  case Strategy::traditional:
    return Stepping{Advance::whole_step, hasNumSteps};
  case Strategy::hip:
  case Strategy::hip_cache:
  case Strategy::lts:
    break;
  }
  // hip: the big step is the minimum num_steps at T of the components that
  // read through the back edge. One of them takes the whole step in one
  // evaluation (its own minimum is at least m); the others sub-step.
  // lts: the flux writer of a flux pair (a recorded flux_window) runs inside
  // its reader's slots, so its smallest estimate no longer bounds the big
  // step; where it bounds it under hip, its largest does (docs/Model.md,
  // "The big step").
  if (strategy == Strategy::lts && component.getFluxWindowAttr())
    return Stepping{Advance::local_flux, boundsBigStep(component)};
  // lts: the reader of a pair takes local steps even without num_steps of
  // its own: its writer's estimates bound its blocks.
  if (strategy == Strategy::lts && component.getLocalWindowAttr() &&
      !hasNumSteps && readsPairWriter(component))
    return Stepping{Advance::local_steps, false};
  bool bounding = boundsBigStep(component);
  if (!hasNumSteps || bounding)
    return Stepping{Advance::whole_step, bounding};
  if (!component.getSubSteppingAttr())
    return component.emitOpError()
           << "has no sub-stepping verdict; run --sim-substep-legality "
              "before deciding how it takes a big step";
  // lts: a grid_sync component whose own reads allow it, or the reader of
  // a flux pair (the recorded local_window), advances each block at its
  // own rate.
  if (strategy == Strategy::lts && component.getLocalWindowAttr())
    return Stepping{Advance::local_steps, false};
  if (*component.getSubStepping() == SubStepping::in_kernel)
    return Stepping{Advance::group_substeps, false};
  return Stepping{Advance::grid_substeps, false};
}

int64_t mlir::sim::getStepCap(SimulationOp simulation, Strategy strategy) {
  return strategy == Strategy::simple ? 1 : simulation.getMaxSteps();
}
