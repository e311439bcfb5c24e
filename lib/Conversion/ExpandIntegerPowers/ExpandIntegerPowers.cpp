//===- ExpandIntegerPowers.cpp - math.ipowi in multiplications ------------===//
//
// Neither the LLVM dialect conversions nor libm nor libdevice lower
// `math.ipowi`, so a component that raises an integer to an integer power
// (Python's `n ** k`) compiled for no backend. This pass writes it out in
// `arith` ops: exponentiation by squaring over every bit of the exponent,
// unrolled, each bit's product selected in or not, so that it is straight
// line code that the CPU lanes widen and the GPU runs without a branch.
// Every backend and the reference functions run the same expansion, so they
// agree bit for bit. Multiplications wrap as `arith.muli` does; a negative
// exponent gives 1 / base^-p in integers: 1 for base 1, +-1 for base -1 and
// 0 otherwise (0 also for base 0, where C would divide by zero).
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/IR/PatternMatch.h"
#include "mlir/Transforms/WalkPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMEXPANDINTEGERPOWERS
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

struct ExpandIntegerPower : OpRewritePattern<math::IPowIOp> {
  using OpRewritePattern::OpRewritePattern;

  LogicalResult matchAndRewrite(math::IPowIOp op,
                                PatternRewriter &rewriter) const override {
    Location loc = op.getLoc();
    Type type = op.getType();
    unsigned bits = getElementTypeOrSelf(type).getIntOrFloatBitWidth();
    auto constant = [&](int64_t value) -> Value {
      Type element = getElementTypeOrSelf(type);
      TypedAttr attr = rewriter.getIntegerAttr(element, value);
      if (auto shaped = dyn_cast<ShapedType>(type))
        attr = SplatElementsAttr::get(shaped, attr);
      return arith::ConstantOp::create(rewriter, loc, type, attr);
    };
    Value one = constant(1), zero = constant(0);
    Value base = op.getLhs(), exponent = op.getRhs();
    // base^p for p >= 0: the bits of p from the lowest, base squared each.
    Value result = one, square = base;
    for (unsigned bit = 0; bit < bits; ++bit) {
      Value shifted = arith::ShRUIOp::create(rewriter, loc, exponent,
                                             constant(int64_t(bit)));
      Value set = arith::CmpIOp::create(
          rewriter, loc, arith::CmpIPredicate::ne,
          arith::AndIOp::create(rewriter, loc, shifted, one), zero);
      Value product = arith::MulIOp::create(rewriter, loc, result, square);
      result = arith::SelectOp::create(rewriter, loc, set, product, result);
      if (bit + 1 < bits)
        square = arith::MulIOp::create(rewriter, loc, square, square);
    }
    if (bits == 1) {
      // i1: 0^0 = 1, 1^1 = 1 and 0^1 = 0 (the exponent's one bit is -1).
      rewriter.replaceOp(op, result);
      return success();
    }
    // p < 0: 1 for base 1, +-1 for base -1 (odd p: -1), else 0.
    Value negative = arith::CmpIOp::create(
        rewriter, loc, arith::CmpIPredicate::slt, exponent, zero);
    Value odd = arith::CmpIOp::create(
        rewriter, loc, arith::CmpIPredicate::ne,
        arith::AndIOp::create(rewriter, loc, exponent, one), zero);
    Value minusOne = constant(-1);
    Value baseIsOne = arith::CmpIOp::create(
        rewriter, loc, arith::CmpIPredicate::eq, base, one);
    Value baseIsMinusOne = arith::CmpIOp::create(
        rewriter, loc, arith::CmpIPredicate::eq, base, minusOne);
    Value signed1 = arith::SelectOp::create(rewriter, loc, odd, minusOne, one);
    Value inverse = arith::SelectOp::create(
        rewriter, loc, baseIsOne, one,
        arith::SelectOp::create(rewriter, loc, baseIsMinusOne, signed1, zero));
    rewriter.replaceOp(
        op, arith::SelectOp::create(rewriter, loc, negative, inverse, result));
    return success();
  }
};

struct SimExpandIntegerPowersPass
    : sim::impl::SimExpandIntegerPowersBase<SimExpandIntegerPowersPass> {
  void runOnOperation() override {
    RewritePatternSet patterns(&getContext());
    patterns.add<ExpandIntegerPower>(&getContext());
    walkAndApplyPatterns(getOperation(), std::move(patterns));
  }
};

} // namespace
