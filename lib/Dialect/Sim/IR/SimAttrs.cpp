//===- SimAttrs.cpp - sim attributes and interpolation functions ----------===//
//
// The interpolation functions build their arithmetic with arith (and vector
// broadcasts for vector elements). Each is written so that fraction 0 and 1
// return the end values exactly: weights are 0 or 1 there, and every weighted
// term is summed, never formed as a difference of end values.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimAttrs.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Builders.h"
#include "mlir/IR/DialectImplementation.h"
#include "llvm/ADT/TypeSwitch.h"

using namespace mlir;
using namespace mlir::sim;

#include "sim/Dialect/Sim/IR/SimEnums.cpp.inc"
#include "sim/Dialect/Sim/IR/SimInterfaces.cpp.inc"

#define GET_ATTRDEF_CLASSES
#include "sim/Dialect/Sim/IR/SimAttrs.cpp.inc"

void SimDialect::registerAttributes() {
  addAttributes<
#define GET_ATTRDEF_LIST
#include "sim/Dialect/Sim/IR/SimAttrs.cpp.inc"
      >();
}

Attribute SimDialect::parseAttribute(DialectAsmParser &parser,
                                     Type type) const {
  SMLoc loc = parser.getCurrentLocation();
  StringRef mnemonic;
  Attribute attr;
  OptionalParseResult result =
      generatedAttributeParser(parser, &mnemonic, type, attr);
  if (!result.has_value()) {
    parser.emitError(loc) << "unknown attribute `" << mnemonic
                          << "` in dialect `sim`";
    return {};
  }
  if (failed(*result))
    return {};
  // `#sim<...>` bodies are parsed from a copy of the text between the angle
  // brackets, and the generated parser stops after the value: check that
  // nothing is left. (`#sim.name<...>` is parsed in place; the enclosing
  // parser checks what follows it.)
  SMLoc rest = parser.getCurrentLocation();
  StringRef spec = parser.getFullSymbolSpec();
  if (rest.getPointer() >= spec.begin() && rest.getPointer() < spec.end()) {
    StringRef text(rest.getPointer(), spec.end() - rest.getPointer());
    parser.emitError(rest)
        << "unexpected '" << text.trim() << "' after the attribute value '"
        << StringRef(spec.begin(), rest.getPointer() - spec.begin()).trim()
        << "'; a value spelled with '-' is written in quotes, as in "
           "#sim<strategy \"hip-cache\">";
    return {};
  }
  return attr;
}

void SimDialect::printAttribute(Attribute attr,
                                DialectAsmPrinter &printer) const {
  (void)generatedAttributePrinter(attr, printer);
}

Value mlir::sim::splatLike(OpBuilder &builder, Location loc, Value scalar,
                           Type type) {
  if (scalar.getType() == type)
    return scalar;
  return vector::BroadcastOp::create(builder, loc, type, scalar);
}

namespace {
/// Small arithmetic helpers on scalar weights of the fraction's type.
struct WeightBuilder {
  OpBuilder &b;
  Location loc;
  Type scalarType;

  Value constant(double value) {
    return arith::ConstantOp::create(b, loc, b.getFloatAttr(scalarType, value));
  }
  Value add(Value x, Value y) { return arith::AddFOp::create(b, loc, x, y); }
  Value sub(Value x, Value y) { return arith::SubFOp::create(b, loc, x, y); }
  Value mul(Value x, Value y) { return arith::MulFOp::create(b, loc, x, y); }
  /// `weight * element`, with the scalar weight splatted for vectors.
  Value scale(Value weight, Value element) {
    return mul(splatLike(b, loc, weight, element.getType()), element);
  }
};
} // namespace

//===----------------------------------------------------------------------===//
// CacheAttr
//===----------------------------------------------------------------------===//

LogicalResult CacheAttr::verify(function_ref<InFlightDiagnostic()> emitError,
                                FlatSymbolRefAttr buffer, int64_t minOffset,
                                int64_t maxOffset) {
  if (minOffset >= maxOffset)
    return emitError() << "#sim.cache of " << buffer
                       << " expects a window of more than one offset "
                          "(lowest below highest), but got "
                       << minOffset << ", " << maxOffset;
  if (uint64_t(maxOffset) - uint64_t(minOffset) > uint64_t(kMaxCacheWindow))
    return emitError() << "#sim.cache of " << buffer << " spans offsets "
                       << minOffset << " to " << maxOffset << ", more than "
                       << kMaxCacheWindow << " apart";
  return success();
}

//===----------------------------------------------------------------------===//
// NoneInterpAttr
//===----------------------------------------------------------------------===//

unsigned NoneInterpAttr::getOrderOfAccuracy() const { return 0; }

bool NoneInterpAttr::isInterpolable() const { return false; }

Value NoneInterpAttr::buildInterpolation(OpBuilder &builder, Location loc,
                                         ValueRange atBegin, ValueRange atEnd,
                                         Value fraction, Value span) const {
  // Callers check isInterpolable() first (--sim-plan-memory rejects the
  // reads that would need this).
  return nullptr;
}

//===----------------------------------------------------------------------===//
// FluxInterpAttr
//===----------------------------------------------------------------------===//

unsigned FluxInterpAttr::getOrderOfAccuracy() const { return 1; }

Value FluxInterpAttr::buildInterpolation(OpBuilder &builder, Location loc,
                                         ValueRange atBegin, ValueRange atEnd,
                                         Value fraction, Value span) const {
  // The writer's value over its whole step: the end value anywhere after
  // the start, the start value exactly at it.
  Value zero = arith::ConstantOp::create(
      builder, loc, builder.getFloatAttr(fraction.getType(), 0.0));
  Value after = arith::CmpFOp::create(builder, loc, arith::CmpFPredicate::OGT,
                                      fraction, zero);
  return arith::SelectOp::create(builder, loc, after, atEnd[0], atBegin[0]);
}

