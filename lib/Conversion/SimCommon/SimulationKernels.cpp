//===- SimulationKernels.cpp - the kernels and plan of a simulation -------===//
//
// Lowers a simulation that went through the front end into kernels (through
// a KernelTarget: GPU or CPU) and a simplan.plan. Everything this file
// decides is *how* to run what the front end recorded: the strategy, the
// schedule and its step bounds, the sub-stepping verdicts, parity and
// snapshots come from the IR.
//
// The size of each big step never travels to the host. A device-resident
// clock (docs/Plan.md) holds T, m, the parity of the halves and the end of
// the run; estimate kernels reduce into it, a one-thread `advance` kernel
// commits the previous big step and decides the next, and every other
// kernel reads T and m from it and does nothing once the run has ended. The
// host can therefore launch many big steps ahead (or replay a graph of one)
// and look at the clock rarely. Because which half of a buffer is the
// source is the clock's parity, no launch argument changes between big
// steps either.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/SimCommon/KernelNames.h"
#include "sim/Conversion/SimCommon/KernelTarget.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Transforms/RegionUtils.h"

using namespace mlir;
using namespace mlir::sim;

//===----------------------------------------------------------------------===//
// KernelBuilder
//===----------------------------------------------------------------------===//

void KernelBuilder::startKernel(Block *entry) {
  kernelEntry = entry;
  constants.clear();
}

Value KernelBuilder::constant(Type type, int64_t value) {
  Value &cached = constants[{type, value}];
  if (!cached) {
    InsertionGuard guard(*this);
    setInsertionPointToStart(kernelEntry);
    cached = arith::ConstantOp::create(*this, loc, type,
                                       getIntegerAttr(type, value));
  }
  return cached;
}

Value KernelBuilder::add(Value a, Value b) {
  return arith::AddIOp::create(*this, loc, a, b);
}
Value KernelBuilder::sub(Value a, Value b) {
  return arith::SubIOp::create(*this, loc, a, b);
}
Value KernelBuilder::mul(Value a, Value b) {
  return arith::MulIOp::create(*this, loc, a, b);
}
Value KernelBuilder::min(Value a, Value b) {
  return arith::MinSIOp::create(*this, loc, a, b);
}
Value KernelBuilder::max(Value a, Value b) {
  return arith::MaxSIOp::create(*this, loc, a, b);
}
Value KernelBuilder::cmp(arith::CmpIPredicate predicate, Value a, Value b) {
  return arith::CmpIOp::create(*this, loc, predicate, a, b);
}
Value KernelBuilder::select(Value cond, Value a, Value b) {
  return arith::SelectOp::create(*this, loc, cond, a, b);
}
Value KernelBuilder::xorOne(Value value) {
  return arith::XOrIOp::create(*this, loc, value, constant(value.getType(), 1));
}
Value KernelBuilder::toIndex(Value value) {
  return arith::IndexCastOp::create(*this, loc, getIndexType(), value);
}
Value KernelBuilder::extend(Value value, Type type) {
  // Flags (i1) extend unsigned, counts and estimates signed.
  if (value.getType().isInteger(1))
    return arith::ExtUIOp::create(*this, loc, type, value);
  return arith::ExtSIOp::create(*this, loc, type, value);
}
Value KernelBuilder::truncate(Value value, Type type) {
  return arith::TruncIOp::create(*this, loc, type, value);
}
Value KernelBuilder::load(Value memref, Value index) {
  return memref::LoadOp::create(*this, loc, memref, index);
}
void KernelBuilder::store(Value value, Value memref, Value index) {
  memref::StoreOp::create(*this, loc, value, memref, index);
}
void KernelBuilder::atomic(arith::AtomicRMWKind kind, Value value, Value memref,
                           Value index) {
  memref::AtomicRMWOp::create(*this, loc, kind, value, memref, index);
}

scf::IfOp
KernelBuilder::ifThenElse(TypeRange types, Value cond,
                          function_ref<SmallVector<Value>()> thenBuilder,
                          function_ref<SmallVector<Value>()> elseBuilder) {
  auto ifOp = scf::IfOp::create(*this, loc, types, cond,
                                /*withElseRegion=*/true);
  InsertionGuard guard(*this);
  for (auto [region, build] :
       {std::pair<Region *, function_ref<SmallVector<Value>()>>{
            &ifOp.getThenRegion(), thenBuilder},
        {&ifOp.getElseRegion(), elseBuilder}}) {
    Block &block = region->front();
    // Without results the builder already added the terminator.
    if (types.empty())
      setInsertionPoint(block.getTerminator());
    else
      setInsertionPointToEnd(&block);
    SmallVector<Value> values = build();
    if (!types.empty())
      scf::YieldOp::create(*this, loc, values);
  }
  return ifOp;
}

