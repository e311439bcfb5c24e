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

/// Returns the item that a read of item `index` reads under boundary rule
/// `rule` in a range of `range` items (both of index type): the item itself
/// inside the range. Under `zero`, `inBounds` receives an i1 that is false
/// where the read returns a zero element (it is left null otherwise). The
/// lowerings resolve every load with it, and --sim-insert-interpolation the
/// item at which a Hermite derivative is read, so the rules are written once.
Value buildBoundaryItem(OpBuilder &builder, Location loc, Boundary rule,
                        Value index, Value range, Value &inBounds);

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_IR_SIMATTRS_H
