//===- Passes.h - sim dialect passes ----------------------------*- C++ -*-===//
//
// Declares the sim passes and their registration.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_TRANSFORMS_PASSES_H
#define SIM_DIALECT_SIM_TRANSFORMS_PASSES_H

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Pass/Pass.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

namespace mlir::sim {

/// Output formats of --sim-print-dependency-graph.
enum class GraphFormat { text, dot };

/// Output formats of --sim-report-memory.
enum class ReportFormat { text, json };

#define GEN_PASS_DECL
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"

#define GEN_PASS_REGISTRATION
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_TRANSFORMS_PASSES_H
