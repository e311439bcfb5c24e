//===- NarrowLoopCounters.cpp - 32-bit counters for scf.for loops ---------===//
//
// A GPU adds and compares 64-bit integers in two instructions each, so a loop
// that counts in `index` (64 bits in the kernels) pays twice for its counter
// in every iteration. A scene's own loops are bounded by 32-bit values, and
// this pass counts them in i32 where no increment can wrap. See the pass
// description in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/Utils/StaticValueUtils.h"
#include "llvm/Support/Debug.h"

#include <limits>

#define DEBUG_TYPE "sim-gpu-narrow-loop-counters"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMGPUNARROWLOOPCOUNTERS
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

constexpr int64_t kInt32Min = std::numeric_limits<int32_t>::min();
constexpr int64_t kInt32Max = std::numeric_limits<int32_t>::max();

/// The values an `index` loop bound can take, when it is made from a value
/// of at most 32 bits.
struct NarrowBound {
  int64_t min, max;
};

/// `bound`'s range when it is a 32-bit constant or an index cast of an
/// integer that fits in i32 (signed: at most 32 bits; unsigned: at most 31).
std::optional<NarrowBound> getNarrowBound(Value bound) {
  if (std::optional<int64_t> constant = getConstantIntValue(bound)) {
    if (*constant < kInt32Min || *constant > kInt32Max)
      return std::nullopt;
    return NarrowBound{*constant, *constant};
  }
  if (auto cast = bound.getDefiningOp<arith::IndexCastOp>()) {
    auto type = dyn_cast<IntegerType>(cast.getIn().getType());
    if (!type || type.getWidth() > 32)
      return std::nullopt;
    int64_t half = int64_t(1) << (type.getWidth() - 1);
    return NarrowBound{-half, half - 1};
  }
  if (auto cast = bound.getDefiningOp<arith::IndexCastUIOp>()) {
    auto type = dyn_cast<IntegerType>(cast.getIn().getType());
    if (!type || type.getWidth() > 31)
      return std::nullopt;
    return NarrowBound{0, (int64_t(1) << type.getWidth()) - 1};
  }
  return std::nullopt;
}

/// `bound` (accepted by getNarrowBound) as an i32 value, built before `loop`.
Value buildNarrowBound(OpBuilder &builder, Location loc, Value bound) {
  Type i32 = builder.getI32Type();
  if (std::optional<int64_t> constant = getConstantIntValue(bound))
    return arith::ConstantIntOp::create(builder, loc, i32, *constant);
  if (auto cast = bound.getDefiningOp<arith::IndexCastOp>()) {
    Value in = cast.getIn();
    if (in.getType() == i32)
      return in;
    return arith::ExtSIOp::create(builder, loc, i32, in);
  }
  auto cast = bound.getDefiningOp<arith::IndexCastUIOp>();
  return arith::ExtUIOp::create(builder, loc, i32, cast.getIn());
}

/// Whether `loop` should count in i32: its trip count is not a constant
/// (LLVM unrolls those loops completely, so no counter is left to narrow, and
/// a narrowed counter in their addresses only costs extensions), its bounds
/// and step are narrow, the step is positive, and the last increment (at
/// most the largest upper bound minus one plus the largest step) stays in
/// i32.
bool shouldNarrow(scf::ForOp loop) {
  if (!loop.getInductionVar().getType().isIndex() || loop.getUnsignedCmp())
    return false;
  if (getConstantIntValue(loop.getLowerBound()) &&
      getConstantIntValue(loop.getUpperBound()) &&
      getConstantIntValue(loop.getStep()))
    return false;
  std::optional<NarrowBound> lower = getNarrowBound(loop.getLowerBound());
  std::optional<NarrowBound> upper = getNarrowBound(loop.getUpperBound());
  std::optional<NarrowBound> step = getNarrowBound(loop.getStep());
  return lower && upper && step && step->min >= 1 &&
         upper->max - 1 + step->max <= kInt32Max;
}

void narrow(scf::ForOp loop) {
  OpBuilder builder(loop);
  Location loc = loop.getLoc();
  Value lower = buildNarrowBound(builder, loc, loop.getLowerBound());
  Value upper = buildNarrowBound(builder, loc, loop.getUpperBound());
  Value step = buildNarrowBound(builder, loc, loop.getStep());
  loop.getLowerBoundMutable().assign(lower);
  loop.getUpperBoundMutable().assign(upper);
  loop.getStepMutable().assign(step);

  Value counter = loop.getInductionVar();
  counter.setType(builder.getI32Type());
  if (counter.use_empty())
    return;
  builder.setInsertionPointToStart(loop.getBody());
  Value asIndex =
      arith::IndexCastOp::create(builder, loc, builder.getIndexType(), counter);
  counter.replaceAllUsesExcept(asIndex, asIndex.getDefiningOp());
}

struct NarrowLoopCountersPass
    : public sim::impl::SimGPUNarrowLoopCountersBase<NarrowLoopCountersPass> {
  void runOnOperation() override {
    getOperation()->walk([](scf::ForOp loop) {
      if (!shouldNarrow(loop))
        return;
      LLVM_DEBUG(llvm::dbgs() << "narrow: " << loop.getLoc() << "\n");
      narrow(loop);
    });
  }
};

} // namespace
