//===- SimToGPU.cpp - simulations to GPU kernels and a host plan ----------===//
//
// Lowers a simulation that went through the front end into a gpu.module of
// kernels and a simplan.plan. Everything this pass decides is *how* to run
// what the front end recorded: the strategy, the schedule and its step
// bounds, the sub-stepping verdict, parity and snapshots come from the IR.
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

#include "sim/Conversion/Passes.h"
#include "sim/Conversion/SimCommon/KernelBody.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/Transforms/RegionUtils.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERTOGPU
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

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

bool isSubStepping(Strategy strategy) {
  return strategy == Strategy::hip || strategy == Strategy::hip_cache;
}

/// A small vocabulary over OpBuilder for the index and i64 arithmetic of
/// kernels, so that the kernel builders read like the algorithm.
struct KernelBuilder : OpBuilder {
  KernelBuilder(MLIRContext *context, Location loc)
      : OpBuilder(context), loc(loc) {}

  /// Starts a new kernel: constants are created once, at its entry.
  void startKernel(Block *entry) {
    kernelEntry = entry;
    constants.clear();
  }
  Value constant(Type type, int64_t value) {
    Value &cached = constants[{type, value}];
    if (!cached) {
      InsertionGuard guard(*this);
      setInsertionPointToStart(kernelEntry);
      cached = arith::ConstantOp::create(*this, loc, type,
                                         getIntegerAttr(type, value));
    }
    return cached;
  }
  Value index(int64_t value) { return constant(getIndexType(), value); }
  Value i64(int64_t value) { return constant(getI64Type(), value); }
  Value i32(int64_t value) { return constant(getI32Type(), value); }
  Value add(Value a, Value b) {
    return arith::AddIOp::create(*this, loc, a, b);
  }
  Value sub(Value a, Value b) {
    return arith::SubIOp::create(*this, loc, a, b);
  }
  Value mul(Value a, Value b) {
    return arith::MulIOp::create(*this, loc, a, b);
  }
  Value min(Value a, Value b) {
    return arith::MinSIOp::create(*this, loc, a, b);
  }
  Value max(Value a, Value b) {
    return arith::MaxSIOp::create(*this, loc, a, b);
  }
  Value cmp(arith::CmpIPredicate predicate, Value a, Value b) {
    return arith::CmpIOp::create(*this, loc, predicate, a, b);
  }
  Value select(Value cond, Value a, Value b) {
    return arith::SelectOp::create(*this, loc, cond, a, b);
  }
  Value toIndex(Value value) {
    return arith::IndexCastOp::create(*this, loc, getIndexType(), value);
  }
  Value toI64(Value value) {
    if (value.getType().isInteger(64))
      return value;
    if (isa<IndexType>(value.getType()))
      return arith::IndexCastOp::create(*this, loc, getI64Type(), value);
    return arith::ExtUIOp::create(*this, loc, getI64Type(), value);
  }
  Value load(Value memref, Value index) {
    return memref::LoadOp::create(*this, loc, memref, index);
  }
  void store(Value value, Value memref, Value index) {
    memref::StoreOp::create(*this, loc, value, memref, index);
  }
  Value slot(Value clock, int64_t slot) { return load(clock, index(slot)); }
  void setSlot(Value clock, int64_t slot, Value value) {
    store(value, clock, index(slot));
  }
  void atomic(arith::AtomicRMWKind kind, Value value, Value memref,
              Value index) {
    memref::AtomicRMWOp::create(*this, loc, kind, value, memref, index);
  }
  Value threadId() {
    return gpu::ThreadIdOp::create(*this, loc, gpu::Dimension::x);
  }
  Value laneId() { return gpu::LaneIdOp::create(*this, loc, nullptr); }
  void barrier() { gpu::BarrierOp::create(*this, loc); }
  Value groupReduce(Value value, gpu::AllReduceOperation op) {
    // Uniform: every lane takes part (padding lanes contribute a neutral
    // value), which is what lets it lower to one redux.sync.
    return gpu::SubgroupReduceOp::create(*this, loc, value, op,
                                         /*uniform=*/true);
  }

  /// scf.if with results; the callbacks build each branch and return what
  /// it yields.
  scf::IfOp ifThenElse(TypeRange types, Value cond,
                       function_ref<SmallVector<Value>()> thenBuilder,
                       function_ref<SmallVector<Value>()> elseBuilder) {
    auto ifOp = scf::IfOp::create(*this, loc, types, cond,
                                  /*withElseRegion=*/true);
    InsertionGuard guard(*this);
    setInsertionPointToStart(&ifOp.getThenRegion().front());
    SmallVector<Value> thenValues = thenBuilder();
    if (!types.empty() || ifOp.getThenRegion().front().empty() ||
        !ifOp.getThenRegion().front().back().hasTrait<OpTrait::IsTerminator>())
      scf::YieldOp::create(*this, loc, thenValues);
    setInsertionPointToStart(&ifOp.getElseRegion().front());
    SmallVector<Value> elseValues = elseBuilder();
    if (!types.empty() || ifOp.getElseRegion().front().empty() ||
        !ifOp.getElseRegion().front().back().hasTrait<OpTrait::IsTerminator>())
      scf::YieldOp::create(*this, loc, elseValues);
    return ifOp;
  }
  /// scf.if without results.
  void ifThen(Value cond, function_ref<void()> thenBuilder) {
    auto ifOp = scf::IfOp::create(*this, loc, TypeRange(), cond,
                                  /*withElseRegion=*/false);
    InsertionGuard guard(*this);
    setInsertionPoint(ifOp.getThenRegion().front().getTerminator());
    thenBuilder();
  }

