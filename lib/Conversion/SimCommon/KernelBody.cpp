//===- KernelBody.cpp - inlining sim bodies into kernels ------------------===//
//
// Bodies are cloned, not converted op by op: everything but the handful of
// sim ops is plain arith/math/scf/vector code that every backend compiles as
// it is. The sim ops are replaced right after cloning, while it is known
// which kernel values they stand for (a component body is inlined more than
// once per kernel, with different values each time: an estimate reads the
// state at T, a sub-step its registers).
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/SimCommon/KernelBody.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/IR/IRMapping.h"
#include "mlir/IR/TypeUtilities.h"
#include "mlir/Transforms/RegionUtils.h"

using namespace mlir;
using namespace mlir::sim;

Value mlir::sim::buildZeroElement(OpBuilder &builder, Location loc, Type type) {
  return arith::ConstantOp::create(builder, loc, type,
                                   builder.getZeroAttr(type));
}

Value mlir::sim::getElementIndex(OpBuilder &builder, Location loc,
                                 const KernelValues &values, Value item,
                                 StringAttr buffer) {
  if (!values.first || (buffer && values.replicated.contains(buffer)))
    return item;
  Value shifted = arith::SubIOp::create(builder, loc, item, values.first);
  if (values.halo == 0)
    return shifted;
  return arith::AddIOp::create(
      builder, loc, shifted,
      arith::ConstantIndexOp::create(builder, loc, values.halo));
}

Value mlir::sim::getHalfOffset(OpBuilder &builder, Location loc,
                               const KernelValues &values, StringAttr buffer,
                               Value blockBase, Value parity) {
  if (!values.replicated.contains(buffer))
    return blockBase;
  Value index =
      arith::IndexCastOp::create(builder, loc, builder.getIndexType(), parity);
  return arith::MulIOp::create(builder, loc, index, values.range);
}

/// Converts a parameter value to the type a `sim.get_param` asks for (the
/// builtins are passed as i64 and may be read as index or i32).
static Value castParam(OpBuilder &builder, Location loc, Value value,
                       Type type) {
  Type from = value.getType();
  if (from == type)
    return value;
  if (isa<IndexType>(type) || isa<IndexType>(from))
    return arith::IndexCastOp::create(builder, loc, type, value);
  if (isa<IntegerType>(from) && isa<IntegerType>(type)) {
    if (from.getIntOrFloatBitWidth() < type.getIntOrFloatBitWidth())
      return arith::ExtSIOp::create(builder, loc, type, value);
    return arith::TruncIOp::create(builder, loc, type, value);
  }
  if (isa<FloatType>(from) && isa<FloatType>(type)) {
    if (from.getIntOrFloatBitWidth() < type.getIntOrFloatBitWidth())
      return arith::ExtFOp::create(builder, loc, type, value);
    return arith::TruncFOp::create(builder, loc, type, value);
  }
  return nullptr;
}

static FailureOr<SmallVector<Value>>
cloneAndLower(OpBuilder &builder, SimulationOp simulation,
              ArrayRef<Operation *> ops, IRMapping &mapping, ValueRange yielded,
              const KernelValues &values);

namespace {

/// Replaces the sim ops of one cloned body.
class BodyLowering {
public:
  BodyLowering(SimulationOp simulation, const KernelValues &values,
               const llvm::DenseMap<StringAttr, FillCacheOp> &fills)
      : simulation(simulation), values(values), fills(fills) {}

