//===- ClockKernels.cpp - the clock's kernels -----------------------------===//
//
// reset_clock (the initial clock), estimate_C (a component's minimum
// num_steps for the next big step) and advance (commits a big step and
// decides the next on the device).
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"

using namespace mlir;
using namespace mlir::sim;

/// Puts the clock in its initial state: T = 0, parity 0, no pending
/// estimate, all counters zero. The host sets the end of each run.
LogicalResult SimulationLowering::emitResetClock(OpBuilder &launches) {
  Kernel kernel = beginKernel(getKernelName(kernels, "reset_clock"));
  Value zero = b.i64(0);
  auto loop =
      scf::ForOp::create(b, b.loc, b.index(0), b.index(clockSlots), b.index(1));
  {
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    b.store(zero, kernel.clock, loop.getInductionVar());
  }
  b.store(b.i64(kNoEstimate64), kernel.clock, b.index(kSlotEstimate));
  return endKernel(kernel, simplan::LaunchShape::single, launches);
}

/// One component's estimate of the next big step: the minimum of
/// `num_steps` over all items at the start T' of the next big step, into the
/// clock (a pair writer's under lts: the largest, capped at the step cap;
/// docs/Model.md, "The big step"). It runs before `advance` commits the
/// current big step, so it computes T' and the parity itself, and does
/// nothing past the end.
LogicalResult SimulationLowering::emitEstimate(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "estimate", component.getSymName()));
  EstimateSlots slots{kSlotEstimate, kSlotEstimateHint};
  auto largest = largestEstimateSlots.find(component);
  if (largest != largestEstimateSlots.end())
    slots =
        EstimateSlots{largest->second, largest->second + kLargestHint, true};
  LaneVar combined =
      target.createLaneVar(b, kernel, b.getI32Type(), b.i32(kNoEstimate));
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0));
  Value next = b.add(begin, size);
  Value nextParity = b.select(stepped, b.xorOne(parity), parity);
  setHalves(kernel, nextParity, nextParity);
  Value end = b.load(kernel.clock, b.index(kSlotEnd));
  Value due = b.cmp(arith::CmpIPredicate::slt, next, end);
  // A kept estimate is taken until advance keeps one. (Its own slot would
  // not do: the groups that run after another wrote it would skip theirs.)
  if (keepsEstimate(component))
    due = arith::AndIOp::create(
        b, b.loc, due,
        b.cmp(arith::CmpIPredicate::eq,
              b.load(kernel.clock, b.index(slots.slot + kLargestKept)),
              b.i64(0)));
  b.ifThen(due,
           [&] { estimateInto(kernel, component, combined, next, slots); });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// Commits the big step that just ended (T += m, flip the parity when it
/// advanced) and decides the next one: m = min(estimate, cap, end - T), 0
/// past the end (under local time steps also at most each pair writer's
/// largest estimate; their sub-steps are cut at the end of any m).
/// Also counts big steps by size and the ones the end cut short (clock slot
/// Cuts), and restarts the sub-step clocks.
LogicalResult SimulationLowering::emitAdvance(OpBuilder &launches,
                                              bool minimumEstimated) {
  Kernel kernel = beginKernel(getKernelName(kernels, "advance"));
  Value clock = kernel.clock;
  auto slot = [&](int64_t index) { return b.load(clock, b.index(index)); };
  auto setSlot = [&](int64_t index, Value value) {
    b.store(value, clock, b.index(index));
  };
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  Value zero = b.i64(0), one = b.i64(1);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, zero);
  Value now = b.add(begin, size);
  Value nowParity = b.select(stepped, b.xorOne(parity), parity);
  Value bigSteps =
      b.add(slot(kSlotBigSteps), b.extend(stepped, b.getI64Type()));
  Value remaining = b.sub(slot(kSlotEnd), now);
  Value cap = b.i64(stepCap);
  Value bound = minimumEstimated ? b.min(slot(kSlotEstimate), cap) : cap;
  // A pair writer's stiff items bound its reader's blocks, not the big
  // step; where all its items ask for short steps, the coarsest does
  // (docs/Model.md, "The big step"). Its slots hold the largest estimate
  // negated, 0 when no item was estimated: the one just taken, and the one
  // kept (keeps_estimate), of which at most one is not 0.
  for (ComponentOp component : order) {
    auto largest = largestEstimateSlots.find(component);
    if (largest == largestEstimateSlots.end())
      continue;
    Value negated = slot(largest->second);
    if (keepsEstimate(component)) {
      negated = b.min(negated, slot(largest->second + kLargestKept));
      setSlot(largest->second + kLargestKept, negated);
    }
    Value estimated = b.cmp(arith::CmpIPredicate::slt, negated, zero);
    bound = b.min(bound, b.select(estimated, b.sub(zero, negated), cap));
    setSlot(largest->second, zero);
    // Each rank's estimate took the largest over its own items: the ranks
    // agree on the global one (the minimum of the negated values).
    if (distributed)
      pendingReduce.push_back(largest->second);
  }
  Value positive = b.cmp(arith::CmpIPredicate::sgt, remaining, zero);
  Value next = b.select(positive, b.min(bound, remaining), zero);
  // A cut: the end of the run, not the estimate or the cap, sizes the big
  // step (a run that ends between two natural big-step boundaries).
  Value cut = b.select(
      positive, b.cmp(arith::CmpIPredicate::slt, remaining, bound), positive);
  Value cuts = b.add(slot(kSlotCuts), b.extend(cut, b.getI64Type()));

  setSlot(kSlotBegin, now);
  setSlot(kSlotSize, next);
  setSlot(kSlotParity, nowParity);
  setSlot(kSlotBigSteps, bigSteps);
  setSlot(kSlotCuts, cuts);
  setSlot(kSlotEstimate, b.i64(kNoEstimate64));
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, next, zero), [&] {
    Value at = b.add(b.index(histogramSlot), b.toIndex(next));
    b.store(b.add(b.load(clock, at), one), clock, at);
  });
  // Each rank's estimate kernels took the minimum over its own items: the
  // ranks agree on the global minimum before the decision.
  if (distributed && minimumEstimated)
    pendingReduce.push_back(kSlotEstimate);
  for (ComponentOp component : order) {
    auto it = subClockSlots.find(component);
    if (it == subClockSlots.end())
      continue;
    setSlot(it->second + kSubBegin, now);
    setSlot(it->second + kSubSize, zero);
    setSlot(it->second + kSubCount, zero);
    // A local_steps component keeps there the big step its levels were
    // last limited for (limit_levels_C on a CPU).
    if (component.getAdvance() != Advance::local_steps)
      setSlot(it->second + kSubEstimate, b.i64(kNoEstimate64));
  }
  return endKernel(kernel, simplan::LaunchShape::single, launches);
}
