//===- KernelTarget.h - what a backend provides to the kernels --*- C++ -*-===//
//
// The kernels of a lowered simulation (the clock updates, estimates,
// Algorithm 2, the grid-wide rounds) are written once, in
// lib/Conversion/SimCommon (SimulationLowering.h), in terms of *groups* of
// items and per-lane *phases*: code that every lane of a group runs, separated
// by group-wide operations (a minimum, a sum into the clock). A KernelTarget
// says what those are on one backend. On a GPU a group is a thread block, a
// phase is the thread's own code and a group operation is a warp reduction plus
// workgroup memory between barriers; on a CPU a group is a loop iteration
// and a phase is a loop over its lanes. Values that live across phases are
// lane variables: one element of private memory per thread on a GPU
// (promoted to registers), one element per lane on a CPU.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_SIMCOMMON_KERNELTARGET_H
#define SIM_CONVERSION_SIMCOMMON_KERNELTARGET_H

#include "sim/Conversion/SimCommon/KernelBody.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Interfaces/FunctionInterfaces.h"

namespace mlir::sim {

/// A small vocabulary over OpBuilder for the index and i64 arithmetic of
/// kernels, so that kernel builders read like the algorithm. Integer
/// constants are created once per kernel, at its entry.
struct KernelBuilder : OpBuilder {
  KernelBuilder(MLIRContext *context, Location loc)
      : OpBuilder(context), loc(loc) {}

  /// Starts a new kernel whose constants go to the start of `entry`.
  void startKernel(Block *entry);
  Value constant(Type type, int64_t value);
  Value index(int64_t value) { return constant(getIndexType(), value); }
  Value i64(int64_t value) { return constant(getI64Type(), value); }
  Value i32(int64_t value) { return constant(getI32Type(), value); }

  Value add(Value a, Value b);
  Value sub(Value a, Value b);
  Value mul(Value a, Value b);
  Value min(Value a, Value b);
  Value max(Value a, Value b);
  Value cmp(arith::CmpIPredicate predicate, Value a, Value b);
  Value select(Value cond, Value a, Value b);
  Value xorOne(Value value);
  /// The largest power of two not above `value` (a positive i64), 0 for 0.
  Value floorPowerOfTwo(Value value);
  Value toIndex(Value value);
  Value extend(Value value, Type type);
  Value truncate(Value value, Type type);
  Value load(Value memref, Value index);
  void store(Value value, Value memref, Value index);
  /// An atomic read-modify-write; returns the value before it.
  Value atomic(arith::AtomicRMWKind kind, Value value, Value memref,
               Value index);
  /// Adds `count` (i64) to the counter at `memref[index]`; the caller whose
  /// addition brings it to `total` resets it to 0 and runs `body`.
  void addAndRunLast(Value count, Value total, Value memref, Value index,
                     function_ref<void()> body);

  /// scf.if with results; the callbacks build each branch and return what
  /// it yields.
  scf::IfOp ifThenElse(TypeRange types, Value cond,
                       function_ref<SmallVector<Value>()> thenBuilder,
                       function_ref<SmallVector<Value>()> elseBuilder);
  /// scf.if without results.
  void ifThen(Value cond, function_ref<void()> thenBuilder);

  Location loc;

private:
  Block *kernelEntry = nullptr;
  llvm::DenseMap<std::pair<Type, int64_t>, Value> constants;
};

/// One lane of a group inside a phase.
struct Lane {
  /// The item the lane holds (index); only meaningful when `active`.
  Value item;
  /// True when the item is below the range (padding lanes are inactive).
  Value active;
  /// Where the lane's element of a lane variable is.
  Value slot;
};

/// A value per lane that lives across phases.
struct LaneVar {
  Value memory;
};

/// Consecutive lanes of a group, `first` to `first + count - 1` (index
/// values), whose items start at `base`; `whole` when they are the whole
/// group.
struct Part {
  Value base, first, count;
  bool whole;
};

/// One kernel under construction.
struct Kernel {
  FunctionOpInterface func;
  /// What the runtime passes for each argument the kernel started with.
  SmallVector<simplan::ArgAttr> args;
  /// Trailing arguments of the target's own (not in the plan), kept.
  unsigned targetArgs = 0;
  Value clock;
  /// The values bodies read; each kernel builder adds the halves,
  /// registers and big step that its bodies see.
  KernelValues values;
  /// Per component that advances in `local_steps`: its groups' sub-steps
  /// (`levels @C`).
  llvm::DenseMap<StringAttr, Value> levels;
  /// The time argument of an exact kernel.
  Value time;
  /// The per-item output array (f64) of a total kernel.
  Value totalOut;
  /// Target-specific state of the kernel (for example its workgroup
  /// memory for group minima).
  llvm::SmallVector<Value> targetState;
  /// Dynamic shared memory of a launch: `sharedPerThread * group size +
  /// sharedFixed` bytes, and the byte offset of the next cache in it.
  int64_t sharedPerThread = 0, sharedFixed = 0;
  Value sharedOffset;
  /// Whether the work of its groups differs widely within a launch (a slot
  /// kernel of local time steps), recorded as `simplan.uneven_groups`.
  bool unevenGroups = false;
};

/// What a backend provides to the kernels.
class KernelTarget {
public:
  virtual ~KernelTarget();