  FailureOr<Value> lower(OpBuilder &builder, Operation *op) {
    Location loc = op->getLoc();
    if (auto param = dyn_cast<GetParamOp>(op)) {
      Value value = values.params.lookup(param.getParam());
      if (!value)
        return op->emitOpError() << "reads a parameter the kernel has no "
                                    "value for";
      Value cast = castParam(builder, loc, value, param.getType());
      if (!cast)
        return op->emitOpError()
               << "cannot convert the parameter's run-time " << value.getType()
               << " to " << param.getType();
      return cast;
    }
    if (auto load = dyn_cast<LoadOp>(op))
      return lowerLoad(builder, load);
    if (auto read = dyn_cast<ReadOp>(op))
      return lowerInitialRead(builder, read);
    return op->emitOpError() << "cannot be lowered here";
  }

private:
  FailureOr<Value> lowerLoad(OpBuilder &builder, LoadOp load) {
    Location loc = load.getLoc();
    StringAttr name = load.getBufferAttr().getAttr();
    BufferOp buffer = simulation.lookupBuffer(load.getBufferAttr());
    Version version = load.getVersion();
    if (version == Version::local)
      if (Value value = values.registers.lookup(name))
        return value;
    if (version == Version::cache)
      return lowerCacheLoad(builder, load);
    bool latestOwn =
        version == Version::local && values.latestOwn.contains(name);
    if (version == Version::local && values.levels && !latestOwn &&
        (values.levelsAtItem || load.getIndex() != values.item))
      return lowerLevelLoad(builder, load, buffer);

    Value memory, base;
    auto halfOf = [&](Value blockBase, Value parity) {
      return blockBase
                 ? getHalfOffset(builder, loc, values, name, blockBase, parity)
                 : Value();
    };
    switch (version) {
    case Version::source:
      memory = values.buffers.lookup(name);
      base = halfOf(values.sourceBase, values.sourceParity);
      break;
    case Version::target:
      memory = values.buffers.lookup(name);
      base = halfOf(values.targetBase, values.targetParity);
      break;
    case Version::local:
      memory = values.buffers.lookup(name);
      base = latestOwn ? halfOf(values.latestBase, values.latestParity)
                       : halfOf(values.localBase, values.localParity);
      break;
    case Version::snapshot:
      memory = values.snapshots.lookup(name);
      break;
    case Version::cache:
      llvm_unreachable("handled above");
    }
    if (!memory || (version != Version::snapshot && !base))
      return load.emitOpError()
             << "reads the " << stringifyVersion(version) << " copy of @"
             << buffer.getSymName() << ", which this kernel does not have";

    Value index = load.getIndex();
    Value inBounds;
    bool replicated = values.replicated.contains(name);
    if (index == values.item)
      index = getElementIndex(builder, loc, values, index, name);
    else if (values.first && !replicated)
      index = lowerGhostIndex(builder, loc, buffer, index, inBounds);
    else
      index = buildBoundaryItem(builder, loc, buffer.getBoundary(), index,
                                values.range, inBounds);
    if (base)
      index = arith::AddIOp::create(builder, loc, base, index);
    Value value = memref::LoadOp::create(builder, loc, memory, index);
    if (inBounds)
      value = arith::SelectOp::create(
          builder, loc, inBounds, value,
          buildZeroElement(builder, loc, value.getType()));
    return value;
  }

  /// A buffer's two halves as a read through the time levels finds them:
  /// its memory, the item's element in a half and the size of a half.
  struct LevelStorage {
    Value memory, item, halfSize;
  };

