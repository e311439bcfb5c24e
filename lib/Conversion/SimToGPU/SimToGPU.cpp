//===- SimToGPU.cpp - simulations to GPU kernels and a host plan ----------===//
//
// The GPU target of the shared kernel algorithms (lib/Conversion/SimCommon,
// SimulationLowering.h): a group of items is a thread block, a lane a thread.
// Kernels loop over the padded range with a grid stride, so every lane of a
// block runs every iteration and group-wide barriers and reductions are legal.
// Group minima and sums are a uniform warp reduction (every lane takes part,
// padding lanes with a neutral value, so it lowers to one redux.sync) followed
// by an atomic into workgroup or global memory.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Conversion/SimCommon/KernelTarget.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Runtime/BundleFormat.h"

#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/LLVMIR/NVVMDialect.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERTOGPU
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

constexpr int32_t kNoValue = std::numeric_limits<int32_t>::max();

MemRefType workgroupMemory(MLIRContext *context, int64_t size, Type type) {
  return MemRefType::get(
      {size}, type, nullptr,
      gpu::AddressSpaceAttr::get(context, gpu::AddressSpace::Workgroup));
}

class GPUKernelTarget : public KernelTarget {
public:
  Operation *createContainer(OpBuilder &b, Location loc,
                             StringRef name) override {
    return gpu::GPUModuleOp::create(b, loc, name);
  }

  Block *createKernel(KernelBuilder &b, Kernel &kernel, StringRef name,
                      TypeRange types) override {
    auto func =
        gpu::GPUFuncOp::create(b, b.loc, name, b.getFunctionType(types, {}));
    func->setAttr(gpu::GPUDialect::getKernelFuncAttrName(), b.getUnitAttr());
    kernel.func = func;
    Block *entry = &func.getBody().front();
    b.setInsertionPointToStart(entry);
    return entry;
  }

  void finishKernel(KernelBuilder &b, Kernel &kernel) override {
    b.setInsertionPointToEnd(&kernel.func.getFunctionBody().front());
    gpu::ReturnOp::create(b, b.loc);
  }

  void forEachGroup(KernelBuilder &b, Kernel &kernel,
                    function_ref<void(Value base)> body) override {
    Value group = gpu::BlockIdOp::create(b, b.loc, gpu::Dimension::x);
    Value groupSize = gpu::BlockDimOp::create(b, b.loc, gpu::Dimension::x);
    Value groups = gpu::GridDimOp::create(b, b.loc, gpu::Dimension::x);
    // Every base is a multiple of the group size, so `base < range` is
    // `base < the padded range` without the 64-bit division that rounds the
    // range up (a subroutine call in SASS, whose registers count against
    // the whole kernel).
    Value begin = b.mul(group, groupSize), end = kernel.values.range;
    Value stride = b.mul(groups, groupSize);
    // A distributed plan's grid is its rank's block (whole groups from its
    // first item, the last rank's last one padded): one round, which the
    // CPU kernels of the same plan also take without the extent.
    if (Value first = kernel.values.first) {
      begin = b.add(begin, first);
      end = b.min(end, b.add(first, stride));
    }
    auto loop = scf::ForOp::create(b, b.loc, begin, end, stride);
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    body(loop.getInductionVar());
  }

  void forEachLane(KernelBuilder &b, Kernel &kernel, Value base,
                   function_ref<void(const Lane &)> body) override {
    Value item = b.add(base, threadId(b));
    Value active = b.cmp(arith::CmpIPredicate::ult, item, kernel.values.range);
    body(Lane{item, active, b.index(0)});
  }

  /// One element of private memory per thread; indices are constant, so
  /// LLVM promotes it to registers.
  LaneVar createLaneVar(KernelBuilder &b, Kernel &kernel, Type type,
                        Value initial) override {
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPointToStart(&kernel.func.getFunctionBody().front());
    Value memory =
        memref::AllocaOp::create(b, b.loc, MemRefType::get({1}, type));
    if (initial) {
      // After the alloca, the initial value and the index, whichever of
      // them comes last in the entry block (constants made earlier sit
      // after an alloca inserted at its start now).
      Value zero = b.index(0);
      Value last = memory;
      for (Value value : {initial, zero})
        if (last.getDefiningOp()->isBeforeInBlock(value.getDefiningOp()))
          last = value;
      b.setInsertionPointAfterValue(last);
      b.store(initial, memory, zero);
    }
    return {memory};
  }