void KernelBuilder::ifThen(Value cond, function_ref<void()> thenBuilder) {
  auto ifOp = scf::IfOp::create(*this, loc, TypeRange(), cond,
                                /*withElseRegion=*/false);
  InsertionGuard guard(*this);
  setInsertionPoint(ifOp.getThenRegion().front().getTerminator());
  thenBuilder();
}

KernelTarget::~KernelTarget() = default;

//===----------------------------------------------------------------------===//
// The simulation
//===----------------------------------------------------------------------===//

namespace {

/// The fixed slots of the clock (docs/Plan.md). Evaluation counters,
/// sub-step clocks and the big-step histogram follow from kFirstFreeSlot.
enum ClockSlot : int64_t {
  kSlotBegin = 0,     // T: first base step of the current big step
  kSlotSize = 1,      // m: its size; 0 once the run has reached its end
  kSlotParity = 2,    // which half holds the state at T
  kSlotEnd = 3,       // the base step the run stops at (set by the host)
  kSlotEstimate = 4,  // minimum of the estimates for the next big step
  kSlotBigSteps = 5,  // big steps taken
  kFirstFreeSlot = 8, // (6 and 7 are reserved)
};

/// Slots of a grid-synchronised component's sub-step clock.
enum SubClockSlot : int64_t {
  kSubBegin = 0,    // local time t of the current sub-step
  kSubSize = 1,     // its size n; 0 once the component reached T + m
  kSubCount = 2,    // sub-steps completed (its parity)
  kSubEstimate = 3, // minimum estimate for the next sub-step
  kSubClockSlots = 4,
};

constexpr int32_t kNoEstimate = std::numeric_limits<int32_t>::max();
constexpr int64_t kNoEstimate64 = std::numeric_limits<int64_t>::max();

/// The bytes one element of `buffer` takes in memory, as the kernels address
/// it (LLVM's alloc size: vectors are padded to a power of two, so
/// vector<3xf32> takes 16 bytes).
int64_t elementStride(BufferOp buffer) {
  int64_t bytes = buffer.getElementBytes();
  return isa<VectorType>(buffer.getElementType()) ? llvm::PowerOf2Ceil(bytes)
                                                  : bytes;
}

bool isSubStepping(Strategy strategy) {
  return strategy == Strategy::hip || strategy == Strategy::hip_cache;
}

class SimulationLowering {
public:
  SimulationLowering(SimulationOp simulation, KernelTarget &target,
                     int64_t groupSize)
      : simulation(simulation), target(target), groupSize(groupSize),
        b(simulation.getContext(), simulation.getLoc()) {}

  LogicalResult run();

private:
  LogicalResult checkFrontEnd();
  void planClock();

  // Kernels and launches.
  Kernel beginKernel(StringRef name, BufferOp exactOf = nullptr,
                     TotalOp totalOf = nullptr);
  LogicalResult endKernel(Kernel &kernel, simplan::LaunchShape shape,
                          OpBuilder &launches, ComponentOp component = nullptr);
  void readClock(Kernel &kernel, Value &begin, Value &size, Value &parity);
  void setHalves(Kernel &kernel, Value parity, Value localParity);
  /// Runs `body` for every lane of every group the invocation handles.
  void forEachItem(Kernel &kernel, function_ref<void(const Lane &)> body);
  /// Counts an evaluation of the lane's item in `count` when it is active.
  void countEvaluation(LaneVar count, const Lane &lane);
  SmallVector<Value> inline_(Region &body, ValueRange args,
                             const KernelValues &values);
  Value estimate(Kernel &kernel, ComponentOp component, Value item, Value time,
                 const KernelValues &values);
  /// The minimum of `component`'s estimates at local time `time` over every
  /// item (through lane variable `minimum`), combined into clock `slot`.
  void estimateInto(Kernel &kernel, ComponentOp component, LaneVar minimum,
                    Value time, int64_t slot);

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
                     Value writeBase, LaneVar count);