  /// Local time steps: item `j`'s state at the reader's local time `T +
  /// slot u` (`u` the big step's unit), from the two time levels its block
  /// keeps. The block of sub-step `s` units has taken `c = ceil(slot / s)`
  /// sub-steps, so its latest level is at `b = min(c s u, m)` after `T` (in
  /// the half `source parity xor (c & 1)`; its last sub-step ends with the
  /// big step) and its previous one at `a = (c s - s) u` (the other
  /// half). In step (`b = slot`): the latest
  /// level; a coarser block ahead in time: the buffer's interpolation
  /// between the two at `(slot - a) / (b - a)`. Where lanes
  /// run side by side the item is loaded from both halves and the levels
  /// selected (KernelValues::levelsFromBothHalves).
  FailureOr<Value> lowerLevelLoad(OpBuilder &builder, LoadOp load,
                                  BufferOp buffer) {
    Location loc = load.getLoc();
    StringAttr name = load.getBufferAttr().getAttr();
    Value memory = values.buffers.lookup(name);
    if (!memory)
      return load.emitOpError() << "reads @" << buffer.getSymName()
                                << ", which this kernel does not have";
    Type type = load.getType();
    auto floatType = cast<FloatType>(mlir::getElementTypeOrSelf(type));
    Value inBounds;
    Value item = buildBoundaryItem(builder, loc, buffer.getBoundary(),
                                   load.getIndex(), values.range, inBounds);
    // Where the item is stored: at the item on one process (and for a
    // replicated buffer, whose halves are the range apart); in a
    // distributed plan in the rank's block or its ghost items, found from
    // the index before the boundary rule, as for any other read. An
    // auxiliary buffer of the interpolation (a Hermite derivative, which
    // the same component writes under the same boundary rule:
    // --sim-substep-legality) is stored alike, unless only one of the two
    // is replicated.
    Value ghost;
    auto storageOf = [&](StringAttr stored, Value storage) -> LevelStorage {
      if (values.replicated.contains(stored))
        return {storage, item, values.range};
      if (!values.first)
        return {storage, item, values.extent};
      if (!ghost) {
        Value unused;
        ghost = lowerGhostIndex(builder, loc, buffer, load.getIndex(), unused);
      }
      return {storage, ghost, values.extent};
    };
    LevelStorage own = storageOf(name, memory);
    Value block = arith::DivUIOp::create(
        builder, loc, item,
        arith::ConstantIndexOp::create(builder, loc, kLevelBlock));
    Value element =
        arith::AddIOp::create(builder, loc, values.levelBase, block);
    Value level = memref::LoadOp::create(builder, loc, values.levels, element);
    // Sub-steps are powers of two: `c s` is `slot` rounded up to a
    // multiple of `s`, and `c` is odd when bit `s` of that is set.
    Value one = arith::ConstantIntOp::create(builder, loc, 1, 64);
    Value zero64 = arith::ConstantIntOp::create(builder, loc, 0, 64);
    Value slot = values.levelSlot;
    Value mask = arith::SubIOp::create(builder, loc, level, one);
    Value latestTime = arith::AndIOp::create(
        builder, loc, arith::AddIOp::create(builder, loc, slot, mask),
        arith::XOrIOp::create(
            builder, loc, mask,
            arith::ConstantIntOp::create(builder, loc, -1, 64)));
    Value isOdd = arith::CmpIOp::create(
        builder, loc, arith::CmpIPredicate::ne,
        arith::AndIOp::create(builder, loc, latestTime, level), zero64);
    // One half at the item.
    auto loadHalf = [&](const LevelStorage &at, Value parity) -> Value {
      Value half = arith::MulIOp::create(
          builder, loc,
          arith::IndexCastOp::create(builder, loc, builder.getIndexType(),
                                     parity),
          at.halfSize);
      return memref::LoadOp::create(
          builder, loc, at.memory,
          arith::AddIOp::create(builder, loc, half, at.item).getResult());
    };
    // Where lanes run side by side (levelsFromBothHalves): both halves at
    // the item, at halves that every lane shares, so that consecutive items
    // load as wide loads whatever their blocks' parities, and a select per
    // lane into the latest and the previous level.
    auto selectLevels = [&](const LevelStorage &at) {
      Value sourceHalf = loadHalf(at, values.sourceParity);
      Value otherHalf = loadHalf(
          at, arith::XOrIOp::create(builder, loc, values.sourceParity, one));
      return std::make_pair(
          arith::SelectOp::create(builder, loc, isOdd, otherHalf, sourceHalf)
              .getResult(),
          arith::SelectOp::create(builder, loc, isOdd, sourceHalf, otherHalf)
              .getResult());
    };
    // The latest level, and a way to the previous one: selected from both
    // halves, or one load from the half the block says.
    Value latest, latestParity, previousLevel;
    if (values.levelsFromBothHalves) {
      std::tie(latest, previousLevel) = selectLevels(own);
    } else {
      Value odd =
          arith::ExtUIOp::create(builder, loc, builder.getI64Type(), isOdd);
      latestParity =
          arith::XOrIOp::create(builder, loc, values.sourceParity, odd);
      latest = loadHalf(own, latestParity);
    }
    Value inStep = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::eq,
                                         latestTime, slot);
    auto select = scf::IfOp::create(builder, loc, TypeRange{type}, inStep,
                                    /*withElseRegion=*/true);
    {
      OpBuilder::InsertionGuard guard(builder);
      builder.setInsertionPointToStart(select.thenBlock());
      scf::YieldOp::create(builder, loc, latest);
      builder.setInsertionPointToStart(select.elseBlock());
      auto previousHalf = [&](const LevelStorage &at) {
        return loadHalf(at,
                        arith::XOrIOp::create(builder, loc, latestParity, one));
      };
      Value previous = previousLevel ? previousLevel : previousHalf(own);
      // In base steps from here: the unit times the units.
      Value latestSteps =
          arith::MulIOp::create(builder, loc, latestTime, values.levelUnit);
      Value previousTime = arith::MulIOp::create(
          builder, loc, arith::SubIOp::create(builder, loc, latestTime, level),
          values.levelUnit);
      Value behind = arith::SubIOp::create(
          builder, loc,
          arith::MulIOp::create(builder, loc, slot, values.levelUnit),
          previousTime);
      Value length = arith::SubIOp::create(
          builder, loc,
          arith::MinSIOp::create(builder, loc, latestSteps, values.levelEnd),
          previousTime);
      Value lengthF = arith::SIToFPOp::create(builder, loc, floatType, length);
      Value fraction = arith::DivFOp::create(
          builder, loc,
          arith::SIToFPOp::create(builder, loc, floatType, behind), lengthF);
      Value dt = castParam(builder, loc, values.params.lookup("dt"), floatType);
      Value span = arith::MulFOp::create(builder, loc, lengthF, dt);
      SmallVector<Value> atBegin = {previous}, atEnd = {latest};
      InterpolationAttrInterface interp = buffer.getInterpolation();
      for (FlatSymbolRefAttr aux : interp.getAuxiliaryBuffers()) {
        Value auxMemory = values.buffers.lookup(aux.getAttr());
        if (!auxMemory)
          return load.emitOpError()
                 << "reads @" << buffer.getSymName() << ", whose interpolation "
                 << "reads " << aux << ", which this kernel does not have";
        LevelStorage auxAt = storageOf(aux.getAttr(), auxMemory);
        Value auxLatest, auxPrevious;
        if (values.levelsFromBothHalves) {
          std::tie(auxLatest, auxPrevious) = selectLevels(auxAt);
        } else {
          auxLatest = loadHalf(auxAt, latestParity);
          auxPrevious = previousHalf(auxAt);
        }
        atEnd.push_back(auxLatest);
        atBegin.push_back(auxPrevious);
      }
      Value value = interp.buildInterpolation(builder, loc, atBegin, atEnd,
                                              fraction, span);
      scf::YieldOp::create(builder, loc, value);
    }
    Value value = select.getResult(0);
    if (inBounds)
      value = arith::SelectOp::create(builder, loc, inBounds, value,
                                      buildZeroElement(builder, loc, type));
    return value;
  }

