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
// Pairs are recognised here too. A flux pair (docs/Model.md,
// "Conservation"): the first component of the schedule writes only
// `#sim.flux` buffers, one component reads them all through windows and
// writes every buffer the first one reads. An item pair ("Item pairs"): the
// first component bounds the big step and writes values, from the state
// that one component writes, that the component reads at its own items (the
// forces and the integrator of particles) or, where the writer keeps state
// of its own, at its neighbours (the two fields of a staggered scheme). The
// pass records the reader's window of the values as `flux_window` on the writer
// and widens the reader's `local_window` by the reads of its own buffers
// through them; a remark on the writer says that the two form a pair, or why
// they cannot.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMSUBSTEPLEGALITY
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// The widest window, in items, at which a pair's reader may read the
/// writer's values (docs/Model.md, "Conservation").
constexpr int64_t kMaxFluxWindow = 4096;

/// The items of a block that chooses one level under lts (the bundle
/// schema's LocalStepBlock).
constexpr int64_t kLevelBlockItems = 32;

/// How a body turns a gather into a window (the dependency analysis bounds
/// both forms): a neighbour list's entry clamped around the item has a
/// known reach.
constexpr llvm::StringLiteral kWindowHint =
    "%i plus a bounded offset, or an index clamped to %i - w .. %i + w with "
    "arith.maxsi and arith.minsi";

/// Why a read of `buffer` at another item cannot be answered from the time
/// levels `writer`'s blocks keep under lts, or an empty string. An
/// interpolation that reads auxiliary buffers (a Hermite derivative) needs
/// them at the same two time levels, which only the buffers `writer`
/// writes have, and at the same item, which one boundary rule gives.
std::string whyLevelsLackAuxiliaries(BufferOp buffer, ComponentOp writer) {
  InterpolationAttrInterface interp = buffer.getInterpolation();
  auto simulation = buffer->getParentOfType<SimulationOp>();
  ArrayAttr writes = writer.getWrites();
  std::string why;
  llvm::raw_string_ostream os(why);
  for (auto [index, aux] : llvm::enumerate(interp.getAuxiliaryBuffers())) {
    BufferOp auxBuffer = simulation.lookupBuffer(aux);
    if (!auxBuffer)
      continue;
    StringRef role = interp.getAuxiliaryBufferRole(index);
    if (!llvm::is_contained(writes, aux)) {
      os << "@" << buffer.getSymName() << "'s interpolation reads " << aux
         << " (" << role << "), which @" << writer.getSymName()
         << " does not write, so it is not kept at every item's two time "
            "levels; let @"
         << writer.getSymName() << " write " << aux
         << ", or use #sim.linear or #sim.cubic for @" << buffer.getSymName();
      break;
    }
    if (auxBuffer.getBoundary() != buffer.getBoundary()) {
      os << "@" << buffer.getSymName() << "'s interpolation reads " << aux
         << " (" << role << ") at @" << buffer.getSymName() << "'s items, but "
         << aux << " has boundary("
         << stringifyBoundary(auxBuffer.getBoundary()) << ") where @"
         << buffer.getSymName() << " has boundary("
         << stringifyBoundary(buffer.getBoundary())
         << "); give both one boundary rule";
      break;
    }
  }
  return why;
}