  Location loc;
  Block *kernelEntry = nullptr;
  llvm::DenseMap<std::pair<Type, int64_t>, Value> constants;
};

/// One kernel under construction.
struct Kernel {
  gpu::GPUFuncOp func;
  /// What the runtime passes for each argument, in order.
  SmallVector<simplan::ArgAttr> args;
  Value clock;
  /// The values bodies read; each kernel builder adds the halves, registers
  /// and big step that its bodies see.
  KernelValues values;
  /// The time argument of an exact kernel.
  Value time;
};

class SimulationLowering {
public:
  SimulationLowering(SimulationOp simulation, int64_t groupSize)
      : simulation(simulation), groupSize(groupSize),
        b(simulation.getContext(), simulation.getLoc()) {}

  LogicalResult run();

private:
  LogicalResult checkFrontEnd();
  void planClock();

  // Kernels and launches.
  Kernel beginKernel(StringRef name, BufferOp exactOf = nullptr);
  LogicalResult endKernel(Kernel &kernel, simplan::LaunchShape shape,
                          OpBuilder &launches, ComponentOp component = nullptr);
  void readClock(Kernel &kernel, Value &begin, Value &size, Value &parity);
  void setHalves(Kernel &kernel, Value parity, Value localParity);
  SmallVector<Value>
  forEachItem(Kernel &kernel, ValueRange inits,
              function_ref<SmallVector<Value>(Value item, Value active,
                                              ValueRange iters)>
                  body);
  void addEvaluations(Kernel &kernel, Value count, ComponentOp component);
  SmallVector<Value> inline_(Region &body, ValueRange args,
                             const KernelValues &values);