  /// Creates the symbol table the kernels of simulation `name` go into
  /// (named `<name>_kernels`) at the builder's insertion point.
  virtual Operation *createContainer(OpBuilder &b, Location loc,
                                     StringRef name) = 0;
  /// Creates an empty kernel `name` taking `types` (plus arguments of the
  /// target's own, appended), sets `kernel.func` and `kernel.targetArgs`,
  /// and returns its entry block with the builder at its start.
  virtual Block *createKernel(KernelBuilder &b, Kernel &kernel, StringRef name,
                              TypeRange types) = 0;
  /// Ends the kernel body.
  virtual void finishKernel(KernelBuilder &b, Kernel &kernel) = 0;

  /// Runs `body` once for each group this invocation handles; `base` is
  /// the first item of the group.
  virtual void forEachGroup(KernelBuilder &b, Kernel &kernel,
                            function_ref<void(Value base)> body) = 0;
  /// forEachGroup, but where the target orders its groups itself (a CPU,
  /// splitsGroups), starting at the group of item `start` (i64) when this
  /// invocation handles it and going round: a hint about which group
  /// matters first (no result may depend on it). The default ignores it.
  virtual void forEachGroupFrom(KernelBuilder &b, Kernel &kernel, Value start,
                                function_ref<void(Value base)> body) {
    forEachGroup(b, kernel, body);
  }
  /// Runs `body` for each lane of the group that starts at `base`.
  virtual void forEachLane(KernelBuilder &b, Kernel &kernel, Value base,
                           function_ref<void(const Lane &)> body) = 0;
  /// Whether one thread runs a group's lanes chunk by chunk (a CPU), so
  /// that a kernel may split a group into parts (forEachLaneOf) and decide
  /// at group level per part (lts: whether the neighbourhood of its items
  /// has one sub-step) rather than for the whole group; where lanes run
  /// side by side (a GPU) a part is the whole group.
  virtual bool splitsGroups() const { return false; }
  /// Whether limit_levels_C (lts) limits each block's sub-step in a lane of
  /// its own (a window minimum per block, all at once: a GPU) or in one
  /// pass over the blocks by one lane (sweeps to
  /// the same fixpoint: a CPU, where a pass costs less than the lanes'
  /// repeated window minima). Both give the same sub-steps and codes.
  virtual bool limitsLevelsPerLane() const { return !splitsGroups(); }
  /// Whether a read through the time levels (lts) loads the item from both
  /// halves and selects its latest level per lane (a CPU: lanes side by
  /// side in SIMD registers, where two wide loads and a select serve a
  /// chunk whose blocks keep their latest levels in different halves, and
  /// one load at a per-lane half is a gather), or loads only the half that
  /// holds it (a GPU: a thread loads one element).
  virtual bool readsLevelsFromBothHalves() const { return splitsGroups(); }
  /// Runs `body(begin, end)` for spans of the items of consecutive groups
  /// this invocation handles, in order, `end` at most the range: where one
  /// thread runs its groups one after another (a CPU, splitsGroups), one
  /// span of all of them, so that a kernel may walk its items across
  /// groups at group level; else each group. `begin` is a group's first
  /// item, and every group of the span starts a multiple of the group
  /// size after it.
  virtual void forEachGroupSpan(KernelBuilder &b, Kernel &kernel,
                                function_ref<void(Value, Value)> body);
  /// Runs `body` for each lane of `part`.
  virtual void forEachLaneOf(KernelBuilder &b, Kernel &kernel, const Part &part,
                             function_ref<void(const Lane &)> body);
  /// Combines the i64 lane variable `value` of every active lane of the
  /// group that starts at `base` with a signed maximum into element
  /// `offset + k / blockSize` of `memory` for every item k from
  /// `item - spreadHigh` to `item - spreadLow` (just `item` by default)
  /// that lies in the range, atomically (groups may run at once). At group
  /// level, after the phase that set `value`. The default is an atomic per
  /// lane and block reached; a target whose lanes run in one thread
  /// combines the lanes that reach each block first. `onlyWriter` says
  /// that nothing else in the launch writes these elements: a block whose
  /// items all lie in the group then needs no atomic.
  virtual void maxPerBlock(KernelBuilder &b, Kernel &kernel, Value base,
                           LaneVar value, int64_t blockSize, Value memory,
                           Value offset, int64_t spreadLow = 0,
                           int64_t spreadHigh = 0, bool onlyWriter = false);