  /// The group minimum rotates through three workgroup slots, which needs
  /// one barrier per minimum: minimum k combines into slot k % 3 after
  /// thread 0 reset it (before the barrier of minimum k - 1) and is read
  /// after the barrier of minimum k; thread 0 resets slot (k + 1) % 3, last
  /// read before the barrier of minimum k - 1.
  void prepareGroupMin(KernelBuilder &b, Kernel &kernel) override {
    auto func = cast<gpu::GPUFuncOp>(kernel.func);
    Value slots = func.addWorkgroupAttribution(
        workgroupMemory(b.getContext(), 3, b.getI32Type()), b.loc);
    // k % 3, as an i32 that cycles through 0, 1, 2: neither a 64-bit
    // remainder nor a counter that could wrap.
    LaneVar slot = createLaneVar(b, kernel, b.getI32Type(), b.i32(0));
    kernel.targetState = {slots, slot.memory};
    b.ifThen(isFirstThread(b),
             [&] { b.store(b.i32(kNoValue), slots, b.index(0)); });
    gpu::BarrierOp::create(b, b.loc);
  }

  Value groupMin(KernelBuilder &b, Kernel &kernel, LaneVar value) override {
    Value slots = kernel.targetState[0], slot = kernel.targetState[1];
    Value mine = b.load(value.memory, b.index(0));
    Value warpMin = reduce(b, mine, gpu::AllReduceOperation::MINSI);
    Value k = b.load(slot, b.index(0));
    Value next = b.select(b.cmp(arith::CmpIPredicate::eq, k, b.i32(2)),
                          b.i32(0), b.add(k, b.i32(1)));
    b.store(next, slot, b.index(0));
    Value current = arith::IndexCastUIOp::create(b, b.loc, b.getIndexType(), k);
    Value upcoming =
        arith::IndexCastUIOp::create(b, b.loc, b.getIndexType(), next);
    b.ifThen(isFirstThread(b),
             [&] { b.store(b.i32(kNoValue), slots, upcoming); });
    b.ifThen(isFirstLane(b), [&] {
      b.atomic(arith::AtomicRMWKind::mins, warpMin, slots, current);
    });
    gpu::BarrierOp::create(b, b.loc);
    return b.load(slots, current);
  }

  void reduceIntoClock(KernelBuilder &b, Kernel &kernel, LaneVar value,
                       arith::AtomicRMWKind kind, int64_t slot) override {
    Value mine = b.load(value.memory, b.index(0));
    Value clockSlot = b.index(slot);
    if (kind == arith::AtomicRMWKind::addi) {
      // Counters: one atomic per warp costs nothing measurable.
      Value sum = reduce(b, mine, gpu::AllReduceOperation::ADD);
      b.ifThen(isFirstLane(b), [&] {
        b.atomic(kind, b.extend(sum, b.getI64Type()), kernel.clock, clockSlot);
      });
      return;
    }
    // Minima: per warp, per group in workgroup memory, then one global
    // atomic per group.
    auto func = cast<gpu::GPUFuncOp>(kernel.func);
    Value groupMin = func.addWorkgroupAttribution(
        workgroupMemory(b.getContext(), 1, b.getI32Type()), b.loc);
    Value first = isFirstThread(b);
    b.ifThen(first, [&] { b.store(b.i32(kNoValue), groupMin, b.index(0)); });
    gpu::BarrierOp::create(b, b.loc);
    Value warpMin = reduce(b, mine, gpu::AllReduceOperation::MINSI);
    b.ifThen(isFirstLane(b), [&] {
      b.atomic(arith::AtomicRMWKind::mins, warpMin, groupMin, b.index(0));
    });
    gpu::BarrierOp::create(b, b.loc);
    b.ifThen(first, [&] {
      Value total = b.extend(b.load(groupMin, b.index(0)), b.getI64Type());
      b.atomic(kind, total, kernel.clock, clockSlot);
    });
  }

  /// Every thread group of the grid counts itself once all its threads are
  /// done (a barrier); the group that completes the grid runs `body` in
  /// one thread. In a distributed plan a group counts its items of the
  /// rank's block instead, as the CPU's invocations do (the kernels of both
  /// targets take the same arguments).
  void afterLastInvocation(KernelBuilder &b, Kernel &kernel, int64_t counter,
                           function_ref<void()> body) override {
    gpu::BarrierOp::create(b, b.loc);
    b.ifThen(isFirstThread(b), [&] {
      auto toI64 = [&](Value value) {
        return arith::IndexCastOp::create(b, b.loc, b.getI64Type(), value)
            .getResult();
      };
      Value mine = b.i64(1);
      Value total = toI64(gpu::GridDimOp::create(b, b.loc, gpu::Dimension::x));
      if (kernel.values.first) {
        Value size =
            toI64(gpu::BlockDimOp::create(b, b.loc, gpu::Dimension::x));
        Value base = b.mul(
            toI64(gpu::BlockIdOp::create(b, b.loc, gpu::Dimension::x)), size);
        total =
            toI64(b.sub(kernel.values.extent, b.index(2 * kernel.values.halo)));
        mine = b.min(size, b.sub(total, base));
      }
      b.addAndRunLast(mine, total, kernel.clock, b.index(counter), body);
    });
  }

  bool hasCaches() const override { return true; }

