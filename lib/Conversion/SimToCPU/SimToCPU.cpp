//===- SimToCPU.cpp - simulations to CPU kernels and a host plan ----------===//
//
// The CPU target of the shared kernel algorithms (lib/Conversion/SimCommon,
// SimulationLowering.h), with the GPU kernels' semantics: one call runs a range
// of groups, a group runs phase by phase (a loop over its lanes between what
// would be barriers on a GPU), and takes the same group-wide sub-step. Kernels
// are func.funcs in a nested module named like the GPU kernel module, with the
// plan's arguments followed by the first group, the end group and the group
// size (docs/Bundle.md: the runtime calls them through `sim_cpu_<kernel>`).
// Clock updates are atomic, so disjoint group ranges may run on different
// threads at once.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Conversion/SimCommon/KernelTarget.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERTOCPU
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

class CPUKernelTarget : public KernelTarget {
public:
  /// --sim-lower-to-cpu=levels-per-lane: the GPU's way of limiting lts
  /// levels, so that tests run it.
  explicit CPUKernelTarget(bool levelsPerLane) : levelsPerLane(levelsPerLane) {}
  bool limitsLevelsPerLane() const override { return levelsPerLane; }

private:
  bool levelsPerLane;

public:
  Operation *createContainer(OpBuilder &b, Location loc,
                             StringRef name) override {
    auto module = ModuleOp::create(b, loc, name);
    return module;
  }

  Block *createKernel(KernelBuilder &b, Kernel &kernel, StringRef name,
                      TypeRange types) override {
    SmallVector<Type> all(types);
    all.append(3, b.getI64Type()); // first group, end group, group size
    auto func =
        func::FuncOp::create(b, b.loc, name, b.getFunctionType(all, {}));
    func->setAttr(simplan::PlanDialect::getGroupArgumentsAttrName(),
                  b.getI64IntegerAttr(3));
    kernel.func = func;
    kernel.targetArgs = 3;
    Block *entry = func.addEntryBlock();
    b.setInsertionPointToStart(entry);
    Value groupSize = b.toIndex(entry->getArgument(all.size() - 1));
    kernel.targetState = {groupSize};
    return entry;
  }

  void finishKernel(KernelBuilder &b, Kernel &kernel) override {
    b.setInsertionPointToEnd(&kernel.func.getFunctionBody().front());
    func::ReturnOp::create(b, b.loc);
  }

  void forEachGroup(KernelBuilder &b, Kernel &kernel,
                    function_ref<void(Value base)> body) override {
    forEachGroupFrom(b, kernel, Value(), body);
  }

  /// The invocation's groups first to end; with `start`, rotated so that
  /// the group of item `start` comes first when the invocation handles it.
  void forEachGroupFrom(KernelBuilder &b, Kernel &kernel, Value start,
                        function_ref<void(Value base)> body) override {
    unsigned count = kernel.func.getNumArguments();
    Value first = b.toIndex(kernel.func.getArgument(count - 3));
    Value end = b.toIndex(kernel.func.getArgument(count - 2));
    Value span, shift;
    if (start) {
      span = b.sub(end, first);
      Value item = b.toIndex(start);
      // A distributed plan's groups are counted from its rank's first item.
      if (kernel.values.first)
        item = b.sub(item, kernel.values.first);
      // Unsigned: a hint below the rank's first item wraps far beyond `end`.
      Value startGroup =
          arith::DivUIOp::create(b, b.loc, item, groupSize(kernel));
      Value offset = b.sub(startGroup, first);
      Value handled = b.cmp(arith::CmpIPredicate::ult, offset, span);
      shift = b.select(handled, offset, b.index(0));
    }
    auto loop = scf::ForOp::create(b, b.loc, first, end, b.index(1));
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    Value group = loop.getInductionVar();
    if (start) {
      Value shifted = b.add(group, shift);
      group = b.select(b.cmp(arith::CmpIPredicate::ult, shifted, end), shifted,
                       b.sub(shifted, span));
    }
    Value base = b.mul(group, groupSize(kernel));
    // A distributed plan's groups are counted from its rank's first item.
    if (kernel.values.first)
      base = b.add(base, kernel.values.first);
    body(base);
  }