  LogicalResult emitResetClock(OpBuilder &launches);
  LogicalResult emitInit(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitExact(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitTotal(TotalOp total, OpBuilder &launches);
  LogicalResult emitEstimate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitAdvance(OpBuilder &launches, bool hasEstimates);
  LogicalResult emitEvaluate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitSubSteps(ComponentOp component, OpBuilder &launches);
  LogicalResult emitRounds(ComponentOp component, OpBuilder &launches);

  SimulationOp simulation;
  KernelTarget &target;
  int64_t groupSize;
  KernelBuilder b;
  Strategy strategy;
  int64_t maxSteps;

  Operation *kernels;
  simplan::PlanOp plan;
  SmallVector<BufferOp> buffers;
  SmallVector<ParamOp> params;
  SmallVector<ComponentOp> order;
  llvm::DenseMap<Operation *, int64_t> evaluationSlots, subClockSlots;
  int64_t histogramSlot = 0, clockSlots = 0;
  /// Set when inlining a body failed inside a builder callback.
  bool bodyFailed = false;
};

} // namespace

//===----------------------------------------------------------------------===//
// Checks
//===----------------------------------------------------------------------===//

LogicalResult SimulationLowering::checkFrontEnd() {
  StrategyAttr strategyAttr = simulation.getStrategyAttr();
  if (!strategyAttr)
    return simulation.emitOpError()
           << "has no memory plan; run the front end (--sim-front-end) "
              "before lowering it";
  strategy = strategyAttr.getValue();
  maxSteps = simulation.getMaxSteps();

  ScheduleOp schedule = simulation.getScheduleOp();
  size_t numComponents = llvm::range_size(simulation.getComponents());
  if (!schedule || schedule.getOrder().size() != numComponents)
    return simulation.emitOpError()
           << "has no complete schedule; run the front end (--sim-front-end) "
              "before lowering it";
  for (FlatSymbolRefAttr name :
       schedule.getOrder().getAsRange<FlatSymbolRefAttr>())
    order.push_back(simulation.lookupComponent(name));

  for (ComponentOp component : order) {
    if (!component.getSubSteppingAttr() || !component.getParityAttr())
      return component.emitOpError()
             << "has no sub-stepping verdict or parity; run the front end "
                "(--sim-front-end) before lowering it";
    WalkResult walk = component.walk([](ReadOp read) {
      read.emitOpError() << "is a view read; run --sim-insert-interpolation "
                            "(or the whole front end) before lowering it";
      return WalkResult::interrupt();
    });
    if (walk.wasInterrupted())
      return failure();
  }
  for (TotalOp total : simulation.getTotals()) {
    WalkResult walk = total.walk([](ReadOp read) {
      read.emitOpError() << "is a view read; run --sim-insert-interpolation "
                            "(or the whole front end) before lowering it";
      return WalkResult::interrupt();
    });
    if (walk.wasInterrupted())
      return failure();
  }
  for (ParamOp param : simulation.getParams()) {
    Type type = cast<TypedAttr>(param.getValue()).getType();
    if (!type.isInteger(32) && !type.isInteger(64) && !type.isIndex() &&
        !type.isF32() && !type.isF64())
      return param.emitOpError()
             << "has type " << type
             << ", which a kernel cannot take as an argument; use i32, i64, "
                "index, f32 or f64";
    params.push_back(param);
  }
  for (BufferOp buffer : simulation.getBuffers())
    buffers.push_back(buffer);
  return success();
}

/// Assigns clock slots: the fixed ones, one evaluation counter per
/// component, a sub-step clock per component that takes grid-wide sub-steps,
/// then the histogram of big-step sizes (index m, 0..max_steps).
void SimulationLowering::planClock() {
  int64_t next = kFirstFreeSlot;
  for (ComponentOp component : order)
    evaluationSlots[component] = next++;
  for (ComponentOp component : order)
    if (isSubStepping(strategy) && component.hasNumSteps() &&
        *component.getSubStepping() == SubStepping::grid_sync) {
      subClockSlots[component] = next;
      next += kSubClockSlots;
    }
  histogramSlot = next;
  clockSlots = next + maxSteps + 1;
}

//===----------------------------------------------------------------------===//
// Kernel scaffolding
//===----------------------------------------------------------------------===//

/// Every kernel starts with every argument a body could read; endKernel drops
/// the ones it does not use, so each launch passes only what its kernel
/// needs.
Kernel SimulationLowering::beginKernel(StringRef name, BufferOp exactOf,
                                       TotalOp totalOf) {
  MLIRContext *context = simulation.getContext();
  auto arg = [&](simplan::ArgKind kind, StringAttr symbol = {}) {
    return simplan::ArgAttr::get(
        context, kind, symbol ? FlatSymbolRefAttr::get(symbol) : nullptr);
  };
  auto dynamic = [](Type element) {
    return MemRefType::get({ShapedType::kDynamic}, element);
  };
  Kernel kernel;
  SmallVector<Type> types;
  types.push_back(dynamic(b.getI64Type()));
  kernel.args.push_back(arg(simplan::ArgKind::clock));
  for (BufferOp buffer : buffers) {
    types.push_back(dynamic(buffer.getElementType()));
    kernel.args.push_back(
        arg(simplan::ArgKind::buffer, buffer.getSymNameAttr()));
  }
  for (BufferOp buffer : buffers)
    if (buffer.getSnapshot()) {
      types.push_back(dynamic(buffer.getElementType()));
      kernel.args.push_back(
          arg(simplan::ArgKind::snapshot, buffer.getSymNameAttr()));
    }
  if (exactOf) {
    types.push_back(dynamic(exactOf.getElementType()));
    kernel.args.push_back(
        arg(simplan::ArgKind::exact, exactOf.getSymNameAttr()));
  }
  if (totalOf) {
    types.push_back(dynamic(b.getF64Type()));
    kernel.args.push_back(
        arg(simplan::ArgKind::total, totalOf.getSymNameAttr()));
  }
  for (ParamOp param : params) {
    // An index parameter is passed as i64 (sim.get_param casts it back).
    Type type = cast<TypedAttr>(param.getValue()).getType();
    types.push_back(type.isIndex() ? b.getI64Type() : type);
    kernel.args.push_back(arg(simplan::ArgKind::param, param.getSymNameAttr()));
  }
  types.push_back(b.getI64Type());
  kernel.args.push_back(arg(simplan::ArgKind::range));
  types.push_back(simulation.getTimeStepType());
  kernel.args.push_back(arg(simplan::ArgKind::dt));
  if (exactOf) {
    types.push_back(b.getF64Type());
    kernel.args.push_back(arg(simplan::ArgKind::time));
  }

  b.setInsertionPointToEnd(&kernels->getRegion(0).front());
  Block *entry = target.createKernel(b, kernel, name, types);
  b.startKernel(entry);

  unsigned position = 0;
  auto next = [&] { return entry->getArgument(position++); };
  kernel.clock = next();
  KernelValues &values = kernel.values;
  for (BufferOp buffer : buffers)
    values.buffers[buffer.getSymNameAttr()] = next();
  for (BufferOp buffer : buffers)
    if (buffer.getSnapshot())
      values.snapshots[buffer.getSymNameAttr()] = next();
  Value exactOut = exactOf ? next() : Value();
  kernel.totalOut = totalOf ? next() : Value();
  for (ParamOp param : params)
    values.params[param.getSymName()] = next();
  Value range = next();
  values.params["range"] = range;
  values.params["dt"] = next();
  values.params["max_steps"] = b.i64(maxSteps);
  values.range = b.toIndex(range);
  if (exactOf) {
    kernel.time = next();
    // The exact kernel's output is addressed like a snapshot.
    values.snapshots[exactOf.getSymNameAttr()] = exactOut;
  }
  return kernel;
}

LogicalResult SimulationLowering::endKernel(Kernel &kernel,
                                            simplan::LaunchShape shape,
                                            OpBuilder &launches,
                                            ComponentOp component) {
  target.finishKernel(b, kernel);
  if (bodyFailed)
    return failure();

  // Drop what the kernel ended up not reading (a constant or cast made for
  // every kernel may be its only use), then the unused arguments; the
  // target's own trailing arguments stay.
  IRRewriter rewriter(b.getContext());
  (void)runRegionDCE(rewriter, kernel.func.getFunctionBody());
  unsigned planArgs = kernel.args.size();
  llvm::BitVector unused(kernel.func.getNumArguments());
  for (unsigned index = 0; index < planArgs; ++index)
    if (kernel.func.getArgument(index).use_empty())
      unused.set(index);
  if (failed(kernel.func.eraseArguments(unused)))
    return failure();
  SmallVector<Attribute> args;
  for (auto [index, arg] : llvm::enumerate(kernel.args))
    if (!unused.test(index))
      args.push_back(arg);

  auto kernelRef = SymbolRefAttr::get(
      SymbolTable::getSymbolName(kernels),
      {FlatSymbolRefAttr::get(SymbolTable::getSymbolName(kernel.func))});
  simplan::LaunchOp::create(
      launches, b.loc, kernelRef,
      simplan::LaunchShapeAttr::get(b.getContext(), shape),
      launches.getArrayAttr(args),
      component ? FlatSymbolRefAttr::get(component.getSymNameAttr())
                : FlatSymbolRefAttr(),
      launches.getI64IntegerAttr(kernel.sharedPerThread),
      launches.getI64IntegerAttr(kernel.sharedFixed));
  return success();
}

void SimulationLowering::readClock(Kernel &kernel, Value &begin, Value &size,
                                   Value &parity) {
  begin = b.load(kernel.clock, b.index(kSlotBegin));
  size = b.load(kernel.clock, b.index(kSlotSize));
  parity = b.load(kernel.clock, b.index(kSlotParity));
}

/// Source and target halves from the clock's parity; `local` loads (own
/// state not in registers) read the half `localParity` selects.
void SimulationLowering::setHalves(Kernel &kernel, Value parity,
                                   Value localParity) {
  KernelValues &values = kernel.values;
  Value range = values.range;
  values.sourceBase = b.mul(b.toIndex(parity), range);
  values.targetBase = b.mul(b.toIndex(b.xorOne(parity)), range);
  values.localBase = b.mul(b.toIndex(localParity), range);
}

void SimulationLowering::forEachItem(Kernel &kernel,
                                     function_ref<void(const Lane &)> body) {
  target.forEachGroup(b, kernel, [&](Value base) {
    target.forEachLane(b, kernel, base, body);
  });
}

void SimulationLowering::countEvaluation(LaneVar count, const Lane &lane) {
  Value one = b.extend(lane.active, b.getI32Type());
  target.laneStore(b, b.add(target.laneLoad(b, count, lane), one), count, lane);
}

SmallVector<Value> SimulationLowering::inline_(Region &body, ValueRange args,
                                               const KernelValues &values) {
  FailureOr<SmallVector<Value>> results =
      inlineBody(b, simulation, body, args, values);
  if (succeeded(results))
    return *results;
  bodyFailed = true;
  // Keep the IR well formed until the failure is reported: zero values of
  // the yielded types.
  SmallVector<Value> zeros;
  for (Type type : body.front().getTerminator()->getOperandTypes())
    zeros.push_back(
        arith::ConstantOp::create(b, b.loc, type, b.getZeroAttr(type)));
  return zeros;
}

/// num_steps of one item, at least 1 (values below 1 count as 1).
Value SimulationLowering::estimate(Kernel &kernel, ComponentOp component,
                                   Value item, Value time,
                                   const KernelValues &values) {
  Value steps = inline_(component.getNumSteps(), {item, time}, values).front();
  return b.max(steps, b.i32(1));
}

void SimulationLowering::estimateInto(Kernel &kernel, ComponentOp component,
                                      LaneVar minimum, Value time,
                                      int64_t slot) {
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value steps = estimate(kernel, component, lane.item, time, values);
      target.laneStore(b, b.min(target.laneLoad(b, minimum, lane), steps),
                       minimum, lane);
    });
  });
  target.reduceIntoClock(b, kernel, minimum, arith::AtomicRMWKind::mins, slot);
}

