//===- InlineConstants.cpp - compute constant buffers where read ----------===//
//
// A `constant` buffer has no writer: its init body is its value at every
// time. Storing it would cost a buffer (two halves under the double-buffer
// model), a copy per big step, an exchange between ranks and an
// interpolation per read, none of which its value needs. So every read of
// it becomes its init body at the item read, after the boundary rule, and
// the buffer goes. The front end runs this pass first, so no later stage,
// lowering or the reference executor ever sees a buffer without a writer.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/IR/IRMapping.h"
#include "mlir/IR/PatternMatch.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMINLINECONSTANTS
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Materialises init bodies at arbitrary items.
class InitMaterializer {
public:
  explicit InitMaterializer(SimulationOp simulation) : simulation(simulation) {
    // Every body's `%i` is an item of the range: a read there needs no
    // boundary rule (the common `@Mass[%i]`).
    for (Operation &op : simulation.getBody().front())
      for (Region &body : op.getRegions())
        if (!body.empty() && body.getNumArguments() > 0 &&
            body.getArgument(0).getType().isIndex())
          inRange.insert(body.getArgument(0));
  }

  /// Replaces `read` (of any buffer) with `buffer`'s init at the item it
  /// reads and erases it.
  void replaceWithInit(RewriterBase &rewriter, ReadOp read) {
    BufferOp buffer = simulation.lookupBuffer(read.getBufferAttr());
    rewriter.setInsertionPoint(read);
    rewriter.replaceOp(
        read, materialize(rewriter, buffer, read.getIndex(), read.getLoc()));
  }

private:
  /// `buffer`'s init at item `index`, as the boundary rule reads it: the
  /// body is evaluated at an item inside the range (for `zero` too, so that
  /// it never sees an index it was not written for), and `zero` then
  /// selects a zero element outside it.
  Value materialize(RewriterBase &rewriter, BufferOp buffer, Value index,
                    Location loc) {
    // An item that a copied init body reads at its own (mapped) item is
    // inside the range already.
    if (inRange.contains(index))
      return copyInit(rewriter, buffer, index);
    Type i64 = rewriter.getI64Type();
    auto constant = [&](int64_t value) -> Value {
      return arith::ConstantIntOp::create(rewriter, loc, i64, value);
    };
    Value range = GetParamOp::create(
        rewriter, loc, i64,
        FlatSymbolRefAttr::get(rewriter.getContext(), "range"));
    Value item = arith::IndexCastOp::create(rewriter, loc, i64, index);
    Value inside;
    Value mapped;
    if (buffer.getBoundary() == Boundary::wrap) {
      // The item modulo range, in [0, range).
      Value rem = arith::RemSIOp::create(rewriter, loc, item, range);
      Value negative = arith::CmpIOp::create(
          rewriter, loc, arith::CmpIPredicate::slt, rem, constant(0));
      Value shifted = arith::AddIOp::create(rewriter, loc, rem, range);
      mapped = arith::SelectOp::create(rewriter, loc, negative, shifted, rem);
    } else {
      Value last = arith::SubIOp::create(rewriter, loc, range, constant(1));
      Value low = arith::MaxSIOp::create(rewriter, loc, item, constant(0));
      mapped = arith::MinSIOp::create(rewriter, loc, low, last);
      if (buffer.getBoundary() == Boundary::zero)
        inside = arith::CmpIOp::create(rewriter, loc, arith::CmpIPredicate::eq,
                                       item, mapped);
    }
    Value mappedIndex = arith::IndexCastOp::create(
        rewriter, loc, rewriter.getIndexType(), mapped);
    Value value = copyInit(rewriter, buffer, mappedIndex);
    if (!inside)
      return value;
    Value zero = arith::ConstantOp::create(
        rewriter, loc, cast<TypedAttr>(rewriter.getZeroAttr(value.getType())));
    return arith::SelectOp::create(rewriter, loc, inside, value, zero);
  }

  /// `buffer`'s init body copied at `item`, an item inside the range.
  Value copyInit(RewriterBase &rewriter, BufferOp buffer, Value item) {
    inRange.insert(item);

    // Clone the init body's operations after the mapping; reads among them
    // are reads of initial states, materialised in turn (init bodies read
    // each other without a cycle, so this ends).
    Block &init = buffer.getInit().front();
    IRMapping mapping;
    mapping.map(buffer.getInitItem(), item);
    SmallVector<ReadOp> reads;
    for (Operation &op : init.without_terminator()) {
      Operation *copy = rewriter.clone(op, mapping);
      copy->walk([&](ReadOp read) { reads.push_back(read); });
    }
    Value value =
        mapping.lookup(cast<YieldOp>(init.getTerminator()).getValues()[0]);
    {
      OpBuilder::InsertionGuard guard(rewriter);
      for (ReadOp read : reads) {
        BufferOp source = simulation.lookupBuffer(read.getBufferAttr());
        rewriter.setInsertionPoint(read);
        Value initial =
            materialize(rewriter, source, read.getIndex(), read.getLoc());
        if (value == read.getResult())
          value = initial;
        rewriter.replaceOp(read, initial);
      }
    }
    return value;
  }

  SimulationOp simulation;
  /// Index values known to lie in [0, range): the bodies' items and the
  /// items init bodies were copied at.
  llvm::DenseSet<Value> inRange;
};

struct SimInlineConstantsPass
    : public sim::impl::SimInlineConstantsBase<SimInlineConstantsPass> {
  void runOnOperation() override {
    SimulationOp simulation = getOperation();
    SmallVector<BufferOp> constants;
    for (BufferOp buffer : simulation.getBuffers())
      if (buffer.getConstant())
        constants.push_back(buffer);
    if (constants.empty())
      return markAllAnalysesPreserved();

    // The reads to replace: those of a constant buffer anywhere but in the
    // constant buffers' own init bodies, which go with them.
    llvm::SmallPtrSet<Operation *, 8> constantOps(constants.begin(),
                                                  constants.end());
    SmallVector<ReadOp> reads;
    simulation.walk([&](ReadOp read) {
      BufferOp buffer = simulation.lookupBuffer(read.getBufferAttr());
      if (!buffer || !buffer.getConstant())
        return;
      Operation *owner =
          read->getParentWithTrait<OpTrait::IsIsolatedFromAbove>();
      if (!constantOps.contains(owner))
        reads.push_back(read);
    });
    IRRewriter rewriter(&getContext());
    InitMaterializer materializer(simulation);
    for (ReadOp read : reads)
      materializer.replaceWithInit(rewriter, read);
    for (BufferOp buffer : constants)
      rewriter.eraseOp(buffer);
  }
};

} // namespace
