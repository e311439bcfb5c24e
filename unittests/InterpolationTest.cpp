//===- InterpolationTest.cpp - interpolation functions --------------------===//
//
// Evaluates the IR that each interpolation function builds, by building it on
// constants and letting MLIR's folder reduce it to a constant. So the tests
// check the exact arithmetic that the passes emit, not a second copy of it:
// exactness at both ends, values in between, and the declared order of
// accuracy (the error ratio when the big step halves).
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimAttrs.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Builders.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/IR/TypeUtilities.h"
#include "mlir/Transforms/GreedyPatternRewriteDriver.h"

#include "gtest/gtest.h"

#include <cmath>

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Prints an attribute or type for gtest failure messages.
template <typename T> std::string str(T entity) {
  std::string text;
  llvm::raw_string_ostream(text) << entity;
  return text;
}

/// The end values handed to an interpolation: the interpolated buffer's value
/// and (for Hermite) its derivative, at T and at T + h.
struct Ends {
  double begin, end, beginSlope, endSlope;
};

class InterpolationTest : public ::testing::Test {
protected:
  InterpolationTest() {
    context
        .loadDialect<SimDialect, arith::ArithDialect, vector::VectorDialect>();
    context.allowUnregisteredDialects();
  }

  InterpolationAttrInterface linear() {
    return cast<InterpolationAttrInterface>(LinearInterpAttr::get(&context));
  }
  InterpolationAttrInterface cubic() {
    return cast<InterpolationAttrInterface>(CubicInterpAttr::get(&context));
  }
  InterpolationAttrInterface hermite() {
    return cast<InterpolationAttrInterface>(HermiteInterpAttr::get(
        &context, FlatSymbolRefAttr::get(&context, "V")));
  }

  /// Builds `interp` on constants of `elementType` (scalar, or a vector whose
  /// every lane holds the same value), folds it, and returns the folded
  /// constant (lane 0 for vectors).
  double evaluate(InterpolationAttrInterface interp, Ends ends, double fraction,
                  double span, Type elementType) {
    OpBuilder builder(&context);
    Location loc = builder.getUnknownLoc();
    OwningOpRef<ModuleOp> module = ModuleOp::create(loc);
    builder.setInsertionPointToEnd(module->getBody());

    Type scalarType = getElementTypeOrSelf(elementType);
    auto element = [&](double value) -> Value {
      Value scalar = arith::ConstantOp::create(
          builder, loc, builder.getFloatAttr(scalarType, value));
      return splatLike(builder, loc, scalar, elementType);
    };
    auto scalar = [&](double value) -> Value {
      return arith::ConstantOp::create(builder, loc,
                                       builder.getFloatAttr(scalarType, value));
    };
    SmallVector<Value> atBegin = {element(ends.begin)};
    SmallVector<Value> atEnd = {element(ends.end)};
    if (!interp.getAuxiliaryBuffers().empty()) {
      atBegin.push_back(element(ends.beginSlope));
      atEnd.push_back(element(ends.endSlope));
    }
    Value result = interp.buildInterpolation(builder, loc, atBegin, atEnd,
                                             scalar(fraction), scalar(span));

    // Keep the result alive through folding with an unregistered sink op.
    OperationState sinkState(loc, "test.sink");
    sinkState.addOperands(result);
    Operation *sink = builder.create(sinkState);

    GreedyRewriteConfig config;
    EXPECT_TRUE(succeeded(
        applyPatternsGreedily(*module, FrozenRewritePatternSet(), config)));
    auto constant = sink->getOperand(0).getDefiningOp<arith::ConstantOp>();
    EXPECT_TRUE(constant) << "interpolation did not fold to a constant";
    if (!constant)
      return NAN;
    Attribute value = constant.getValue();
    if (auto dense = dyn_cast<DenseElementsAttr>(value))
      return (*dense.getValues<APFloat>().begin()).convertToDouble();
    return cast<FloatAttr>(value).getValueAsDouble();
  }

  double evaluate(InterpolationAttrInterface interp, Ends ends, double fraction,
                  double span = 1.0) {
    return evaluate(interp, ends, fraction, span, Float64Type::get(&context));
  }

  MLIRContext context;
};

/// A smooth signal and its derivative for the convergence tests.
double signal(double t) { return std::sin(3.0 * t) + std::exp(0.5 * t); }
double signalSlope(double t) {
  return 3.0 * std::cos(3.0 * t) + 0.5 * std::exp(0.5 * t);
}

/// The largest interpolation error of `interp` on `signal` over a big step of
/// length `h` starting at t0, sampled at interior fractions.
template <typename Eval> double maxError(Eval &&eval, double t0, double h) {
  Ends ends{signal(t0), signal(t0 + h), signalSlope(t0), signalSlope(t0 + h)};
  double worst = 0.0;
  for (double fraction : {0.1, 0.25, 0.4, 0.5, 0.6, 0.75, 0.9})
    worst = std::max(
        worst, std::fabs(eval(ends, fraction, h) - signal(t0 + fraction * h)));
  return worst;
}