SmallVector<SimulationLowering::Cache>
SimulationLowering::createCaches(Kernel &kernel, ComponentOp component) {
  SmallVector<Cache> caches;
  auto stride = [&](FillCacheOp fill) {
    return elementStride(simulation.lookupBuffer(fill.getBufferAttr()));
  };
  SmallVector<FillCacheOp> fills(
      component.getEvaluate().front().getOps<FillCacheOp>());
  // The plan is the same for every target: the launch asks for the caches'
  // bytes even where a target keeps none (the CPU runtime ignores them).
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
  for (Cache cache : caches) {
    int64_t low = cache.fill.getMinOffsetAttr().getInt();
    int64_t halo = cache.fill.getMaxOffsetAttr().getInt() - low;
    Value count = b.add(target.groupSize(b, kernel), b.index(halo));
    Value first = b.add(base, b.index(low));
    target.forEachSlot(b, kernel, count, [&](Value slot) {
      Value item = b.add(first, slot);
      KernelValues values = kernel.values;
      values.item = nullptr; // the fill reads other items: boundary rules
      FailureOr<Value> value = inlineCacheFill(
          b, simulation, component.getEvaluate(), {item, time, steps, dt},
          cache.fill.getBufferAttr(), item, values);
      if (failed(value)) {
        bodyFailed = true;
        return;
      }
      b.store(*value, cache.memory, slot);
    });
    kernel.values.caches[cache.fill.getBufferAttr().getAttr()] = {cache.memory,
                                                                  first, count};
  }
  target.barrier(b);
}

