//===- SimDialect.h - the sim dialect ---------------------------*- C++ -*-===//
//
// Declares the `sim` dialect class.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMDIALECT_H
#define SIM_DIALECT_SIM_IR_SIMDIALECT_H

#include "mlir/IR/Dialect.h"

#include "sim/Dialect/Sim/IR/SimDialect.h.inc"

#endif // SIM_DIALECT_SIM_IR_SIMDIALECT_H
