//===- SimInterfaces.h - sim dialect interfaces -----------------*- C++ -*-===//
//
// Declares InterpolationAttrInterface, the extension point for interpolation
// functions.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMINTERFACES_H
#define SIM_DIALECT_SIM_IR_SIMINTERFACES_H

#include "mlir/IR/Attributes.h"
#include "mlir/IR/Builders.h"
#include "mlir/IR/BuiltinAttributes.h"
#include "mlir/IR/Value.h"

#include "sim/Dialect/Sim/IR/SimInterfaces.h.inc"

#endif // SIM_DIALECT_SIM_IR_SIMINTERFACES_H
