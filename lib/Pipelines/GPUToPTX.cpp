//===- GPUToPTX.cpp - the GPU back end: gpu.modules to PTX ----------------===//
//
// The device half of upstream's gpu-lower-to-nvvm-pipeline, without its host
// half (which calls the mgpu* wrappers of libmlir_cuda_runtime; our runtime
// launches the PTX itself). Every lowering is an upstream pass; the order:
//
//   gpu.module(sim-nvvm-check-target{attaching chip})
//                                           the chip, before its attribute's
//                                           verifier (crashes on "")
//   nvvm-attach-target{chip features O ftz} #nvvm.target on every gpu.module
//   gpu.module(
//     sim-fused-multiply-add                vector.fma to llvm.intr.fma (one
//                                           rounding on every backend)
//     sim-gpu-narrow-loop-counters          only with narrow-loop-counters
//                                           (--sim-gpu-narrow-loops)
//     sim-gpu-unroll-loops{factor}          only with unroll other than 1
//                                           (--sim-gpu-unroll)
//     convert-scf-to-cf                     loops and ifs to blocks
//     expand-strided-metadata               subviews to reinterpret_casts
//     sim-gpu-lower-subgroup-reduce         only for a chip before sm_80 (no
//                                           redux.sync): warp shuffles
//     convert-gpu-to-nvvm{has-redux}        gpu, arith, cf, memref, vector,
//                                           index, ub and the math functions
//                                           of libdevice to LLVM/NVVM
//     convert-nvvm-to-llvm                  NVVM ops that are inline PTX
//                                           (nvvm.inline_ptx) to
//                                           llvm.inline_asm
//     convert-math-to-llvm                  the other math ops (ctlz, ...),
//                                           which convert-gpu-to-nvvm skips
//     reconcile-unrealized-casts
//     sim-flush-subnormals                  only with ftz (--sim-ftz): .ftz
//                                           f32 instructions
//     sim-nvvm-extern-dynamic-shared-memory
//     sim-nvvm-set-data-layout              NVPTX's, before the translation
//                                           aligns i64 accesses by it
//     sim-nvvm-check-target{libdevice})
//   gpu-module-to-binary{format=isa toolkit}  PTX text in a gpu.binary
//
// Memrefs keep their descriptors (no bare pointers): the kernels take
// dynamic memrefs, which the bare-pointer convention cannot express.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Target/PTX/Passes.h"

#include "mlir/Conversion/ArithToLLVM/ArithToLLVM.h"
#include "mlir/Conversion/ControlFlowToLLVM/ControlFlowToLLVM.h"
#include "mlir/Conversion/FuncToLLVM/ConvertFuncToLLVM.h"
#include "mlir/Conversion/GPUToNVVM/GPUToNVVMPass.h"
#include "mlir/Conversion/IndexToLLVM/IndexToLLVM.h"
#include "mlir/Conversion/MathToLLVM/MathToLLVM.h"
#include "mlir/Conversion/MemRefToLLVM/MemRefToLLVM.h"
#include "mlir/Conversion/NVVMToLLVM/NVVMToLLVM.h"
#include "mlir/Conversion/ReconcileUnrealizedCasts/ReconcileUnrealizedCasts.h"
#include "mlir/Conversion/SCFToControlFlow/SCFToControlFlow.h"
#include "mlir/Conversion/UBToLLVM/UBToLLVM.h"
#include "mlir/Conversion/VectorToLLVM/ConvertVectorToLLVM.h"
#include "mlir/Dialect/ControlFlow/IR/ControlFlow.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/GPU/Transforms/Passes.h"
#include "mlir/Dialect/Index/IR/IndexDialect.h"
#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/LLVMIR/NVVMDialect.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/MemRef/Transforms/Passes.h"
#include "mlir/Dialect/UB/IR/UBOps.h"
#include "mlir/IR/DialectRegistry.h"
#include "mlir/Target/LLVM/NVVM/Target.h"
#include "mlir/Target/LLVM/NVVM/Utils.h"
#include "mlir/Target/LLVMIR/Dialect/Builtin/BuiltinToLLVMIRTranslation.h"
#include "mlir/Target/LLVMIR/Dialect/GPU/GPUToLLVMIRTranslation.h"
#include "mlir/Target/LLVMIR/Dialect/LLVMIR/LLVMToLLVMIRTranslation.h"
#include "mlir/Target/LLVMIR/Dialect/NVVM/NVVMToLLVMIRTranslation.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Path.h"

using namespace mlir;
using namespace mlir::sim;

/// Whether `chip` (sm_XX, sm_XXa, sm_XXf) has `redux.sync`, which
/// gpu.subgroup_reduce lowers to: sm_80 and later.
static bool hasRedux(StringRef chip) {
  unsigned version = 0;
  if (!chip.consume_front("sm_"))
    return false;
  chip = chip.take_while(llvm::isDigit);
  return !chip.getAsInteger(10, version) && version >= 80;
}

/// The CUDA toolkit root for `cudaPath`: itself, else gpu-module-to-binary's
/// search ($CUDA_ROOT, $CUDA_HOME, $CUDA_PATH), else the usual location.
static std::string getCUDARoot(StringRef cudaPath) {
  if (!cudaPath.empty())
    return cudaPath.str();
  if (StringRef fromEnvironment = NVVM::getCUDAToolkitPath();
      !fromEnvironment.empty())
    return fromEnvironment.str();
  return "/usr/local/cuda";
}

