//===- SimulationLowering.h - kernels and plan of a simulation --*- C++ -*-===//
//
// The lowering of one simulation that went through the front end into
// kernels (through a KernelTarget: GPU or CPU) and a simplan.plan. Its
// methods live in one file per concern (lib/Conversion/SimCommon/):
//
//   SimulationLowering.cpp   checks, the clock layout, kernel scaffolding,
//                            the plan and its phases (run)
//   ClockKernels.cpp         reset_clock, estimate_C, advance
//   StateKernels.cpp         init_B, exact_B, total_T
//   EvaluateKernels.cpp      evaluate_C and the hip-cache caches
//   SubStepKernels.cpp       substep_C: group sub-steps in one kernel
//   GridSubStepKernels.cpp   snapshot_B, the rounds of grid-wide sub-steps,
//                            parity_C
//   LocalStepKernels.cpp     levels_C, limit_levels_C, the slots of local
//                            time steps, local_parity_C
//
// Everything here decides *how* to run what the front end recorded: the
// strategy, the schedule, how each component advances (`advance`,
// `estimates`, `step_cap`), parity and snapshots come from the IR.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_SIMCOMMON_SIMULATIONLOWERING_H
#define SIM_CONVERSION_SIMCOMMON_SIMULATIONLOWERING_H

#include "sim/Conversion/SimCommon/KernelTarget.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Runtime/bundle_generated.h"

#include <limits>

namespace mlir::sim {

/// The fixed slots of the device clock: the layout is the bundle schema's
/// (runtime/schema/bundle.fbs, ClockSlot), which the runtime reads.
/// Evaluation counters, sub-step clocks and the big-step histogram follow
/// from kFirstFreeSlot.
constexpr int64_t kSlotBegin = int64_t(::sim::bundle::ClockSlot::Begin);
constexpr int64_t kSlotSize = int64_t(::sim::bundle::ClockSlot::Size);
constexpr int64_t kSlotParity = int64_t(::sim::bundle::ClockSlot::Parity);
constexpr int64_t kSlotEnd = int64_t(::sim::bundle::ClockSlot::End);
constexpr int64_t kSlotEstimate = int64_t(::sim::bundle::ClockSlot::Estimate);
constexpr int64_t kSlotBigSteps = int64_t(::sim::bundle::ClockSlot::BigSteps);
constexpr int64_t kSlotCuts = int64_t(::sim::bundle::ClockSlot::Cuts);
constexpr int64_t kSlotEstimateHint =
    int64_t(::sim::bundle::ClockSlot::EstimateHint);
constexpr int64_t kFirstFreeSlot = int64_t(::sim::bundle::ClockSlot::FirstFree);

/// Slots of a grid-sub-stepping component's sub-step clock, from its first.
constexpr int64_t kSubBegin = int64_t(::sim::bundle::SubClockSlot::Begin);
constexpr int64_t kSubSize = int64_t(::sim::bundle::SubClockSlot::Size);
constexpr int64_t kSubCount = int64_t(::sim::bundle::SubClockSlot::Done);
constexpr int64_t kSubEstimate = int64_t(::sim::bundle::SubClockSlot::Estimate);
constexpr int64_t kSubUnit = int64_t(::sim::bundle::SubClockSlot::Unit);
constexpr int64_t kSubUnitRequest =
    int64_t(::sim::bundle::SubClockSlot::UnitRequest);
/// UnitRequest holds num_steps less this bias: negative for every
/// num_steps of 1 or more, so that 0 is the identity of its minimum.
constexpr int64_t kUnitBias = (int64_t(1) << 31) - 1;
constexpr int64_t kLargestHint =
    int64_t(::sim::bundle::LargestEstimateSlot::Hint);
constexpr int64_t kLargestKept =
    int64_t(::sim::bundle::LargestEstimateSlot::Kept);
constexpr int64_t kLargestSlots =
    int64_t(::sim::bundle::LargestEstimateSlot::Slots);

/// Local time steps: the code levels_C combines sub-steps into
/// (kLevelCode - sub-step, by an atomic maximum whose identity is 0). The
/// block size, kLevelBlock, is in KernelBody.h.
constexpr int64_t kLevelCode = int64_t(1) << 62;
static_assert(kLevelBlock == int64_t(::sim::bundle::LocalStepBlock::Items),
              "the kernels' level blocks and the bundle schema's differ");
/// The sections of `levels @C`, each one i64 per block: the two halves of
/// levels_C's codes, then, for the big step, the neighbourhood codes for
/// local_step_C and for a flux writer's local_flux_E, the ends of their
/// runs of equal codes, the blocks' sub-steps and the codes kept when the
/// levels do not change (LocalStepKernels.cpp).
constexpr int64_t kLevelStepCodes = 2, kLevelFluxCodes = 3, kLevelStepRuns = 4,
                  kLevelFluxRuns = 5, kLevelSteps = 6, kLevelCached = 7;
static_assert(int64_t(::sim::bundle::LocalStepLevels::Steps) == kLevelSteps &&
                  int64_t(::sim::bundle::LocalStepLevels::Cached) ==
                      kLevelCached &&
                  int64_t(::sim::bundle::LocalStepLevels::Sections) ==
                      kLevelCached + 1,
              "the kernels' level sections and the bundle schema's differ");

/// No estimate yet: the identity of the minimum.
constexpr int32_t kNoEstimate = std::numeric_limits<int32_t>::max();
constexpr int64_t kNoEstimate64 = std::numeric_limits<int64_t>::max();

/// The bytes one element of `buffer` takes in memory, as the kernels address
/// it (LLVM's alloc size: vectors are padded to a power of two, so
/// vector<3xf32> takes 16 bytes).
int64_t getElementStride(BufferOp buffer);

class SimulationLowering {
public:
  SimulationLowering(SimulationOp simulation, KernelTarget &target,
                     int64_t groupSize)
      : simulation(simulation), target(target), groupSize(groupSize),
        b(simulation.getContext(), simulation.getLoc()) {}

