//===- SimulationLowering.cpp - checks, the clock, kernels and the plan ---===//
//
// The driver of the lowering of one simulation (SimulationLowering.h): it
// checks that the front end recorded everything, lays out the clock, gives
// every kernel its arguments and its launch, and builds the plan's phases
// from the kernel families of the other files.
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

#include "sim/Conversion/SimCommon/SimulationLowering.h"
#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Analysis/Scheduling.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Transforms/RegionUtils.h"

using namespace mlir;
using namespace mlir::sim;

int64_t mlir::sim::getElementStride(BufferOp buffer) {
  int64_t bytes = buffer.getElementBytes();
  return isa<VectorType>(buffer.getElementType()) ? llvm::PowerOf2Ceil(bytes)
                                                  : bytes;
}

LogicalResult SimulationLowering::checkFrontEnd() {
  if (failed(simulation.checkConstantsInlined("")))
    return failure();
  StrategyAttr strategyAttr = simulation.getStrategyAttr();
  if (!strategyAttr || !simulation.getStepCapAttr())
    return simulation.emitOpError()
           << "has no memory plan; run the front end (--sim-front-end) "
              "before lowering it";
  strategy = strategyAttr.getValue();
  maxSteps = simulation.getMaxSteps();
  stepCap = simulation.getStepCapAttr().getInt();
  if (IntegerAttr halo = simulation.getDistributedHaloAttr()) {
    distributed = true;
    distributedHalo = halo.getInt();
  }

  std::optional<SmallVector<ComponentOp>> scheduled =
      simulation.getScheduledOrder();
  if (!scheduled)
    return simulation.emitOpError()
           << "has no complete schedule; run the front end (--sim-front-end) "
              "before lowering it";
  order = std::move(*scheduled);

  for (ComponentOp component : order) {
    if (!component.getSubSteppingAttr() || !component.getAdvanceAttr() ||
        !component.getParityAttr())
      return component.emitOpError()
             << "has no sub-stepping verdict, advance or parity; run the "
                "front end (--sim-front-end) before lowering it";
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
  return checkRecordedDecisions();
}

/// The text that ends every error about a record that disagrees with
/// another: what to do.
static constexpr StringLiteral kStaleRecords =
    "; the records are stale or were edited by hand: run the front end "
    "(--sim-front-end) again";

/// The lowering reads what the front end recorded and re-derives none of
/// it, so a record that disagrees with the records it was decided from, or
/// with the body (a hand edit, or a pass rerun alone after a change),
/// would compile into wrong results without a word. Each check ties one
/// record to what it was decided from.
LogicalResult SimulationLowering::checkRecordedDecisions() {
  // How each component advances follows from the strategy, the schedule's
  // step bounds and the sub-stepping verdict (decideStepping, the one
  // place that decides it).
  for (ComponentOp component : order) {
    FailureOr<Stepping> stepping = decideStepping(component, strategy);
    if (failed(stepping))
      return failure();
    if (stepping->advance == component.getAdvance() &&
        stepping->estimates == component.getEstimates())
      continue;
    return component.emitOpError()
           << "records advance " << stringifyAdvance(*component.getAdvance())
           << (component.getEstimates() ? " with" : " without")
           << " estimates, but under strategy " << stringifyStrategy(strategy)
           << " its schedule's bounded_by and its sub-stepping verdict give "
           << stringifyAdvance(stepping->advance)
           << (stepping->estimates ? " with" : " without") << " estimates"
           << kStaleRecords;
  }

  // The verdicts and versions against the loads of the bodies.
  DependencyAnalysis analysis(simulation);
  for (ComponentOp component : order) {
    unsigned position = *simulation.getSchedulePosition(component);
    WalkResult walk =
        component.walk([&](LoadOp load) {
          BufferOp buffer = simulation.lookupBuffer(load.getBufferAttr());
          ComponentOp writer = simulation.getWriter(buffer);
          BodyKind body = getEnclosingBody(load)->kind;
          AccessPattern pattern = analysis.getPattern(load);
          std::string where = pattern.isGather()
                                  ? std::string("through a gather")
                                  : "at " + pattern.str();
          // An in_window cache load is lowered without a check: its index
          // must be inside the fill's window, which the cache always holds.
          if (load.getInWindow()) {
            FillCacheOp fill = findFillCache(load, load.getBufferAttr());
            int64_t min = fill.getMinOffsetAttr().getInt();
            int64_t max = fill.getMaxOffsetAttr().getInt();
            if (pattern.isGather() || pattern.getMinOffset() < min ||
                pattern.getMaxOffset() > max) {
              load.emitOpError()
                  << "is marked in_window, but reads @" << buffer.getSymName()
                  << " " << where << ", outside the window [" << min << ", "
                  << max << "] of its fill" << kStaleRecords;
              return WalkResult::interrupt();
            }
          }
          if (writer == component) {
            // in_kernel sub-steps let each thread own its item's state: a read
            // of another item could see it between sub-steps.
            if (component.getSubStepping() == SubStepping::in_kernel &&
                !pattern.isOwn()) {
              load.emitOpError()
                  << "reads @" << buffer.getSymName() << ", which @"
                  << component.getSymName() << " writes, " << where << ", but @"
                  << component.getSymName()
                  << " records the sub-stepping verdict in_kernel, which holds "
                     "only for reads of its own item"
                  << kStaleRecords;
              return WalkResult::interrupt();
            }
            // Local steps limit the levels of the blocks inside local_window
            // only: a read outside it could see a block two levels apart.
            DenseI64ArrayAttr window = component.getLocalWindowAttr();
            if (component.getAdvance() == Advance::local_steps &&
                body == BodyKind::Evaluate && !pattern.isOwn() &&
                (pattern.isGather() || pattern.getMinOffset() < window[0] ||
                 pattern.getMaxOffset() > window[1])) {
              load.emitOpError()
                  << "reads @" << buffer.getSymName() << ", which @"
                  << component.getSymName() << " writes, " << where
                  << ", outside the local_window [" << window[0] << ", "
                  << window[1] << "] that its local steps are planned for"
                  << kStaleRecords;
              return WalkResult::interrupt();
            }
            return WalkResult::advance();
          }
          // A buffer whose writer runs later in the step holds only its value
          // at T while this component runs: its target half is the previous
          // big step's.
          bool backEdge = *simulation.getSchedulePosition(writer) > position;
          Version version = load.getVersion();
          if (backEdge &&
              (version == Version::target || version == Version::cache)) {
            load.emitOpError()
                << "loads the " << stringifyVersion(version) << " copy of @"
                << buffer.getSymName() << ", but its writer @"
                << writer.getSymName() << " runs after @"
                << component.getSymName()
                << " in the schedule, so only its value at T (the source copy) "
                   "exists when @"
                << component.getSymName() << " runs" << kStaleRecords;
            return WalkResult::interrupt();
          }
          // Without sub-steps (simple, traditional) a component evaluates once
          // per big step: at its end it reads an earlier component's buffer
          // at T + m, and estimates from the values at T.
          Version expected =
              body == BodyKind::Evaluate ? Version::target : Version::source;
          if (!backEdge && !isSubSteppingStrategy(strategy) &&
              version != expected) {
            load.emitOpError()
                << "loads the " << stringifyVersion(version) << " copy of @"
                << buffer.getSymName() << ", but under strategy "
                << stringifyStrategy(strategy) << " its "
                << stringifyBodyKind(body) << " body reads a buffer that @"
                << writer.getSymName() << " wrote earlier in the step at "
                << (body == BodyKind::Evaluate ? "the end of the big step (the "
                                                 "target copy)"
                                               : "its start (the source copy)")
                << kStaleRecords;
            return WalkResult::interrupt();
          }
          return WalkResult::advance();
        });
    if (walk.wasInterrupted())
      return failure();
  }
  return success();
}

/// Assigns clock slots: the fixed ones, one evaluation counter per
/// component, a sub-step clock per component that takes grid-wide or local
/// sub-steps, the largest estimate and its hint per pair writer that
/// estimates, then the histogram of big-step sizes (index m, 0..max_steps).
void SimulationLowering::planClock() {
  int64_t next = kFirstFreeSlot;
  for (ComponentOp component : order)
    evaluationSlots[component] = next++;
  for (ComponentOp component : order)
    if (component.getAdvance() == Advance::grid_substeps ||
        component.getAdvance() == Advance::local_steps) {
      subClockSlots[component] = next;
      next += simplan::subClockSlots(*component.getAdvance());
    }
  for (ComponentOp component : order)
    if (component.getAdvance() == Advance::local_flux &&
        component.getEstimates()) {
      largestEstimateSlots[component] = next;
      next += kLargestSlots;
    }
  histogramSlot = next;
  clockSlots = next + maxSteps + 1;
}

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
  for (ComponentOp component : order)
    if (component.getAdvance() == Advance::local_steps) {
      types.push_back(dynamic(b.getI64Type()));
      kernel.args.push_back(
          arg(simplan::ArgKind::levels, component.getSymNameAttr()));
    }
  for (ParamOp param : params) {
    // An index parameter is passed as i64 (sim.get_param casts it back).
    Type type = cast<TypedAttr>(param.getValue()).getType();
    types.push_back(type.isIndex() ? b.getI64Type() : type);
    kernel.args.push_back(arg(simplan::ArgKind::param, param.getSymNameAttr()));
  }
  types.push_back(b.getI64Type());
  kernel.args.push_back(arg(simplan::ArgKind::range));
  if (distributed) {
    types.push_back(b.getI64Type());
    kernel.args.push_back(arg(simplan::ArgKind::first));
    types.push_back(b.getI64Type());
    kernel.args.push_back(arg(simplan::ArgKind::extent));
  }
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
  for (ComponentOp component : order)
    if (component.getAdvance() == Advance::local_steps)
      kernel.levels[component.getSymNameAttr()] = next();
  for (ParamOp param : params)
    values.params[param.getSymName()] = next();
  Value range = next();
  values.params["range"] = range;
  values.range = b.toIndex(range);
  values.extent = values.range;
  if (distributed) {
    values.first = b.toIndex(next());
    values.extent = b.toIndex(next());
    values.halo = distributedHalo;
    for (BufferOp buffer : buffers)
      if (buffer.getReplicated())
        values.replicated.insert(buffer.getSymNameAttr());
  }
  values.params["dt"] = next();
  values.params["max_steps"] = b.i64(maxSteps);
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

  // What every launch of the kernel must agree with (the launch verifier and
  // the runtime check it): its shared memory and the clock it addresses.
  kernel.func->setAttr(
      simplan::PlanDialect::getSharedAttrName(),
      b.getDenseI64ArrayAttr({kernel.sharedPerThread, kernel.sharedFixed}));
  kernel.func->setAttr(simplan::PlanDialect::getClockSlotsAttrName(),
                       b.getI64IntegerAttr(clockSlots));
  if (kernel.unevenGroups)
    kernel.func->setAttr(simplan::PlanDialect::getUnevenGroupsAttrName(),
                         b.getUnitAttr());

  auto kernelRef = SymbolRefAttr::get(
      SymbolTable::getSymbolName(kernels),
      {FlatSymbolRefAttr::get(SymbolTable::getSymbolName(kernel.func))});
  // Distributed plans: a launch that writes a component's buffers sends
  // the ghost items of those that some read reaches at other items.
  SmallVector<Attribute> exchange = std::move(pendingExchange);
  SmallVector<Attribute> exchangeSnapshots =
      std::move(pendingExchangeSnapshots);
  SmallVector<int64_t> reduce = std::move(pendingReduce);
  SmallVector<Attribute> reduceLevels = std::move(pendingReduceLevels);
  pendingReduceLevels.clear();
  pendingExchange.clear();
  pendingExchangeSnapshots.clear();
  pendingReduce.clear();
  // A component that advances by whole_step or group_substeps writes the
  // target half only (the source half holds T for its readers), and so
  // does a parity copy: only that half's ghosts travel. A grid-wide
  // sub-step writes the half its sub-step count selects, and only that one
  // travels; a local time step's slot writes the blocks that start a
  // sub-step at it, each into the half its sub-step count selects, and
  // only those travel; a flux pair's slot writes the target half of the
  // interfaces due at it, and those of the blocks where the pair's reader
  // starts a sub-step travel.
  SmallVector<Attribute> exchangeTargets, exchangeSubStep, exchangeLocalStep,
      exchangeLocalFlux;
  WrittenHalf written = pendingWrittenHalf;
  pendingWrittenHalf = WrittenHalf::Advance;
  if (distributed && component) {
    SmallVector<Attribute> *list = &exchange;
    if (written == WrittenHalf::Target ||
        (written == WrittenHalf::Advance &&
         (component.getAdvance() == Advance::whole_step ||
          component.getAdvance() == Advance::group_substeps)))
      list = &exchangeTargets;
    else if (written == WrittenHalf::SubStep)
      list = &exchangeSubStep;
    else if (written == WrittenHalf::LocalStep)
      list = &exchangeLocalStep;
    else if (written == WrittenHalf::LocalFlux)
      list = &exchangeLocalFlux;
    for (FlatSymbolRefAttr write :
         component.getWrites().getAsRange<FlatSymbolRefAttr>())
      if (travels(simulation.lookupBuffer(write)))
        list->push_back(write);
  }
  simplan::LaunchOp::create(
      launches, b.loc, kernelRef,
      simplan::LaunchShapeAttr::get(b.getContext(), shape),
      launches.getArrayAttr(args),
      component ? FlatSymbolRefAttr::get(component.getSymNameAttr())
                : FlatSymbolRefAttr(),
      launches.getI64IntegerAttr(kernel.sharedPerThread),
      launches.getI64IntegerAttr(kernel.sharedFixed),
      reduce.empty() ? DenseI64ArrayAttr()
                     : launches.getDenseI64ArrayAttr(reduce),
      exchange.empty() ? ArrayAttr() : launches.getArrayAttr(exchange),
      exchangeSnapshots.empty() ? ArrayAttr()
                                : launches.getArrayAttr(exchangeSnapshots),
      reduceLevels.empty() ? ArrayAttr() : launches.getArrayAttr(reduceLevels),
      exchangeTargets.empty() ? ArrayAttr()
                              : launches.getArrayAttr(exchangeTargets),
      exchangeSubStep.empty() ? ArrayAttr()
                              : launches.getArrayAttr(exchangeSubStep),
      exchangeLocalStep.empty() ? ArrayAttr()
                                : launches.getArrayAttr(exchangeLocalStep),
      exchangeLocalFlux.empty() ? ArrayAttr()
                                : launches.getArrayAttr(exchangeLocalFlux));
  return success();
}

