//===- DefineEdgeCases.cpp - one result for what LLVM leaves undefined ----===//
//
// A scene's bodies are arith, math and scf ops, and LLVM leaves some of
// them undefined for some operands: an integer division by 0 (x86 traps:
// the process died with SIGFPE when a parameter was set to 0), a signed
// division of the smallest integer by -1 (traps too), a shift by the bit
// width or more and a float-to-integer conversion out of range or of NaN
// (poison: the CPU's SIMD lanes and its scalar reference functions gave
// different values), and an `scf.for` whose step is not positive (the
// run never ended). A result that depends on the backend, or no result,
// is what a user must never get, so this pass gives each case one defined
// result before any backend sees the bodies (docs/Model.md, "Other
// rules"):
//
//   x / 0 = 0 and x % 0 = x (so x = (x / d) * d + x % d still holds),
//   for every division and remainder, signed or not, floor and ceil too;
//   x / -1 = -x (wrapping, as arith.muli wraps) and x % -1 = 0;
//   a shift by the width or more: 0 (shli, shrui), the sign (shrsi);
//   fptosi / fptoui saturate: NaN gives 0, values past the type's ends
//   its ends (as PTX's cvt.rzi and LLVM's fptosi.sat);
//   an scf.for whose step is not positive runs no iteration.
//
// An op whose operand rules the case out (a constant divisor other than 0
// and -1, a constant shift below the width, a constant step above 0) is
// left alone, so the paper scenes' constant divisions keep their
// multiplications by the reciprocal. A constant step of 0 or less is a
// mistake rather than an edge case: an error at the loop.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/IR/Matchers.h"
#include "mlir/IR/PatternMatch.h"
#include "mlir/IR/TypeUtilities.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMDEFINEEDGECASES
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Builds the guards of one op, in the op's (scalar or vector) type.
struct GuardBuilder {
  IRRewriter &rewriter;
  Location loc;

  /// A constant of `type` (splat for a vector) holding `value` (an integer
  /// of the element type's width, or a float).
  Value constant(Type type, TypedAttr element) {
    TypedAttr attr = element;
    if (auto shaped = dyn_cast<ShapedType>(type))
      attr = SplatElementsAttr::get(shaped, element);
    return arith::ConstantOp::create(rewriter, loc, type, attr);
  }
  Value integer(Type type, const APInt &value) {
    return constant(type,
                    rewriter.getIntegerAttr(getElementTypeOrSelf(type), value));
  }
  Value integer(Type type, int64_t value) {
    return constant(type,
                    rewriter.getIntegerAttr(getElementTypeOrSelf(type), value));
  }
  Value floating(Type type, const APFloat &value) {
    return constant(type,
                    rewriter.getFloatAttr(getElementTypeOrSelf(type), value));
  }
  Value cmpi(arith::CmpIPredicate predicate, Value lhs, Value rhs) {
    return arith::CmpIOp::create(rewriter, loc, predicate, lhs, rhs);
  }
  Value cmpf(arith::CmpFPredicate predicate, Value lhs, Value rhs) {
    return arith::CmpFOp::create(rewriter, loc, predicate, lhs, rhs);
  }
  Value select(Value condition, Value ifTrue, Value ifFalse) {
    return arith::SelectOp::create(rewriter, loc, condition, ifTrue, ifFalse);
  }
};

/// Replaces the uses `value` has now with what `define` builds from it (the
/// ops `define` creates read `value` and keep reading it).
static void redirectUses(IRRewriter &rewriter, Value value,
                         function_ref<Value()> define) {
  SmallVector<OpOperand *> uses;
  for (OpOperand &use : value.getUses())
    uses.push_back(&use);
  Value defined = define();
  for (OpOperand *use : uses)
    rewriter.modifyOpInPlace(use->getOwner(), [&] { use->set(defined); });
}

/// Whether `value` is a constant integer (or splat) for which `isSafe`
/// holds.
static bool isConstantWhere(Value value,
                            function_ref<bool(const APInt &)> isSafe) {
  APInt constant;
  return matchPattern(value, m_ConstantInt(&constant)) && isSafe(constant);
}