  void forEachLane(KernelBuilder &b, Kernel &kernel, Value base,
                   function_ref<void(const Lane &)> body) override {
    auto loop =
        scf::ForOp::create(b, b.loc, b.index(0), groupSize(kernel), b.index(1));
    // The lanes of a phase are independent (GPU threads between barriers):
    // --sim-vectorize-lanes may run them side by side.
    loop->setAttr(simplan::PlanDialect::getLanesAttrName(), b.getUnitAttr());
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    Value lane = loop.getInductionVar();
    Value item = b.add(base, lane);
    Value active = b.cmp(arith::CmpIPredicate::ult, item, kernel.values.range);
    body(Lane{item, active, lane});
  }

  bool splitsGroups() const override { return true; }

  /// The invocation's groups, first to end, as one span.
  void forEachGroupSpan(KernelBuilder &b, Kernel &kernel,
                        function_ref<void(Value, Value)> body) override {
    unsigned count = kernel.func.getNumArguments();
    Value first = b.toIndex(kernel.func.getArgument(count - 3));
    Value end = b.toIndex(kernel.func.getArgument(count - 2));
    b.ifThen(b.cmp(arith::CmpIPredicate::ult, first, end), [&] {
      Value begin = b.mul(first, groupSize(kernel));
      Value stop = b.mul(end, groupSize(kernel));
      // A distributed plan's groups are counted from its rank's first item.
      if (kernel.values.first) {
        begin = b.add(begin, kernel.values.first);
        stop = b.add(stop, kernel.values.first);
      }
      body(begin, b.min(stop, kernel.values.range));
    });
  }

  void forEachLaneOf(KernelBuilder &b, Kernel &kernel, const Part &part,
                     function_ref<void(const Lane &)> body) override {
    auto loop = scf::ForOp::create(b, b.loc, part.first,
                                   b.add(part.first, part.count), b.index(1));
    loop->setAttr(simplan::PlanDialect::getLanesAttrName(), b.getUnitAttr());
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    Value lane = loop.getInductionVar();
    Value item = b.add(part.base, b.sub(lane, part.first));
    Value active = b.cmp(arith::CmpIPredicate::ult, item, kernel.values.range);
    body(Lane{item, active, lane});
  }

