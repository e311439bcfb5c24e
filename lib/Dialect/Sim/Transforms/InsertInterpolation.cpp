//===- InsertInterpolation.cpp - view reads to explicit loads -------------===//
//
// Eq. (2) of the paper made explicit. A view read "B at item j at my local
// time" becomes loads of specific copies of B and, for a buffer already
// advanced in this big step under a sub-stepping strategy, the arithmetic of
// B's interpolation function at the reader's local time. Everything a
// lowering needs is then in the IR: which copy every load reads (from the
// memory plan), and the fraction as arithmetic on sim.big_step and the body's
// time arguments.
//
// The fraction is (t_end - T) / m with integer times, so it is exactly 0 at
// the start and exactly 1 at the end of the big step, and there a read loads
// the one copy it means (an scf.if on the local time) without the
// interpolation's arithmetic: every strategy then agrees with `simple`
// whenever a big step is one base step (signed zeros and all, as the
// reference executor), and a big step of 1 costs no interpolation.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/IR/PatternMatch.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMINSERTINTERPOLATION
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Builds, on demand and once per scalar type, the interpolation fraction and
/// the big step's length in time units at the start of one body.
class BodyTime {
public:
  /// `time` is the body's local time argument `%t`; `steps` the sub-step
  /// length `%n` in evaluate, null in num_steps (it reads at `t`).
  BodyTime(Region &body, Value time, Value steps, FloatType dtType)
      : body(body), time(time), steps(steps), dtType(dtType) {}

  Value getFraction(FloatType type) {
    auto it = fractions.find(type);
    if (it != fractions.end())
      return it->second;
    Value offset = getOffset();
    OpBuilder builder = atBodyStart();
    Location loc = body.getLoc();
    Value offsetF = arith::SIToFPOp::create(builder, loc, type, offset);
    Value sizeF =
        arith::SIToFPOp::create(builder, loc, type, getBigStep().second);
    Value fraction = arith::DivFOp::create(builder, loc, offsetF, sizeF);
    track({offsetF, sizeF, fraction});
    return fractions[type] = fraction;
  }

  /// Whether the body reads at the start (`offset == 0`) and at the end
  /// (`offset == m`) of the big step: there every read is one copy, loaded
  /// as it is, without the interpolation's arithmetic.
  std::pair<Value, Value> getEnds() {
    if (!atStart) {
      Value offset = getOffset();
      OpBuilder builder = atBodyStart();
      Location loc = body.getLoc();
      Value zero = arith::ConstantIntOp::create(builder, loc, 0, 64);
      atStart = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::eq,
                                      offset, zero);
      atEnd = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::eq,
                                    offset, getBigStep().second);
      track({zero, atStart, atEnd});
    }
    return {atStart, atEnd};
  }

  Value getSpan(FloatType type) {
    auto it = spans.find(type);
    if (it != spans.end())
      return it->second;
    OpBuilder builder = atBodyStart();
    Location loc = body.getLoc();
    Value sizeF =
        arith::SIToFPOp::create(builder, loc, type, getBigStep().second);
    // dt is a run-time value (a kernel argument), not a constant of the
    // scene: one compiled scene runs at any dt.
    Value dt =
        GetParamOp::create(builder, loc, dtType,
                           FlatSymbolRefAttr::get(builder.getContext(), "dt"));
    track({sizeF, dt});
    if (type.getWidth() != dtType.getWidth()) {
      dt = type.getWidth() > dtType.getWidth()
               ? Value(arith::ExtFOp::create(builder, loc, type, dt))
               : Value(arith::TruncFOp::create(builder, loc, type, dt));
      track({dt});
    }
    Value span = arith::MulFOp::create(builder, loc, sizeF, dt);
    track({span});
    return spans[type] = span;
  }

  /// Erases what was built but ended up unused (for example the span of a
  /// linear interpolation), newest first.
  void eraseUnused() {
    for (Operation *op : llvm::reverse(created))
      if (op->use_empty())
        op->erase();
  }

