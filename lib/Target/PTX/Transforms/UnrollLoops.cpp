//===- UnrollLoops.cpp - unroll the kernels' innermost loops --------------===//
//
// LLVM's NVPTX back end leaves a loop of unknown trip count rolled when its
// body is large, so the load loop of a scene pays its counter, compare and
// branch every round; nvcc unrolls the same loop of a hand-written kernel.
// The pass unrolls such loops itself, computing the trip count in 64 bits so
// that a 32-bit counter cannot wrap (upstream's loopUnrollByFactor computes it
// in the counter's type). See the pass description in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/Utils/StaticValueUtils.h"
#include "mlir/IR/IRMapping.h"
#include "mlir/Interfaces/LoopLikeInterface.h"
#include "llvm/Support/Debug.h"

#include <limits>

#define DEBUG_TYPE "sim-gpu-unroll-loops"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMGPUUNROLLLOOPS
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Whether `loop` is one to unroll by `factor`: innermost, counting up by a
/// constant step that `factor` copies still fit in the counter's type, with
/// a trip count that is not a constant.
bool shouldUnroll(scf::ForOp loop, unsigned factor) {
  if (loop.getUnsignedCmp())
    return false;
  std::optional<int64_t> step = getConstantIntValue(loop.getStep());
  if (!step || *step < 1)
    return false;
  Type counterType = loop.getInductionVar().getType();
  unsigned width =
      counterType.isIndex() ? 64 : cast<IntegerType>(counterType).getWidth();
  if (width < 2 || width > 64)
    return false;
  int64_t largest = width == 64 ? std::numeric_limits<int64_t>::max()
                                : (int64_t(1) << (width - 1)) - 1;
  if (*step > largest / factor)
    return false;
  if (getConstantIntValue(loop.getLowerBound()) &&
      getConstantIntValue(loop.getUpperBound()))
    return false;
  bool innermost = true;
  loop.getBody()->walk([&](LoopLikeOpInterface) { innermost = false; });
  return innermost;
}

/// Splits `loop` into a main loop of `factor` bodies per iteration over the
/// largest multiple of `factor` iterations, and `loop` itself for the rest.
void unroll(scf::ForOp loop, unsigned factor) {
  OpBuilder builder(loop);
  Location loc = loop.getLoc();
  Type counterType = loop.getInductionVar().getType();
  int64_t step = *getConstantIntValue(loop.getStep());

  // The trip count, in 64 bits (index for an index counter).
  Type wideType = counterType.isIndex() ? counterType : builder.getI64Type();
  auto widen = [&](Value value) -> Value {
    if (value.getType() == wideType)
      return value;
    return arith::ExtSIOp::create(builder, loc, wideType, value);
  };
  auto constant = [&](Type type, int64_t value) -> Value {
    if (type.isIndex())
      return arith::ConstantIndexOp::create(builder, loc, value);
    return arith::ConstantIntOp::create(builder, loc, type, value);
  };
  Value lower = widen(loop.getLowerBound());
  Value upper = widen(loop.getUpperBound());
  Value trips = arith::SubIOp::create(builder, loc, upper, lower);
  if (step > 1)
    trips = arith::DivSIOp::create(
        builder, loc,
        arith::AddIOp::create(builder, loc, trips,
                              constant(wideType, step - 1)),
        constant(wideType, step));
  Value remainder =
      arith::RemSIOp::create(builder, loc, trips, constant(wideType, factor));
  Value mainSpan = arith::SubIOp::create(builder, loc, trips, remainder);
  if (step > 1)
    mainSpan =
        arith::MulIOp::create(builder, loc, mainSpan, constant(wideType, step));
  Value mainEnd = arith::AddIOp::create(builder, loc, lower, mainSpan);
  // No iterations (an empty or reversed range): the main loop ends where it
  // starts, so its end stays between the bounds and fits the counter.
  Value any = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::sgt,
                                    trips, constant(wideType, 0));
  mainEnd = arith::SelectOp::create(builder, loc, any, mainEnd, lower);
  if (mainEnd.getType() != counterType)
    mainEnd = arith::TruncIOp::create(builder, loc, counterType, mainEnd);

  Block *body = loop.getBody();
  auto main = scf::ForOp::create(
      builder, loc, loop.getLowerBound(), mainEnd,
      constant(counterType, step * factor), loop.getInitArgs(),
      [&](OpBuilder &nested, Location nestedLoc, Value counter,
          ValueRange iterArgs) {
        SmallVector<Value> carried(iterArgs);
        for (unsigned copy = 0; copy < factor; ++copy) {
          IRMapping mapping;
          Value copyCounter = counter;
          if (copy > 0) {
            // counter + copy * step < mainEnd: no wrap.
            Value offset =
                counterType.isIndex()
                    ? Value(arith::ConstantIndexOp::create(nested, nestedLoc,
                                                           copy * step))
                    : Value(arith::ConstantIntOp::create(
                          nested, nestedLoc, counterType, copy * step));
            copyCounter =
                arith::AddIOp::create(nested, nestedLoc, counter, offset);
          }
          mapping.map(loop.getInductionVar(), copyCounter);
          mapping.map(loop.getRegionIterArgs(), carried);
          for (Operation &op : body->without_terminator())
            nested.clone(op, mapping);
          carried.clear();
          for (Value yielded : body->getTerminator()->getOperands())
            carried.push_back(mapping.lookupOrDefault(yielded));
        }
        scf::YieldOp::create(nested, nestedLoc, carried);
      });

  // The original loop takes what is left, from where the main loop ended.
  loop.getLowerBoundMutable().assign(mainEnd);
  loop.getInitArgsMutable().assign(main.getResults());
}

/// The most copies of a body the pass makes.
constexpr unsigned kMaxFactor = 32;

struct UnrollLoopsPass
    : public sim::impl::SimGPUUnrollLoopsBase<UnrollLoopsPass> {
  using Base::Base;

  void runOnOperation() override {
    // Each copy of a load loop's body is tens of instructions, and LLVM's
    // and ptxas's time grows with the copies: 256 took a minute and 3 MB of
    // PTX, 1000 did not finish. nvcc unrolls such a loop by 2 to 4.
    if (factor == 0 || factor > kMaxFactor) {
      // A file's top module has no location of its own ("file:0:0"): at its
      // first operation then.
      Operation *at = getOperation();
      if (auto module = dyn_cast<ModuleOp>(at);
          module && !module.getBody()->empty())
        at = &module.getBody()->front();
      at->emitError() << "sim-gpu-unroll-loops: the factor must be from 1 to "
                      << kMaxFactor << ", not "
                      << static_cast<unsigned>(factor);
      return signalPassFailure();
    }
    if (factor <= 1)
      return;
    SmallVector<scf::ForOp> loops;
    getOperation()->walk([&](scf::ForOp loop) {
      if (shouldUnroll(loop, factor))
        loops.push_back(loop);
    });
    for (scf::ForOp loop : loops) {
      LLVM_DEBUG(llvm::dbgs() << "unroll: " << loop.getLoc() << "\n");
      unroll(loop, factor);
    }
  }
};

} // namespace