std::string mlir::sim::getLibdevicePath(StringRef cudaPath) {
  SmallString<256> path(getCUDARoot(cudaPath));
  llvm::sys::path::append(path, "nvvm", "libdevice", "libdevice.10.bc");
  return std::string(path);
}

void mlir::sim::buildSimGPUToPTXPipeline(OpPassManager &pm,
                                         const GPUTargetOptions &target) {
  GpuNVVMAttachTargetOptions attach;
  attach.chip = target.chip;
  attach.features = target.features;
  attach.optLevel = target.optLevel;
  // libdevice's FTZ variants (__nvvm_reflect("__CUDA_FTZ")).
  attach.ftzFlag = target.flushSubnormals;
  // The chip first: the target attribute's verifier, which runs right after
  // attaching it, crashes on an empty one.
  SimNVVMCheckTargetOptions chip;
  chip.attaching = true;
  chip.chip = target.chip;
  pm.addNestedPass<gpu::GPUModuleOp>(createSimNVVMCheckTarget(chip));
  pm.addPass(createGpuNVVMAttachTarget(attach));

  OpPassManager &kernels = pm.nest<gpu::GPUModuleOp>();
  kernels.addPass(createSimFusedMultiplyAdd());
  if (target.narrowLoopCounters)
    kernels.addPass(createSimGPUNarrowLoopCounters());
  // (A factor of 0 goes to the pass too, which refuses it.)
  if (target.unroll != 1) {
    SimGPUUnrollLoopsOptions unroll;
    unroll.factor = target.unroll;
    kernels.addPass(createSimGPUUnrollLoops(unroll));
  }
  // No conversion lowers math.ipowi: multiplications, as on the CPU.
  kernels.addPass(createSimExpandIntegerPowers());
  // High-level vector ops as 1-D ones, as on the CPU.
  kernels.addPass(createSimLowerVectorOps());
  kernels.addPass(createSCFToControlFlowPass());
  kernels.addPass(memref::createExpandStridedMetadataPass());
  // Warp reductions: redux.sync from sm_80, shuffles before.
  bool redux = hasRedux(target.chip);
  if (!redux)
    kernels.addPass(createSimGPULowerSubgroupReduce());
  ConvertGpuOpsToNVVMOpsOptions toNVVM;
  toNVVM.hasRedux = redux;
  toNVVM.useBarePtrCallConv = false;
  kernels.addPass(createConvertGpuOpsToNVVMOps(toNVVM));
  kernels.addPass(createConvertNVVMToLLVMPass());
  kernels.addPass(createConvertMathToLLVMPass());
  kernels.addPass(createReconcileUnrealizedCastsPass());
  if (target.flushSubnormals)
    kernels.addPass(createSimFlushSubnormals());
  kernels.addPass(createSimNVVMExternDynamicSharedMemory());
  kernels.addPass(createSimNVVMSetDataLayout());

  // gpu-module-to-binary links libdevice from the toolkit it is given; when
  // there is none it links nothing and says nothing, so the check pass
  // rejects libdevice calls instead.
  std::string libdevice = getLibdevicePath(target.cudaPath);
  SimNVVMCheckTargetOptions check;
  check.libdevice = libdevice;
  kernels.addPass(createSimNVVMCheckTarget(check));

  GpuModuleToBinaryPassOptions toBinary;
  toBinary.compilationTarget = "isa";
  if (llvm::sys::fs::is_regular_file(libdevice))
    toBinary.toolkitPath = getCUDARoot(target.cudaPath);
  pm.addPass(createGpuModuleToBinaryPass(toBinary));
}

void mlir::sim::registerGPUToPTXDependencies(DialectRegistry &registry) {
  registry.insert<cf::ControlFlowDialect, func::FuncDialect, gpu::GPUDialect,
                  index::IndexDialect, LLVM::LLVMDialect, memref::MemRefDialect,
                  NVVM::NVVMDialect, ub::UBDialect>();
  // convert-gpu-to-nvvm lowers every loaded dialect through its
  // ConvertToLLVMPatternInterface; a dialect without one stays unlowered.
  arith::registerConvertArithToLLVMInterface(registry);
  cf::registerConvertControlFlowToLLVMInterface(registry);
  index::registerConvertIndexToLLVMInterface(registry);
  registerConvertFuncToLLVMInterface(registry);
  registerConvertMathToLLVMInterface(registry);
  registerConvertMemRefToLLVMInterface(registry);
  registerConvertNVVMToLLVMInterface(registry);
  ub::registerConvertUBToLLVMInterface(registry);
  vector::registerConvertVectorToLLVMInterface(registry);
  // gpu-module-to-binary: the #nvvm.target serializer and the translations
  // of what a lowered gpu.module contains.
  NVVM::registerNVVMTargetInterfaceExternalModels(registry);
  registerBuiltinDialectTranslation(registry);
  registerGPUDialectTranslation(registry);
  registerLLVMDialectTranslation(registry);
  registerNVVMDialectTranslation(registry);
}

void mlir::sim::registerGPUToPTXPasses() {
  registerGpuNVVMAttachTarget();
  memref::registerExpandStridedMetadataPass();
  registerGpuModuleToBinaryPass();
  // The conversions' register functions come only with
  // mlir/Conversion/Passes.h, which includes every conversion there is.
  registerPass([] { return createSCFToControlFlowPass(); });
  registerPass([] { return createConvertGpuOpsToNVVMOps(); });
  registerPass([] { return createConvertNVVMToLLVMPass(); });
  registerPass([] { return createConvertMathToLLVMPass(); });
  registerPass([] { return createReconcileUnrealizedCastsPass(); });
  registerSimPTXPasses();
}