  LogicalResult run();

private:
  LogicalResult checkFrontEnd();
  LogicalResult checkRecordedDecisions();
  void planClock();

  // Kernels and launches.
  Kernel beginKernel(StringRef name, BufferOp exactOf = nullptr,
                     TotalOp totalOf = nullptr);
  LogicalResult endKernel(Kernel &kernel, simplan::LaunchShape shape,
                          OpBuilder &launches, ComponentOp component = nullptr);
  void readClock(Kernel &kernel, Value &begin, Value &size, Value &parity);
  /// readClock, and the values of a kernel whose bodies run in the big
  /// step: both halves from the clock's parity (`local` loads the source)
  /// and `sim.big_step`.
  void readBigStep(Kernel &kernel, Value &begin, Value &size, Value &parity);
  /// The element of `item` in the kernel's total arrays and in `buffer`'s
  /// snapshot or exact array.
  Value element(Kernel &kernel, Value item, StringAttr buffer = {}) {
    return getElementIndex(b, b.loc, kernel.values, item, buffer);
  }
  /// The element of `item` in `buffer`'s storage, in the half `parity`
  /// selects, whose block offset is `blockBase`.
  Value at(Kernel &kernel, StringAttr buffer, Value blockBase, Value parity,
           Value item) {
    return b.add(
        getHalfOffset(b, b.loc, kernel.values, buffer, blockBase, parity),
        element(kernel, item, buffer));
  }
  /// Distributed plans: whether `buffer` travels between ranks after it is
  /// written (its ghost items, or all of it when it is replicated).
  static bool travels(BufferOp buffer) {
    return buffer.getHaloAttr() || buffer.getReplicated();
  }
  void setHalves(Kernel &kernel, Value parity, Value localParity);
  /// Runs `body` for every lane of every group the invocation handles.
  void forEachItem(Kernel &kernel, function_ref<void(const Lane &)> body);
  /// Copies `item` of every buffer in `writes` from the source half to the
  /// target half (the parity copy after an even number of sub-steps).
  void copyToTarget(Kernel &kernel, ArrayRef<FlatSymbolRefAttr> writes,
                    Value item);
  /// Counts an evaluation of the lane's item in `count` when it is active.
  void countEvaluation(LaneVar count, const Lane &lane);
  SmallVector<Value> inline_(Region &body, ValueRange args,
                             const KernelValues &values);
  Value estimate(Kernel &kernel, ComponentOp component, Value item, Value time,
                 const KernelValues &values);
  /// A pair writer's largest estimate cannot change during a run, so its
  /// clock slot keeps it (`keeps_estimate`).
  bool keepsEstimate(ComponentOp writer);
  /// Where an estimate reduces: the minimum of `num_steps` over every item
  /// into clock `slot` (starting from the group of `hintSlot`), or, for
  /// `largest`, the maximum of `num_steps` capped at the step cap, kept
  /// negated so that the clock's minima (and a distributed run's all-reduce
  /// of them) combine it; 0 is then no estimate.
  struct EstimateSlots {
    int64_t slot;
    int64_t hintSlot;
    bool largest = false;
  };
  /// `component`'s estimates at local time `time` over every item (through
  /// lane variable `combined`), combined into the clock as `slots` says.
  void estimateInto(Kernel &kernel, ComponentOp component, LaneVar combined,
                    Value time, EstimateSlots slots);

