//===- SubStepKernels.cpp - group sub-steps inside one kernel -------------===//
//
// substep_C, Algorithm 2 for components that advance by `group_substeps`:
// the own state in registers, sub-steps of the group minimum of num_steps,
// the target written once.
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"

using namespace mlir;
using namespace mlir::sim;

/// Algorithm 2 for an in_kernel component with num_steps: each lane keeps
/// its item's state in registers from T to T + m, the group takes sub-steps
/// of the group-wide minimum of num_steps, and the target is written once.
/// When m = 1 there is one sub-step of 1, taken as evaluate_C takes it.
LogicalResult SimulationLowering::emitSubSteps(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "substep", component.getSymName()));
  auto writes =
      llvm::to_vector(component.getWrites().getAsRange<FlatSymbolRefAttr>());
  LaneVar count = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
  LaneVar steps = target.createLaneVar(b, kernel, b.getI32Type());
  SmallVector<LaneVar> state;
  for (FlatSymbolRefAttr name : writes)
    state.push_back(target.createLaneVar(
        b, kernel, simulation.lookupBuffer(name).getElementType()));
  Value begin, size, parity;
  readBigStep(kernel, begin, size, parity);
  Value dt = kernel.values.params.lookup("dt");
  SmallVector<Cache> caches = createCaches(kernel, component);

  // A written buffer the bodies never read at the local time (C1 of
  // gravity-like writes B1 and reads only B0) needs no value at T: every
  // sub-step sets its register before anything reads it.
  SmallVector<std::pair<FlatSymbolRefAttr, LaneVar>> initial;
  for (auto [written, var] : llvm::zip_equal(writes, state)) {
    FlatSymbolRefAttr name = written;
    bool read = component
                    .walk([&](LoadOp load) {
                      return load.getBufferAttr() == name &&
                                     load.getVersion() == Version::local
                                 ? WalkResult::interrupt()
                                 : WalkResult::advance();
                    })
                    .wasInterrupted();
    if (read)
      initial.push_back({name, var});
  }

  // The values a lane's bodies read: its registers.
  auto laneValues = [&](const Lane &lane) {
    KernelValues values = kernel.values;
    values.item = lane.item;
    for (auto [name, var] : llvm::zip_equal(writes, state))
      values.registers[name.getAttr()] = target.laneLoad(b, var, lane);
    return values;
  };

  // The sub-steps of every group.
  auto subStepGroups = [&](Value end) {
    target.forEachGroup(b, kernel, [&](Value base) {
      // Own state at T into registers, where the bodies read it.
      if (!initial.empty())
        target.forEachLane(b, kernel, base, [&](const Lane &lane) {
          b.ifThen(lane.active, [&] {
            for (auto [name, var] : initial)
              target.laneStore(
                  b,
                  b.load(kernel.values.buffers.lookup(name.getAttr()),
                         at(kernel, name.getAttr(), kernel.values.sourceBase,
                            kernel.values.sourceParity, lane.item)),
                  var, lane);
          });
        });
      // Sub-steps until the group reaches T + m (the same for every
      // lane).
      auto loop = scf::WhileOp::create(b, b.loc, b.getI64Type(), begin);
      Block *before =
          b.createBlock(&loop.getBefore(), {}, b.getI64Type(), b.loc);
      scf::ConditionOp::create(
          b, b.loc,
          b.cmp(arith::CmpIPredicate::slt, before->getArgument(0), end),
          before->getArguments());
      Block *after = b.createBlock(&loop.getAfter(), {}, b.getI64Type(), b.loc);
      Value time = after->getArgument(0);
      // The group's items, computed again in every sub-step: everything
      // the bodies derive from them (the clamped address of every window
      // read) would otherwise be hoisted out of the loop and held in
      // registers across it, several times the registers of the sub-step
      // itself.
      Value stepBase = target.opaque(b, base);
      auto groupStep = [&] {
        target.forEachLane(b, kernel, stepBase, [&](const Lane &lane) {
          auto estimated = b.ifThenElse(
              b.getI32Type(), lane.active,
              [&] {
                return SmallVector<Value>{estimate(kernel, component, lane.item,
                                                   time, laneValues(lane))};
              },
              [&] { return SmallVector<Value>{b.i32(kNoEstimate)}; });
          target.laneStore(b, estimated.getResult(0), steps, lane);
        });
        Value groupMin =
            b.extend(target.groupMin(b, kernel, steps), b.getI64Type());
        return SmallVector<Value>{b.min(groupMin, b.sub(end, time))};
      };
      // With one base step left the sub-step is 1 whatever the estimates
      // say (none is below 1): no estimates, no minimum. That is every
      // big step of 1 and the last sub-step of many others.
      Value last = b.cmp(arith::CmpIPredicate::eq, b.sub(end, time), b.i64(1));
      Value subStep =
          b.ifThenElse(
               b.getI64Type(), last,
               [&] { return SmallVector<Value>{b.i64(1)}; }, groupStep)
              .getResult(0);
      Value subStep32 = b.truncate(subStep, b.getI32Type());
      if (!caches.empty()) {
        // The caches of the previous sub-step are free once every lane
        // has passed the barrier of this sub-step's minimum; without a
        // minimum there was none.
        b.ifThen(last, [&] { target.barrier(b); });
        fillCaches(kernel, component, caches, stepBase, time, subStep32, dt);
      }
      target.forEachLane(b, kernel, stepBase, [&](const Lane &lane) {
        b.ifThen(lane.active, [&] {
          SmallVector<Value> results =
              inline_(component.getEvaluate(), {lane.item, time, subStep32, dt},
                      laneValues(lane));
          for (auto [value, var] : llvm::zip_equal(results, state))
            target.laneStore(b, value, var, lane);
        });
        countEvaluation(count, lane);
      });
      scf::YieldOp::create(b, b.loc, b.add(time, subStep));
      b.setInsertionPointAfter(loop);
      // The target half, once.
      target.forEachLane(b, kernel, base, [&](const Lane &lane) {
        b.ifThen(lane.active, [&] {
          for (auto [name, var] : llvm::zip_equal(writes, state))
            b.store(target.laneLoad(b, var, lane),
                    kernel.values.buffers.lookup(name.getAttr()),
                    at(kernel, name.getAttr(), kernel.values.targetBase,
                       kernel.values.targetParity, lane.item));
        });
      });
    });
  };

  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    target.prepareGroupMin(b, kernel);
    Value end = b.add(begin, size);
    if (!target.evaluatesUnitBigStep()) {
      subStepGroups(end);
    } else {
      Value single = b.cmp(arith::CmpIPredicate::eq, size, b.i64(1));
      // m = 1: one sub-step of 1, which is what evaluate_C does with n = 1
      // (own state at T, other buffers at T + 1): no registers, no
      // estimate, no minimum. With per-item step counts most big steps
      // are 1.
      b.ifThenElse(
          TypeRange{}, single,
          [&] {
            evaluateItems(kernel, component, caches, begin, b.i32(1),
                          kernel.values.targetBase, kernel.values.targetParity,
                          count);
            return SmallVector<Value>{};
          },
          [&] {
            subStepGroups(end);
            return SmallVector<Value>{};
          });
    }
    target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                           evaluationSlots.lookup(component));
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}
