//===- PlanMemory.cpp - stepping, snapshots, parity copies and caches -----===//
//
// Records how each component takes a big step under the strategy (`advance`,
// `estimates`, and the simulation's `step_cap`, decided once by
// decideStepping in lib/Analysis/Scheduling.cpp), then plans the memory that
// needs beyond the two halves of every buffer.
// Algorithm 2 snapshots every interpolated buffer and copies after an even
// number of sub-steps because its sub-steps ping-pong between the halves. We
// keep an in_kernel component's state in registers between sub-steps (each
// thread owns its item, which is exactly what --sim-substep-legality proved),
// so its source half is never overwritten during the big step: that half is
// the value at T, and neither a snapshot nor a parity copy is needed. A
// component without num_steps takes the whole big step in one evaluation, so
// it does not ping-pong either, and neither does one that bounds the hip big
// step (its minimum num_steps at T is at least m, so it takes m at once).
// Only the other grid_sync components with num_steps ping-pong through
// memory and pay for both.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "llvm/ADT/MapVector.h"
#include "llvm/ADT/SetVector.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMPLANMEMORY
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

/// The most shared memory a GPU gives one group (227 KiB, sm_90 and sm_100
/// once a kernel opts in; sm_75 gives 64 KiB, which the runtime checks when
/// a session is made).
static constexpr int64_t kMaxSharedPerGroup = 227 * 1024;

namespace {

/// True when `component`'s sub-steps ping-pong between the halves of its
/// buffers through memory: it takes grid-wide sub-steps (its recorded
/// `advance`). Every other way of advancing reads the source half and
/// writes the target half once.
bool pingPongs(ComponentOp component) {
  return component.getAdvance() == Advance::grid_substeps ||
         component.getAdvance() == Advance::local_steps;
}

struct PlanMemoryPass : public sim::impl::SimPlanMemoryBase<PlanMemoryPass> {
  using SimPlanMemoryBase::SimPlanMemoryBase;

  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    if (failed(checkBeforeInterpolation(simulation, getArgument(),
                                        "its memory plan is")))
      return signalPassFailure();
    if (groupSize < 1) {
      simulation.emitError()
          << "--sim-plan-memory needs a positive group-size, but got "
          << static_cast<int64_t>(groupSize);
      return signalPassFailure();
    }
    auto &analysis = getAnalysis<DependencyAnalysis>();
    if (failed(checkPrerequisites(analysis)))
      return signalPassFailure();

    MLIRContext *context = &getContext();
    // How each component takes a big step first: the memory plan follows
    // from it.
    for (ComponentOp component : analysis.getComponents()) {
      FailureOr<Stepping> stepping = decideStepping(component, strategy);
      if (failed(stepping))
        return signalPassFailure();
      component.setAdvanceAttr(AdvanceAttr::get(context, stepping->advance));
      component.setEstimates(stepping->estimates);
    }
    for (ComponentOp component : analysis.getComponents()) {
      component.setInvariantLevels(component.getAdvance() ==
                                       Advance::local_steps &&
                                   hasInvariantLevels(analysis, component));
      component.setInvariantEstimate(
          component.getAdvance() == Advance::grid_substeps &&
          component.hasNumSteps() && hasInvariantNumSteps(analysis, component));
    }
    // An lts request that no component can use plans what hip plans: say
    // so (the sub-stepping remarks say why for each grid_sync component).
    if (strategy == Strategy::lts &&
        llvm::none_of(analysis.getComponents(), [](ComponentOp component) {
          return component.getAdvance() == Advance::local_steps;
        })) {
      InFlightDiagnostic remark = simulation.emitRemark();
      // The sub-stepping remarks say what a component would do under lts;
      // with max_steps 1 none does it, whatever they say.
      if (simulation.getMaxSteps() <= 1) {
        remark << "strategy lts: max_steps is 1, so every big step is one "
                  "base step and every strategy steps as simple does: no "
                  "component takes local time steps (what the remarks of "
                  "--sim-substep-legality say about lts holds from "
                  "max_steps 2)";
      } else {
        remark << "strategy lts: no component takes local time steps, so the "
                  "plan is hip's; a component takes them when it has "
                  "num_steps, reads a buffer it writes at other items through "
                  "a window (@B[%i + c]) and does not bound the big step "
                  "(read through the back edge), or when it reads at its own "
                  "items what the component that bounds the big step "
                  "computes from its state (a pair, docs/Model.md); the "
                  "remarks of --sim-substep-legality say why each component "
                  "that reads its own buffers at other items, and each pair, "
                  "does not";
        SmallVector<ComponentOp> bounding;
        for (ComponentOp component : analysis.getComponents())
          if (boundsBigStep(component))
            bounding.push_back(component);
        if (!bounding.empty()) {
          remark << "; the big step is bounded by ";
          llvm::interleaveComma(bounding, remark, [&](ComponentOp component) {
            remark << "@" << component.getSymName();
          });
        }
      }
    }
    simulation.setStrategyAttr(StrategyAttr::get(context, strategy));
    simulation.setStepCapAttr(IntegerAttr::get(
        IntegerType::get(context, 32), getStepCap(simulation, strategy)));
    // Decided afresh (also the distributed decisions, which
    // --sim-plan-halos adds after this pass for a distributed compile only:
    // left over in a scene otherwise, they would plan a distributed run
    // without its ghosts).
    simulation.removeDistributedHaloAttr();
    for (BufferOp buffer : simulation.getBuffers()) {
      buffer.removeSnapshotAttr();
      buffer.removeHaloAttr();
      buffer.removeReplicatedAttr();
      buffer.removeSnapshotGhostsAttr();
    }