  /// A group cache of hip-cache: the fill the front end recorded and its
  /// memory.
  struct Cache {
    FillCacheOp fill;
    Value memory;
  };
  /// The caches of `component`'s evaluate body, on targets that keep them.
  SmallVector<Cache> createCaches(Kernel &kernel, ComponentOp component);
  /// Fills the caches of the group at `base` for an evaluation from local
  /// time `time` of `steps` base steps, points `kernel.values` at them and
  /// waits for the group.
  void fillCaches(Kernel &kernel, ComponentOp component, ArrayRef<Cache> caches,
                  Value base, Value time, Value steps, Value dt);
  /// Evaluates every item of the invocation once, from local time `time`
  /// over `steps` base steps (i32), filling the caches of each group first,
  /// writes the results at element offset `writeBase` and counts the
  /// evaluations in `count`.
  void evaluateItems(Kernel &kernel, ComponentOp component,
                     ArrayRef<Cache> caches, Value time, Value steps,
                     Value writeBase, Value writeParity, LaneVar count);

  LogicalResult emitResetClock(OpBuilder &launches);
  LogicalResult emitInit(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitExact(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitTotal(TotalOp total, OpBuilder &launches);
  LogicalResult emitEstimate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitAdvance(OpBuilder &launches, bool minimumEstimated);
  LogicalResult emitEvaluate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitSubSteps(ComponentOp component, OpBuilder &launches);
  LogicalResult emitRounds(ComponentOp component, OpBuilder &launches);
  LogicalResult emitLocalSteps(ComponentOp component, OpBuilder &launches);
  /// The flux writer (`advance = local_flux`) whose fluxes `reader` reads,
  /// or null.
  ComponentOp findFluxWriter(ComponentOp reader);
  /// Snapshots of the value at T of `component`'s buffers that the plan
  /// snapshots, before it ping-pongs between the halves.
  LogicalResult emitSnapshots(ComponentOp component, OpBuilder &launches);

  SimulationOp simulation;
  KernelTarget &target;
  int64_t groupSize;
  KernelBuilder b;
  Strategy strategy;
  int64_t maxSteps, stepCap;
  /// A plan for many processes (the simulation's `distributed_halo`): its
  /// kernels address a rank's block with `distributedHalo` ghost items on
  /// each side.
  bool distributed = false;
  int64_t distributedHalo = 0;
  /// Distributed plans: what the next endKernel records on its launch
  /// besides the exchange of its component's buffers (clock slots to
  /// all-reduce before it, buffers and snapshots whose ghosts travel after
  /// it).
  SmallVector<int64_t> pendingReduce;
  SmallVector<Attribute> pendingExchange, pendingExchangeSnapshots;
  /// Components whose levels every rank replaces by their maximum over the
  /// ranks before the next launch (`reduce_max_levels`).
  SmallVector<Attribute> pendingReduceLevels;
  /// Which half of its component's buffers the next endKernel's launch
  /// writes, so which half of them travels: `Advance` by the component's
  /// advance (the target half for whole_step and group_substeps, both
  /// otherwise), `Target` the target half (a parity copy), `SubStep` the
  /// half a grid-wide sub-step writes (`exchange_sub_step`), `LocalStep`
  /// the blocks a local time step's slot starts and the halves they write
  /// (`exchange_local_step`).
  enum class WrittenHalf { Advance, Target, SubStep, LocalStep, LocalFlux };
  WrittenHalf pendingWrittenHalf = WrittenHalf::Advance;

  Operation *kernels;
  simplan::PlanOp plan;
  SmallVector<BufferOp> buffers;
  SmallVector<ParamOp> params;
  SmallVector<ComponentOp> order;
  llvm::DenseMap<Operation *, int64_t> evaluationSlots, subClockSlots;
  /// A pair writer's estimate under lts (docs/Model.md, "The big step"): its
  /// largest num_steps, negated, the group where it last reached the step
  /// cap, and the estimate kept (kLargestSlots from the slot recorded).
  llvm::DenseMap<Operation *, int64_t> largestEstimateSlots;
  int64_t histogramSlot = 0, clockSlots = 0;
  /// Set when inlining a body failed inside a builder callback.
  bool bodyFailed = false;
};

} // namespace mlir::sim

#endif // SIM_CONVERSION_SIMCOMMON_SIMULATIONLOWERING_H
