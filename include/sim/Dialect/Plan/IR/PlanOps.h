//===- PlanOps.h - simplan dialect, attributes and operations ---*- C++ -*-===//
//
// Declares the simplan dialect: the host plan of a lowered simulation.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_PLAN_IR_PLANOPS_H
#define SIM_DIALECT_PLAN_IR_PLANOPS_H

#include "mlir/Bytecode/BytecodeOpInterface.h"
#include "mlir/IR/BuiltinAttributes.h"
#include "mlir/IR/Dialect.h"
#include "mlir/IR/OpDefinition.h"
#include "mlir/IR/OpImplementation.h"
#include "mlir/IR/RegionKindInterface.h"
#include "mlir/IR/SymbolTable.h"
#include "sim/Dialect/Sim/IR/SimAttrs.h"

#include "sim/Dialect/Plan/IR/PlanDialect.h.inc"
#include "sim/Dialect/Plan/IR/PlanEnums.h.inc"

#define GET_ATTRDEF_CLASSES
#include "sim/Dialect/Plan/IR/PlanAttrs.h.inc"

#define GET_OP_CLASSES
#include "sim/Dialect/Plan/IR/PlanOps.h.inc"

namespace mlir::simplan {
/// The slots of the sub-step clock of a component that advances in
/// `advance` (the bundle schema's SubClockWidth): grid-wide sub-steps use
/// four, local time steps six (docs/Plan.md, "The clock").
int64_t subClockSlots(mlir::sim::Advance advance);
} // namespace mlir::simplan

#endif // SIM_DIALECT_PLAN_IR_PLANOPS_H