TEST_F(InterpolationTest, DeclaredOrders) {
  EXPECT_EQ(linear().getOrderOfAccuracy(), 2u);
  EXPECT_EQ(cubic().getOrderOfAccuracy(), 1u);
  EXPECT_EQ(hermite().getOrderOfAccuracy(), 4u);
  EXPECT_TRUE(linear().getAuxiliaryBuffers().empty());
  ASSERT_EQ(hermite().getAuxiliaryBuffers().size(), 1u);
  EXPECT_EQ(hermite().getAuxiliaryBuffers()[0].getValue(), "V");
  EXPECT_EQ(hermite().getAuxiliaryBufferRole(0), "derivative");
}

/// interp(none) declares that a buffer has no value between step ends; the
/// functions that build one say they do.
TEST_F(InterpolationTest, NoneIsNotInterpolable) {
  auto none = cast<InterpolationAttrInterface>(NoneInterpAttr::get(&context));
  EXPECT_FALSE(none.isInterpolable());
  EXPECT_EQ(none.getOrderOfAccuracy(), 0u);
  EXPECT_TRUE(none.getAuxiliaryBuffers().empty());
  EXPECT_TRUE(linear().isInterpolable());
  EXPECT_TRUE(cubic().isInterpolable());
  EXPECT_TRUE(hermite().isInterpolable());
}

/// Both ends are exact, bit for bit, in f32 and f64 and for vectors: this is
/// what makes every strategy agree with `simple` when all big steps are one
/// base step.
TEST_F(InterpolationTest, ExactAtBothEnds) {
  // Values chosen so that a + (b - a) * f would not reproduce b exactly.
  Ends ends{0.1, 0.7000000000000001, -1.3, 2.9};
  Type f32 = Float32Type::get(&context);
  Type f64 = Float64Type::get(&context);
  Type vec = VectorType::get({4}, f32);
  for (InterpolationAttrInterface interp : {linear(), cubic(), hermite()}) {
    for (Type type : {f32, f64, vec}) {
      bool isF32 = getElementTypeOrSelf(type).isF32();
      double begin = isF32 ? double(float(ends.begin)) : ends.begin;
      double end = isF32 ? double(float(ends.end)) : ends.end;
      EXPECT_EQ(evaluate(interp, ends, 0.0, 0.3, type), begin)
          << "interp " << str(Attribute(interp)) << " type " << str(type);
      EXPECT_EQ(evaluate(interp, ends, 1.0, 0.3, type), end)
          << "interp " << str(Attribute(interp)) << " type " << str(type);
    }
  }
}

TEST_F(InterpolationTest, ValuesInBetween) {
  Ends ends{2.0, 6.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(evaluate(linear(), ends, 0.25), 3.0);
  EXPECT_DOUBLE_EQ(evaluate(linear(), ends, 0.5), 4.0);
  // Smoothstep: s(0.5) = 0.5, s(0.25) = 0.15625.
  EXPECT_DOUBLE_EQ(evaluate(cubic(), ends, 0.5), 4.0);
  EXPECT_DOUBLE_EQ(evaluate(cubic(), ends, 0.25), 2.0 + 4.0 * 0.15625);
  // Hermite with zero slopes is the smoothstep too.
  EXPECT_DOUBLE_EQ(evaluate(hermite(), ends, 0.25), 2.0 + 4.0 * 0.15625);
  // Vector lanes get the same weights.
  EXPECT_FLOAT_EQ(evaluate(linear(), ends, 0.25, 1.0,
                           VectorType::get({3}, Float32Type::get(&context))),
                  3.0f);
}

/// Cubic Hermite reproduces any cubic polynomial; the derivative is scaled by
/// the span of the big step in time units.
TEST_F(InterpolationTest, HermiteIsExactForCubics) {
  auto cubicPoly = [](double t) {
    return 1.0 + 2.0 * t - 3.0 * t * t + 0.5 * t * t * t;
  };
  auto cubicSlope = [](double t) { return 2.0 - 6.0 * t + 1.5 * t * t; };
  double t0 = 0.7, h = 0.9;
  Ends ends{cubicPoly(t0), cubicPoly(t0 + h), cubicSlope(t0),
            cubicSlope(t0 + h)};
  for (double fraction : {0.1, 0.3, 0.5, 0.8})
    EXPECT_NEAR(evaluate(hermite(), ends, fraction, h),
                cubicPoly(t0 + fraction * h), 1e-12);
}

/// Halving the big step divides the error by about 2^p, p the declared order.
TEST_F(InterpolationTest, ConvergesAtTheDeclaredOrder) {
  for (InterpolationAttrInterface interp : {linear(), cubic(), hermite()}) {
    auto eval = [&](Ends ends, double fraction, double h) {
      return evaluate(interp, ends, fraction, h);
    };
    double t0 = 0.3;
    double coarse = maxError(eval, t0, 0.08);
    double fine = maxError(eval, t0, 0.04);
    ASSERT_GT(fine, 0.0);
    double observedOrder = std::log2(coarse / fine);
    EXPECT_NEAR(observedOrder, interp.getOrderOfAccuracy(), 0.25)
        << "interp " << str(Attribute(interp)) << ": errors " << coarse
        << " -> " << fine;
  }
}

} // namespace