    llvm::SetVector<Operation *> snapshots;
    for (ComponentOp component : analysis.getComponents()) {
      component.removeCachesAttr();
      component.setParityAttr(ParityAttr::get(
          context, pingPongs(component) ? Parity::copy_if_even : Parity::none));
      if (!isSubSteppingStrategy(strategy))
        continue;

      for (const BufferAccess &access : analysis.getAccesses(component)) {
        if (access.reads.front().getRole() != ReadRole::interpolate)
          continue;
        // The value at T of the buffer and of its interpolation's auxiliary
        // buffers must survive until this reader runs.
        SmallVector<BufferOp> atBegin = {access.buffer};
        for (FlatSymbolRefAttr aux :
             access.buffer.getInterpolation().getAuxiliaryBuffers())
          if (BufferOp auxBuffer = simulation.lookupBuffer(aux))
            atBegin.push_back(auxBuffer);
        for (BufferOp buffer : atBegin)
          if (ComponentOp writer = analysis.getWriter(buffer);
              writer && pingPongs(writer))
            snapshots.insert(buffer);
      }
      if (strategy == Strategy::hip_cache)
        planCaches(analysis, component);
    }
    for (Operation *buffer : snapshots)
      cast<BufferOp>(buffer).setSnapshot(true);
    markAnalysesPreserved<DependencyAnalysis>();
  }

  /// True when `component`'s num_steps (if any) depends on the item and
  /// the parameters only: it reads neither its local time nor a buffer
  /// (every buffer has a writer, so any buffer may change).
  static bool hasInvariantNumSteps(const DependencyAnalysis &analysis,
                                   ComponentOp component) {
    if (!component.hasNumSteps())
      return true;
    if (!component.getNumStepsTime().use_empty())
      return false;
    return llvm::none_of(analysis.getAccesses(component),
                         [&](const BufferAccess &access) {
                           return access.body == BodyKind::NumSteps;
                         });
  }

  /// True when the levels of `reader`'s blocks cannot change from one big
  /// step to the next: its num_steps, and that of every flux writer whose
  /// fluxes it reads (their estimates bound its blocks too), depends on
  /// the item and the parameters only. It reads neither its local time nor
  /// a buffer (every buffer has a writer, so any buffer may change).
  static bool hasInvariantLevels(const DependencyAnalysis &analysis,
                                 ComponentOp reader) {
    auto invariant = [&](ComponentOp component) {
      return hasInvariantNumSteps(analysis, component);
    };
    if (!invariant(reader))
      return false;
    for (const BufferAccess &access : analysis.getAccesses(reader))
      if (ComponentOp writer = analysis.getWriter(access.buffer);
          writer && writer != reader &&
          writer.getAdvance() == Advance::local_flux && !invariant(writer))
        return false;
    return true;
  }

