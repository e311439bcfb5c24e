//===- ExpandTanh.cpp - f32 tanh as glibc computes it, in arithmetic ------===//
//
// On the CPU a math.tanh on f32 becomes a call of libm's tanhf per element:
// about 33 cycles each, between which every live SIMD register is spilled,
// and in the paper scenes three quarters of the time. glibc's tanhf (up to
// at least 2.36, Debian 12) is fdlibm's: tanh from expm1f, both plain f32
// arithmetic and bit manipulation. This pass writes that algorithm out in
// arith ops, every path computed and the right one selected per element, so
// a vector of lanes computes it in SIMD instructions and every element gets
// exactly the bits glibc's tanhf returns (checked on all 2^32 inputs; see
// docs/Reference.md). f64 and other math ops are left to libm.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/IR/PatternMatch.h"
#include "mlir/Transforms/WalkPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMEXPANDTANH
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

/// Builds f32 (or vector of f32) arithmetic and its i32 twin in one shape.
class Builder {
public:
  Builder(PatternRewriter &rewriter, Location loc, Type floatType)
      : b(rewriter), loc(loc), floatType(floatType) {
    Type i32 = b.getI32Type();
    if (auto vector = dyn_cast<VectorType>(floatType))
      intType = vector.clone(i32);
    else
      intType = i32;
  }

  Value f(float value) { return splat(floatType, b.getF32FloatAttr(value)); }
  Value bitsF(uint32_t bits) { return f(llvm::bit_cast<float>(bits)); }
  Value i(int32_t value) { return splat(intType, b.getI32IntegerAttr(value)); }
  Value add(Value x, Value y) { return arith::AddFOp::create(b, loc, x, y); }
  Value sub(Value x, Value y) { return arith::SubFOp::create(b, loc, x, y); }
  Value mul(Value x, Value y) { return arith::MulFOp::create(b, loc, x, y); }
  Value div(Value x, Value y) { return arith::DivFOp::create(b, loc, x, y); }
  Value neg(Value x) { return arith::NegFOp::create(b, loc, x); }
  Value addi(Value x, Value y) { return arith::AddIOp::create(b, loc, x, y); }
  Value subi(Value x, Value y) { return arith::SubIOp::create(b, loc, x, y); }
  Value andi(Value x, Value y) { return arith::AndIOp::create(b, loc, x, y); }
  Value ori(Value x, Value y) { return arith::OrIOp::create(b, loc, x, y); }
  Value shl(Value x, Value y) { return arith::ShLIOp::create(b, loc, x, y); }
  Value shr(Value x, Value y) { return arith::ShRUIOp::create(b, loc, x, y); }
  Value minsi(Value x, Value y) { return arith::MinSIOp::create(b, loc, x, y); }
  Value maxsi(Value x, Value y) { return arith::MaxSIOp::create(b, loc, x, y); }
  Value cmp(arith::CmpIPredicate predicate, Value x, Value y) {
    return arith::CmpIOp::create(b, loc, predicate, x, y);
  }
  Value select(Value c, Value x, Value y) {
    return arith::SelectOp::create(b, loc, c, x, y);
  }
  Value bits(Value x) { return arith::BitcastOp::create(b, loc, intType, x); }
  Value fromBits(Value x) {
    return arith::BitcastOp::create(b, loc, floatType, x);
  }
  Value toInt(Value x) { return arith::FPToSIOp::create(b, loc, intType, x); }
  Value toFloat(Value x) {
    return arith::SIToFPOp::create(b, loc, floatType, x);
  }

private:
  Value splat(Type type, TypedAttr scalar) {
    if (auto shaped = dyn_cast<ShapedType>(type))
      return arith::ConstantOp::create(
          b, loc, type, DenseElementsAttr::get(shaped, Attribute(scalar)));
    return arith::ConstantOp::create(b, loc, type, scalar);
  }

  PatternRewriter &b;
  Location loc;
  Type floatType, intType;
};

/// math.tanh on f32 as glibc's __tanhf and the __expm1f it calls, every
/// branch evaluated and selected. Each line names the fdlibm statement it
/// computes; the operations and their order are fdlibm's, so the rounding
/// is too.
struct ExpandTanh : OpRewritePattern<math::TanhOp> {
  using OpRewritePattern::OpRewritePattern;