  LogicalResult emitResetClock(OpBuilder &launches);
  LogicalResult emitInit(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitExact(BufferOp buffer, OpBuilder &launches);
  LogicalResult emitEstimate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitAdvance(OpBuilder &launches, bool hasEstimates);
  LogicalResult emitEvaluate(ComponentOp component, OpBuilder &launches);
  LogicalResult emitSubSteps(ComponentOp component, OpBuilder &launches);
  LogicalResult emitRounds(ComponentOp component, OpBuilder &launches);

  SimulationOp simulation;
  int64_t groupSize;
  KernelBuilder b;
  Strategy strategy;
  int64_t maxSteps;

  gpu::GPUModuleOp kernels;
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
              "before --sim-lower-to-gpu";
  strategy = strategyAttr.getValue();
  maxSteps = simulation.getMaxSteps();

  ScheduleOp schedule = simulation.getScheduleOp();
  size_t numComponents = llvm::range_size(simulation.getComponents());
  if (!schedule || schedule.getOrder().size() != numComponents)
    return simulation.emitOpError()
           << "has no complete schedule; run the front end (--sim-front-end) "
              "before --sim-lower-to-gpu";
  for (FlatSymbolRefAttr name :
       schedule.getOrder().getAsRange<FlatSymbolRefAttr>())
    order.push_back(simulation.lookupComponent(name));

  for (ComponentOp component : order) {
    if (!component.getSubSteppingAttr() || !component.getParityAttr())
      return component.emitOpError()
             << "has no sub-stepping verdict or parity; run the front end "
                "(--sim-front-end) before --sim-lower-to-gpu";
    WalkResult walk = component.walk([](ReadOp read) {
      read.emitOpError() << "is a view read; run --sim-insert-interpolation "
                            "(or the whole front end) before "
                            "--sim-lower-to-gpu";
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
Kernel SimulationLowering::beginKernel(StringRef name, BufferOp exactOf) {
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

  b.setInsertionPointToEnd(kernels.getBody());
  kernel.func =
      gpu::GPUFuncOp::create(b, b.loc, name, b.getFunctionType(types, {}));
  kernel.func->setAttr(gpu::GPUDialect::getKernelFuncAttrName(),
                       b.getUnitAttr());
  Block &entry = kernel.func.getBody().front();
  b.setInsertionPointToStart(&entry);
  b.startKernel(&entry);

  unsigned position = 0;
  auto next = [&] { return entry.getArgument(position++); };
  kernel.clock = next();
  KernelValues &values = kernel.values;
  for (BufferOp buffer : buffers)
    values.buffers[buffer.getSymNameAttr()] = next();
  for (BufferOp buffer : buffers)
    if (buffer.getSnapshot())
      values.snapshots[buffer.getSymNameAttr()] = next();
  Value exactOut = exactOf ? next() : Value();
  for (ParamOp param : params)
    values.params[param.getSymName()] = next();
  Value range = next();
  values.params["range"] = range;
  values.params["dt"] = next();
  values.params["max_steps"] = b.i64(maxSteps);
  values.range = b.toIndex(range);
  if (exactOf) {
    kernel.time = next();
    // The exact kernel's output is addressed like a one-half buffer.
    values.snapshots[exactOf.getSymNameAttr()] = exactOut;
  }
  return kernel;
}

LogicalResult SimulationLowering::endKernel(Kernel &kernel,
                                            simplan::LaunchShape shape,
                                            OpBuilder &launches,
                                            ComponentOp component) {
  b.setInsertionPointToEnd(&kernel.func.getBody().front());
  gpu::ReturnOp::create(b, b.loc);
  if (bodyFailed)
    return failure();

  // Drop what the kernel ended up not reading (a constant or cast made for
  // every kernel may be its only use), then the unused arguments.
  IRRewriter rewriter(b.getContext());
  (void)runRegionDCE(rewriter, kernel.func.getBody());
  llvm::BitVector unused(kernel.func.getNumArguments());
  for (BlockArgument argument : kernel.func.getArguments())
    if (argument.use_empty())
      unused.set(argument.getArgNumber());
  if (failed(kernel.func.eraseArguments(unused)))
    return failure();
  SmallVector<Attribute> args;
  for (auto [index, arg] : llvm::enumerate(kernel.args))
    if (!unused.test(index))
      args.push_back(arg);

  auto kernelRef =
      SymbolRefAttr::get(kernels.getSymNameAttr(),
                         {FlatSymbolRefAttr::get(kernel.func.getNameAttr())});
  simplan::LaunchOp::create(
      launches, b.loc, kernelRef,
      simplan::LaunchShapeAttr::get(b.getContext(), shape),
      launches.getArrayAttr(args),
      component ? FlatSymbolRefAttr::get(component.getSymNameAttr())
                : FlatSymbolRefAttr(),
      /*shared_per_thread=*/0,
      /*shared_fixed=*/0);
  return success();
}

void SimulationLowering::readClock(Kernel &kernel, Value &begin, Value &size,
                                   Value &parity) {
  begin = b.slot(kernel.clock, kSlotBegin);
  size = b.slot(kernel.clock, kSlotSize);
  parity = b.slot(kernel.clock, kSlotParity);
}

/// Source and target halves from the clock's parity; `local` loads (own
/// state not in registers) read the half `localParity` selects.
void SimulationLowering::setHalves(Kernel &kernel, Value parity,
                                   Value localParity) {
  KernelValues &values = kernel.values;
  Value one = b.i64(1);
  Value range = values.range;
  values.sourceBase = b.mul(b.toIndex(parity), range);
  values.targetBase = b.mul(b.toIndex(b.sub(one, parity)), range);
  values.localBase = b.mul(b.toIndex(localParity), range);
}

/// The padded grid-stride loop of Algorithms 1 and 2: every lane of a group
/// runs every iteration (so group-wide barriers and reductions are legal),
/// `active` tells the lanes that hold an item.
SmallVector<Value> SimulationLowering::forEachItem(
    Kernel &kernel, ValueRange inits,
    function_ref<SmallVector<Value>(Value item, Value active, ValueRange iters)>
        body) {
  Value range = kernel.values.range;
  Value groupId = gpu::BlockIdOp::create(b, b.loc, gpu::Dimension::x);
  Value groupSize = gpu::BlockDimOp::create(b, b.loc, gpu::Dimension::x);
  Value groups = gpu::GridDimOp::create(b, b.loc, gpu::Dimension::x);
  Value thread = b.threadId();
  Value start = b.mul(groupId, groupSize);
  Value stride = b.mul(groups, groupSize);
  Value padded =
      b.mul(arith::CeilDivUIOp::create(b, b.loc, range, groupSize), groupSize);
  auto loop = scf::ForOp::create(b, b.loc, start, padded, stride, inits);
  OpBuilder::InsertionGuard guard(b);
  // The builder adds a terminator only for loops without results.
  if (inits.empty())
    loop.getBody()->getTerminator()->erase();
  b.setInsertionPointToEnd(loop.getBody());
  Value item = b.add(loop.getInductionVar(), thread);
  Value active = b.cmp(arith::CmpIPredicate::ult, item, range);
  SmallVector<Value> results = body(item, active, loop.getRegionIterArgs());
  scf::YieldOp::create(b, b.loc, results);
  return loop.getResults();
}

/// Adds a kernel's item evaluations to the component's counter: one
/// warp-wide sum and one atomic per warp, so counting costs nothing
/// measurable.
void SimulationLowering::addEvaluations(Kernel &kernel, Value count,
                                        ComponentOp component) {
  Value sum = b.groupReduce(count, gpu::AllReduceOperation::ADD);
  Value first = b.cmp(arith::CmpIPredicate::eq, b.laneId(), b.index(0));
  b.ifThen(first, [&] {
    b.atomic(arith::AtomicRMWKind::addi,
             arith::ExtUIOp::create(b, b.loc, b.getI64Type(), sum),
             kernel.clock, b.index(evaluationSlots.lookup(component)));
  });
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

//===----------------------------------------------------------------------===//
// Kernels
//===----------------------------------------------------------------------===//

/// Puts the clock in its initial state: T = 0, parity 0, no pending
/// estimate, all counters zero. The host sets the end of each run.
LogicalResult SimulationLowering::emitResetClock(OpBuilder &launches) {
  Kernel kernel = beginKernel("reset_clock");
  Value zero = b.i64(0);
  auto loop =
      scf::ForOp::create(b, b.loc, b.index(0), b.index(clockSlots), b.index(1));
  {
    OpBuilder::InsertionGuard guard(b);
    b.setInsertionPoint(loop.getBody()->getTerminator());
    b.store(zero, kernel.clock, loop.getInductionVar());
  }
  b.setSlot(kernel.clock, kSlotEstimate, b.i64(kNoEstimate64));
  return endKernel(kernel, simplan::LaunchShape::single, launches);
}

/// The initial state of one buffer, into half 0.
LogicalResult SimulationLowering::emitInit(BufferOp buffer,
                                           OpBuilder &launches) {
  Kernel kernel = beginKernel(("init_" + buffer.getSymName()).str());
  Value memory = kernel.values.buffers.lookup(buffer.getSymNameAttr());
  forEachItem(kernel, {}, [&](Value item, Value active, ValueRange) {
    b.ifThen(active, [&] {
      KernelValues values = kernel.values;
      values.item = item;
      SmallVector<Value> result = inline_(buffer.getInit(), {item}, values);
      b.store(result.front(), memory, item);
    });
    return SmallVector<Value>();
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// The exact solution of one buffer at the launch's time argument.
LogicalResult SimulationLowering::emitExact(BufferOp buffer,
                                            OpBuilder &launches) {
  Kernel kernel = beginKernel(("exact_" + buffer.getSymName()).str(), buffer);
  Value out = kernel.values.snapshots.lookup(buffer.getSymNameAttr());
  kernel.values.snapshots.erase(buffer.getSymNameAttr());
  forEachItem(kernel, {}, [&](Value item, Value active, ValueRange) {
    b.ifThen(active, [&] {
      KernelValues values = kernel.values;
      values.item = item;
      SmallVector<Value> result =
          inline_(buffer.getExact(), {item, kernel.time}, values);
      b.store(result.front(), out, item);
    });
    return SmallVector<Value>();
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// One component's estimate of the next big step: the minimum of
/// `num_steps` (at least 1) over all items at the start T' of the next big
/// step, reduced per warp, per group (shared atomic) and into the clock
/// (one global atomic per group). It runs before `advance` commits the
/// current big step, so it computes T' and the parity itself.
LogicalResult SimulationLowering::emitEstimate(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel = beginKernel(("estimate_" + component.getSymName()).str());
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0));
  Value next = b.add(begin, size);
  Value nextParity = b.select(
      stepped, arith::XOrIOp::create(b, b.loc, parity, b.i64(1)), parity);
  setHalves(kernel, nextParity, nextParity);
  Value end = b.slot(kernel.clock, kSlotEnd);
  Value pending = b.cmp(arith::CmpIPredicate::slt, next, end);

  auto slotType = MemRefType::get(
      {1}, b.getI32Type(), nullptr,
      gpu::AddressSpaceAttr::get(b.getContext(), gpu::AddressSpace::Workgroup));
  Value groupMin = kernel.func.addWorkgroupAttribution(slotType, b.loc);
  b.ifThen(pending, [&] {
    Value thread = b.threadId();
    Value first = b.cmp(arith::CmpIPredicate::eq, thread, b.index(0));
    b.ifThen(first, [&] { b.store(b.i32(kNoEstimate), groupMin, b.index(0)); });
    b.barrier();
    Value none = b.i32(kNoEstimate);
    SmallVector<Value> mins = forEachItem(
        kernel, {none}, [&](Value item, Value active, ValueRange iters) {
          auto estimate = b.ifThenElse(
              b.getI32Type(), active,
              [&] {
                KernelValues values = kernel.values;
                values.item = item;
                Value steps =
                    inline_(component.getNumSteps(), {item, next}, values)
                        .front();
                return SmallVector<Value>{b.max(steps, b.i32(1))};
              },
              [&] { return SmallVector<Value>{none}; });
          return SmallVector<Value>{b.min(iters[0], estimate.getResult(0))};
        });
    Value warpMin = b.groupReduce(mins[0], gpu::AllReduceOperation::MINSI);
    Value lane0 = b.cmp(arith::CmpIPredicate::eq, b.laneId(), b.index(0));
    b.ifThen(lane0, [&] {
      b.atomic(arith::AtomicRMWKind::mins, warpMin, groupMin, b.index(0));
    });
    b.barrier();
    b.ifThen(first, [&] {
      Value value = arith::ExtSIOp::create(b, b.loc, b.getI64Type(),
                                           b.load(groupMin, b.index(0)));
      b.atomic(arith::AtomicRMWKind::mins, value, kernel.clock,
               b.index(kSlotEstimate));
    });
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches);
}

/// Commits the big step that just ended (T += m, flip the parity when it
/// advanced) and decides the next one: m = min(estimate, cap, end - T), 0
/// past the end. Also counts big steps by size and restarts the sub-step
/// clocks.
LogicalResult SimulationLowering::emitAdvance(OpBuilder &launches,
                                              bool hasEstimates) {
  Kernel kernel = beginKernel("advance");
  Value clock = kernel.clock;
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  Value zero = b.i64(0), one = b.i64(1);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, size, zero);
  Value now = b.add(begin, size);
  Value nowParity =
      b.select(stepped, arith::XOrIOp::create(b, b.loc, parity, one), parity);
  Value bigSteps =
      b.add(b.slot(clock, kSlotBigSteps),
            arith::ExtUIOp::create(b, b.loc, b.getI64Type(), stepped));
  Value remaining = b.sub(b.slot(clock, kSlotEnd), now);
  Value cap = b.i64(strategy == Strategy::simple ? 1 : maxSteps);
  Value bound = hasEstimates ? b.min(b.slot(clock, kSlotEstimate), cap) : cap;
  Value positive = b.cmp(arith::CmpIPredicate::sgt, remaining, zero);
  Value next = b.select(positive, b.min(bound, remaining), zero);

  b.setSlot(clock, kSlotBegin, now);
  b.setSlot(clock, kSlotSize, next);
  b.setSlot(clock, kSlotParity, nowParity);
  b.setSlot(clock, kSlotBigSteps, bigSteps);
  b.setSlot(clock, kSlotEstimate, b.i64(kNoEstimate64));
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, next, zero), [&] {
    Value at = b.add(b.index(histogramSlot), b.toIndex(next));
    b.store(b.add(b.load(clock, at), one), clock, at);
  });
  for (ComponentOp component : order) {
    auto it = subClockSlots.find(component);
    if (it == subClockSlots.end())
      continue;
    b.setSlot(clock, it->second + kSubBegin, now);
    b.setSlot(clock, it->second + kSubSize, zero);
    b.setSlot(clock, it->second + kSubCount, zero);
    b.setSlot(clock, it->second + kSubEstimate, b.i64(kNoEstimate64));
  }
  return endKernel(kernel, simplan::LaunchShape::single, launches);
}

/// One evaluation per item with n = m (simple, traditional, and hip
/// components without num_steps): reads the state at T, writes the target
/// once.
LogicalResult SimulationLowering::emitEvaluate(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel = beginKernel(("evaluate_" + component.getSymName()).str());
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  kernel.values.bigStepBegin = begin;
  kernel.values.bigStepSize = size;
  Value steps = arith::TruncIOp::create(b, b.loc, b.getI32Type(), size);
  Value dt = kernel.values.params.lookup("dt");
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    SmallVector<Value> counts = forEachItem(
        kernel, {b.i32(0)}, [&](Value item, Value active, ValueRange iters) {
          b.ifThen(active, [&] {
            KernelValues values = kernel.values;
            values.item = item;
            SmallVector<Value> results = inline_(
                component.getEvaluate(), {item, begin, steps, dt}, values);
            for (auto [name, value] : llvm::zip_equal(
                     component.getWrites().getAsRange<FlatSymbolRefAttr>(),
                     results))
              b.store(value, values.buffers.lookup(name.getAttr()),
                      b.add(values.targetBase, item));
          });
          Value one = arith::ExtUIOp::create(b, b.loc, b.getI32Type(), active);
          return SmallVector<Value>{b.add(iters[0], one)};
        });
    addEvaluations(kernel, counts[0], component);
  });
  return endKernel(kernel, simplan::LaunchShape::items, launches, component);
}

/// Algorithm 2 for an in_kernel component with num_steps: each lane keeps
/// its item's state in registers from T to T + m, the group takes sub-steps
/// of the group-wide minimum of num_steps, and the target is written once.
///
/// The group minimum rotates through three workgroup slots, which needs one
/// barrier per sub-step: in sub-step k, lanes combine into slot k % 3 after
/// thread 0 reset it (before the barrier of sub-step k - 1) and read it after
/// the barrier of sub-step k; thread 0 resets slot (k + 1) % 3, last read
/// before the barrier of sub-step k - 1.
LogicalResult SimulationLowering::emitSubSteps(ComponentOp component,
                                               OpBuilder &launches) {
  Kernel kernel = beginKernel(("substep_" + component.getSymName()).str());
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  kernel.values.bigStepBegin = begin;
  kernel.values.bigStepSize = size;
  Value dt = kernel.values.params.lookup("dt");
  auto writes =
      llvm::to_vector(component.getWrites().getAsRange<FlatSymbolRefAttr>());
  SmallVector<Type> stateTypes;
  for (FlatSymbolRefAttr name : writes)
    stateTypes.push_back(simulation.lookupBuffer(name).getElementType());

  auto slotType = MemRefType::get(
      {3}, b.getI32Type(), nullptr,
      gpu::AddressSpaceAttr::get(b.getContext(), gpu::AddressSpace::Workgroup));
  Value slots = kernel.func.addWorkgroupAttribution(slotType, b.loc);
  b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
    Value thread = b.threadId();
    Value lane = b.laneId();
    Value first = b.cmp(arith::CmpIPredicate::eq, thread, b.index(0));
    Value lane0 = b.cmp(arith::CmpIPredicate::eq, lane, b.index(0));
    Value none = b.i32(kNoEstimate);
    b.ifThen(first, [&] { b.store(none, slots, b.index(0)); });
    b.barrier();
    Value end = b.add(begin, size);
    Value single = b.cmp(arith::CmpIPredicate::eq, size, b.i64(1));

    SmallVector<Value> totals = forEachItem(
        kernel, {b.index(0), b.i32(0)},
        [&](Value item, Value active, ValueRange iters) {
          // Own state at T into registers (padding lanes hold zeros).
          auto initial = b.ifThenElse(
              stateTypes, active,
              [&] {
                SmallVector<Value> state;
                for (FlatSymbolRefAttr name : writes)
                  state.push_back(
                      b.load(kernel.values.buffers.lookup(name.getAttr()),
                             b.add(kernel.values.sourceBase, item)));
                return state;
              },
              [&] {
                SmallVector<Value> zeros;
                for (Type type : stateTypes)
                  zeros.push_back(buildZeroElement(b, b.loc, type));
                return zeros;
              });
          SmallVector<Value> inits = {begin, iters[0], iters[1]};
          llvm::append_range(inits, initial.getResults());
          SmallVector<Type> types = {b.getI64Type(), b.getIndexType(),
                                     b.getI32Type()};
          llvm::append_range(types, stateTypes);

          auto loop = scf::WhileOp::create(b, b.loc, types, inits);
          Block *before =
              b.createBlock(&loop.getBefore(), {}, types,
                            SmallVector<Location>(types.size(), b.loc));
          Value more =
              b.cmp(arith::CmpIPredicate::slt, before->getArgument(0), end);
          scf::ConditionOp::create(b, b.loc, more, before->getArguments());
          Block *after =
              b.createBlock(&loop.getAfter(), {}, types,
                            SmallVector<Location>(types.size(), b.loc));
          Value time = after->getArgument(0);
          Value subStep = after->getArgument(1);
          Value count = after->getArgument(2);
          ValueRange state = after->getArguments().drop_front(3);
          KernelValues values = kernel.values;
          values.item = item;
          for (auto [name, value] : llvm::zip_equal(writes, state))
            values.registers[name.getAttr()] = value;

          // The sub-step: 1 when m = 1, else the group minimum of num_steps
          // clamped to the end of the big step.
          auto decided = b.ifThenElse(
              {b.getI64Type(), b.getIndexType()}, single,
              [&] { return SmallVector<Value>{b.i64(1), subStep}; },
              [&] {
                auto estimate = b.ifThenElse(
                    b.getI32Type(), active,
                    [&] {
                      Value steps =
                          inline_(component.getNumSteps(), {item, time}, values)
                              .front();
                      return SmallVector<Value>{b.max(steps, b.i32(1))};
                    },
                    [&] { return SmallVector<Value>{none}; });
                Value warpMin = b.groupReduce(estimate.getResult(0),
                                              gpu::AllReduceOperation::MINSI);
                Value three = b.index(3);
                Value current =
                    arith::RemUIOp::create(b, b.loc, subStep, three);
                Value nextSubStep = b.add(subStep, b.index(1));
                Value upcoming =
                    arith::RemUIOp::create(b, b.loc, nextSubStep, three);
                b.ifThen(first, [&] { b.store(none, slots, upcoming); });
                b.ifThen(lane0, [&] {
                  b.atomic(arith::AtomicRMWKind::mins, warpMin, slots, current);
                });
                b.barrier();
                Value groupMin = arith::ExtSIOp::create(
                    b, b.loc, b.getI64Type(), b.load(slots, current));
                Value steps = b.min(groupMin, b.sub(end, time));
                return SmallVector<Value>{steps, nextSubStep};
              });
          Value steps = decided.getResult(0);
          Value steps32 =
              arith::TruncIOp::create(b, b.loc, b.getI32Type(), steps);
          auto advanced = b.ifThenElse(
              stateTypes, active,
              [&] {
                return inline_(component.getEvaluate(),
                               {item, time, steps32, dt}, values);
              },
              [&] { return SmallVector<Value>(state); });
          Value evaluated = b.add(
              count, arith::ExtUIOp::create(b, b.loc, b.getI32Type(), active));
          SmallVector<Value> yielded = {b.add(time, steps),
                                        decided.getResult(1), evaluated};
          llvm::append_range(yielded, advanced.getResults());
          scf::YieldOp::create(b, b.loc, yielded);

          b.setInsertionPointAfter(loop);
          // The target half, once.
          b.ifThen(active, [&] {
            for (auto [name, value] :
                 llvm::zip_equal(writes, loop.getResults().drop_front(3)))
              b.store(value, kernel.values.buffers.lookup(name.getAttr()),
                      b.add(kernel.values.targetBase, item));
          });
          return SmallVector<Value>{loop.getResult(1), loop.getResult(2)};
        });
    addEvaluations(kernel, totals[1], component);
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
  {
    InFlightDiagnostic remark = component.emitRemark()
                                << "@" << name << " takes its sub-steps as "
                                << maxSteps
                                << " rounds of launches with a grid-wide "
                                   "sub-step decided on the device";
    for (FlatSymbolRefAttr write :
         component.getWrites().getAsRange<FlatSymbolRefAttr>())
      if (simulation.lookupBuffer(write).getSnapshot())
        remark << ", a snapshot of " << write << " before them";
    if (component.getParity() == Parity::copy_if_even)
      remark << ", and a copy after an even number of sub-steps";
  }
  auto writes =
      llvm::to_vector(component.getWrites().getAsRange<FlatSymbolRefAttr>());
  Value dt;

  // Snapshots of the value at T.
  for (FlatSymbolRefAttr write : writes) {
    BufferOp buffer = simulation.lookupBuffer(write);
    if (!buffer.getSnapshot())
      continue;
    Kernel kernel = beginKernel(("snapshot_" + buffer.getSymName()).str());
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    setHalves(kernel, parity, parity);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)), [&] {
      forEachItem(kernel, {}, [&](Value item, Value active, ValueRange) {
        b.ifThen(active, [&] {
          Value value = b.load(kernel.values.buffers.lookup(write.getAttr()),
                               b.add(kernel.values.sourceBase, item));
          b.store(value, kernel.values.snapshots.lookup(write.getAttr()), item);
        });
        return SmallVector<Value>();
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
    Kernel kernel = beginKernel(("substep_estimate_" + name).str());
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    Value subBegin = b.slot(kernel.clock, sub + kSubBegin);
    Value subSize = b.slot(kernel.clock, sub + kSubSize);
    Value subCount = b.slot(kernel.clock, sub + kSubCount);
    Value now = b.add(subBegin, subSize);
    Value stepped = b.cmp(arith::CmpIPredicate::sgt, subSize, b.i64(0));
    Value done = b.add(
        subCount, arith::ExtUIOp::create(b, b.loc, b.getI64Type(), stepped));
    Value readParity = arith::XOrIOp::create(
        b, b.loc, parity, arith::AndIOp::create(b, b.loc, done, b.i64(1)));
    setHalves(kernel, parity, readParity);
    kernel.values.bigStepBegin = begin;
    kernel.values.bigStepSize = size;
    Value pending = b.cmp(arith::CmpIPredicate::slt, now, b.add(begin, size));
    b.ifThen(pending, [&] {
      Value none = b.i32(kNoEstimate);
      SmallVector<Value> mins = forEachItem(
          kernel, {none}, [&](Value item, Value active, ValueRange iters) {
            auto estimate = b.ifThenElse(
                b.getI32Type(), active,
                [&] {
                  KernelValues values = kernel.values;
                  values.item = item;
                  Value steps =
                      inline_(component.getNumSteps(), {item, now}, values)
                          .front();
                  return SmallVector<Value>{b.max(steps, b.i32(1))};
                },
                [&] { return SmallVector<Value>{none}; });
            return SmallVector<Value>{b.min(iters[0], estimate.getResult(0))};
          });
      // One global atomic per warp: the rounds are the rare fallback.
      Value warpMin = b.groupReduce(mins[0], gpu::AllReduceOperation::MINSI);
      Value lane0 = b.cmp(arith::CmpIPredicate::eq, b.laneId(), b.index(0));
      b.ifThen(lane0, [&] {
        b.atomic(arith::AtomicRMWKind::mins,
                 arith::ExtSIOp::create(b, b.loc, b.getI64Type(), warpMin),
                 kernel.clock, b.index(sub + kSubEstimate));
      });
    });
    if (failed(endKernel(kernel, simplan::LaunchShape::items, roundLaunches)))
      return failure();
  }

  // Commit the previous sub-step, decide the next.
  {
    Kernel kernel = beginKernel(("substep_advance_" + name).str());
    Value clock = kernel.clock;
    Value begin = b.slot(clock, kSlotBegin);
    Value size = b.slot(clock, kSlotSize);
    Value zero = b.i64(0);
    Value subSize = b.slot(clock, sub + kSubSize);
    Value now = b.add(b.slot(clock, sub + kSubBegin), subSize);
    Value stepped = b.cmp(arith::CmpIPredicate::sgt, subSize, zero);
    Value count =
        b.add(b.slot(clock, sub + kSubCount),
              arith::ExtUIOp::create(b, b.loc, b.getI64Type(), stepped));
    Value remaining = b.sub(b.add(begin, size), now);
    Value positive = b.cmp(arith::CmpIPredicate::sgt, remaining, zero);
    Value next = b.select(
        positive, b.min(b.slot(clock, sub + kSubEstimate), remaining), zero);
    b.setSlot(clock, sub + kSubBegin, now);
    b.setSlot(clock, sub + kSubSize, next);
    b.setSlot(clock, sub + kSubCount, count);
    b.setSlot(clock, sub + kSubEstimate, b.i64(kNoEstimate64));
    if (failed(endKernel(kernel, simplan::LaunchShape::single, roundLaunches)))
      return failure();
  }

  // The sub-step: read one half, write the other.
  {
    Kernel kernel = beginKernel(("substep_" + name).str());
    Value begin, size, parity;
    readClock(kernel, begin, size, parity);
    Value subBegin = b.slot(kernel.clock, sub + kSubBegin);
    Value subSize = b.slot(kernel.clock, sub + kSubSize);
    Value subCount = b.slot(kernel.clock, sub + kSubCount);
    Value readParity = arith::XOrIOp::create(
        b, b.loc, parity, arith::AndIOp::create(b, b.loc, subCount, b.i64(1)));
    setHalves(kernel, parity, readParity);
    Value writeBase =
        b.mul(b.toIndex(arith::XOrIOp::create(b, b.loc, readParity, b.i64(1))),
              kernel.values.range);
    kernel.values.bigStepBegin = begin;
    kernel.values.bigStepSize = size;
    dt = kernel.values.params.lookup("dt");
    Value steps = arith::TruncIOp::create(b, b.loc, b.getI32Type(), subSize);
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, subSize, b.i64(0)), [&] {
      SmallVector<Value> counts = forEachItem(
          kernel, {b.i32(0)}, [&](Value item, Value active, ValueRange iters) {
            b.ifThen(active, [&] {
              KernelValues values = kernel.values;
              values.item = item;
              SmallVector<Value> results = inline_(
                  component.getEvaluate(), {item, subBegin, steps, dt}, values);
              for (auto [write, value] : llvm::zip_equal(writes, results))
                b.store(value, values.buffers.lookup(write.getAttr()),
                        b.add(writeBase, item));
            });
            Value one =
                arith::ExtUIOp::create(b, b.loc, b.getI32Type(), active);
            return SmallVector<Value>{b.add(iters[0], one)};
          });
      addEvaluations(kernel, counts[0], component);
    });
    if (failed(endKernel(kernel, simplan::LaunchShape::items, roundLaunches,
                         component)))
      return failure();
  }

  if (component.getParity() != Parity::copy_if_even)
    return success();
  // The parity copy: after an even number of sub-steps the result is in the
  // source half.
  Kernel kernel = beginKernel(("parity_" + name).str());
  Value begin, size, parity;
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  Value subSize = b.slot(kernel.clock, sub + kSubSize);
  Value stepped = b.cmp(arith::CmpIPredicate::sgt, subSize, b.i64(0));
  Value count =
      b.add(b.slot(kernel.clock, sub + kSubCount),
            arith::ExtUIOp::create(b, b.loc, b.getI64Type(), stepped));
  Value even =
      b.cmp(arith::CmpIPredicate::eq,
            arith::AndIOp::create(b, b.loc, count, b.i64(1)), b.i64(0));
  Value copy = arith::AndIOp::create(
      b, b.loc, even, b.cmp(arith::CmpIPredicate::sgt, size, b.i64(0)));
  b.ifThen(copy, [&] {
    forEachItem(kernel, {}, [&](Value item, Value active, ValueRange) {
      b.ifThen(active, [&] {
        for (FlatSymbolRefAttr write : writes) {
          Value memory = kernel.values.buffers.lookup(write.getAttr());
          b.store(b.load(memory, b.add(kernel.values.sourceBase, item)), memory,
                  b.add(kernel.values.targetBase, item));
        }
      });
      return SmallVector<Value>();
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
  MLIRContext *context = simulation.getContext();
  StringRef name = simulation.getSymName();

  OpBuilder top(simulation);
  kernels = gpu::GPUModuleOp::create(top, simulation.getLoc(),
                                     (name + "_kernels").str());
  plan = simplan::PlanOp::create(
      top, simulation.getLoc(), simulation.getSymNameAttr(),
      top.getStringAttr(stringifyStrategy(strategy)),
      FlatSymbolRefAttr::get(kernels.getSymNameAttr()),
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
    Type element = buffer.getElementType();
    // Element stride as the kernels address it (LLVM's alloc size: vectors
    // are padded to a power of two, so vector<3xf32> takes 16 bytes).
    int64_t bytes = buffer.getElementBytes();
    int64_t stride =
        isa<VectorType>(element) ? llvm::PowerOf2Ceil(bytes) : bytes;
    simplan::BufferOp::create(
        planBuilder, buffer.getLoc(), buffer.getSymNameAttr(),
        TypeAttr::get(element), planBuilder.getI64IntegerAttr(stride),
        unitIf(buffer.getSnapshot()),
        unitIf(observed.contains(buffer.getSymNameAttr())),
        unitIf(!buffer.getExact().empty()));
  }
  for (ComponentOp component : order)
    simplan::ComponentOp::create(
        planBuilder, component.getLoc(), component.getSymNameAttr(),
        component.getWrites(),
        planBuilder.getI64IntegerAttr(evaluationSlots.lookup(component)));

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
  {
    // The same kernel as in the step phase: launch it again.
    auto advance = *llvm::find_if(
        step.getBlock()->getOps<simplan::LaunchOp>(),
        [](simplan::LaunchOp launch) {
          return launch.getKernel().getLeafReference() == "advance";
        });
    finish.clone(*advance.getOperation());
  }

  // exact: the exact solutions the scene declares.
  bool anyExact = llvm::any_of(
      buffers, [](BufferOp buffer) { return !buffer.getExact().empty(); });
  if (anyExact) {
    OpBuilder exact = phase(simplan::PhaseKind::exact);
    for (BufferOp buffer : buffers)
      if (!buffer.getExact().empty() && failed(emitExact(buffer, exact)))
        return failure();
  }
  (void)context;
  simulation.erase();
  return success();
}

namespace {
struct SimLowerToGPUPass
    : public sim::impl::SimLowerToGPUBase<SimLowerToGPUPass> {
  using SimLowerToGPUBase::SimLowerToGPUBase;

  void runOnOperation() override {
    ModuleOp module = getOperation();
    if (groupSize <= 0 || groupSize % 32 != 0) {
      module.emitError() << "--sim-lower-to-gpu needs a group size that is a "
                            "positive multiple of 32 (a warp), not "
                         << static_cast<int64_t>(groupSize);
      return signalPassFailure();
    }
    SmallVector<SimulationOp> simulations(module.getOps<SimulationOp>());
    for (SimulationOp simulation : simulations)
      if (failed(SimulationLowering(simulation, groupSize).run()))
        return signalPassFailure();
    module->setAttr(gpu::GPUDialect::getContainerModuleAttrName(),
                    UnitAttr::get(&getContext()));
  }
};
} // namespace
