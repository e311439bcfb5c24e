//===- Passes.h - sim conversion passes -------------------------*- C++ -*-===//
//
// Declares the conversions out of the sim dialect.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_PASSES_H
#define SIM_CONVERSION_PASSES_H

#include "sim/Dialect/Plan/IR/PlanOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/LLVMIR/NVVMDialect.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/Pass/Pass.h"

namespace mlir::sim {

/// The attribute of a `--sim-lower-to-reference` module that holds the
/// reference model, a dictionary (docs/Reference.md, "The reference model").
constexpr llvm::StringLiteral kReferenceModelAttrName = "sim.reference_model";

#define GEN_PASS_DECL
#include "sim/Conversion/Passes.h.inc"

#define GEN_PASS_REGISTRATION
#include "sim/Conversion/Passes.h.inc"

} // namespace mlir::sim

#endif // SIM_CONVERSION_PASSES_H
