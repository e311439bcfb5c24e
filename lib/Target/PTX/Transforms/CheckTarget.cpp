//===- CheckTarget.cpp - check a lowered gpu.module before serializing ----===//
//
// gpu-module-to-binary reports some problems late and far from their cause
// (an op without lowering becomes "missing LLVMTranslationDialectInterface"
// on the whole module) and others not at all: an unknown chip or feature is
// a warning on stderr followed by PTX for another chip, and a libdevice call
// without libdevice stays an unresolved `call.uni __nv_expf` that only fails
// when the driver loads the PTX, and a symbol name PTX cannot spell aborts
// the process in LLVM's printer. This pass turns each into an error at the
// construct. See the pass description in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/LLVMIR/NVVMDialect.h"
#include "llvm/ADT/MapVector.h"
#include "llvm/ADT/StringExtras.h"
#include "llvm/ADT/StringSet.h"
#include "llvm/ADT/StringSwitch.h"
#include "llvm/Config/Targets.h"
#include "llvm/MC/MCSubtargetInfo.h"
#include "llvm/MC/TargetRegistry.h"
#include "llvm/Support/FileSystem.h"
#include "llvm/Support/Threading.h"
#include "llvm/TargetParser/Triple.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMNVVMCHECKTARGET
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

#if LLVM_HAS_NVPTX_TARGET
extern "C" void LLVMInitializeNVPTXTargetInfo();
extern "C" void LLVMInitializeNVPTXTargetMC();
#endif

using namespace mlir;
using namespace mlir::sim;