void SimulationLowering::readClock(Kernel &kernel, Value &begin, Value &size,
                                   Value &parity) {
  begin = b.load(kernel.clock, b.index(kSlotBegin));
  size = b.load(kernel.clock, b.index(kSlotSize));
  parity = b.load(kernel.clock, b.index(kSlotParity));
}

void SimulationLowering::readBigStep(Kernel &kernel, Value &begin, Value &size,
                                     Value &parity) {
  readClock(kernel, begin, size, parity);
  setHalves(kernel, parity, parity);
  kernel.values.bigStepBegin = begin;
  kernel.values.bigStepSize = size;
}

/// Source and target halves from the clock's parity; `local` loads (own
/// state not in registers) read the half `localParity` selects.
void SimulationLowering::setHalves(Kernel &kernel, Value parity,
                                   Value localParity) {
  KernelValues &values = kernel.values;
  Value extent = values.extent;
  values.sourceParity = parity;
  values.targetParity = b.xorOne(parity);
  values.localParity = localParity;
  values.sourceBase = b.mul(b.toIndex(parity), extent);
  values.targetBase = b.mul(b.toIndex(values.targetParity), extent);
  values.localBase = b.mul(b.toIndex(localParity), extent);
}

void SimulationLowering::forEachItem(Kernel &kernel,
                                     function_ref<void(const Lane &)> body) {
  target.forEachGroup(b, kernel, [&](Value base) {
    target.forEachLane(b, kernel, base, body);
  });
}