  /// One atomic per block and group instead of one per lane: the lanes that
  /// reach each block the group's items reach are folded first (so that
  /// the lanes' phase has no atomic and runs in SIMD chunks). With
  /// `onlyWriter`, a block whose items all lie in the group is written by
  /// no other group: a plain maximum, where the atomic's compare-and-swap
  /// loop cost 9% of an lts run whose levels change every big step.
  void maxPerBlock(KernelBuilder &b, Kernel &kernel, Value base, LaneVar value,
                   int64_t blockSize, Value memory, Value offset,
                   int64_t spreadLow, int64_t spreadHigh,
                   bool onlyWriter) override {
    Value range = kernel.values.range;
    Value end = b.min(b.add(base, groupSize(kernel)), range);
    // The items the lanes [base, end) reach: [base - spreadHigh,
    // end - spreadLow) within the range (signed: below 0 near the start).
    Value low = b.max(b.sub(base, b.index(spreadHigh)), b.index(0));
    Value high = b.min(b.sub(end, b.index(spreadLow)), range);
    if (spreadLow == 0 && spreadHigh == 0) {
      // Each lane reaches its own item only: where the group starts on a
      // block boundary (a group size that is a multiple of the block, as
      // the default is), each of its whole blocks takes its lanes' maximum
      // in a few SIMD instructions, where the general loop below cost
      // about 80 instructions per block. The general loop takes the rest:
      // a last block the range cuts short, or every block of a group that
      // starts inside one.
      Value size = b.index(blockSize);
      Value aligned =
          b.cmp(arith::CmpIPredicate::eq,
                arith::RemUIOp::create(b, b.loc, base, size), b.index(0));
      Value wholeBlocks = b.select(
          aligned, arith::DivUIOp::create(b, b.loc, b.sub(end, base), size),
          b.index(0));
      Value firstBlock = arith::DivUIOp::create(b, b.loc, base, size);
      auto blocks =
          scf::ForOp::create(b, b.loc, b.index(0), wholeBlocks, b.index(1));
      {
        OpBuilder::InsertionGuard guard(b);
        b.setInsertionPoint(blocks.getBody()->getTerminator());
        // One vector load of the block's lanes and a reduction: as a loop
        // of scalar loads LLVM vectorized the blocks loop instead, with a
        // gather per lane.
        Value lanes = vector::LoadOp::create(
            b, b.loc, VectorType::get({blockSize}, b.getI64Type()),
            value.memory, ValueRange{b.mul(blocks.getInductionVar(), size)});
        Value largest = vector::ReductionOp::create(
            b, b.loc, vector::CombiningKind::MAXSI, lanes);
        Value element =
            b.add(offset, b.add(firstBlock, blocks.getInductionVar()));
        if (onlyWriter)
          b.store(b.max(b.load(memory, element), largest), memory, element);
        else
          b.atomic(arith::AtomicRMWKind::maxs, largest, memory, element);
      }
      low = b.add(base, b.mul(wholeBlocks, size));
    }
    b.ifThen(b.cmp(arith::CmpIPredicate::slt, low, high), [&] {
      Value size = b.index(blockSize);
      Value firstBlock = arith::DivUIOp::create(b, b.loc, low, size);
      Value endBlock =
          b.add(arith::DivUIOp::create(b, b.loc, b.sub(high, b.index(1)), size),
                b.index(1));
      auto blocks =
          scf::ForOp::create(b, b.loc, firstBlock, endBlock, b.index(1));
      OpBuilder::InsertionGuard guard(b);
      b.setInsertionPoint(blocks.getBody()->getTerminator());
      Value block = blocks.getInductionVar();
      // The block's items the lanes reach, then the lanes that reach them.
      Value first = b.max(b.mul(block, size), low);
      Value last = b.min(b.mul(b.add(block, b.index(1)), size), high);
      Value fromLane =
          b.sub(b.max(b.add(first, b.index(spreadLow)), base), base);
      Value toLane = b.sub(b.min(b.add(last, b.index(spreadHigh)), end), base);
      auto lanes = scf::ForOp::create(
          b, b.loc, fromLane, toLane, b.index(1),
          ValueRange{b.i64(std::numeric_limits<int64_t>::min())});
      {
        OpBuilder::InsertionGuard inner(b);
        b.setInsertionPointToEnd(lanes.getBody());
        scf::YieldOp::create(
            b, b.loc,
            b.max(lanes.getRegionIterArg(0),
                  b.load(value.memory, lanes.getInductionVar())));
      }
      Value element = b.add(offset, block);
      auto atomic = [&] {
        b.atomic(arith::AtomicRMWKind::maxs, lanes.getResult(0), memory,
                 element);
      };
      if (!onlyWriter || spreadLow != 0 || spreadHigh != 0) {
        atomic();
        return;
      }
      Value blockEnd = b.min(b.mul(b.add(block, b.index(1)), size), range);
      Value inGroup = arith::AndIOp::create(
          b, b.loc, b.cmp(arith::CmpIPredicate::uge, b.mul(block, size), base),
          b.cmp(arith::CmpIPredicate::ule, blockEnd, end));
      b.ifThenElse(
          TypeRange{}, inGroup,
          [&]() -> SmallVector<Value> {
            b.store(b.max(b.load(memory, element), lanes.getResult(0)), memory,
                    element);
            return {};
          },
          [&]() -> SmallVector<Value> {
            atomic();
            return {};
          });
    });
  }

  /// One element per lane of the group, on the stack of the call.
  LaneVar createLaneVar(KernelBuilder &b, Kernel &kernel, Type type,
                        Value initial) override {
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointAfterValue(groupSize(kernel));
    Value memory = memref::AllocaOp::create(
        b, b.loc, MemRefType::get({ShapedType::kDynamic}, type),
        ValueRange{groupSize(kernel)});
    if (initial) {
      auto loop = scf::ForOp::create(b, b.loc, b.index(0), groupSize(kernel),
                                     b.index(1));
      b.setInsertionPoint(loop.getBody()->getTerminator());
      b.store(initial, memory, loop.getInductionVar());
    }
    return {memory};
  }

  Value groupSize(KernelBuilder &, Kernel &kernel) override {
    return kernel.targetState[0];
  }

  void prepareGroupMin(KernelBuilder &, Kernel &) override {}

  Value groupMin(KernelBuilder &b, Kernel &kernel, LaneVar value) override {
    return fold(b, kernel, value, arith::AtomicRMWKind::mins);
  }

  bool reducesPerGroup() const override { return true; }
  bool evaluatesUnitBigStep() const override { return true; }

