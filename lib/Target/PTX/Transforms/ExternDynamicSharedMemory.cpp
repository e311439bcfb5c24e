//===- ExternDynamicSharedMemory.cpp - dynamic shared memory as extern ----===//
//
// gpu.dynamic_shared_memory must become PTX's `.extern .shared ... name[]`,
// the only form the driver places after the kernel's static shared memory.
// Upstream lowers it to an internal zero-sized global instead, which ptxas
// allocates as one static byte next to the workgroup attributions, so the
// dynamic array overlaps them. The pass makes that global an external
// declaration (what clang emits for CUDA's `extern __shared__`). See the pass
// description in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/LLVMIR/NVVMDialect.h"
#include "llvm/Support/Debug.h"

#define DEBUG_TYPE "sim-nvvm-extern-dynamic-shared-memory"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMNVVMEXTERNDYNAMICSHAREDMEMORY
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Whether `global` is what upstream makes of gpu.dynamic_shared_memory: an
/// internal, uninitialized, zero-sized array in shared memory.
bool isDynamicSharedMemory(LLVM::GlobalOp global) {
  auto array = dyn_cast<LLVM::LLVMArrayType>(global.getGlobalType());
  return array && array.getNumElements() == 0 &&
         global.getAddrSpace() ==
             static_cast<unsigned>(NVVM::NVVMMemorySpace::Shared) &&
         global.getLinkage() == LLVM::Linkage::Internal &&
         !global.getValueOrNull() && !global.getInitializerBlock();
}

struct ExternDynamicSharedMemoryPass
    : public sim::impl::SimNVVMExternDynamicSharedMemoryBase<
          ExternDynamicSharedMemoryPass> {
  void runOnOperation() override {
    for (auto global : getOperation().getOps<LLVM::GlobalOp>()) {
      if (!isDynamicSharedMemory(global))
        continue;
      LLVM_DEBUG(llvm::dbgs() << "extern: " << global.getSymName() << "\n");
      global.setLinkage(LLVM::Linkage::External);
    }
  }
};

} // namespace