namespace {

/// Reports the first operation of each kind that is not in the LLVM or NVVM
/// dialect: gpu-module-to-binary can translate nothing else.
LogicalResult checkLowered(gpu::GPUModuleOp module) {
  llvm::StringSet<> reported;
  bool failed = false;
  module.getBody()->walk([&](Operation *op) {
    if (isa<LLVM::LLVMDialect, NVVM::NVVMDialect>(op->getDialect()))
      return;
    failed = true;
    if (reported.insert(op->getName().getStringRef()).second)
      op->emitOpError("was not lowered to the LLVM and NVVM dialects; the "
                      "PTX pipeline has no lowering for it");
  });
  return failure(failed);
}

/// Whether PTX and LLVM's NVPTX printer both take `name` as it is: a letter
/// then letters, digits, `_` and `$`, or `_` or `$` then at least one of
/// those (PTX also allows a leading `%`, the printer does not).
bool isPTXIdentifier(StringRef name) {
  auto follows = [](char c) {
    return llvm::isAlnum(c) || c == '_' || c == '$';
  };
  if (name.empty() || !llvm::all_of(name, follows) || llvm::isDigit(name[0]))
    return false;
  return llvm::isAlpha(name[0]) || name.size() > 1;
}

/// Reports each function and global whose name PTX cannot spell. LLVM's
/// NVPTX printer aborts the process on such a name ("Symbol name with
/// unsupported characters") or prints one that ptxas rejects. It renames
/// private and internal symbols itself (every other character becomes
/// `_$_`), but keeps a leading digit, and cannot rename the others: their
/// names are what a host looks kernels up by.
LogicalResult checkSymbolNames(gpu::GPUModuleOp module) {
  bool failed = false;
  auto check = [&](Operation *op, StringRef name, LLVM::Linkage linkage) {
    bool local =
        linkage == LLVM::Linkage::Private || linkage == LLVM::Linkage::Internal;
    std::string printed;
    for (char c : name) {
      if (local && !llvm::isAlnum(c) && c != '_' && c != '$')
        printed += "_$_";
      else
        printed += c;
    }
    if (isPTXIdentifier(printed))
      return;
    failed = true;
    op->emitError() << "the symbol name \"" << name
                    << "\" is not a PTX identifier (letters, digits, '_' "
                       "and '$', not starting with a digit), so no PTX can "
                       "name it; rename the symbol";
  };
  for (auto func : module.getOps<LLVM::LLVMFuncOp>())
    check(func, func.getName(), func.getLinkage());
  for (auto global : module.getOps<LLVM::GlobalOp>())
    check(global, global.getSymName(), global.getLinkage());
  return failure(failed);
}

/// The oldest chip the kernels run on: sm_70 (Volta), the first with
/// shfl.sync.
constexpr unsigned kOldestChip = 70;

/// The oldest PTX ISA version (major * 10 + minor) that supports `chip`,
/// from the "Supported Targets" of NVIDIA's PTX release history; none for a
/// chip not listed here (no check then).
std::optional<unsigned> getMinimumPTXVersion(StringRef chip) {
  return llvm::StringSwitch<std::optional<unsigned>>(chip)
      .Cases({"sm_20", "sm_21", "sm_30", "sm_35"}, 32)
      .Cases({"sm_32", "sm_50"}, 40)
      .Cases({"sm_37", "sm_52"}, 41)
      .Case("sm_53", 42)
      .Cases({"sm_60", "sm_61", "sm_62"}, 50)
      .Case("sm_70", 60)
      .Case("sm_72", 61)
      .Case("sm_75", 63)
      .Case("sm_80", 70)
      .Case("sm_86", 71)
      .Case("sm_87", 74)
      .Cases({"sm_89", "sm_90"}, 78)
      .Case("sm_90a", 80)
      .Cases({"sm_100", "sm_100a", "sm_101", "sm_101a"}, 86)
      .Cases({"sm_120", "sm_120a"}, 87)
      .Default(std::nullopt);
}

/// Checks the chip and the features of `target` against LLVM's NVPTX back
/// end, which otherwise only warns and compiles for a default chip.
LogicalResult checkTarget(gpu::GPUModuleOp module,
                          NVVM::NVVMTargetAttr target) {
#if LLVM_HAS_NVPTX_TARGET
  static llvm::once_flag initialized;
  llvm::call_once(initialized, [] {
    LLVMInitializeNVPTXTargetInfo();
    LLVMInitializeNVPTXTargetMC();
  });
  llvm::Triple triple(target.getTriple());
  std::string error;
  const llvm::Target *llvmTarget =
      llvm::TargetRegistry::lookupTarget(triple, error);
  if (!llvmTarget)
    return module.emitError() << "cannot compile for the target triple '"
                              << target.getTriple() << "': " << error;
  std::unique_ptr<llvm::MCSubtargetInfo> subtarget(
      llvmTarget->createMCSubtargetInfo(triple, "", ""));
  if (!subtarget->isCPUStringValid(target.getChip()))
    return module.emitError()
           << "unknown NVIDIA GPU '" << target.getChip()
           << "': LLVM's NVPTX back end knows chips such as sm_80, sm_90, "
              "sm_90a and sm_100";
  // The kernels exchange values between the lanes of a warp with
  // shfl.sync (and redux.sync from sm_80), which older chips do not have:
  // LLVM would abort the process selecting it.
  StringRef chipNumber = target.getChip();
  unsigned smVersion = 0;
  if (chipNumber.consume_front("sm_") &&
      !chipNumber.take_while(llvm::isDigit).getAsInteger(10, smVersion) &&
      smVersion < kOldestChip)
    return module.emitError()
           << "sim's GPU kernels need sm_" << kOldestChip
           << " or later (warp shuffles, shfl.sync), not " << target.getChip();
  llvm::StringSet<> known;
  for (const llvm::SubtargetFeatureKV &feature :
       subtarget->getAllProcessorFeatures())
    known.insert(feature.Key);
  SmallVector<StringRef> features;
  target.getFeatures().split(features, ',', /*MaxSplit=*/-1,
                             /*KeepEmpty=*/false);
  unsigned requested = 0;
  for (StringRef feature : features) {
    StringRef name = feature.trim();
    bool enabled = name.starts_with("+");
    if (!name.consume_front("+") && !name.consume_front("-"))
      return module.emitError()
             << "the PTX feature '" << feature
             << "' must start with '+' or '-' (e.g. '+ptx80')";
    if (!known.contains(name))
      return module.emitError()
             << "unknown PTX feature '" << feature
             << "': LLVM's NVPTX back end knows PTX ISA versions such as "
                "+ptx78, +ptx80 and +ptx86";
    unsigned version = 0;
    StringRef number = name;
    if (enabled && number.consume_front("ptx") &&
        !number.getAsInteger(10, version))
      requested = std::max(requested, version);
  }
  // LLVM aborts the process on a PTX ISA older than the chip's ("PTX
  // version 6.0 does not support target 'sm_90'").
  std::optional<unsigned> needed = getMinimumPTXVersion(target.getChip());
  if (requested && needed && requested < *needed)
    return module.emitError()
           << "PTX ISA " << requested / 10 << "." << requested % 10
           << " (the features '" << target.getFeatures() << "') is older than "
           << target.getChip() << " needs: give +ptx" << *needed
           << " or later, or no PTX version (the chip's oldest PTX ISA is "
              "the default)";
  return success();
#else
  return module.emitError() << "this LLVM was built without the NVPTX back end";
#endif
}

/// Reports each libdevice function the module calls when `libdevice` is not
/// a file, at its first call (which carries the math op's location).
LogicalResult checkLibdevice(gpu::GPUModuleOp module, StringRef libdevice) {
  if (!libdevice.empty() && llvm::sys::fs::is_regular_file(libdevice))
    return success();
  llvm::StringSet<> declared;
  for (auto func : module.getOps<LLVM::LLVMFuncOp>())
    if (func.isExternal() && func.getName().starts_with("__nv_"))
      declared.insert(func.getName());
  if (declared.empty())
    return success();
  llvm::MapVector<StringRef, Operation *> firstCalls;
  module.walk([&](LLVM::CallOp call) {
    std::optional<StringRef> callee = call.getCallee();
    if (callee && declared.contains(*callee))
      firstCalls.insert({*callee, call});
  });
  for (auto [callee, call] : firstCalls) {
    InFlightDiagnostic diag = emitError(call->getLoc())
                              << "this operation needs the libdevice function '"
                              << callee << "', but ";
    if (libdevice.empty())
      diag << "no CUDA toolkit was found";
    else
      diag << "there is no libdevice at '" << libdevice << "'";
    diag << "; give the CUDA toolkit's root with the pipeline option "
            "cuda-path (sim-translate's --sim-cuda-path) or with $CUDA_HOME";
  }
  return failure();
}

struct CheckTargetPass
    : public sim::impl::SimNVVMCheckTargetBase<CheckTargetPass> {
  using Base::Base;

  void runOnOperation() override {
    gpu::GPUModuleOp module = getOperation();
    // Before nvvm-attach-target: the chip it will attach, alone (the
    // module is not lowered yet).
    if (attaching) {
      if (failed(checkTarget(
              module, NVVM::NVVMTargetAttr::get(&getContext(), /*optLevel=*/2,
                                                "nvptx64-nvidia-cuda", chip))))
        signalPassFailure();
      return;
    }
    bool ok = succeeded(checkLowered(module));
    ok &= succeeded(checkSymbolNames(module));
    if (ArrayAttr targets = module.getTargetsAttr())
      for (Attribute target : targets)
        if (auto nvvm = dyn_cast<NVVM::NVVMTargetAttr>(target))
          ok &= succeeded(checkTarget(module, nvvm));
    ok &= succeeded(checkLibdevice(module, libdevice));
    if (!ok)
      signalPassFailure();
  }
};

} // namespace