  /// hip-cache keeps, per thread group, the interpolated values that
  /// neighbouring threads share: the window `[lo, hi]` around the group's
  /// items over every interpolated window read of a buffer (own-item reads
  /// count as offset 0; a gather has no locality and is not counted). A
  /// cache is planned only where it can be hit: with at least two items,
  /// a window of more than one offset (otherwise no thread reads another
  /// thread's value), and a halo smaller than the group.
  void planCaches(const DependencyAnalysis &analysis, ComponentOp component) {
    SimulationOp simulation = analysis.getSimulation();
    if (simulation.getRangeAttr().getInt() < 2)
      return;
    llvm::MapVector<Operation *, std::pair<int64_t, int64_t>> windows;
    for (const BufferAccess &access : analysis.getAccesses(component)) {
      for (ReadOp read : access.reads) {
        AccessPattern pattern = analysis.getPattern(read);
        if (read.getRole() != ReadRole::interpolate || pattern.isGather())
          continue;
        auto [it, inserted] = windows.try_emplace(
            access.buffer, pattern.getMinOffset(), pattern.getMaxOffset());
        if (!inserted)
          it->second = {std::min(it->second.first, pattern.getMinOffset()),
                        std::max(it->second.second, pattern.getMaxOffset())};
      }
    }
    SmallVector<Attribute> caches;
    // A group keeps its caches in shared memory: (group + halo) elements
    // each, padded as the kernels address them. No GPU gives a group more
    // than kMaxSharedPerGroup, so a cache past it could never run at this
    // group size; its reads interpolate from global memory instead, as
    // under hip, and a remark says so.
    int64_t bytes = 0;
    for (auto [buffer, window] : windows) {
      auto [lo, hi] = window;
      if (hi <= lo || hi - lo >= groupSize)
        continue;
      auto cached = cast<BufferOp>(buffer);
      int64_t element = cached.getElementBytes();
      if (isa<VectorType>(cached.getElementType()))
        element = int64_t(llvm::PowerOf2Ceil(uint64_t(element)));
      int64_t cacheBytes = (int64_t(groupSize) + hi - lo) * element;
      if (bytes + cacheBytes > kMaxSharedPerGroup) {
        component.emitRemark()
            << "under hip-cache @" << component.getSymName()
            << " keeps no cache of @" << cached.getSymName() << ": "
            << (bytes ? "with its other caches it" : "it") << " would take "
            << bytes + cacheBytes << " bytes of shared memory in a group of "
            << static_cast<int64_t>(groupSize) << ", more than the "
            << kMaxSharedPerGroup
            << " any GPU gives a group; its reads interpolate from global "
               "memory as under hip (a smaller group size or a narrower "
               "window lets it cache)";
        continue;
      }
      bytes += cacheBytes;
      caches.push_back(CacheAttr::get(
          &getContext(), FlatSymbolRefAttr::get(cached.getSymNameAttr()), lo,
          hi));
    }
    if (!caches.empty())
      component.setCachesAttr(ArrayAttr::get(&getContext(), caches));
  }

  /// The plan relies on read roles and sub-stepping verdicts; without them it
  /// would silently plan too little memory.
  LogicalResult checkPrerequisites(const DependencyAnalysis &analysis) {
    for (ComponentOp component : analysis.getComponents()) {
      if (isSubSteppingStrategy(strategy) && !component.getSubSteppingAttr())
        return component.emitOpError()
               << "has no sub-stepping verdict; run --sim-substep-legality "
                  "before --sim-plan-memory";
      for (const BufferAccess &access : analysis.getAccesses(component)) {
        for (ReadOp read : access.reads) {
          if (!read.getRoleAttr())
            return read.emitOpError()
                   << "has no read role; run --sim-schedule before "
                      "--sim-plan-memory";
          if (read.getRole() == ReadRole::interpolate &&
              failed(checkInterpolable(read, access.buffer, component,
                                       access.body, strategy)))
            return failure();
        }
      }
    }
    return success();
  }
};

} // namespace