  Value groupSize(KernelBuilder &b, Kernel &) override {
    return gpu::BlockDimOp::create(b, b.loc, gpu::Dimension::x);
  }

  /// Caches live in dynamic shared memory, one after another; each starts
  /// at a multiple of its element size because SimulationLowering creates
  /// them by decreasing element size.
  Value createCache(KernelBuilder &b, Kernel &kernel, Type elementType,
                    int64_t stride, int64_t halo) override {
    MLIRContext *context = b.getContext();
    auto workgroup =
        gpu::AddressSpaceAttr::get(context, gpu::AddressSpace::Workgroup);
    Value base = gpu::DynamicSharedMemoryOp::create(
        b, b.loc,
        MemRefType::get({ShapedType::kDynamic}, b.getI8Type(), nullptr,
                        workgroup));
    Value count = b.add(groupSize(b, kernel), b.index(halo));
    Value offset = kernel.sharedOffset ? kernel.sharedOffset : b.index(0);
    Value cache =
        memref::ViewOp::create(b, b.loc,
                               MemRefType::get({ShapedType::kDynamic},
                                               elementType, nullptr, workgroup),
                               base, offset, ValueRange{count});
    kernel.sharedOffset = b.add(offset, b.mul(count, b.index(stride)));
    return cache;
  }

  void forEachSlot(KernelBuilder &b, Kernel &kernel, Value count,
                   function_ref<void(Value slot)> body) override {
    auto loop =
        scf::ForOp::create(b, b.loc, threadId(b), count, groupSize(b, kernel));
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    body(loop.getInductionVar());
  }

  void barrier(KernelBuilder &b) override { gpu::BarrierOp::create(b, b.loc); }

  /// A `mov` in inline PTX. LLVM sees inline assembly with side effects,
  /// which it neither hoists out of a loop nor merges with another; ptxas
  /// sees a copy, which costs nothing.
  Value opaque(KernelBuilder &b, Value value) override {
    Value wide = arith::IndexCastUIOp::create(b, b.loc, b.getI64Type(), value);
    auto copy = NVVM::InlinePtxOp::create(
        b, b.loc, TypeRange{b.getI64Type()}, ValueRange{wide}, ValueRange{},
        "mov.b64 $0, $1;", /*predicate=*/Value());
    return arith::IndexCastUIOp::create(b, b.loc, b.getIndexType(),
                                        copy.getResult(0));
  }

private:
  static Value threadId(KernelBuilder &b) {
    return gpu::ThreadIdOp::create(b, b.loc, gpu::Dimension::x);
  }
  static Value isFirstThread(KernelBuilder &b) {
    return b.cmp(arith::CmpIPredicate::eq, threadId(b), b.index(0));
  }
  static Value isFirstLane(KernelBuilder &b) {
    Value lane = gpu::LaneIdOp::create(b, b.loc, nullptr);
    return b.cmp(arith::CmpIPredicate::eq, lane, b.index(0));
  }
  /// Uniform: every lane takes part, which is what lets it lower to one
  /// redux.sync.
  static Value reduce(KernelBuilder &b, Value value,
                      gpu::AllReduceOperation op) {
    return gpu::SubgroupReduceOp::create(b, b.loc, value, op,
                                         /*uniform=*/true);
  }
};

struct SimLowerToGPUPass
    : public mlir::sim::impl::SimLowerToGPUBase<SimLowerToGPUPass> {
  using SimLowerToGPUBase::SimLowerToGPUBase;

  void runOnOperation() override {
    ModuleOp module = getOperation();
    SmallVector<SimulationOp> simulations(module.getOps<SimulationOp>());
    // A bundle plans groups up to kMaxGroupSize (its CPU kernels take any
    // size; sim-run chooses another for a GPU run, at most 1024).
    if (groupSize <= 0 || groupSize % 32 != 0 ||
        groupSize > int64_t(::sim::bundle::kMaxGroupSize)) {
      // Located at the scenes it would lower (the module has no location of
      // its own in a file).
      Location loc =
          simulations.empty() ? module.getLoc() : simulations.front().getLoc();
      emitError(loc) << "--sim-lower-to-gpu needs a group size that is a "
                        "multiple of 32 (a warp) from 32 to "
                     << ::sim::bundle::kMaxGroupSize << ", not "
                     << static_cast<int64_t>(groupSize);
      return signalPassFailure();
    }
    if (failed(SimulationOp::checkLoweredNamesAreFree(
            simulations, "_kernels", "kernels", getArgument())))
      return signalPassFailure();
    GPUKernelTarget target;
    for (SimulationOp simulation : simulations)
      if (failed(lowerSimulation(simulation, target, groupSize)))
        return signalPassFailure();
    module->setAttr(gpu::GPUDialect::getContainerModuleAttrName(),
                    UnitAttr::get(&getContext()));
  }
};

} // namespace