void SimulationLowering::evaluateItems(Kernel &kernel, ComponentOp component,
                                       ArrayRef<Cache> caches, Value time,
                                       Value steps, Value writeBase,
                                       LaneVar count) {
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
          b.store(value, values.buffers.lookup(name.getAttr()),
                  b.add(writeBase, lane.item));
      });
      countEvaluation(count, lane);
    });
  });
}

//===----------------------------------------------------------------------===//
// Kernels
//===----------------------------------------------------------------------===//

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

/// The initial state of one buffer, into half 0.
LogicalResult SimulationLowering::emitInit(BufferOp buffer,
                                           OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "init", buffer.getSymName()));
  Value memory = kernel.values.buffers.lookup(buffer.getSymNameAttr());
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value = inline_(buffer.getInit(), {lane.item}, values).front();
      b.store(value, memory, lane.item);
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// The exact solution of one buffer at the launch's time argument.
LogicalResult SimulationLowering::emitExact(BufferOp buffer,
                                            OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "exact", buffer.getSymName()), buffer);
  Value out = kernel.values.snapshots.lookup(buffer.getSymNameAttr());
  kernel.values.snapshots.erase(buffer.getSymNameAttr());
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value =
          inline_(buffer.getExact(), {lane.item, kernel.time}, values).front();
      b.store(value, out, lane.item);
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// The value of one total at every item, at the current T (after a run's
/// finish, or after init): reads load the source half, the one the clock's
/// parity selects. The per-item values go out as f64; the runtime sums them.
LogicalResult SimulationLowering::emitTotal(TotalOp total,
                                            OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "total", total.getSymName()),
                  /*exactOf=*/nullptr, total);
  Value parity = b.load(kernel.clock, b.index(kSlotParity));
  kernel.values.sourceBase = b.mul(b.toIndex(parity), kernel.values.range);
  forEachItem(kernel, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      KernelValues values = kernel.values;
      values.item = lane.item;
      Value value = inline_(total.getBody(), {lane.item}, values).front();
      if (!value.getType().isF64())
        value = arith::ExtFOp::create(b, b.loc, b.getF64Type(), value);
      b.store(value, kernel.totalOut, lane.item);
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// One component's estimate of the next big step: the minimum of
/// `num_steps` over all items at the start T' of the next big step, into the
/// clock. It runs before `advance` commits the current big step, so it
/// computes T' and the parity itself, and does nothing past the end.
LogicalResult SimulationLowering::emitEstimate(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel =
      beginKernel(getKernelName(kernels, "estimate", component.getSymName()));
  LaneVar minimum =
      target.createLaneVar(b, kernel, b.getI32Type(), b.i32(kNoEstimate));
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0));
  Value next = b.add(begin, size);
  Value nextParity = b.select(stepped, b.xorOne(parity), parity);
  setHalves(kernel, nextParity, nextParity);
  Value end = b.load(kernel.clock, b.index(kSlotEnd));
  b.ifThen(b.cmp(arith::CmpIPredicate::slt, next, end), [&] {
    estimateInto(kernel, component, minimum, next, kSlotEstimate);
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// Commits the big step that just ended (T += m, flip the parity when it
/// advanced) and decides the next one: m = min(estimate, cap, end - T), 0
/// past the end. Also counts big steps by size and restarts the sub-step
/// clocks.
LogicalResult SimulationLowering::emitAdvance(OpBuilder &launches,
                                              bool hasEstimates) {
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
  Value cap = b.i64(strategy == Strategy::simple ? 1 : maxSteps);
  Value bound = hasEstimates ? b.min(slot(kSlotEstimate), cap) : cap;
  Value positive = b.cmp(arith::CmpIPredicate::sgt, remaining, zero);
  Value next = b.select(positive, b.min(bound, remaining), zero);

  setSlot(kSlotBegin, now);
  setSlot(kSlotSize, next);
  setSlot(kSlotParity, nowParity);
  setSlot(kSlotBigSteps, bigSteps);
  setSlot(kSlotEstimate, b.i64(kNoEstimate64));
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, next, zero), [&] {
    Value at = b.add(b.index(histogramSlot), b.toIndex(next));
    b.store(b.add(b.load(clock, at), one), clock, at);
  });
  for (ComponentOp component : order) {
    auto it = subClockSlots.find(component);
    if (it == subClockSlots.end())
      continue;
    setSlot(it->second + kSubBegin, now);
    setSlot(it->second + kSubSize, zero);
    setSlot(it->second + kSubCount, zero);
    setSlot(it->second + kSubEstimate, b.i64(kNoEstimate64));
  }
  return endKernel(kernel, simplan::LaunchShape::single, launches);
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
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  kernel.values.bigStepBegin = begin;
  kernel.values.bigStepSize = size;
  Value steps = b.truncate(size, b.getI32Type());
  SmallVector<Cache> caches = createCaches(kernel, component);
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    evaluateItems(kernel, component, caches, begin, steps,
                  kernel.values.targetBase, count);
    target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                           evaluationSlots.lookup(component));
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}