  /// A distributed plan's read of another item: the ghost items hold what
  /// the boundary rule reads outside the rank's block (the exchanges after
  /// each write put it there), so the element is the item's own, clamped
  /// into the rank's storage for the padding lanes of a last group, which
  /// read past the halo and whose values nobody uses. `zero` still returns
  /// zero outside [0, range): ghost items beyond the range hold nothing.
  Value lowerGhostIndex(OpBuilder &builder, Location loc, BufferOp buffer,
                        Value index, Value &inBounds) {
    if (buffer.getBoundary() == Boundary::zero)
      inBounds = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::ult,
                                       index, values.range);
    Value element = getElementIndex(builder, loc, values, index);
    Value zero = arith::ConstantIndexOp::create(builder, loc, 0);
    Value last =
        arith::SubIOp::create(builder, loc, values.extent,
                              arith::ConstantIndexOp::create(builder, loc, 1));
    Value low = arith::MaxSIOp::create(builder, loc, element, zero);
    return arith::MinSIOp::create(builder, loc, low, last);
  }

  /// Inside the group's cached items, the cache; elsewhere (or without a
  /// cache) the value the fill computes, at the read item.
  FailureOr<Value> lowerCacheLoad(OpBuilder &builder, LoadOp load) {
    Location loc = load.getLoc();
    StringAttr name = load.getBufferAttr().getAttr();
    FillCacheOp fill = fills.lookup(name);
    if (!fill)
      return load.emitOpError() << "loads the cache of " << load.getBufferAttr()
                                << ", but the body fills none";
    auto compute = [&]() -> FailureOr<Value> {
      IRMapping mapping;
      Block &block = fill.getBody().front();
      mapping.map(block.getArgument(0), load.getIndex());
      SmallVector<Operation *> ops;
      for (Operation &op : block.without_terminator())
        ops.push_back(&op);
      FailureOr<SmallVector<Value>> results =
          cloneAndLower(builder, simulation, ops, mapping,
                        block.getTerminator()->getOperands(), values);
      if (failed(results))
        return failure();
      return results->front();
    };
    CacheView view = values.caches.lookup(name);
    if (!view.memory)
      return compute();
    Value offset =
        arith::SubIOp::create(builder, loc, load.getIndex(), view.first);
    // A read of the body's own item plus an offset inside the fill's window
    // (in_window, which the analysis proved and checkRecordedDecisions
    // checked) is always cached: the cache holds the group's items from its
    // first plus the window's minimum to its last plus the window's maximum,
    // and the item is one of the group's. It needs no check and no
    // fallback, whose addresses and registers the kernel would otherwise
    // carry.
    if (values.item && load.getInWindow())
      return memref::LoadOp::create(builder, loc, view.memory, offset)
          .getResult();
    Value inside = arith::CmpIOp::create(
        builder, loc, arith::CmpIPredicate::ult, offset, view.size);
    auto branch = scf::IfOp::create(builder, loc, load.getType(), inside,
                                    /*withElseRegion=*/true);
    OpBuilder::InsertionGuard guard(builder);
    builder.setInsertionPointToStart(&branch.getThenRegion().front());
    scf::YieldOp::create(
        builder, loc,
        ValueRange{memref::LoadOp::create(builder, loc, view.memory, offset)});
    builder.setInsertionPointToStart(&branch.getElseRegion().front());
    FailureOr<Value> computed = compute();
    if (failed(computed))
      return failure();
    scf::YieldOp::create(builder, loc, ValueRange{*computed});
    return branch.getResult(0);
  }

  /// A read in an init or exact body sees the initial state: the read
  /// buffer's init body at the read item. Init bodies are pure functions of
  /// the item (the verifier rejects cycles between them), so recomputing it
  /// needs neither a copy of the initial state nor an order of init kernels.
  FailureOr<Value> lowerInitialRead(OpBuilder &builder, ReadOp read) {
    Location loc = read.getLoc();
    BufferOp buffer = simulation.lookupBuffer(read.getBufferAttr());
    if (read.getRoleAttr())
      return read.emitOpError()
             << "is a view read of a component; run --sim-insert-interpolation "
                "before lowering";
    Value inBounds;
    Value index = read.getIndex();
    if (index != values.item)
      index = buildBoundaryItem(builder, loc, buffer.getBoundary(), index,
                                values.range, inBounds);
    KernelValues initValues;
    initValues.range = values.range;
    initValues.extent = values.extent;
    initValues.replicated = values.replicated;
    initValues.params = values.params;
    initValues.item = index;
    FailureOr<SmallVector<Value>> results =
        inlineBody(builder, simulation, buffer.getInit(), {index}, initValues);
    if (failed(results))
      return failure();
    Value value = results->front();
    if (inBounds)
      value = arith::SelectOp::create(
          builder, loc, inBounds, value,
          buildZeroElement(builder, loc, value.getType()));
    return value;
  }

  SimulationOp simulation;
  const KernelValues &values;
  const llvm::DenseMap<StringAttr, FillCacheOp> &fills;
};

} // namespace