struct SubstepLegalityPass
    : public sim::impl::SimSubstepLegalityBase<SubstepLegalityPass> {
  using Base::Base;

  /// A remark that explains a verdict: emitted with `remarks`, else built
  /// (notes and all) and dropped, so that every path records the same.
  InFlightDiagnostic explain(Operation *op) {
    InFlightDiagnostic remark = op->emitRemark();
    if (!remarks)
      remark.abandon();
    return remark;
  }

  /// A remark about a flux or item pair, which only lts forms: emitted
  /// with `remarks` and `pair-remarks`.
  InFlightDiagnostic explainPair(Operation *op) {
    InFlightDiagnostic remark = explain(op);
    if (!pairRemarks)
      remark.abandon();
    return remark;
  }

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
      component.removeLocalReadsAttr();
      if (!hazard)
        continue;
      InFlightDiagnostic remark =
          explain(component)
          << "@" << component.getSymName()
          << " needs a grid-wide barrier between sub-steps: its "
          << stringifyBodyKind(hazard->body) << " body reads @"
          << hazard->buffer.getSymName() << ", which it writes, "
          << describeWhere(hazard->pattern)
          << ", so a thread could read another item while that item is "
             "between sub-steps";
      // The note points at the window read that reaches farthest, the one
      // that sets how wide the window is (in a 2-D stencil on a flattened
      // grid the read of the row above, not of the item to the left), or
      // at a gather (under lts a gather gets a note of its own).
      auto reach = [&](ReadOp read) -> int64_t {
        AccessPattern pattern = analysis.getPattern(read);
        if (pattern.isOwn())
          return -1;
        if (pattern.isGather())
          return 0;
        return std::max(-pattern.getMinOffset(), pattern.getMaxOffset());
      };
      ReadOp offending =
          *llvm::max_element(hazard->reads, [&](ReadOp a, ReadOp b) {
            return reach(a) < reach(b);
          });
      remark.attachNote(offending.getLoc())
          << "reads @" << hazard->buffer.getSymName() << " "
          << describeWhere(analysis.getPattern(offending));
      recordLocalWindow(analysis, component, offending, remark);
    }
    for (ComponentOp component : analysis.getComponents())
      component.removeFluxWindowAttr();
    for (ComponentOp component : analysis.getComponents())
      recordPair(analysis, component);
    markAllAnalysesPreserved();
  }

  /// "at i-1..i+1", or "through a gather".
  static std::string describeWhere(const AccessPattern &pattern) {
    return pattern.isGather() ? "through a gather" : "at " + pattern.str();
  }

  /// Records `flux_window` on `writer` and widens its reader's
  /// `local_window` when the two form a pair; emits a remark that says so,
  /// or why not, when `writer` writes a `#sim.flux` buffer, or when it is an
  /// entry that bounds the big step and whose values one component reads.
  void recordPair(const DependencyAnalysis &analysis, ComponentOp writer) {
    SmallVector<BufferOp> outputs = analysis.getWrittenBuffers(writer);
    auto isFlux = [](BufferOp buffer) {
      return isa<FluxInterpAttr>(buffer.getInterpolation());
    };
    // A flux pair (docs/Model.md, "Conservation") or an item pair ("Item
    // pairs"): each of the writer's items then steps with the coarsest
    // block that reads it.
    bool fluxPair = llvm::any_of(outputs, isFlux);
    StringRef name = writer.getSymName();
    ScheduleOp schedule = analysis.getSimulation().getScheduleOp();
    bool isEntry = schedule && !schedule.getOrder().empty() &&
                   cast<FlatSymbolRefAttr>(schedule.getOrder()[0]).getAttr() ==
                       writer.getSymNameAttr();
    // The one component other than the writer that reads the writer's
    // values, if there is one. A writer that also reads them (a kick that
    // updates its own velocity) has the shape and is refused below with a
    // remark.
    ComponentOp reader;
    bool oneReader = true;
    for (ComponentOp component : analysis.getComponents())
      for (const BufferAccess &access : analysis.getAccesses(component))
        if (component != writer && llvm::is_contained(outputs, access.buffer)) {
          if (reader && reader != component)
            oneReader = false;
          reader = component;
        }
    if (!fluxPair) {
      // Only the shape of a pair is worth a remark: the entry, whose
      // num_steps bounds the big step, computes values that one component
      // reads from the state that component alone writes.
      if (!isEntry || !boundsBigStep(writer) || !reader || !oneReader)
        return;
      // A reader that writes fluxes is the writer of a flux pair placed
      // after its cells: its own remark says to name it first, and advice
      // about the cells' state as an item pair's values would mislead.
      if (llvm::any_of(analysis.getWrittenBuffers(reader), isFlux))
        return;
      for (const BufferAccess &access : analysis.getAccesses(writer)) {
        ComponentOp producer = analysis.getWriter(access.buffer);
        if (producer && producer != reader && producer != writer)
          return;
        // A stencil of its own is no pair shape (its remark says how it
        // could take local steps); a read of its own item (a kick that
        // updates its velocity) is, and is refused below.
        if (producer == writer && !access.pattern.isOwn())
          return;
      }
    }
    StringRef readerName = reader ? reader.getSymName() : StringRef();
    auto refuse = [&]() {
      InFlightDiagnostic remark = explainPair(writer);
      if (fluxPair)
        remark << "under lts @" << name
               << " and the readers of its fluxes take the big step as under "
                  "hip: ";
      else
        remark << "under lts @" << name << " and @" << readerName
               << " form no pair, and @" << name
               << "'s num_steps bounds the big step as under hip: ";
      return remark;
    };
    if (fluxPair) {
      for (BufferOp buffer : outputs)
        if (!isFlux(buffer)) {
          refuse() << "it also writes @" << buffer.getSymName()
                   << ", which is not #sim.flux; a flux writer writes only "
                      "fluxes (move @"
                   << buffer.getSymName() << " to another component)";
          return;
        }
      for (BufferOp buffer : outputs)
        if (buffer.getBoundary() != outputs.front().getBoundary()) {
          refuse() << "its fluxes @" << outputs.front().getSymName() << " and @"
                   << buffer.getSymName()
                   << " have different boundary rules; give them one";
          return;
        }
    }
    // The offsets the reader reads the values at, and a buffer of the
    // writer's own state that it reads at its own item.
    std::optional<AccessPattern> fluxWindow;
    BufferOp ownState;
    const BufferAccess *neighbourRead = nullptr;
    for (ComponentOp component : analysis.getComponents())
      for (const BufferAccess &access : analysis.getAccesses(component)) {
        if (!llvm::is_contained(outputs, access.buffer))
          continue;
        if (component == writer && fluxPair) {
          refuse() << "it reads its own flux @" << access.buffer.getSymName()
                   << "; a flux writer computes fluxes from the state of "
                      "the component that reads them";
          return;
        }
        // A writer that keeps state of its own reads it at its own item
        // in evaluate: each of its items is evaluated once per step of
        // the item, so the read is of the item's latest value (allowed
        // below only where the reader reads the values at other items).
        if (component == writer && access.body == BodyKind::Evaluate &&
            access.pattern.isOwn()) {
          ownState = access.buffer;
          continue;
        }
        if (component == writer && access.body != BodyKind::Evaluate) {
          refuse() << "it reads its own @" << access.buffer.getSymName()
                   << " in its " << stringifyBodyKind(access.body)
                   << " body; under lts its items are evaluated at "
                      "different times, so read @"
                   << access.buffer.getSymName()
                   << " only in evaluate, at the item's own index";
          return;
        }
        if (component != reader) {
          refuse() << "both @" << component.getSymName() << " and @"
                   << reader.getSymName()
                   << " read its fluxes; a flux "
                      "pair has one reader, which updates the conserved "
                      "state";
          return;
        }
        if (access.body != BodyKind::Evaluate) {
          refuse() << "@" << component.getSymName() << " reads @"
                   << access.buffer.getSymName() << " in its "
                   << stringifyBodyKind(access.body) << " body; read "
                   << (fluxPair ? "fluxes" : "@" + name.str() + "'s values")
                   << " only in evaluate";
          return;
        }
        if (access.pattern.isGather()) {
          refuse() << "@" << component.getSymName() << " reads @"
                   << access.buffer.getSymName()
                   << " through a gather; the items that share an "
                      "interface must be known: read it through a window ("
                   << kWindowHint << ")";
          return;
        }
        if (!access.pattern.isOwn() && !neighbourRead)
          neighbourRead = &access;
        fluxWindow =
            fluxWindow ? fluxWindow->join(access.pattern) : access.pattern;
      }
    if (!reader) {
      refuse() << "no component reads its fluxes";
      return;
    }
    // Every interface's estimate bounds the blocks of all the items that
    // read it: a window of more than kMaxFluxWindow items would combine
    // thousands of blocks per interface (the GPU's levels kernel has an
    // atomic per block an interface reaches).
    if (fluxWindow->getMaxOffset() - fluxWindow->getMinOffset() >=
        kMaxFluxWindow) {
      refuse() << "@" << readerName << " reads its fluxes at "
               << fluxWindow->str() << ", more than " << kMaxFluxWindow
               << " items apart; read them within " << kMaxFluxWindow
               << " items of the reading item";
      return;
    }
    // A writer without state of its own computes its values from the
    // reader's state alone (a force): read at other items, each value would
    // be held over the steps of the coarsest block that reads it, which only
    // a flux means.
    if (!fluxPair && !ownState && neighbourRead) {
      refuse() << "@" << readerName << " reads @"
               << neighbourRead->buffer.getSymName() << " at "
               << neighbourRead->pattern.str() << "; read @"
               << neighbourRead->buffer.getSymName()
               << " only at the item's own index, or make it #sim.flux so "
                  "that its value holds over its writer's step";
      return;
    }
    // State of the writer's own makes it a dynamical component with a rate
    // of its own (a slow component next to a fast one, which hip's big
    // step already serves). Tying each of its items to the steps of the
    // blocks that read it suits the two halves of a staggered scheme, where
    // the reader reads the writer's items as interfaces between its own;
    // read at the reader's own items only (a kick and a drift), it would
    // evaluate a slow writer at its reader's rate.
    if (ownState && fluxWindow->isOwn()) {
      refuse() << "it reads its own @" << ownState.getSymName() << ", and @"
               << readerName << " reads @" << name
               << "'s values only at its own items; in an item pair @" << name
               << " computes its values from @" << readerName
               << "'s state alone: let @" << name << " write only what @"
               << readerName
               << " needs (a force or an acceleration, in a buffer of its "
                  "own) and @"
               << readerName << " write @" << ownState.getSymName()
               << " instead, updating it from its own state";
      return;
    }
    // The items that read item j of the writer's values come from the
    // window under the boundary rule of its buffers: one rule for all.
    if (!fluxPair && !fluxWindow->isOwn())
      for (BufferOp buffer : outputs)
        if (buffer.getBoundary() != outputs.front().getBoundary()) {
          refuse() << "@" << readerName << " reads its values at "
                   << fluxWindow->str() << ", and @"
                   << outputs.front().getSymName() << " and @"
                   << buffer.getSymName()
                   << " have different boundary rules; give them one";
          return;
        }
    if (!isEntry) {
      refuse() << "it is not the first component of the step; name it "
                  "first in sim.schedule so that it reads @"
               << readerName << "'s state through the back edge";
      return;
    }
    // What the writer reads: only the reader's buffers (or buffers nobody
    // writes), through windows of buffers with an interpolation of their own.
    std::optional<AccessPattern> cellWindow;
    for (const BufferAccess &access : analysis.getAccesses(writer)) {
      ComponentOp producer = analysis.getWriter(access.buffer);
      // Its own state, read at its own item (checked above).
      if (!producer || producer == writer)
        continue;
      StringRef buffer = access.buffer.getSymName();
      if (producer != reader) {
        refuse() << "it reads @" << buffer << ", which @"
                 << producer.getSymName() << " writes; a flux writer reads "
                 << "only the state of the component that reads its fluxes (@"
                 << readerName << ")";
        return;
      }
      if (access.body != BodyKind::Evaluate)
        continue;
      if (access.pattern.isGather()) {
        refuse() << "it reads @" << buffer
                 << " through a gather; read it through a window ("
                 << kWindowHint << ") so that the blocks "
                 << (fluxPair ? "an interface" : "an item of @" + name.str())
                 << " reads are known";
        return;
      }
      InterpolationAttrInterface interp = access.buffer.getInterpolation();
      if (!interp.isInterpolable()) {
        refuse() << "it reads @" << buffer
                 << ", whose value between two time levels is not an "
                    "interpolation of the two; use #sim.linear or #sim.cubic";
        return;
      }
      if (std::string why = whyLevelsLackAuxiliaries(access.buffer, reader);
          !why.empty()) {
        refuse() << "it reads @" << buffer << ": " << why;
        return;
      }
      cellWindow =
          cellWindow ? cellWindow->join(access.pattern) : access.pattern;
    }
    // The blocks' steps come from the reader's num_steps and the writer's
    // at the items they read; without either, no block has a step.
    if (!reader.hasNumSteps() && !writer.hasNumSteps()) {
      refuse() << "neither @" << name << " nor @" << readerName
               << " has num_steps, so the blocks have no step of their own";
      return;
    }
    if (reader.getSubStepping() == SubStepping::grid_sync &&
        !reader.getLocalWindowAttr()) {
      refuse() << "@" << readerName
               << " cannot take local time steps (see its remark)";
      return;
    }
    // The reader's state reaches the reader through the fluxes: the window
    // of its blocks' neighbours is widened by the flux writer's window.
    AccessPattern cells = cellWindow.value_or(AccessPattern::own());
    AccessPattern through = AccessPattern::window(
        fluxWindow->getMinOffset() + cells.getMinOffset(),
        fluxWindow->getMaxOffset() + cells.getMaxOffset());
    AccessPattern window = through.join(AccessPattern::own());
    if (DenseI64ArrayAttr own = reader.getLocalWindowAttr())
      window = window.join(AccessPattern::window(own[0], own[1]));
    reader.setLocalWindowAttr(DenseI64ArrayAttr::get(
        &getContext(), {window.getMinOffset(), window.getMaxOffset()}));
    // Reads through the pair's values join the reader's own: its kernels
    // test the whole window.
    reader.removeLocalReadsAttr();
    // The writer reads that state from the reader's time levels: its
    // window bounds the blocks one interface's evaluation reaches.
    AccessPattern state = cells.join(AccessPattern::own());
    writer.setLocalWindowAttr(DenseI64ArrayAttr::get(
        &getContext(), {state.getMinOffset(), state.getMaxOffset()}));
    writer.setFluxWindowAttr(
        DenseI64ArrayAttr::get(&getContext(), {fluxWindow->getMinOffset(),
                                               fluxWindow->getMaxOffset()}));
    // Under clamp, an interface read past an end of the range is the last
    // one again: a cell there takes a flux that no cell gives back, and the
    // scene's totals drift under every strategy.
    if (fluxPair && outputs.front().getBoundary() == Boundary::clamp &&
        !fluxWindow->isOwn())
      outputs.front().emitRemark()
          << "@" << outputs.front().getSymName() << " has boundary(clamp): @"
          << readerName << "'s reads at " << fluxWindow->str()
          << " past an end of the range take the last interface again, "
             "which no cell gives back, so a total of @"
          << readerName
          << "'s state is not conserved; boundary(zero) closes the ends, "
             "boundary(wrap) makes a ring";
    if (fluxPair)
      explainPair(writer) << "@" << name << " and @" << readerName
                          << " form a flux pair: under lts every interface of "
                             "its fluxes steps with the coarsest block that "
                             "reads it (at "
                          << fluxWindow->str() << "), and @" << readerName
                          << "'s blocks take local time steps (window "
                          << window.str() << ")";
    else if (fluxWindow->isOwn())
      explainPair(writer)
          << "@" << name << " and @" << readerName
          << " form an item pair: under lts @" << name
          << " evaluates an item whenever its block starts a "
             "sub-step, so its num_steps bounds that block rather than "
             "the big step (only its largest value does), and @"
          << readerName << "'s blocks take local time steps (window "
          << window.str() << ")";
    else
      explainPair(writer)
          << "@" << name << " and @" << readerName
          << " form an item pair: under lts @" << name
          << " evaluates an item whenever the coarsest block that reads "
             "it (at "
          << fluxWindow->str() << ") starts a sub-step, and @" << readerName
          << " reads the value it computed then until the next one, so "
             "its num_steps bounds that block rather than the big step "
             "(only its largest value does), and @"
          << readerName << "'s blocks take local time steps (window "
          << window.str() << ")";
  }

  /// A schedule that starts a step at another component and under which
  /// `component` reads nothing through the back edge, so that it no longer
  /// bounds the big step; the first such entry in the current order. The
  /// rest of the order is the graph's, or else the current one's.
  /// A schedule that only moves the bound onto another component that
  /// reads its own buffers at other items (another stencil, which would
  /// gain from local steps as much) is not returned: whether it helps
  /// depends on the two components' num_steps at run time, and that one's
  /// remark would suggest the first order back. The first such schedule is
  /// left in `movesBound`, with the stencils it would make bound the step
  /// in `newBounds`.
  static std::optional<Schedule>
  findScheduleWithoutBound(const DependencyAnalysis &analysis,
                           ComponentOp component,
                           std::optional<Schedule> &movesBound,
                           SmallVectorImpl<ComponentOp> &newBounds) {
    movesBound.reset();
    newBounds.clear();
    auto readsOwnNeighbours = [&](ComponentOp other) {
      return llvm::any_of(analysis.getAccesses(other),
                          [&](const BufferAccess &access) {
                            return access.body == BodyKind::Evaluate &&
                                   analysis.getWriter(access.buffer) == other &&
                                   !access.pattern.isOwn();
                          });
    };
    SmallVector<ComponentOp> current = getUserOrder(analysis.getSimulation());
    for (ComponentOp entry : current) {
      if (entry == component)
        continue;
      SmallVector<ComponentOp> rotated{entry};
      for (ComponentOp other : current)
        if (other != entry)
          rotated.push_back(other);
      for (ArrayRef<ComponentOp> order :
           {ArrayRef<ComponentOp>(rotated).take_front(),
            ArrayRef<ComponentOp>(rotated)}) {
        FailureOr<Schedule> schedule =
            computeSchedule(analysis, order, /*emitDiagnostics=*/false);
        if (failed(schedule))
          continue;
        SmallVector<ComponentOp> bounds = schedule->getHipStepBounds(analysis);
        if (llvm::is_contained(bounds, component))
          continue;
        if (llvm::any_of(bounds, readsOwnNeighbours)) {
          if (!movesBound) {
            movesBound = *schedule;
            llvm::append_range(
                newBounds, llvm::make_filter_range(bounds, readsOwnNeighbours));
          }
          continue;
        }
        return std::move(*schedule);
      }
    }
    return std::nullopt;
  }

  /// Records `local_reads` on `component`: the windows of its reads of its
  /// own buffers in evaluate, merged where they overlap or touch, when they
  /// leave a gap of more than two blocks inside `window` (a stencil on a
  /// flattened grid, whose window spans rows it does not read): the reads
  /// of a block's items then skip a block between them, whichever block it
  /// is. Whether a block's neighbourhood is in step then depends only on
  /// the blocks those windows reach: the same bits, fewer reads through the
  /// levels.
  void recordLocalReads(const DependencyAnalysis &analysis,
                        ComponentOp component, const AccessPattern &window) {
    // The block's own items, which every neighbourhood holds.
    SmallVector<std::pair<int64_t, int64_t>> reads = {{0, 0}};
    for (const BufferAccess &access : analysis.getAccesses(component))
      if (access.body == BodyKind::Evaluate &&
          analysis.getWriter(access.buffer) == component)
        for (ReadOp read : access.reads) {
          AccessPattern pattern = analysis.getPattern(read);
          reads.emplace_back(pattern.getMinOffset(), pattern.getMaxOffset());
        }
    llvm::sort(reads);
    SmallVector<std::pair<int64_t, int64_t>> merged;
    for (auto [lo, hi] : reads) {
      if (!merged.empty() && lo <= merged.back().second + 1)
        merged.back().second = std::max(merged.back().second, hi);
      else
        merged.emplace_back(lo, hi);
    }
    bool gap = false;
    for (size_t k = 1; k < merged.size(); ++k)
      gap |= merged[k].first - merged[k - 1].second > 2 * kLevelBlockItems;
    if (!gap || merged.front().first != window.getMinOffset() ||
        merged.back().second != window.getMaxOffset())
      return;
    SmallVector<int64_t> flat;
    for (auto [lo, hi] : merged)
      flat.append({lo, hi});
    component.setLocalReadsAttr(DenseI64ArrayAttr::get(&getContext(), flat));
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
      // num_steps runs at T, where every block is: its reads of its own
      // buffers, a gather included, see no level boundary, and neither
      // limit the blocks' levels nor widen the window.
      if (access.body != BodyKind::Evaluate ||
          analysis.getWriter(access.buffer) != component)
        continue;
      BufferOp buffer = access.buffer;
      StringRef name = buffer.getSymName();
      if (access.pattern.isGather()) {
        ReadOp gather = *llvm::find_if(access.reads, [&](ReadOp read) {
          return analysis.getPattern(read).isGather();
        });
        remark << "; under lts it cannot take local time steps: its "
               << stringifyBodyKind(access.body) << " body reads @" << name
               << " through a gather, so the blocks it reads are not known; "
                  "a window ("
               << kWindowHint
               << ") lets the levels of neighbouring blocks be limited";
        if (std::string wrapped = describeHandWrappedRead(gather, buffer);
            !wrapped.empty())
          remark << "; " << wrapped;
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
      if (std::string why = whyLevelsLackAuxiliaries(buffer, component);
          !why.empty()) {
        remark << "; under lts it cannot take local time steps: " << why;
        return;
      }
      window = window.join(access.pattern);
    }
    // A component that bounds the big step (it reads through the back
    // edge) takes it in one evaluation under lts too.
    if (boundsBigStep(component)) {
      remark << "; under lts it still takes the big step whole: it reads "
                "through the back edge, so its num_steps bounds the big step "
                "of the whole scene (per-region big steps are not built, "
                "docs/Model.md); a component that does not bound it takes "
                "local time steps";
      std::optional<Schedule> movesBound;
      SmallVector<ComponentOp> newBounds;
      auto printOrder = [&](const Schedule &schedule) {
        remark << "'sim.schedule [";
        llvm::interleaveComma(schedule.getOrder(), remark, [&](ComponentOp c) {
          remark << "@" << c.getSymName();
        });
        remark << "]'";
      };
      if (std::optional<Schedule> other = findScheduleWithoutBound(
              analysis, component, movesBound, newBounds)) {
        remark << ": ";
        printOrder(*other);
        remark << " would start a step at @" << other->getEntry().getSymName()
               << ", which then reads through the back edge, and @"
               << component.getSymName() << " would not bound it";
      } else if (movesBound) {
        // Say what the other order trades rather than that it helps: the
        // better start depends on num_steps values the compiler cannot see.
        remark << "; ";
        printOrder(*movesBound);
        remark << " would let @" << component.getSymName()
               << " take local time steps, but ";
        llvm::interleave(
            newBounds, remark,
            [&](ComponentOp c) { remark << "@" << c.getSymName(); }, " and ");
        remark << (newBounds.size() == 1 ? ", which reads its own neighbours "
                                           "too, would bound the big step "
                                           "instead"
                                         : ", which read their own neighbours "
                                           "too, would bound the big step "
                                           "instead")
               << ": start the step at the component whose num_steps is the "
                  "larger and varies less across items";
        // Stencils that read each other through the back edge advance
        // together in one component: its blocks keep all their buffers at
        // their time levels, and nothing bounds the big step but what it
        // reads of other components.
        SmallVector<BufferOp> merged = analysis.getWrittenBuffers(component);
        for (ComponentOp other : newBounds)
          llvm::append_range(merged, analysis.getWrittenBuffers(other));
        remark << "; or write ";
        for (auto [index, buffer] : llvm::enumerate(merged))
          remark << (index == 0                   ? ""
                     : index + 1 == merged.size() ? " and "
                                                  : ", ")
                 << "@" << buffer.getSymName();
        remark << " in one component (writes(";
        llvm::interleaveComma(merged, remark, [&](BufferOp b) {
          remark << "@" << b.getSymName();
        });
        remark << ")), which reads them at its blocks' time levels and takes "
                  "local time steps unless it reads another component's "
                  "buffer through the back edge";
      }
      return;
    }
    component.setLocalWindowAttr(DenseI64ArrayAttr::get(
        &getContext(), {window.getMinOffset(), window.getMaxOffset()}));
    recordLocalReads(analysis, component, window);
    // Blocks of 32 items: the bundle schema's LocalStepBlock.
    remark << "; under lts its blocks of 32 items take local time steps "
              "(window "
           << window.str() << ")";
  }
};

} // namespace
