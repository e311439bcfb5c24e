//===- GridSubStepKernels.cpp - grid-wide sub-steps as rounds of launches
//---===//
//
// For components that advance by `grid_substeps`: the snapshots of the
// value at T, max_steps rounds of (estimate, decide, sub-step) launches
// ping-ponging between the halves, and the parity copy (Algorithm 2, lines
// 41-44).
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"

using namespace mlir;
using namespace mlir::sim;

/// Snapshots of the value at T of the buffers later components read
/// between T and T + m, before `component` ping-pongs between the halves.
LogicalResult SimulationLowering::emitSnapshots(ComponentOp component,
                                                OpBuilder &launches) {
  for (FlatSymbolRefAttr write :
       component.getWrites().getAsRange<FlatSymbolRefAttr>()) {
    BufferOp buffer = simulation.lookupBuffer(write);
    if (!buffer.getSnapshot())
      continue;
    Kernel kernel =
        beginKernel(getKernelName(kernels, "snapshot", buffer.getSymName()));
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    setHalves(kernel, parity, parity);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
      forEachItem(kernel, [&](const Lane &lane) {
        b.ifThen(lane.active, [&] {
          Value value =
              b.load(kernel.values.buffers.lookup(write.getAttr()),
                     at(kernel, write.getAttr(), kernel.values.sourceBase,
                        kernel.values.sourceParity, lane.item));
          b.store(value, kernel.values.snapshots.lookup(write.getAttr()),
                  element(kernel, lane.item, write.getAttr()));
        });
      });
    });
    // Only a later component reads the snapshot, and only where it reads
    // other items do its ghosts travel (--sim-plan-halos decided).
    if (distributed && travels(buffer) && buffer.getSnapshotGhosts())
      pendingExchangeSnapshots.push_back(write);
    if (failed(endKernel(kernel, simplan::LaunchShape::items, launches)))
      return failure();
  }

  return success();
}

