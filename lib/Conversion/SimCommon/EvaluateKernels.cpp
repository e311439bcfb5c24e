//===- EvaluateKernels.cpp - one evaluation per item and big step ---------===//
//
// evaluate_C, for components that take the whole big step (`advance =
// whole_step`), and the hip-cache group caches that evaluations of every
// kind fill (Fig. 8 of the paper).
//
//===----------------------------------------------------------------------===//

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/SimulationLowering.h"
#include "llvm/ADT/MapVector.h"

using namespace mlir;
using namespace mlir::sim;

SmallVector<SimulationLowering::Cache>
SimulationLowering::createCaches(Kernel &kernel, ComponentOp component) {
  SmallVector<Cache> caches;
  auto stride = [&](FillCacheOp fill) {
    return getElementStride(simulation.lookupBuffer(fill.getBufferAttr()));
  };
  SmallVector<FillCacheOp> fills(
      component.getEvaluate().front().getOps<FillCacheOp>());
  // The plan is the same for every target: the launch asks for the caches'
  // bytes, which a CPU runtime ignores (its kernels keep the caches on the
  // stack) and a target without caches does not need.
  for (FillCacheOp fill : fills) {
    kernel.sharedPerThread += stride(fill);
    kernel.sharedFixed += stride(fill) * (fill.getMaxOffsetAttr().getInt() -
                                          fill.getMinOffsetAttr().getInt());
  }
  if (!target.hasCaches())
    return caches;
  // By decreasing element size, so every cache is aligned to its elements
  // (then by name, so the layout does not depend on the body's order).
  llvm::sort(fills, [&](FillCacheOp a, FillCacheOp b) {
    return std::make_pair(-stride(a), a.getBuffer()) <
           std::make_pair(-stride(b), b.getBuffer());
  });
  for (FillCacheOp fill : fills) {
    BufferOp buffer = simulation.lookupBuffer(fill.getBufferAttr());
    int64_t halo =
        fill.getMaxOffsetAttr().getInt() - fill.getMinOffsetAttr().getInt();
    caches.push_back(
        {fill, target.createCache(b, kernel, buffer.getElementType(),
                                  stride(fill), halo)});
  }
  return caches;
}

/// Fig. 8 of the paper: the group interpolates the values of its window once
/// into shared memory (every lane fills some slots, padding lanes too),
/// then reads inside the window come from there.
void SimulationLowering::fillCaches(Kernel &kernel, ComponentOp component,
                                    ArrayRef<Cache> caches, Value base,
                                    Value time, Value steps, Value dt) {
  kernel.values.caches.clear();
  if (caches.empty())
    return;
  // Caches of the same window share one loop over the slots (and so the
  // item's boundary rule and the interpolation weights).
  llvm::MapVector<std::pair<int64_t, int64_t>, SmallVector<Cache>> windows;
  for (Cache cache : caches)
    windows[{cache.fill.getMinOffsetAttr().getInt(),
             cache.fill.getMaxOffsetAttr().getInt()}]
        .push_back(cache);
  for (auto &entry : windows) {
    int64_t low = entry.first.first, high = entry.first.second;
    ArrayRef<Cache> sharing = entry.second;
    Value count = b.add(target.groupSize(b, kernel), b.index(high - low));
    Value first = b.add(base, b.index(low));
    // The fills read other items than the lane's: boundary rules.
    KernelValues values = kernel.values;
    values.item = nullptr;
    target.forEachSlot(b, kernel, count, [&](Value slot) {
      Value item = b.add(first, slot);
      for (Cache cache : sharing) {
        FailureOr<Value> value = inlineCacheFill(
            b, simulation, component.getEvaluate(), {item, time, steps, dt},
            cache.fill.getBufferAttr(), item, values);
        if (failed(value)) {
          bodyFailed = true;
          return;
        }
        b.store(*value, cache.memory, slot);
      }
    });
    for (Cache cache : sharing)
      kernel.values.caches[cache.fill.getBufferAttr().getAttr()] = {
          cache.memory, first, count};
  }
  target.barrier(b);
}

void SimulationLowering::evaluateItems(Kernel &kernel, ComponentOp component,
                                       ArrayRef<Cache> caches, Value time,
                                       Value steps, Value writeBase,
                                       Value writeParity, LaneVar count) {
  Value dt = kernel.values.params.lookup("dt");
  target.forEachGroup(b, kernel, [&](Value base) {
    if (!caches.empty()) {
      // The previous group's reads of the caches are done.
      target.barrier(b);
      fillCaches(kernel, component, caches, base, time, steps, dt);
    }
    target.forEachLane(b, kernel, base, [&](const Lane &lane) {
      b.ifThen(lane.active, [&] {
        KernelValues values = kernel.values;
        values.item = lane.item;
        SmallVector<Value> results = inline_(
            component.getEvaluate(), {lane.item, time, steps, dt}, values);
        for (auto [name, value] : llvm::zip_equal(
                 component.getWrites().getAsRange<FlatSymbolRefAttr>(),
                 results))
          b.store(
              value, values.buffers.lookup(name.getAttr()),
              at(kernel, name.getAttr(), writeBase, writeParity, lane.item));
      });
      countEvaluation(count, lane);
    });
  });
}

/// One evaluation per item with n = m (simple, traditional, and hip
/// components without num_steps or that bound the step): reads the state
/// at T, writes the target once.
LogicalResult SimulationLowering::emitEvaluate(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "evaluate", component.getSymName()));
  LaneVar count = target.createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
  Value begin, size, parity;
  readBigStep(kernel, begin, size, parity);
  Value steps = b.truncate(size, b.getI32Type());
  SmallVector<Cache> caches = createCaches(kernel, component);
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    evaluateItems(kernel, component, caches, begin, steps,
                  kernel.values.targetBase, kernel.values.targetParity, count);
    target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                           evaluationSlots.lookup(component));
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}