/// Algorithm 2 for an in_kernel component with num_steps: each lane keeps
/// its item's state in registers from T to T + m, the group takes sub-steps
/// of the group-wide minimum of num_steps, and the target is written once.
/// When m = 1 there is one sub-step of 1: no num_steps, no reduction.
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
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  kernel.values.bigStepBegin = begin;
  kernel.values.bigStepSize = size;
  Value dt = kernel.values.params.lookup("dt");
  SmallVector<Cache> caches = createCaches(kernel, component);

  // The values a lane's bodies read: its registers.
  auto laneValues = [&](const Lane &lane) {
    KernelValues values = kernel.values;
    values.item = lane.item;
    for (auto [name, var] : llvm::zip_equal(writes, state))
      values.registers[name.getAttr()] = target.laneLoad(b, var, lane);
    return values;
  };

  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    target.prepareGroupMin(b, kernel);
    Value end = b.add(begin, size);
    Value single = b.cmp(arith::CmpIPredicate::eq, size, b.i64(1));
    target.forEachGroup(b, kernel, [&](Value base) {
      // Own state at T into registers.
      target.forEachLane(b, kernel, base, [&](const Lane &lane) {
        b.ifThen(lane.active, [&] {
          for (auto [name, var] : llvm::zip_equal(writes, state))
            target.laneStore(
                b,
                b.load(kernel.values.buffers.lookup(name.getAttr()),
                       b.add(kernel.values.sourceBase, lane.item)),
                var, lane);
        });
      });
      // Sub-steps until the group reaches T + m (the same for every lane).
      auto loop = scf::WhileOp::create(b, b.loc, b.getI64Type(), begin);
      Block *before =
          b.createBlock(&loop.getBefore(), {}, b.getI64Type(), b.loc);
      scf::ConditionOp::create(
          b, b.loc,
          b.cmp(arith::CmpIPredicate::slt, before->getArgument(0), end),
          before->getArguments());
      Block *after = b.createBlock(&loop.getAfter(), {}, b.getI64Type(), b.loc);
      Value time = after->getArgument(0);
      auto decided = b.ifThenElse(
          b.getI64Type(), single, [&] { return SmallVector<Value>{b.i64(1)}; },
          [&] {
            target.forEachLane(b, kernel, base, [&](const Lane &lane) {
              auto estimated = b.ifThenElse(
                  b.getI32Type(), lane.active,
                  [&] {
                    return SmallVector<Value>{estimate(
                        kernel, component, lane.item, time, laneValues(lane))};
                  },
                  [&] { return SmallVector<Value>{b.i32(kNoEstimate)}; });
              target.laneStore(b, estimated.getResult(0), steps, lane);
            });
            Value groupMin =
                b.extend(target.groupMin(b, kernel, steps), b.getI64Type());
            return SmallVector<Value>{b.min(groupMin, b.sub(end, time))};
          });
      Value subStep = decided.getResult(0);
      Value subStep32 = b.truncate(subStep, b.getI32Type());
      if (!caches.empty()) {
        // The caches of the previous sub-step are free once every lane has
        // passed the barrier of this sub-step's minimum; when m = 1 there
        // was none.
        b.ifThen(single, [&] { target.barrier(b); });
        fillCaches(kernel, component, caches, base, time, subStep32, dt);
      }
      target.forEachLane(b, kernel, base, [&](const Lane &lane) {
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
                    b.add(kernel.values.targetBase, lane.item));
        });
      });
    });
    target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                           evaluationSlots.lookup(component));
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
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

  // Snapshots of the value at T.
  for (FlatSymbolRefAttr write : writes) {
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
          Value value = b.load(kernel.values.buffers.lookup(write.getAttr()),
                               b.add(kernel.values.sourceBase, lane.item));
          b.store(value, kernel.values.snapshots.lookup(write.getAttr()),
                  lane.item);
        });
      });
    });
    if (failed(endKernel(kernel, simplan::LaunchShape::items, launches)))
      return failure();
  }

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
    b.ifThen(b.cmp(arith::CmpIPredicate::slt, now, b.add(begin, size)), [&] {
      estimateInto(kernel, component, minimum, now, sub + kSubEstimate);
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
    b.store(b.i64(kNoEstimate64), clock, b.index(sub + kSubEstimate));
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
    Value writeBase =
        b.mul(b.toIndex(b.xorOne(readParity)), kernel.values.range);
    kernel.values.bigStepBegin = begin;
    kernel.values.bigStepSize = size;
    Value steps = b.truncate(subSize, b.getI32Type());
    SmallVector<Cache> caches = createCaches(kernel, component);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, subSize, b.i64(0)), [&] {
      evaluateItems(kernel, component, caches, subBegin, steps, writeBase,
                    count);
      target.reduceIntoClock(b, kernel, count, arith::AtomicRMWKind::addi,
                             evaluationSlots.lookup(component));
    });
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
      b.ifThen(lane.active, [&] {
        for (FlatSymbolRefAttr write : writes) {
          Value memory = kernel.values.buffers.lookup(write.getAttr());
          b.store(b.load(memory, b.add(kernel.values.sourceBase, lane.item)),
                  memory, b.add(kernel.values.targetBase, lane.item));
        }
      });
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}