/// Clones `ops` (in order) with `mapping`, then replaces the sim ops in the
/// clones. A `sim.fill_cache` stays as it is (its region is lowered where a
/// cache load or fill clones it) and is erased at the end.
static FailureOr<SmallVector<Value>>
cloneAndLower(OpBuilder &builder, SimulationOp simulation,
              ArrayRef<Operation *> ops, IRMapping &mapping, ValueRange yielded,
              const KernelValues &values) {
  SmallVector<Operation *> simOps;
  llvm::DenseMap<StringAttr, FillCacheOp> fills;
  for (Operation *op : ops) {
    Operation *clone = builder.clone(*op, mapping);
    clone->walk<WalkOrder::PreOrder>([&](Operation *nested) {
      if (auto fill = dyn_cast<FillCacheOp>(nested)) {
        fills[fill.getBufferAttr().getAttr()] = fill;
        return WalkResult::skip();
      }
      if (isa<SimDialect>(nested->getDialect()))
        simOps.push_back(nested);
      return WalkResult::advance();
    });
  }
  SmallVector<Value> results;
  for (Value value : yielded)
    results.push_back(mapping.lookupOrDefault(value));

  BodyLowering lowering(simulation, values, fills);
  for (Operation *op : simOps) {
    OpBuilder::InsertionGuard guard(builder);
    builder.setInsertionPoint(op);
    SmallVector<Value> replacements;
    if (auto bigStep = dyn_cast<BigStepOp>(op)) {
      if (!values.bigStepBegin)
        return op->emitOpError()
               << "asks for the big step in a body that runs before the big "
                  "step is decided";
      replacements = {values.bigStepBegin, values.bigStepSize};
    } else {
      FailureOr<Value> value = lowering.lower(builder, op);
      if (failed(value))
        return failure();
      replacements = {*value};
    }
    for (auto [result, replacement] :
         llvm::zip_equal(op->getResults(), replacements)) {
      result.replaceAllUsesWith(replacement);
      for (Value &value : results)
        if (value == result)
          value = replacement;
    }
    op->erase();
  }
  for (auto &entry : fills)
    entry.second->erase();
  return results;
}