void SimulationLowering::copyToTarget(Kernel &kernel,
                                      ArrayRef<FlatSymbolRefAttr> writes,
                                      Value item) {
  for (FlatSymbolRefAttr write : writes) {
    Value memory = kernel.values.buffers.lookup(write.getAttr());
    b.store(b.load(memory, at(kernel, write.getAttr(), kernel.values.sourceBase,
                              kernel.values.sourceParity, item)),
            memory,
            at(kernel, write.getAttr(), kernel.values.targetBase,
               kernel.values.targetParity, item));
  }
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

bool SimulationLowering::keepsEstimate(ComponentOp writer) {
  // A pair's reader keeps its levels when neither its num_steps nor its
  // writer's can change during a run (invariant_levels), so neither can the
  // writer's largest estimate.
  if (!largestEstimateSlots.contains(writer))
    return false;
  return llvm::any_of(order, [&](ComponentOp reader) {
    return reader.getAdvance() == Advance::local_steps &&
           reader.getInvariantLevels() && findFluxWriter(reader) == writer;
  });
}

/// num_steps of one item, at least 1 (values below 1 count as 1).
Value SimulationLowering::estimate(Kernel &kernel, ComponentOp component,
                                   Value item, Value time,
                                   const KernelValues &values) {
  Value steps = inline_(component.getNumSteps(), {item, time}, values).front();
  return b.max(steps, b.i32(1));
}

void SimulationLowering::estimateInto(Kernel &kernel, ComponentOp component,
                                      LaneVar combined, Value time,
                                      EstimateSlots slots) {
  // A minimum is final once it holds 1 (an estimate is at least 1), the
  // largest estimate once it holds the step cap (a longer one bounds
  // nothing): what the slot holds then.
  Value settled = b.i64(slots.largest ? -stepCap : 1);
  int64_t slot = slots.slot;
  auto lanes = [&](Value base) {
    target.forEachLane(b, kernel, base, [&](const Lane &lane) {
      b.ifThen(lane.active, [&] {
        KernelValues values = kernel.values;
        values.item = lane.item;
        Value steps = estimate(kernel, component, lane.item, time, values);
        if (slots.largest)
          steps = b.sub(b.i32(0), b.min(steps, b.i32(int32_t(stepCap))));
        target.laneStore(b, b.min(target.laneLoad(b, combined, lane), steps),
                         combined, lane);
      });
    });
  };
  if (!target.reducesPerGroup()) {
    // Groups run side by side and combine once, after the last: a group
    // that starts when the slot already holds its settled value (an earlier
    // group found it) skips its num_steps. Each lane reads the slot itself
    // (one broadcast load per warp); a value read early is only larger, so
    // it skips less, never wrongly, and the combination after the loop is
    // the same for every lane.
    target.forEachGroup(b, kernel, [&](Value base) {
      Value current = b.load(kernel.clock, b.index(slot));
      b.ifThen(b.cmp(arith::CmpIPredicate::sgt, current, settled),
               [&] { lanes(base); });
    });
    target.reduceIntoClock(b, kernel, combined, arith::AtomicRMWKind::mins,
                           slot);
    return;
  }
  // An estimate is at least 1, so once the slot holds 1 (an item of this or
  // an earlier group, or another estimate of the same decision) no item can
  // change it: the groups after that skip their num_steps (a largest
  // estimate: once it holds the step cap). With per-item step counts nearly
  // every group holds an item at 1, and the estimate would otherwise cost as
  // much as a component's evaluation. The slot ends at the same value either
  // way.
  //
  // An estimate starts at the group where the last one found an item at 1
  // (clock slot EstimateHint, which the big step's estimate and the rounds
  // of grid-wide sub-steps share; a largest estimate has a hint of its own,
  // where it last reached the cap): a stiff item that holds every big step
  // or sub-step at 1 is usually where it was, and the groups before it
  // would otherwise be estimated in vain in every big step or round (the
  // rounds of a state-dependent num_steps cost as much as the sub-steps
  // without it). Estimates that find their 1 in different places move the
  // hint back and forth, which costs no more than starting at group 0.
  // Only the order of the groups depends on the hint, and no result
  // depends on the order.
  Value hint = b.atomic(arith::AtomicRMWKind::addi, b.i64(0), kernel.clock,
                        b.index(slots.hintSlot));
  auto group = [&](Value base) {
    Value current = b.atomic(arith::AtomicRMWKind::addi, b.i64(0), kernel.clock,
                             b.index(slot));
    b.ifThen(b.cmp(arith::CmpIPredicate::sgt, current, settled), [&] {
      lanes(base);
      target.reduceIntoClock(b, kernel, combined, arith::AtomicRMWKind::mins,
                             slot);
      Value after = b.atomic(arith::AtomicRMWKind::addi, b.i64(0), kernel.clock,
                             b.index(slot));
      b.ifThen(b.cmp(arith::CmpIPredicate::eq, after, settled), [&] {
        b.atomic(arith::AtomicRMWKind::assign,
                 arith::IndexCastOp::create(b, b.loc, b.getI64Type(), base),
                 kernel.clock, b.index(slots.hintSlot));
      });
    });
  };
  target.forEachGroupFrom(b, kernel, hint, group);
}

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
      top.getI64IntegerAttr(stepCap), top.getI64IntegerAttr(groupSize),
      top.getI64IntegerAttr(clockSlots), top.getI64IntegerAttr(histogramSlot),
      distributed ? top.getI64IntegerAttr(distributedHalo) : IntegerAttr());
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
        planBuilder.getI64IntegerAttr(getElementStride(buffer)),
        unitIf(buffer.getSnapshot()),
        unitIf(observed.contains(buffer.getSymNameAttr())),
        unitIf(!buffer.getExact().empty()), buffer.getHaloAttr(),
        buffer.getReplicatedAttr());
  }
  for (ComponentOp component : order) {
    auto slotAttr = [&](const llvm::DenseMap<Operation *, int64_t> &slots) {
      auto found = slots.find(component);
      return found == slots.end()
                 ? IntegerAttr()
                 : planBuilder.getI64IntegerAttr(found->second);
    };
    simplan::ComponentOp::create(
        planBuilder, component.getLoc(), component.getSymNameAttr(),
        component.getWrites(),
        planBuilder.getI64IntegerAttr(evaluationSlots.lookup(component)),
        component.getAdvanceAttr(), unitIf(component.getEstimates()),
        slotAttr(subClockSlots),
        /*level_reach=*/IntegerAttr(), /*keeps_levels=*/UnitAttr(),
        slotAttr(largestEstimateSlots), unitIf(keepsEstimate(component)));
  }

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
  // The estimates, the decision, then every component as the front end
  // recorded it advances. `minimumEstimated`: some estimate takes the
  // minimum into clock slot Estimate (a pair writer's largest estimate has
  // slots of its own).
  bool minimumEstimated = false;
  for (ComponentOp component : order) {
    if (!component.getEstimates())
      continue;
    minimumEstimated |= !largestEstimateSlots.contains(component);
    if (failed(emitEstimate(component, step)))
      return failure();
  }
  if (failed(emitAdvance(step, minimumEstimated)))
    return failure();
  for (ComponentOp component : order) {
    LogicalResult result = success();
    switch (component.getAdvance().value()) {
    case Advance::whole_step:
      result = emitEvaluate(component, step);
      break;
    case Advance::group_substeps:
      result = emitSubSteps(component, step);
      break;
    case Advance::grid_substeps:
      result = emitRounds(component, step);
      break;
    case Advance::local_steps:
      result = emitLocalSteps(component, step);
      break;
    case Advance::local_flux:
      // Runs inside the slots of the component that reads its fluxes.
      if (llvm::none_of(order, [&](ComponentOp reader) {
            return reader.getAdvance() == Advance::local_steps &&
                   findFluxWriter(reader) == component;
          }))
        result = component.emitOpError()
                 << "advances in local_flux, but no component that takes "
                    "local time steps reads its fluxes";
      break;
    }
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