//===----------------------------------------------------------------------===//
// The simulation
//===----------------------------------------------------------------------===//

LogicalResult SimulationLowering::run() {
  if (failed(checkFrontEnd()))
    return failure();
  planClock();
  StringRef name = simulation.getSymName();

  OpBuilder top(simulation);
  kernels = target.createContainer(top, simulation.getLoc(),
                                   (name + "_kernels").str());
  plan = simplan::PlanOp::create(
      top, simulation.getLoc(), simulation.getSymNameAttr(),
      top.getStringAttr(stringifyStrategy(strategy)),
      FlatSymbolRefAttr::get(SymbolTable::getSymbolName(kernels)),
      top.getI64IntegerAttr(simulation.getRange()),
      cast<TypedAttr>(simulation.getDt()), top.getI64IntegerAttr(maxSteps),
      top.getI64IntegerAttr(groupSize), top.getI64IntegerAttr(clockSlots),
      top.getI64IntegerAttr(histogramSlot));
  Block *body = &plan.getBody().emplaceBlock();
  auto unitIf = [&](bool set) { return set ? top.getUnitAttr() : UnitAttr(); };
  OpBuilder planBuilder = OpBuilder::atBlockEnd(body);

  // Symbols.
  llvm::DenseSet<StringAttr> observed;
  if (ObserveOp observe = simulation.getObserveOp())
    for (FlatSymbolRefAttr buffer :
         observe.getBuffers().getAsRange<FlatSymbolRefAttr>())
      observed.insert(buffer.getAttr());
  for (ParamOp param : params)
    simplan::ParamOp::create(planBuilder, param.getLoc(),
                             param.getSymNameAttr(), param.getValue());
  for (BufferOp buffer : buffers) {
    simplan::BufferOp::create(
        planBuilder, buffer.getLoc(), buffer.getSymNameAttr(),
        TypeAttr::get(buffer.getElementType()),
        planBuilder.getI64IntegerAttr(elementStride(buffer)),
        unitIf(buffer.getSnapshot()),
        unitIf(observed.contains(buffer.getSymNameAttr())),
        unitIf(!buffer.getExact().empty()));
  }
  for (ComponentOp component : order)
    simplan::ComponentOp::create(
        planBuilder, component.getLoc(), component.getSymNameAttr(),
        component.getWrites(),
        planBuilder.getI64IntegerAttr(evaluationSlots.lookup(component)));

  for (TotalOp total : simulation.getTotals())
    simplan::TotalOp::create(planBuilder, total.getLoc(),
                             total.getSymNameAttr(), total.getValueTypeAttr());

  auto phase = [&](simplan::PhaseKind kind) {
    auto op = simplan::PhaseOp::create(planBuilder, simulation.getLoc(), kind);
    return OpBuilder::atBlockEnd(&op.getBody().emplaceBlock());
  };

  // init: the clock, then every buffer's initial state.
  OpBuilder init = phase(simplan::PhaseKind::init);
  if (failed(emitResetClock(init)))
    return failure();
  for (BufferOp buffer : buffers)
    if (failed(emitInit(buffer, init)))
      return failure();

  // step: estimates, the decision, the components in schedule order.
  OpBuilder step = phase(simplan::PhaseKind::step);
  SmallVector<ComponentOp> estimated;
  if (strategy == Strategy::traditional) {
    for (ComponentOp component : order)
      if (component.hasNumSteps())
        estimated.push_back(component);
  } else if (isSubStepping(strategy)) {
    if (ArrayAttr bounds = simulation.getScheduleOp().getBoundedByAttr())
      for (FlatSymbolRefAttr bound : bounds.getAsRange<FlatSymbolRefAttr>())
        if (ComponentOp component = simulation.lookupComponent(bound);
            component && component.hasNumSteps())
          estimated.push_back(component);
  }
  for (ComponentOp component : estimated)
    if (failed(emitEstimate(component, step)))
      return failure();
  if (failed(emitAdvance(step, !estimated.empty())))
    return failure();
  for (ComponentOp component : order) {
    LogicalResult result = success();
    // A component that bounds the big step takes it in one sub-step: at T
    // the minimum of its num_steps over any group is at least the minimum
    // over all items, which is m. So it needs neither num_steps again nor
    // a reduction.
    if (!isSubStepping(strategy) || !component.hasNumSteps() ||
        llvm::is_contained(estimated, component))
      result = emitEvaluate(component, step);
    else if (*component.getSubStepping() == SubStepping::in_kernel)
      result = emitSubSteps(component, step);
    else
      result = emitRounds(component, step);
    if (failed(result))
      return failure();
  }

  // finish: commit the last big step (advance with nothing left to do).
  OpBuilder finish = phase(simplan::PhaseKind::finish);
  for (auto launch : step.getBlock()->getOps<simplan::LaunchOp>())
    if (launch.getKernel().getLeafReference() == "advance")
      finish.clone(*launch.getOperation());

  // exact: the exact solutions the scene declares.
  if (llvm::any_of(buffers, [](BufferOp buffer) {
        return !buffer.getExact().empty();
      })) {
    OpBuilder exact = phase(simplan::PhaseKind::exact);
    for (BufferOp buffer : buffers)
      if (!buffer.getExact().empty() && failed(emitExact(buffer, exact)))
        return failure();
  }

  // total: the per-item values of the totals the scene declares.
  if (!simulation.getTotals().empty()) {
    OpBuilder totals = phase(simplan::PhaseKind::total);
    for (TotalOp total : simulation.getTotals())
      if (failed(emitTotal(total, totals)))
        return failure();
  }
  simulation.erase();
  return success();
}

LogicalResult mlir::sim::lowerSimulation(SimulationOp simulation,
                                         KernelTarget &target,
                                         int64_t groupSize) {
  return SimulationLowering(simulation, target, groupSize).run();
}