FailureOr<SmallVector<Value>>
mlir::sim::inlineBody(OpBuilder &builder, SimulationOp simulation, Region &body,
                      ValueRange arguments, const KernelValues &values) {
  if (!body.hasOneBlock())
    return emitError(body.getLoc()) << "a body with more than one block "
                                       "cannot be lowered";
  Block &block = body.front();
  IRMapping mapping;
  mapping.map(block.getArguments(), arguments);
  SmallVector<Operation *> ops;
  for (Operation &op : block.without_terminator())
    ops.push_back(&op);
  return cloneAndLower(builder, simulation, ops, mapping,
                       block.getTerminator()->getOperands(), values);
}

FailureOr<Value> mlir::sim::inlineCacheFill(OpBuilder &builder,
                                            SimulationOp simulation,
                                            Region &body, ValueRange arguments,
                                            FlatSymbolRefAttr buffer,
                                            Value index,
                                            const KernelValues &values) {
  Block &block = body.front();
  FillCacheOp fill;
  for (auto candidate : block.getOps<FillCacheOp>())
    if (candidate.getBufferAttr() == buffer)
      fill = candidate;
  if (!fill)
    return emitError(body.getLoc()) << "the body fills no cache of " << buffer;

  // The body's ops the fill depends on (its time values), in body order.
  llvm::SetVector<Value> captured;
  getUsedValuesDefinedAbove(fill.getBody(), captured);
  llvm::SmallPtrSet<Operation *, 16> needed;
  SmallVector<Value> worklist(captured.begin(), captured.end());
  while (!worklist.empty()) {
    Operation *def = worklist.pop_back_val().getDefiningOp();
    if (!def || def->getBlock() != &block || !needed.insert(def).second)
      continue;
    def->walk([&](Operation *nested) {
      llvm::append_range(worklist, nested->getOperands());
    });
  }
  SmallVector<Operation *> ops;
  for (Operation &op : block)
    if (needed.contains(&op))
      ops.push_back(&op);
  Block &fillBlock = fill.getBody().front();
  for (Operation &op : fillBlock.without_terminator())
    ops.push_back(&op);

  IRMapping mapping;
  mapping.map(block.getArguments(), arguments);
  mapping.map(fillBlock.getArgument(0), index);
  FailureOr<SmallVector<Value>> results =
      cloneAndLower(builder, simulation, ops, mapping,
                    fillBlock.getTerminator()->getOperands(), values);
  if (failed(results))
    return failure();
  return results->front();
}