/// A grid_sync component with num_steps: its sub-steps read other items of
/// its own buffers, so every sub-step is a launch of its own and its size is
/// the minimum over the whole range. Before them: snapshots of the buffers
/// later components interpolate; then at most max_steps rounds of (estimate,
/// decide, sub-step) ping-ponging between the halves; after them the parity
/// copy when an even number of sub-steps left the result in the source half
/// (Algorithm 2, lines 41-44).
LogicalResult SimulationLowering::emitRounds(ComponentOp component,
                                             OpBuilder &launches) {
  int64_t sub = subClockSlots.lookup(component);
  StringRef name = component.getSymName();
  auto writes =
      llvm::to_vector(component.getWrites().getAsRange<FlatSymbolRefAttr>());
  {
    InFlightDiagnostic remark = component.emitRemark()
                                << "@" << name << " takes its sub-steps as "
                                << maxSteps
                                << " rounds of launches with a grid-wide "
                                   "sub-step decided on the device";
    for (FlatSymbolRefAttr write : writes)
      if (simulation.lookupBuffer(write).getSnapshot())
        remark << ", a snapshot of " << write << " before them";
    if (component.getParity() == Parity::copy_if_even)
      remark << ", and a copy after an even number of sub-steps";
  }
  // The sub-steps done so far, counting the pending one.
  auto subStepsDone = [&](Kernel &kernel) {
    Value size = b.load(kernel.clock, b.index(sub + kSubSize));
    Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0));
    return b.add(b.load(kernel.clock, b.index(sub + kSubCount)),
                 b.extend(stepped, b.getI64Type()));
  };
  auto odd = [&](Value count) {
    return arith::AndIOp::create(b, b.loc, count, b.i64(1)).getResult();
  };

  if (failed(emitSnapshots(component, launches)))
    return failure();

  auto round = simplan::RepeatOp::create(launches, b.loc,
                                         launches.getI64IntegerAttr(maxSteps));
  round.getBody().emplaceBlock();
  OpBuilder roundLaunches = OpBuilder::atBlockEnd(&round.getBody().front());

  // The sub-step's estimate at the local time the pending sub-step reaches.
  {
    Kernel kernel =
        beginKernel(getKernelName(kernels, "substep_estimate", name));
    LaneVar minimum =
        target.createLaneVar(b, kernel, b.getI32Type(), b.i32(kNoEstimate));
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    Value now = b.add(b.load(kernel.clock, b.index(sub + kSubBegin)),
                      b.load(kernel.clock, b.index(sub + kSubSize)));
    Value readParity =
        arith::XOrIOp::create(b, b.loc, parity, odd(subStepsDone(kernel)));
    setHalves(kernel, parity, readParity);
    kernel.values.bigStepBegin = begin;
    kernel.values.bigStepSize = size;
    // With one base step left (or none) the next sub-step is 1 (or none)
    // whatever the estimate says, none being below 1: no estimate. That
    // is every big step of 1 and the last sub-step of many others.
    Value due = b.cmp(arith::CmpIPredicate::sgt, b.sub(b.add(begin, size), now),
                      b.i64(1));
    // An invariant_estimate component's num_steps is the same at every
    // time: the minimum of the big step's first round (no sub-step done
    // or pending) holds for the others, which substep_advance_C keeps.
    // Where the stiff items hold the sub-step at 1, every round would
    // otherwise estimate the range again (as much as a second
    // evaluation per base step).
    if (component.getInvariantEstimate())
      due = arith::AndIOp::create(
          b, b.loc, due,
          b.cmp(arith::CmpIPredicate::eq, subStepsDone(kernel), b.i64(0)));
    b.ifThen(due, [&] {
      estimateInto(kernel, component, minimum, now,
                   {sub + kSubEstimate, kSlotEstimateHint});
    });
    if (failed(endKernel(kernel, simplan::LaunchShape::items, roundLaunches)))
      return failure();
  }

  // Commit the previous sub-step, decide the next.
  {
    Kernel kernel =
        beginKernel(getKernelName(kernels, "substep_advance", name));
    Value clock = kernel.clock;
    auto slot = [&](int64_t index) { return b.load(clock, b.index(index)); };
    Value zero = b.i64(0);
    Value end = b.add(slot(kSlotBegin), slot(kSlotSize));
    Value done = subStepsDone(kernel);
    Value now = b.add(slot(sub + kSubBegin), slot(sub + kSubSize));
    Value remaining = b.sub(end, now);
    Value positive = b.cmp(arith::CmpIPredicate::sgt, remaining, zero);
    Value next =
        b.select(positive, b.min(slot(sub + kSubEstimate), remaining), zero);
    b.store(now, clock, b.index(sub + kSubBegin));
    b.store(next, clock, b.index(sub + kSubSize));
    b.store(done, clock, b.index(sub + kSubCount));
    // The next round estimates again, unless the estimate holds for the
    // whole big step (invariant_estimate: advance clears it for the next).
    if (!component.getInvariantEstimate())
      b.store(b.i64(kNoEstimate64), clock, b.index(sub + kSubEstimate));
    // The estimate is each rank's minimum: the ranks agree on the global
    // one first.
    if (distributed)
      pendingReduce.push_back(sub + kSubEstimate);
    if (failed(endKernel(kernel, simplan::LaunchShape::single, roundLaunches)))
      return failure();
  }

  // The sub-step: read one half, write the other.
  {
    Kernel kernel = beginKernel(getKernelName(kernels, "substep", name));
    LaneVar count = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    Value subBegin = b.load(kernel.clock, b.index(sub + kSubBegin));
    Value subSize = b.load(kernel.clock, b.index(sub + kSubSize));
    Value subCount = b.load(kernel.clock, b.index(sub + kSubCount));
    Value readParity = arith::XOrIOp::create(b, b.loc, parity, odd(subCount));
    setHalves(kernel, parity, readParity);
    Value writeParity = b.xorOne(readParity);
    Value writeBase = b.mul(b.toIndex(writeParity), kernel.values.extent);
    kernel.values.bigStepBegin = begin;
    kernel.values.bigStepSize = size;
    Value steps = b.truncate(subSize, b.getI32Type());
    SmallVector<Cache> caches = createCaches(kernel, component);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, subSize, b.i64(0)), [&] {
      evaluateItems(kernel, component, caches, subBegin, steps, writeBase,
                    writeParity, count);
      target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                             evaluationSlots.lookup(component));
    });
    pendingWrittenHalf = WrittenHalf::SubStep;
    if (failed(endKernel(kernel, simplan::LaunchShape::items, roundLaunches,
                         component)))
      return failure();
  }

  if (component.getParity() != Parity::copy_if_even)
    return success();
  // The parity copy: after an even number of sub-steps the result is in the
  // source half.
  Kernel kernel = beginKernel(getKernelName(kernels, "parity", name));
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  Value even =
      b.cmp(arith::CmpIPredicate::eq, odd(subStepsDone(kernel)), b.i64(0));
  Value copy = arith::AndIOp::create(
      b, b.loc, even, b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)));
  b.ifThen(copy, [&] {
    forEachItem(kernel, [&](const Lane &lane) {
      b.ifThen(lane.active, [&] { copyToTarget(kernel, writes, lane.item); });
    });
  });
  pendingWrittenHalf = WrittenHalf::Target;
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}