private:
  /// The local time at which the body reads, from the start of the big
  /// step: the end of the sub-step in evaluate, its start in num_steps.
  Value getOffset() {
    if (offset)
      return offset;
    auto [begin, size] = getBigStep();
    OpBuilder builder = atBodyStart();
    Location loc = body.getLoc();
    Value end = time;
    if (steps) {
      Value steps64 =
          arith::ExtSIOp::create(builder, loc, builder.getI64Type(), steps);
      track({steps64});
      end = arith::AddIOp::create(builder, loc, end, steps64);
      track({end});
    }
    offset = arith::SubIOp::create(builder, loc, end, begin);
    track({offset});
    return offset;
  }

  std::pair<Value, Value> getBigStep() {
    if (!bigStep) {
      OpBuilder builder(&body.front(), body.front().begin());
      bigStep = BigStepOp::create(builder, body.getLoc(), builder.getI64Type(),
                                  builder.getI64Type());
      created.insert(created.begin(), bigStep);
      prologue.insert(bigStep);
    }
    return {bigStep.getBegin(), bigStep.getSize()};
  }

public:
  /// A builder after the body's time values (they dominate what it builds):
  /// after the last op built at the body's start so far. Not before the
  /// body's first op of its own: that may be a read, which the pass
  /// replaces and erases.
  OpBuilder atBodyStart() {
    Operation *last = getBigStep().first.getDefiningOp();
    while (Operation *next = last->getNextNode()) {
      if (!prologue.contains(next))
        break;
      last = next;
    }
    OpBuilder builder(body.getContext(), &listener);
    builder.setInsertionPointAfter(last);
    return builder;
  }

private:
  void track(std::initializer_list<Value> values) {
    for (Value value : values)
      created.push_back(value.getDefiningOp());
  }

  /// Records what the builders of atBodyStart insert (the time values, the
  /// hip-cache fills, and what those hold).
  struct PrologueListener : OpBuilder::Listener {
    explicit PrologueListener(llvm::DenseSet<Operation *> &ops) : ops(ops) {}
    void notifyOperationInserted(Operation *op,
                                 OpBuilder::InsertPoint) override {
      ops.insert(op);
    }
    llvm::DenseSet<Operation *> &ops;
  };

  Region &body;
  Value time, steps;
  FloatType dtType;
  BigStepOp bigStep;
  llvm::DenseSet<Operation *> prologue;
  PrologueListener listener{prologue};
  SmallVector<Operation *> created;
  llvm::DenseMap<Type, Value> fractions, spans;
  Value offset, atStart, atEnd;
};

