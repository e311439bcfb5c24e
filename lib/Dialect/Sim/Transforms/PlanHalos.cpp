//===- PlanHalos.cpp - the ghost items of a distributed run ---------------===//
//
// A distributed run gives every rank a block of the range (docs/
// Distributed.md). Its kernels read other items only through windows, so
// the items a rank reads outside its block are known before it runs: the
// recorded windows of every read, joined per buffer. This pass records
// them. A gather may read an item of any rank: its buffer is recorded
// replicated, every rank holding all of it.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "llvm/ADT/MapVector.h"
#include "llvm/ADT/SetVector.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMPLANHALOS
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

struct PlanHalosPass : public sim::impl::SimPlanHalosBase<PlanHalosPass> {
  using SimPlanHalosBase::SimPlanHalosBase;

  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    if (failed(checkBeforeInterpolation(simulation, getArgument(),
                                        "its halos are")))
      return signalPassFailure();
    const DependencyAnalysis &analysis = getAnalysis<DependencyAnalysis>();

    // Per buffer: the items below and above the read item it is read at,
    // and whether a gather reads it.
    llvm::MapVector<Operation *, std::pair<int64_t, int64_t>> halos;
    llvm::SetVector<Operation *> replicated;
    // Buffers whose snapshot (their value at T) some interpolating read
    // takes at other items; the snapshots of the others need no ghosts.
    llvm::SetVector<Operation *> snapshotGhosts;
    auto record = [&](ReadOp read, const AccessPattern &pattern,
                      StringRef body) {
      BufferOp buffer = simulation.lookupBuffer(read.getBufferAttr());
      if (!buffer)
        return;
      // An interpolated read reads the auxiliary buffers of its
      // interpolation (a Hermite derivative) at the same items.
      SmallVector<BufferOp> reached = {buffer};
      bool interpolates =
          read.getRoleAttr() && read.getRole() == ReadRole::interpolate;
      // So does a read of another item's time levels under lts: of a
      // buffer a local_steps component writes, read by that component
      // or by the writer of its pair (the derivative has the same
      // writer and boundary rule: --sim-substep-legality).
      auto reader = read->getParentOfType<ComponentOp>();
      ComponentOp writer = analysis.getWriter(buffer);
      bool readsLevels =
          reader && writer && !pattern.isOwn() &&
          writer.getAdvance() == Advance::local_steps &&
          (reader == writer || reader.getAdvance() == Advance::local_flux);
      if (interpolates || readsLevels)
        for (FlatSymbolRefAttr aux :
             buffer.getInterpolation().getAuxiliaryBuffers())
          if (BufferOp auxBuffer = simulation.lookupBuffer(aux))
            reached.push_back(auxBuffer);
      // An interpolated read at other items reads their snapshots
      // there too (those that have one).
      if (interpolates && (pattern.isGather() || pattern.getMinOffset() != 0 ||
                           pattern.getMaxOffset() != 0))
        for (BufferOp target : reached)
          if (target.getSnapshot())
            snapshotGhosts.insert(target);
      if (pattern.isGather()) {
        InFlightDiagnostic remark = read.emitRemark();
        remark << "reads " << read.getBufferAttr() << " in " << body
               << " through a gather: every rank holds all of it, and the "
                  "blocks its writer computes travel to every rank after "
                  "each write (an all-gather); a window (the item plus a "
                  "constant offset) would need only the items next to "
                  "each block";
        if (std::string wrapped = describeHandWrappedRead(read, buffer);
            !wrapped.empty())
          remark << "; " << wrapped;
        for (BufferOp target : reached)
          replicated.insert(target);
        return;
      }
      int64_t below = std::max<int64_t>(0, -pattern.getMinOffset());
      int64_t above = std::max<int64_t>(0, pattern.getMaxOffset());
      if (below == 0 && above == 0)
        return;
      // Past an end of the range, a derivative with another boundary
      // rule is read at the interpolated buffer's item under that
      // buffer's rule (InsertInterpolation.cpp); under wrap that item
      // lies at the other end of the range, on another rank, and not
      // among the derivative's ghost items, which follow its own rule.
      if (interpolates && buffer.getBoundary() == Boundary::wrap)
        for (BufferOp aux : ArrayRef(reached).drop_front())
          if (aux.getBoundary() != Boundary::wrap &&
              !replicated.contains(aux)) {
            read.emitRemark()
                << "reads " << read.getBufferAttr() << " in " << body
                << " at other items; past an end of the range its "
                   "derivative "
                << FlatSymbolRefAttr::get(aux.getSymNameAttr()) << " (boundary("
                << stringifyBoundary(aux.getBoundary())
                << ")) is read at the item " << read.getBufferAttr()
                << "'s boundary(wrap) gives, at the other end of the "
                   "range, so every rank holds all of "
                << FlatSymbolRefAttr::get(aux.getSymNameAttr())
                << " (an all-gather after each write); with one boundary "
                   "rule for both only the items next to each block "
                   "would travel";
            replicated.insert(aux);
          }
      for (BufferOp target : reached) {
        auto [it, inserted] = halos.try_emplace(target, below, above);
        if (!inserted)
          it->second = {std::max(it->second.first, below),
                        std::max(it->second.second, above)};
      }
    };
    for (const ReadInfo &info : analysis.getReads()) {
      // Init and exact bodies are recomputed at the item they read (the
      // kernels never load an initial state), so they need no ghosts.
      if (info.body != BodyKind::NumSteps && info.body != BodyKind::Evaluate)
        continue;
      record(info.read, info.pattern,
             info.body == BodyKind::NumSteps ? "num_steps" : "evaluate");
    }
    for (auto [read, pattern] : analysis.getTotalReads())
      record(read, pattern, "a total");

    int64_t largest = 0;
    Builder builder(&getContext());
    // Decided afresh: what a previous run of this pass (or a hand-written
    // scene) left is replaced.
    for (BufferOp buffer : simulation.getBuffers()) {
      buffer.removeHaloAttr();
      buffer.removeReplicatedAttr();
      buffer.removeSnapshotGhostsAttr();
    }
    for (Operation *op : replicated)
      cast<BufferOp>(op).setReplicatedAttr(builder.getUnitAttr());
    for (Operation *op : snapshotGhosts)
      cast<BufferOp>(op).setSnapshotGhostsAttr(builder.getUnitAttr());
    // A replicated buffer holds every item: it needs no ghosts.
    for (auto [op, halo] : halos) {
      if (replicated.contains(op))
        continue;
      cast<BufferOp>(op).setHaloAttr(
          builder.getDenseI64ArrayAttr({halo.first, halo.second}));
      largest = std::max({largest, halo.first, halo.second});
    }
    simulation.setDistributedHaloAttr(builder.getI64IntegerAttr(largest));
    markAllAnalysesPreserved();
  }
};

} // namespace
