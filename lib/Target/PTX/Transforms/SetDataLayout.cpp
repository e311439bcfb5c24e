//===- SetDataLayout.cpp - NVPTX's data layout on a gpu.module ------------===//
//
// gpu-module-to-binary sets the target's data layout only after translating
// to LLVM IR, so loads and stores without an alignment took LLVM's default
// (an i64 aligned to 4 bytes) and were split into two 32-bit accesses. The
// pass gives the gpu.module the data layout first. See the pass description
// in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "llvm/TargetParser/Triple.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMNVVMSETDATALAYOUT
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

struct SetDataLayoutPass
    : public sim::impl::SimNVVMSetDataLayoutBase<SetDataLayoutPass> {
  using Base::Base;

  void runOnOperation() override {
    gpu::GPUModuleOp module = getOperation();
    StringRef name = LLVM::LLVMDialect::getDataLayoutAttrName();
    if (module->hasAttr(name))
      return;
    std::string layout =
        llvm::Triple("nvptx64-nvidia-cuda").computeDataLayout();
    module->setAttr(name, StringAttr::get(&getContext(), layout));
  }
};

} // namespace
