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

/// The most offsets a cache's window (#sim.cache, sim.fill_cache) spans: a
/// group's window lives in shared memory, and the plan budgets far less;
/// the bound keeps the sizes computed from it far from overflowing.
constexpr int64_t kMaxCacheWindow = int64_t(1) << 20;

/// Returns `scalar` as a value of `type`: itself when `type` is the scalar
/// type, a splat when `type` is a vector of it. Interpolation functions use it
/// to scale vector elements by scalar weights.
Value splatLike(OpBuilder &builder, Location loc, Value scalar, Type type);

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_IR_SIMATTRS_H