/// Divisions and remainders: by 0 they give 0 and the dividend; signed, by
/// -1 they give the negated dividend and 0 (the one quotient that does not
/// fit, the smallest integer's, wraps to itself).
static void defineDivision(IRRewriter &rewriter, Operation *op) {
  bool isSigned = isa<arith::DivSIOp, arith::RemSIOp, arith::CeilDivSIOp,
                      arith::FloorDivSIOp>(op);
  bool isRemainder = isa<arith::RemSIOp, arith::RemUIOp>(op);
  Value dividend = op->getOperand(0), divisor = op->getOperand(1);
  if (isConstantWhere(divisor, [&](const APInt &value) {
        return !value.isZero() && (!isSigned || !value.isAllOnes());
      }))
    return;
  rewriter.setInsertionPoint(op);
  GuardBuilder b{rewriter, op->getLoc()};
  Type type = divisor.getType();
  Value zero = b.integer(type, 0), one = b.integer(type, 1);
  Value byZero = b.cmpi(arith::CmpIPredicate::eq, divisor, zero);
  Value byMinusOne;
  Value unsafe = byZero;
  if (isSigned) {
    byMinusOne = b.cmpi(arith::CmpIPredicate::eq, divisor, b.integer(type, -1));
    unsafe = arith::OrIOp::create(rewriter, op->getLoc(), byZero, byMinusOne);
  }
  // The division itself never sees 0 or -1; its result for the divisor 1
  // is the dividend (and the remainder 0), which the selects below replace
  // where the divisor was one of them.
  Value safeDivisor = b.select(unsafe, one, divisor);
  rewriter.modifyOpInPlace(op, [&] { op->setOperand(1, safeDivisor); });
  rewriter.setInsertionPointAfter(op);
  redirectUses(rewriter, op->getResult(0), [&]() -> Value {
    Value result = op->getResult(0);
    // x % 1 = 0 is already x % -1.
    if (isRemainder)
      return b.select(byZero, dividend, result);
    Value defined = result;
    if (isSigned) {
      Value negated =
          arith::SubIOp::create(rewriter, op->getLoc(), zero, dividend);
      defined = b.select(byMinusOne, negated, defined);
    }
    return b.select(byZero, zero, defined);
  });
}

/// Shifts by the width or more: 0 for shli and shrui, the sign for shrsi.
static void defineShift(IRRewriter &rewriter, Operation *op) {
  Type type = op->getResult(0).getType();
  Type element = getElementTypeOrSelf(type);
  // The width of `index` is the target's; such shifts are left to it.
  if (!element.isInteger())
    return;
  unsigned width = element.getIntOrFloatBitWidth();
  Value value = op->getOperand(0), amount = op->getOperand(1);
  if (isConstantWhere(amount,
                      [&](const APInt &count) { return count.ult(width); }))
    return;
  rewriter.setInsertionPointAfter(op);
  GuardBuilder b{rewriter, op->getLoc()};
  Value inRange = b.cmpi(arith::CmpIPredicate::ult, amount,
                         b.integer(type, int64_t(width)));
  Value beyond =
      isa<arith::ShRSIOp>(op)
          ? arith::ShRSIOp::create(rewriter, op->getLoc(), value,
                                   b.integer(type, int64_t(width - 1)))
                .getResult()
          : b.integer(type, 0);
  redirectUses(rewriter, op->getResult(0),
               [&] { return b.select(inRange, op->getResult(0), beyond); });
}