  LogicalResult matchAndRewrite(math::TanhOp op,
                                PatternRewriter &rewriter) const override {
    Type type = op.getType();
    if (!getElementTypeOrSelf(type).isF32())
      return rewriter.notifyMatchFailure(op, "not f32");
    using P = arith::CmpIPredicate;
    Builder b(rewriter, op.getLoc(), type);
    Value x = op.getOperand();
    Value jx = b.bits(x);
    Value ix = b.andi(jx, b.i(0x7fffffff));
    Value ax = b.fromBits(ix);
    // Lanes whose result does not come from expm1f (|x| >= 22, inf, NaN)
    // feed it 1 instead, so that no conversion below leaves i32's range.
    Value finiteSmall = b.cmp(P::ult, ix, b.i(0x41b00000));
    Value axe = b.select(finiteSmall, ax, b.f(1.0f));
    // |x| >= 1: t = expm1f(two*fabsf(x)); else t = expm1f(-two*fabsf(x)).
    Value big = b.cmp(P::uge, ix, b.i(0x3f800000));
    Value u = b.select(big, b.mul(b.f(2.0f), axe), b.mul(b.f(-2.0f), axe));

    // __expm1f(u) for u in [2, 44) or (-2, -2^-54]: the paths it can take.
    Value hu = b.andi(b.bits(u), b.i(0x7fffffff));
    Value negative = b.cmp(P::slt, b.bits(u), b.i(0));
    // Argument reduction. |u| < 1.5 ln2 (u < 0 here): hi = x + ln2_hi,
    // lo = -ln2_lo, k = -1.
    Value ln2Hi = b.bitsF(0x3f317180), ln2Lo = b.bitsF(0x3717f7d1);
    Value near = b.cmp(P::ult, hu, b.i(0x3F851592));
    // Else k = invln2*x + (xsb==0 ? 0.5 : -0.5); t = k; hi = x - t*ln2_hi;
    // lo = t*ln2_lo.
    Value half = b.select(negative, b.f(-0.5f), b.f(0.5f));
    Value kFar = b.toInt(b.add(b.mul(b.bitsF(0x3fb8aa3b), u), half));
    Value tFar = b.toFloat(kFar);
    Value hi = b.select(near, b.add(u, ln2Hi), b.sub(u, b.mul(tFar, ln2Hi)));
    Value lo = b.select(near, b.neg(ln2Lo), b.mul(tFar, ln2Lo));
    Value reduced = b.sub(hi, lo);           // x = hi - lo
    Value c = b.sub(b.sub(hi, reduced), lo); // c = (hi - x) - lo
    // |u| > 0.5 ln2 reduces; else k = 0.
    Value reduce = b.cmp(P::ugt, hu, b.i(0x3eb17218));
    Value k = b.select(reduce, b.select(near, b.i(-1), kFar), b.i(0));
    Value xr = b.select(reduce, reduced, u);
    // x is now in primary range.
    Value hfx = b.mul(b.f(0.5f), xr);
    Value hxs = b.mul(xr, hfx);
    Value r1 = b.add(
        b.f(1.0f),
        b.mul(
            hxs,
            b.add(
                b.bitsF(0xbd088889),
                b.mul(
                    hxs,
                    b.add(
                        b.bitsF(0x3ad00d01),
                        b.mul(hxs,
                              b.add(b.bitsF(0xb8a670cd),
                                    b.mul(hxs,
                                          b.add(b.bitsF(0x36867e54),
                                                b.mul(hxs,
                                                      b.bitsF(
                                                          0xb457edbb)))))))))));
    Value t = b.sub(b.f(3.0f), b.mul(r1, hfx));
    Value e = b.mul(hxs, b.div(b.sub(r1, t), b.sub(b.f(6.0f), b.mul(xr, t))));
    // k == 0: return x - (x*e - hxs).
    Value whenZero = b.sub(xr, b.sub(b.mul(xr, e), hxs));
    // e = (x*(e-c)-c); e -= hxs.
    Value ek = b.sub(b.sub(b.mul(xr, b.sub(e, c)), c), hxs);
    // k == -1: return 0.5*(x-e)-0.5.
    Value whenMinusOne = b.sub(b.mul(b.f(0.5f), b.sub(xr, ek)), b.f(0.5f));
    Value exponent = b.shl(k, b.i(23));
    // k <= -2 || k > 56: y = one-(e-x); add k to y's exponent; y - one.
    Value yFar = b.sub(b.f(1.0f), b.sub(ek, xr));
    Value whenFar =
        b.sub(b.fromBits(b.addi(b.bits(yFar), exponent)), b.f(1.0f));
    // k < 23: t = 1-2^-k (0x3f800000 - (0x1000000>>k)); y = t-(e-x); add k.
    Value kShift = b.minsi(b.maxsi(k, b.i(1)), b.i(30));
    Value tLow =
        b.fromBits(b.subi(b.i(0x3f800000), b.shr(b.i(0x1000000), kShift)));
    Value yLow = b.sub(tLow, b.sub(ek, xr));
    Value whenLow = b.fromBits(b.addi(b.bits(yLow), exponent));
    // Else: t = 2^-k ((0x7f-k)<<23); y = x-(e+t); y += one; add k.
    Value kBias = b.minsi(b.maxsi(k, b.i(0)), b.i(126));
    Value tHigh = b.fromBits(b.shl(b.subi(b.i(0x7f), kBias), b.i(23)));
    Value yHigh = b.add(b.sub(xr, b.add(ek, tHigh)), b.f(1.0f));
    Value whenHigh = b.fromBits(b.addi(b.bits(yHigh), exponent));
    Value far = b.ori(b.cmp(P::sle, k, b.i(-2)), b.cmp(P::sgt, k, b.i(56)));
    Value result = b.select(b.cmp(P::slt, k, b.i(23)), whenLow, whenHigh);
    result = b.select(far, whenFar, result);
    result = b.select(b.cmp(P::eq, k, b.i(-1)), whenMinusOne, result);
    result = b.select(b.cmp(P::eq, k, b.i(0)), whenZero, result);
    // |u| < 2^-25: return x (x - ((huge+x) - (huge+x)) is x).
    Value expm1 = b.select(b.cmp(P::ult, hu, b.i(0x33000000)), u, result);

    // Back in __tanhf. |x| >= 1: z = one - two/(t+two); else z = -t/(t+two).
    // Both paths divide by t+two: the numerator is selected first, so each
    // lane pays one division and gets the quotient its own path computes.
    Value quotient =
        b.div(b.select(big, b.f(2.0f), b.neg(expm1)), b.add(expm1, b.f(2.0f)));
    Value z = b.select(big, b.sub(b.f(1.0f), quotient), quotient);
    // |x| >= 22: z = one - tiny.
    z = b.select(finiteSmall, z, b.sub(b.f(1.0f), b.f(1.0e-30f)));
    // return (jx>=0) ? z : -z.
    Value r = b.select(b.cmp(P::sge, jx, b.i(0)), z, b.neg(z));
    // |x| < 2^-55: x*(one+x); x == +-0: x.
    r = b.select(b.cmp(P::ult, ix, b.i(0x24000000)),
                 b.mul(x, b.add(b.f(1.0f), x)), r);
    r = b.select(b.cmp(P::eq, ix, b.i(0)), x, r);
    // inf or NaN: one/x + one (x >= 0), one/x - one (x < 0). For +-inf that
    // is +-1, which the path above already gives (one - tiny rounds to one),
    // so only NaN is left, and x + x returns it as one/x +- one does (the NaN
    // operand, quieted): no division for a case that is not a value.
    Value isNan = b.cmp(P::ugt, ix, b.i(0x7f800000));
    Value nan = b.add(x, x);
    r = b.select(isNan, nan, r);
    rewriter.replaceOp(op, r);
    return success();
  }
};

struct SimExpandTanhPass : sim::impl::SimExpandTanhBase<SimExpandTanhPass> {
  void runOnOperation() override {
    // One walk: the expansion has no tanh in it, and nothing else changes
    // (no folding, no CSE), so the kernels keep every other op.
    RewritePatternSet patterns(&getContext());
    patterns.add<ExpandTanh>(&getContext());
    walkAndApplyPatterns(getOperation(), std::move(patterns));
  }
};

} // namespace
