//===- Passes.h - passes of the PTX back end --------------------*- C++ -*-===//
//
// Declares the passes of the GPU back end (the kernels' loops; fixes and
// checks of gpu.modules lowered to NVVM before they are serialized to PTX),
// and their registration.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_TARGET_PTX_PASSES_H
#define SIM_TARGET_PTX_PASSES_H

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Pass/Pass.h"

namespace mlir::sim {

#define GEN_PASS_DECL
#include "sim/Target/PTX/Passes.h.inc"

#define GEN_PASS_REGISTRATION
#include "sim/Target/PTX/Passes.h.inc"

} // namespace mlir::sim

#endif // SIM_TARGET_PTX_PASSES_H