/// Float-to-integer conversions saturate, and NaN gives 0.
static void defineConversion(IRRewriter &rewriter, Operation *op) {
  bool isSigned = isa<arith::FPToSIOp>(op);
  Value input = op->getOperand(0);
  Type resultType = op->getResult(0).getType();
  Type inputType = input.getType();
  auto floatType = cast<FloatType>(getElementTypeOrSelf(inputType));
  unsigned width = getElementTypeOrSelf(resultType).getIntOrFloatBitWidth();
  rewriter.setInsertionPointAfter(op);
  GuardBuilder b{rewriter, op->getLoc()};
  // The first value past the top: 2^(w-1) signed, 2^w unsigned, exact in
  // any float type whose range holds it, else infinity (every finite value
  // of the type then fits, as f16's do in i32).
  APFloat top(floatType.getFloatSemantics());
  APInt power = APInt::getOneBitSet(width + 1, isSigned ? width - 1 : width);
  (void)top.convertFromAPInt(power, /*IsSigned=*/false,
                             APFloat::rmNearestTiesToEven);
  bool topIsInfinite = top.isInfinity();
  Value tooHigh =
      b.cmpf(arith::CmpFPredicate::OGE, input, b.floating(inputType, top));
  // Signed: below -2^(w-1) (which itself fits); unsigned: -1 or below
  // (values in (-1, 0) truncate to 0, which fits).
  APFloat bottom = isSigned ? -top
                            : APFloat::getOne(floatType.getFloatSemantics(),
                                              /*Negative=*/true);
  Value tooLow = b.cmpf(isSigned && !topIsInfinite ? arith::CmpFPredicate::OLT
                                                   : arith::CmpFPredicate::OLE,
                        input, b.floating(inputType, bottom));
  Value isNaN = b.cmpf(arith::CmpFPredicate::UNO, input, input);
  APInt highest =
      isSigned ? APInt::getSignedMaxValue(width) : APInt::getMaxValue(width);
  APInt lowest =
      isSigned ? APInt::getSignedMinValue(width) : APInt::getZero(width);
  redirectUses(rewriter, op->getResult(0), [&] {
    Value defined =
        b.select(tooLow, b.integer(resultType, lowest), op->getResult(0));
    defined = b.select(tooHigh, b.integer(resultType, highest), defined);
    return b.select(isNaN, b.integer(resultType, 0), defined);
  });
}

struct SimDefineEdgeCasesPass
    : public sim::impl::SimDefineEdgeCasesBase<SimDefineEdgeCasesPass> {
  void runOnOperation() override {
    SmallVector<Operation *> divisions, shifts, conversions;
    SmallVector<scf::ForOp> loops;
    bool failed = false;
    getOperation()->walk([&](Operation *op) {
      if (isa<arith::DivSIOp, arith::DivUIOp, arith::RemSIOp, arith::RemUIOp,
              arith::CeilDivSIOp, arith::CeilDivUIOp, arith::FloorDivSIOp>(op))
        divisions.push_back(op);
      else if (isa<arith::ShLIOp, arith::ShRSIOp, arith::ShRUIOp>(op))
        shifts.push_back(op);
      else if (isa<arith::FPToSIOp, arith::FPToUIOp>(op))
        conversions.push_back(op);
      else if (auto loop = dyn_cast<scf::ForOp>(op)) {
        APInt step;
        if (matchPattern(loop.getStep(), m_ConstantInt(&step))) {
          bool positive = loop.getUnsignedCmp() ? !step.isZero()
                                                : step.isStrictlyPositive();
          if (!positive) {
            loop.emitError() << "scf.for has the constant step "
                             << llvm::toString(step, 10, !loop.getUnsignedCmp())
                             << ", so it never ends: give it a positive step";
            failed = true;
          }
          return;
        }
        loops.push_back(loop);
      }
    });
    if (failed)
      return signalPassFailure();

    IRRewriter rewriter(&getContext());
    for (Operation *op : divisions)
      defineDivision(rewriter, op);
    for (Operation *op : shifts)
      defineShift(rewriter, op);
    for (Operation *op : conversions)
      defineConversion(rewriter, op);
    // A step that is not positive runs no iteration: the upper bound
    // becomes the lower one.
    for (scf::ForOp loop : loops) {
      rewriter.setInsertionPoint(loop);
      GuardBuilder b{rewriter, loop.getLoc()};
      Value step = loop.getStep();
      Value zero = b.integer(step.getType(), 0);
      Value positive = b.cmpi(loop.getUnsignedCmp() ? arith::CmpIPredicate::ne
                                                    : arith::CmpIPredicate::sgt,
                              step, zero);
      Value upper =
          b.select(positive, loop.getUpperBound(), loop.getLowerBound());
      rewriter.modifyOpInPlace(loop, [&] { loop.setUpperBound(upper); });
    }
  }
};

} // namespace