  /// A lane variable of `type`, created at the kernel entry and, when
  /// `initial` is given (a value available there), set to it in every lane.
  virtual LaneVar createLaneVar(KernelBuilder &b, Kernel &kernel, Type type,
                                Value initial = nullptr) = 0;

  /// Prepares repeated group minima (groupMin); called once before the
  /// first group, at the kernel's top level.
  virtual void prepareGroupMin(KernelBuilder &b, Kernel &kernel) = 0;
  /// The minimum of an i32 lane variable over the group, the same value in
  /// every lane. Called at group level (outside phases), the same number of
  /// times by every lane.
  virtual Value groupMin(KernelBuilder &b, Kernel &kernel, LaneVar value) = 0;
  /// Combines an i32 lane variable over every lane of the invocation into
  /// clock slot `slot` (as i64) with `kind` (`mins` or `addi`). Called once,
  /// after the last group, at the kernel's top level; or, where
  /// reducesPerGroup, at group level once per group.
  virtual void reduceIntoClock(KernelBuilder &b, Kernel &kernel, LaneVar value,
                               arith::AtomicRMWKind kind, int64_t slot) = 0;
  /// Runs `body` once per launch, in the invocation that gets there last,
  /// when every invocation of the launch has got there: at the kernel's top
  /// level, at its end. Invocations count themselves in clock slot
  /// `counter`, which is 0 before the launch and left 0 (so the next
  /// launch finds it so). What the invocations read before this point may
  /// be changed by `body` (a single-thread launch after this one, saved).
  virtual void afterLastInvocation(KernelBuilder &b, Kernel &kernel,
                                   int64_t counter,
                                   function_ref<void()> body) = 0;
  /// Whether a group may decide on its own, from a clock slot that other
  /// groups of the same launch change atomically, to skip its lanes, and
  /// then combine its lanes into that slot itself (reduceIntoClock at group
  /// level): a target whose threads run whole groups one after another (a
  /// CPU). Where lanes of a group run side by side (a GPU) each would read
  /// the slot on its own, and the combination synchronises them.
  virtual bool reducesPerGroup() const { return false; }
  /// Whether a sub-step kernel takes a big step of 1 as evaluate_C does
  /// (own state read where it lies, no registers, no group minimum), in a
  /// second copy of the component's body next to the sub-step loop. On a
  /// CPU that copy is the faster code for m = 1 and costs only code size;
  /// on a GPU a kernel's registers are the maximum over both copies, and
  /// the copy raised hip-cache's beyond 1.25x the hand-written kernel's
  /// (Target/PTX/registers.test).
  virtual bool evaluatesUnitBigStep() const { return false; }

  /// Whether the backend keeps hip-cache's shared-memory caches. Without
  /// them a cache load computes its value (the results are the same).
  virtual bool hasCaches() const { return false; }
  /// The number of lanes of a group, at the builder's position.
  virtual Value groupSize(KernelBuilder &b, Kernel &kernel) = 0;
  /// A cache of `elementType` elements (`stride` bytes each) for a group's
  /// items plus `halo` more, created at the builder's position (the
  /// kernel's top level).
  virtual Value createCache(KernelBuilder &b, Kernel &kernel, Type elementType,
                            int64_t stride, int64_t halo) {
    llvm_unreachable("this target keeps no caches");
  }
  /// Runs `body(slot)` for each of `count` slots, spread over the lanes of
  /// the group (at group level).
  virtual void forEachSlot(KernelBuilder &b, Kernel &kernel, Value count,
                           function_ref<void(Value slot)> body) {
    llvm_unreachable("this target keeps no caches");
  }
  /// Waits for every lane of the group (nothing on a target whose phases
  /// run one after another).
  virtual void barrier(KernelBuilder &b) {}
  /// `value` (index), through an operation the optimiser cannot see
  /// through or move, at the builder's position. Inside a loop, what is
  /// computed from the result is computed again in every iteration instead
  /// of being hoisted out of the loop and kept in registers across it: on
  /// a GPU, where registers limit occupancy, the addresses of a body's
  /// reads are cheaper to recompute than to keep. The default is `value`.
  virtual Value opaque(KernelBuilder &b, Value value) { return value; }

  Value laneLoad(KernelBuilder &b, LaneVar var, const Lane &lane) {
    return b.load(var.memory, lane.slot);
  }
  void laneStore(KernelBuilder &b, Value value, LaneVar var, const Lane &lane) {
    b.store(value, var.memory, lane.slot);
  }
};

/// Lowers one simulation that went through the front end: creates its
/// kernels through `target` and a `simplan.plan` next to the simulation,
/// then erases the simulation.
LogicalResult lowerSimulation(SimulationOp simulation, KernelTarget &target,
                              int64_t groupSize);

} // namespace mlir::sim

#endif // SIM_CONVERSION_SIMCOMMON_KERNELTARGET_H