//===----------------------------------------------------------------------===//
// LinearInterpAttr
//===----------------------------------------------------------------------===//

unsigned LinearInterpAttr::getOrderOfAccuracy() const { return 2; }

Value LinearInterpAttr::buildInterpolation(OpBuilder &builder, Location loc,
                                           ValueRange atBegin, ValueRange atEnd,
                                           Value fraction, Value span) const {
  WeightBuilder w{builder, loc, fraction.getType()};
  Value weightBegin = w.sub(w.constant(1.0), fraction);
  return w.add(w.scale(weightBegin, atBegin[0]), w.scale(fraction, atEnd[0]));
}

//===----------------------------------------------------------------------===//
// CubicInterpAttr
//===----------------------------------------------------------------------===//

unsigned CubicInterpAttr::getOrderOfAccuracy() const { return 1; }

Value CubicInterpAttr::buildInterpolation(OpBuilder &builder, Location loc,
                                          ValueRange atBegin, ValueRange atEnd,
                                          Value fraction, Value span) const {
  WeightBuilder w{builder, loc, fraction.getType()};
  // s = f^2 (3 - 2f): exactly 0 at f = 0 and exactly 1 at f = 1.
  Value twoF = w.mul(w.constant(2.0), fraction);
  Value s = w.mul(w.mul(fraction, fraction), w.sub(w.constant(3.0), twoF));
  Value weightBegin = w.sub(w.constant(1.0), s);
  return w.add(w.scale(weightBegin, atBegin[0]), w.scale(s, atEnd[0]));
}

//===----------------------------------------------------------------------===//
// HermiteInterpAttr
//===----------------------------------------------------------------------===//

unsigned HermiteInterpAttr::getOrderOfAccuracy() const { return 4; }

SmallVector<FlatSymbolRefAttr> HermiteInterpAttr::getAuxiliaryBuffers() const {
  return {getDerivative()};
}

StringRef HermiteInterpAttr::getAuxiliaryBufferRole(unsigned index) const {
  return "derivative";
}

Value HermiteInterpAttr::buildInterpolation(OpBuilder &builder, Location loc,
                                            ValueRange atBegin,
                                            ValueRange atEnd, Value fraction,
                                            Value span) const {
  WeightBuilder w{builder, loc, fraction.getType()};
  Value f = fraction;
  Value one = w.constant(1.0);
  Value oneMinusF = w.sub(one, f);
  Value oneMinusFSq = w.mul(oneMinusF, oneMinusF);
  Value fSq = w.mul(f, f);
  // Hermite basis in factored form, so that every weight is exactly 0 or 1
  // at both ends.
  Value h00 = w.mul(w.add(one, w.mul(w.constant(2.0), f)), oneMinusFSq);
  Value h10 = w.mul(f, oneMinusFSq);
  Value h01 = w.mul(fSq, w.sub(w.constant(3.0), w.mul(w.constant(2.0), f)));
  Value h11 = w.mul(fSq, w.sub(f, one));
  // Derivatives are per time unit; the basis is over the unit interval.
  Value h10Span = w.mul(h10, span);
  Value h11Span = w.mul(h11, span);
  Value sum = w.add(w.scale(h00, atBegin[0]), w.scale(h10Span, atBegin[1]));
  sum = w.add(sum, w.scale(h01, atEnd[0]));
  return w.add(sum, w.scale(h11Span, atEnd[1]));
}

Value mlir::sim::buildBoundaryItem(OpBuilder &builder, Location loc,
                                   Boundary rule, Value index, Value range,
                                   Value &inBounds) {
  Value zero = arith::ConstantIndexOp::create(builder, loc, 0);
  switch (rule) {
  case Boundary::clamp: {
    Value one = arith::ConstantIndexOp::create(builder, loc, 1);
    Value last = arith::SubIOp::create(builder, loc, range, one);
    Value low = arith::MaxSIOp::create(builder, loc, index, zero);
    return arith::MinSIOp::create(builder, loc, low, last);
  }
  case Boundary::wrap: {
    // Nearly every read lies inside the range: only the others divide, in a
    // branch that a GPU warp or a CPU chunk of lanes takes at the range's
    // ends only (a remainder per read cost more than the evaluation on the
    // CPU, and is a long sequence in PTX).
    Value inside = arith::CmpIOp::create(
        builder, loc, arith::CmpIPredicate::ult, index, range);
    auto branch = scf::IfOp::create(builder, loc, TypeRange{index.getType()},
                                    inside, /*withElseRegion=*/true);
    OpBuilder inRange = OpBuilder::atBlockEnd(branch.thenBlock());
    scf::YieldOp::create(inRange, loc, index);
    OpBuilder outside = OpBuilder::atBlockEnd(branch.elseBlock());
    // remsi keeps the sign of the dividend: move negative remainders up.
    Value rem = arith::RemSIOp::create(outside, loc, index, range);
    Value negative = arith::CmpIOp::create(
        outside, loc, arith::CmpIPredicate::slt, rem, zero);
    Value up = arith::AddIOp::create(outside, loc, rem, range);
    Value wrapped = arith::SelectOp::create(outside, loc, negative, up, rem);
    scf::YieldOp::create(outside, loc, wrapped);
    return branch.getResult(0);
  }
  case Boundary::zero: {
    // One unsigned compare covers both ends (negative indices wrap high).
    inBounds = arith::CmpIOp::create(builder, loc, arith::CmpIPredicate::ult,
                                     index, range);
    return arith::SelectOp::create(builder, loc, inBounds, index, zero);
  }
  }
  llvm_unreachable("unknown boundary rule");
}
