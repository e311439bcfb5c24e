//===- FlushSubnormals.cpp - functions that flush subnormals to zero ------===//
//
// `sim-translate --sim-ftz` compiles a scene whose floating-point arithmetic
// treats subnormal values as zero. LLVM learns it from the functions'
// denormal modes: NVPTX then selects the `.ftz` f32 instructions, and every
// target folds constants the way the hardware will compute.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/LLVMIR/LLVMDialect.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMFLUSHSUBNORMALS
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

struct SimFlushSubnormalsPass
    : sim::impl::SimFlushSubnormalsBase<SimFlushSubnormalsPass> {
  void runOnOperation() override {
    // Output and input mode alike: a subnormal result becomes a zero of its
    // sign, and a subnormal operand is read as one.
    StringAttr mode = StringAttr::get(&getContext(), "preserve-sign");
    getOperation()->walk([&](LLVM::LLVMFuncOp func) {
      if (func.isExternal())
        return;
      func.setDenormalFpMathAttr(mode);
      func.setDenormalFpMathF32Attr(mode);
    });
  }
};

} // namespace