  /// hip-cache's group caches on the stack of the invocation (created at
  /// the kernel's top level, so once per call): the window's values
  /// interpolated once per item and sub-step instead of at every read of
  /// them, as in shared memory on a GPU.
  bool hasCaches() const override { return true; }
  Value createCache(KernelBuilder &b, Kernel &kernel, Type elementType, int64_t,
                    int64_t halo) override {
    Value count = b.add(groupSize(kernel), b.index(halo));
    return memref::AllocaOp::create(
        b, b.loc, MemRefType::get({ShapedType::kDynamic}, elementType),
        ValueRange{count});
  }
  /// The slots as a loop of lanes (--sim-vectorize-lanes fills them in SIMD
  /// chunks).
  void forEachSlot(KernelBuilder &b, Kernel &kernel, Value count,
                   function_ref<void(Value slot)> body) override {
    auto loop = scf::ForOp::create(b, b.loc, b.index(0), count, b.index(1));
    loop->setAttr(simplan::PlanDialect::getLanesAttrName(), b.getUnitAttr());
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    body(loop.getInductionVar());
  }

  void reduceIntoClock(KernelBuilder &b, Kernel &kernel, LaneVar value,
                       arith::AtomicRMWKind kind, int64_t slot) override {
    Value total = fold(b, kernel, value, kind);
    b.atomic(kind, b.extend(total, b.getI64Type()), kernel.clock,
             b.index(slot));
  }

  /// An invocation runs groups `first` to `end` of the launch: it adds
  /// them (a distributed plan: their items) to the counter, and the one
  /// that completes the launch (a launch may come in several ranges) runs
  /// `body`.
  void afterLastInvocation(KernelBuilder &b, Kernel &kernel, int64_t counter,
                           function_ref<void()> body) override {
    unsigned count = kernel.func.getNumArguments();
    Value first = kernel.func.getArgument(count - 3);
    Value end = kernel.func.getArgument(count - 2);
    Value size = kernel.func.getArgument(count - 1);
    Value mine = b.sub(end, first);
    Value total;
    if (kernel.values.first) {
      // A distributed plan's launch covers the rank's block (its extent
      // less the ghost items on each side): count its items, as the GPU's
      // thread groups do (the kernels of both targets take the same
      // arguments).
      total = arith::IndexCastOp::create(
          b, b.loc, b.getI64Type(),
          b.sub(kernel.values.extent, b.index(2 * kernel.values.halo)));
      mine = b.sub(b.min(b.mul(end, size), total), b.mul(first, size));
    } else {
      Value range = arith::IndexCastOp::create(b, b.loc, b.getI64Type(),
                                               kernel.values.range);
      total = arith::DivUIOp::create(b, b.loc,
                                     b.sub(b.add(range, size), b.i64(1)), size);
    }
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, mine, b.i64(0)), [&] {
      b.addAndRunLast(mine, total, kernel.clock, b.index(counter), body);
    });
  }

private:
  static Value groupSize(Kernel &kernel) { return kernel.targetState[0]; }

  /// The minimum or sum of an i32 lane variable over the group's lanes.
  static Value fold(KernelBuilder &b, Kernel &kernel, LaneVar value,
                    arith::AtomicRMWKind kind) {
    bool isMin = kind == arith::AtomicRMWKind::mins;
    Value neutral = b.i32(isMin ? std::numeric_limits<int32_t>::max() : 0);
    auto loop = scf::ForOp::create(b, b.loc, b.index(0), groupSize(kernel),
                                   b.index(1), neutral);
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToEnd(loop.getBody());
    Value element = b.load(value.memory, loop.getInductionVar());
    Value acc = loop.getRegionIterArgs().front();
    scf::YieldOp::create(b, b.loc,
                         isMin ? b.min(acc, element) : b.add(acc, element));
    return loop.getResult(0);
  }
};

struct SimLowerToCPUPass
    : public sim::impl::SimLowerToCPUBase<SimLowerToCPUPass> {
  using SimLowerToCPUBase::SimLowerToCPUBase;

  void runOnOperation() override {
    ModuleOp module = getOperation();
    SmallVector<SimulationOp> simulations(module.getOps<SimulationOp>());
    if (groupSize <= 0) {
      // Located at the scenes it would lower (the module has no location of
      // its own in a file).
      Location loc =
          simulations.empty() ? module.getLoc() : simulations.front().getLoc();
      emitError(loc) << "--sim-lower-to-cpu needs a positive group size, not "
                     << static_cast<int64_t>(groupSize);
      return signalPassFailure();
    }
    CPUKernelTarget target(levelsPerLane);
    if (failed(SimulationOp::checkLoweredNamesAreFree(
            simulations, "_kernels", "kernels", getArgument())))
      return signalPassFailure();
    for (SimulationOp simulation : simulations)
      if (failed(lowerSimulation(simulation, target, groupSize)))
        return signalPassFailure();
  }
};

} // namespace