struct InsertInterpolationPass
    : public sim::impl::SimInsertInterpolationBase<InsertInterpolationPass> {
  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    if (failed(simulation.checkConstantsInlined(getArgument())))
      return signalPassFailure();
    StrategyAttr strategy = simulation.getStrategyAttr();
    if (!strategy) {
      simulation.emitOpError()
          << "has no memory plan; run --sim-plan-memory before "
             "--sim-insert-interpolation";
      return signalPassFailure();
    }
    if (failed(checkSchedule(simulation)))
      return signalPassFailure();

    // What the analysis found about each read, taken before any read is
    // replaced. A read whose index it proves to be the body's own item
    // although it is another value (`%i + 0`, a round trip through i64)
    // loads at `%i` itself, so that every lowering sees the own item as the
    // own item (a local load at another index reads another item's time
    // levels, which an `interp(none)` or `#sim.hermite` buffer cannot give
    // under lts). A cache load of a read it bounds inside the fill's window
    // is marked in_window (the cache always holds it).
    readPatterns.clear();
    auto &analysis = getAnalysis<DependencyAnalysis>();
    simulation.walk([&](ReadOp read) {
      readPatterns.try_emplace(read, analysis.getPattern(read));
    });

    bool subSteps = isSubSteppingStrategy(strategy.getValue());
    for (ComponentOp component : simulation.getComponents()) {
      if (component.hasNumSteps() &&
          failed(rewriteBody(simulation, component, component.getNumSteps(),
                             BodyKind::NumSteps, subSteps)))
        return signalPassFailure();
      if (failed(rewriteBody(simulation, component, component.getEvaluate(),
                             BodyKind::Evaluate, subSteps)))
        return signalPassFailure();
    }
    for (TotalOp total : simulation.getTotals())
      rewriteTotal(total);
  }

  /// A total reads every buffer at T, after a run: the source copy (the
  /// half the clock's parity selects), whatever the strategy.
  void rewriteTotal(TotalOp total) {
    SmallVector<ReadOp> reads;
    total.getBody().walk([&](ReadOp read) { reads.push_back(read); });
    IRRewriter rewriter(&getContext());
    for (ReadOp read : reads) {
      rewriter.setInsertionPoint(read);
      rewriter.replaceOpWithNewOp<LoadOp>(
          read, read.getType(), read.getBufferAttr(), read.getIndex(),
          VersionAttr::get(&getContext(), Version::source));
    }
  }

  /// An interpolation's auxiliary buffers must be advanced before the
  /// reader, which needs every component's position in the schedule.
  LogicalResult checkSchedule(SimulationOp simulation) {
    for (ComponentOp component : simulation.getComponents())
      if (!simulation.getSchedulePosition(component))
        return simulation.emitOpError()
               << "has no complete schedule; run --sim-schedule before "
                  "--sim-insert-interpolation";
    return success();
  }

  LogicalResult rewriteBody(SimulationOp simulation, ComponentOp component,
                            Region &body, BodyKind kind, bool subSteps) {
    SmallVector<ReadOp> reads;
    body.walk([&](ReadOp read) { reads.push_back(read); });
    bool isEvaluate = kind == BodyKind::Evaluate;
    BodyTime time(body,
                  isEvaluate ? component.getEvaluateTime()
                             : component.getNumStepsTime(),
                  isEvaluate ? Value(component.getEvaluateSteps()) : Value(),
                  simulation.getTimeStepType());
    IRRewriter rewriter(&getContext());
    fills.clear();
    for (ReadOp read : reads) {
      if (!read.getRoleAttr())
        return read.emitOpError()
               << "has no read role; run --sim-schedule before "
                  "--sim-insert-interpolation";
      rewriter.setInsertionPoint(read);
      FailureOr<Value> value = rewriteRead(rewriter, simulation, component,
                                           read, kind, subSteps, time);
      if (failed(value))
        return failure();
      rewriter.replaceOp(read, *value);
    }
    time.eraseUnused();
    return success();
  }

  FailureOr<Value> rewriteRead(IRRewriter &rewriter, SimulationOp simulation,
                               ComponentOp component, ReadOp read,
                               BodyKind kind, bool subSteps, BodyTime &time) {
    Location loc = read.getLoc();
    auto loadAt = [&](OpBuilder &builder, BufferOp buffer, Version version,
                      Value index) -> Value {
      return LoadOp::create(builder, loc, buffer.getElementType(),
                            FlatSymbolRefAttr::get(buffer.getSymNameAttr()),
                            index, VersionAttr::get(&getContext(), version));
    };
    Value item = kind == BodyKind::Evaluate ? component.getEvaluateItem()
                                            : component.getNumStepsItem();
    auto found = readPatterns.find(read);
    AccessPattern pattern =
        found != readPatterns.end() ? found->second : AccessPattern::gather();
    Value index = pattern.isOwn() ? item : read.getIndex();
    auto load = [&](BufferOp buffer, Version version) -> Value {
      return loadAt(rewriter, buffer, version, index);
    };
    BufferOp buffer = simulation.lookupBuffer(read.getBufferAttr());
    switch (read.getRole().value()) {
    case ReadRole::own:
      return load(buffer, Version::local);
    case ReadRole::back_edge:
      // The flux writer of a flux pair runs in its reader's slots: it reads
      // the reader's state at its own local time, from the reader's time
      // levels (docs/Model.md, "Conservation"); its estimate is at T.
      if (component.getAdvance() == Advance::local_flux &&
          kind == BodyKind::Evaluate)
        return load(buffer, Version::local);
      return load(buffer, Version::source);
    case ReadRole::interpolate:
      break;
    }
    if (!subSteps)
      // One evaluation per big step: it reads the end of the step; estimates
      // are taken at its start.
      return load(buffer, kind == BodyKind::Evaluate ? Version::target
                                                     : Version::source);

    // A flux holds its writer's value over the whole step, and evaluate
    // reads at the end of its sub-step, after T: always the target. So does
    // the reader of an item pair: its writer evaluated the item when the
    // item's block started the sub-step (docs/Model.md, "Item pairs").
    ComponentOp producer = simulation.getWriter(buffer);
    if ((isa<FluxInterpAttr>(buffer.getInterpolation()) ||
         (producer && producer.getAdvance() == Advance::local_flux)) &&
        kind == BodyKind::Evaluate)
      return load(buffer, Version::target);

    // --sim-plan-memory rejects these reads; a hand-written plan may not.
    if (failed(checkInterpolable(read, buffer, component, kind,
                                 simulation.getStrategy().value())))
      return failure();
    // A buffer without an interpolation is read only where no intermediate
    // time is (checkInterpolable): by a component that takes the big step
    // whole, at its end in evaluate and at its start in num_steps.
    if (!buffer.getInterpolation().isInterpolable())
      return load(buffer, kind == BodyKind::Evaluate ? Version::target
                                                     : Version::source);
    InterpolationAttrInterface interp = buffer.getInterpolation();
    SmallVector<BufferOp> inputs = {buffer};
    for (FlatSymbolRefAttr aux : interp.getAuxiliaryBuffers()) {
      BufferOp auxBuffer = simulation.lookupBuffer(aux);
      ComponentOp writer = simulation.getWriter(auxBuffer);
      if (writer == component)
        return read.emitOpError()
               << "interpolates @" << buffer.getSymName() << " with " << interp
               << ", which needs @" << auxBuffer.getSymName()
               << " at the end of the big step, but @" << component.getSymName()
               << " writes @" << auxBuffer.getSymName()
               << " itself, so it is not there while @"
               << component.getSymName()
               << " runs; use #sim.linear or #sim.cubic for @"
               << buffer.getSymName() << ", or write @"
               << auxBuffer.getSymName() << " in a component that runs before";
      if (*simulation.getSchedulePosition(writer) >=
          *simulation.getSchedulePosition(component))
        return read.emitOpError()
               << "interpolates @" << buffer.getSymName() << " with " << interp
               << ", which needs @" << auxBuffer.getSymName()
               << " at the end of the big step, but its writer @"
               << writer.getSymName() << " does not run before @"
               << component.getSymName() << " in the step";
      inputs.push_back(auxBuffer);
    }
    // The interpolated value at an item, built where `builder` points.
    FloatType scalarType = buffer.getScalarType();
    Value fraction = time.getFraction(scalarType);
    Value span = time.getSpan(scalarType);
    Version beginVersion =
        buffer.getSnapshot() ? Version::snapshot : Version::source;
    auto [startsStep, endsStep] = time.getEnds();
    // At the ends of the big step the value is the copy itself, exactly
    // (the reference executor returns it so too, whatever the function);
    // between them, the interpolation. The branches are uniform over a
    // group's sub-step, and the end is every read of a big step of 1.
    auto interpolateAt = [&](OpBuilder &builder, Value index) {
      Type type = read.getType();
      auto atEndIf = scf::IfOp::create(builder, loc, type, endsStep,
                                       /*withElseRegion=*/true);
      OpBuilder::InsertionGuard guard(builder);
      builder.setInsertionPointToStart(atEndIf.thenBlock());
      scf::YieldOp::create(builder, loc,
                           loadAt(builder, buffer, Version::target, index));
      builder.setInsertionPointToStart(atEndIf.elseBlock());
      auto atStartIf = scf::IfOp::create(builder, loc, type, startsStep,
                                         /*withElseRegion=*/true);
      scf::YieldOp::create(builder, loc, atStartIf.getResult(0));
      builder.setInsertionPointToStart(atStartIf.thenBlock());
      scf::YieldOp::create(builder, loc,
                           loadAt(builder, buffer, beginVersion, index));
      builder.setInsertionPointToStart(atStartIf.elseBlock());
      SmallVector<Value> atBegin, atEnd;
      for (BufferOp input : inputs) {
        if (input == buffer || input.getBoundary() == buffer.getBoundary()) {
          atBegin.push_back(
              loadAt(builder, input,
                     input.getSnapshot() ? Version::snapshot : Version::source,
                     index));
          atEnd.push_back(loadAt(builder, input, Version::target, index));
          continue;
        }
        // An auxiliary buffer (a Hermite derivative) with another boundary
        // rule: outside the range the read is the interpolated buffer's
        // item under its own rule, and the derivative is read at that item
        // (zero: no item, a zero derivative), as the reference executor
        // resolves the item once. Each load would apply its own rule.
        Value range = arith::IndexCastOp::create(
            builder, loc, builder.getIndexType(),
            GetParamOp::create(
                builder, loc, builder.getI64Type(),
                FlatSymbolRefAttr::get(builder.getContext(), "range")));
        Value inside;
        Value auxIndex = buildBoundaryItem(builder, loc, buffer.getBoundary(),
                                           index, range, inside);
        for (Version version :
             {input.getSnapshot() ? Version::snapshot : Version::source,
              Version::target}) {
          Value value = loadAt(builder, input, version, auxIndex);
          if (inside)
            value = arith::SelectOp::create(
                builder, loc, inside, value,
                arith::ConstantOp::create(
                    builder, loc,
                    cast<TypedAttr>(builder.getZeroAttr(value.getType()))));
          (version == Version::target ? atEnd : atBegin).push_back(value);
        }
      }
      scf::YieldOp::create(builder, loc,
                           interp.buildInterpolation(builder, loc, atBegin,
                                                     atEnd, fraction, span));
      return atEndIf.getResult(0);
    };

    // hip-cache: a recorded cache of this buffer is filled once per sub-step
    // (at the end of the sub-step, as evaluate reads), and the read loads
    // it. num_steps reads at another time and does not use it.
    CacheAttr cache = findCache(component, read.getBufferAttr());
    if (cache && kind == BodyKind::Evaluate) {
      FillCacheOp &fill = fills[buffer.getSymNameAttr()];
      if (!fill) {
        OpBuilder builder = time.atBodyStart();
        fill = FillCacheOp::create(
            builder, loc, read.getBufferAttr(),
            builder.getI64IntegerAttr(cache.getMinOffset()),
            builder.getI64IntegerAttr(cache.getMaxOffset()));
        Block *block = builder.createBlock(&fill.getBody(), {},
                                           builder.getIndexType(), loc);
        Value value = interpolateAt(builder, block->getArgument(0));
        YieldOp::create(builder, loc, value);
      }
      Value cached = load(buffer, Version::cache);
      if (!pattern.isGather() &&
          pattern.getMinOffset() >= cache.getMinOffset() &&
          pattern.getMaxOffset() <= cache.getMaxOffset())
        cached.getDefiningOp<LoadOp>().setInWindow(true);
      return cached;
    }
    return interpolateAt(rewriter, index);
  }

  static CacheAttr findCache(ComponentOp component, FlatSymbolRefAttr buffer) {
    if (ArrayAttr caches = component.getCachesAttr())
      for (auto cache : caches.getAsRange<CacheAttr>())
        if (cache.getBuffer() == buffer)
          return cache;
    return nullptr;
  }

  /// The cache fills of the body being rewritten, by buffer.
  llvm::DenseMap<StringAttr, FillCacheOp> fills;
  /// The analysis' pattern of every read (runOnOperation).
  llvm::DenseMap<Operation *, AccessPattern> readPatterns;
};

} // namespace
