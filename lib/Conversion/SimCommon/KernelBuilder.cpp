//===- KernelBuilder.cpp - the vocabulary kernels are written in ----------===//
//
// KernelBuilder's index and i64 arithmetic, memory accesses and structured
// control flow over OpBuilder (include/sim/Conversion/SimCommon/
// KernelTarget.h): constants are made once per kernel at its entry.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/SimCommon/KernelTarget.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"

using namespace mlir;
using namespace mlir::sim;

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
Value KernelBuilder::atomic(arith::AtomicRMWKind kind, Value value,
                            Value memref, Value index) {
  return memref::AtomicRMWOp::create(*this, loc, kind, value, memref, index);
}

void KernelBuilder::addAndRunLast(Value count, Value total, Value memref,
                                  Value index, function_ref<void()> body) {
  Value before = atomic(arith::AtomicRMWKind::addi, count, memref, index);
  ifThen(cmp(arith::CmpIPredicate::eq, add(before, count), total), [&] {
    store(i64(0), memref, index);
    body();
  });
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

void KernelTarget::forEachGroupSpan(KernelBuilder &b, Kernel &kernel,
                                    function_ref<void(Value, Value)> body) {
  forEachGroup(b, kernel, [&](Value base) {
    body(base, b.min(b.add(base, groupSize(b, kernel)), kernel.values.range));
  });
}

void KernelTarget::forEachLaneOf(KernelBuilder &b, Kernel &kernel,
                                 const Part &part,
                                 function_ref<void(const Lane &)> body) {
  assert(part.whole && "a target that splits groups runs their parts");
  forEachLane(b, kernel, part.base, body);
}

void KernelTarget::maxPerBlock(KernelBuilder &b, Kernel &kernel, Value base,
                               LaneVar value, int64_t blockSize, Value memory,
                               Value offset, int64_t spreadLow,
                               int64_t spreadHigh, bool) {
  // The items `lane.item - shift` (shift in [spreadLow, spreadHigh]) that
  // lie in the range form one interval, whose blocks are consecutive: one
  // atomic per block it reaches (at most `blocks`), not per shift.
  int64_t blocks = (spreadHigh - spreadLow + blockSize - 1) / blockSize + 1;
  forEachLane(b, kernel, base, [&](const Lane &lane) {
    b.ifThen(lane.active, [&] {
      Value element = laneLoad(b, value, lane);
      Value first = b.max(b.sub(lane.item, b.index(spreadHigh)), b.index(0));
      Value last = b.min(b.sub(lane.item, b.index(spreadLow)),
                         b.sub(kernel.values.range, b.index(1)));
      b.ifThen(b.cmp(arith::CmpIPredicate::sle, first, last), [&] {
        Value firstBlock =
            arith::DivUIOp::create(b, b.loc, first, b.index(blockSize));
        Value lastBlock =
            arith::DivUIOp::create(b, b.loc, last, b.index(blockSize));
        for (int64_t k = 0; k < blocks; ++k) {
          Value block = b.add(firstBlock, b.index(k));
          auto emit = [&] {
            b.atomic(arith::AtomicRMWKind::maxs, element, memory,
                     b.add(offset, block));
          };
          // The interval reaches at least one block.
          if (k == 0)
            emit();
          else
            b.ifThen(b.cmp(arith::CmpIPredicate::ule, block, lastBlock), emit);
        }
      });
    });
  });
}

Value KernelBuilder::floorPowerOfTwo(Value value) {
  // Smear the highest set bit into every lower one, then keep it alone.
  for (int64_t shift : {1, 2, 4, 8, 16, 32})
    value = arith::OrIOp::create(
        *this, loc, value,
        arith::ShRUIOp::create(*this, loc, value,
                               constant(value.getType(), shift)));
  return sub(value, arith::ShRUIOp::create(*this, loc, value,
                                           constant(value.getType(), 1)));
}
