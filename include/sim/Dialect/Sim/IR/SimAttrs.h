//===- SimAttrs.h - sim dialect attributes ----------------------*- C++ -*-===//
//
// Declares the sim enumerations and attributes (interpolation functions).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMATTRS_H
#define SIM_DIALECT_SIM_IR_SIMATTRS_H

#include "mlir/IR/Attributes.h"
#include "mlir/IR/BuiltinAttributes.h"
#include "mlir/IR/DialectImplementation.h"

#include "sim/Dialect/Sim/IR/SimEnums.h.inc"
#include "sim/Dialect/Sim/IR/SimInterfaces.h"

#define GET_ATTRDEF_CLASSES
#include "sim/Dialect/Sim/IR/SimAttrs.h.inc"

namespace mlir::sim {

/// Returns `scalar` as a value of `type`: itself when `type` is the scalar
/// type, a splat when `type` is a vector of it. Interpolation functions use it
/// to scale vector elements by scalar weights.
Value splatLike(OpBuilder &builder, Location loc, Value scalar, Type type);

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_IR_SIMATTRS_H
