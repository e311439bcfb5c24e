//===- TranslateToPTX.cpp - scenes and gpu.modules to PTX -----------------===//
//
// The translations of sim-translate that end in PTX text. Each parses its
// input, runs a pass pipeline that leaves gpu.binary ops holding PTX (built
// by lib/Pipelines, the same pipelines sim-opt runs) and writes the PTX:
//
//   --sim-to-ptx   a scene: buildSimToGPUPipeline (front end, lowering to
//                  GPU kernels, GPU back end)
//   --gpu-to-ptx   gpu.modules: buildSimGPUToPTXPipeline only
//
// The options are translation options (--sim-chip=...), since
// mlir-translate-style tools have no pipeline syntax. Failures are
// diagnostics at the input's locations.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/TranslateToPTX.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Pipelines/Pipelines.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/Parser/Parser.h"
#include "mlir/Pass/PassManager.h"
#include "mlir/Tools/mlir-translate/Translation.h"
#include "llvm/Support/CommandLine.h"
#include "llvm/Support/SourceMgr.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

/// The translation options, registered only by registerToPTXTranslations
/// (so only in sim-translate). Their defaults are those of the pipelines'
/// option structs.
struct PTXTranslationOptions {
  const SimToGPUOptions defaults;
  llvm::cl::OptionCategory category{"PTX options (--sim-to-ptx, --gpu-to-ptx)"};
  llvm::cl::opt<Strategy> strategy{
      "sim-strategy",
      llvm::cl::desc("--sim-to-ptx: the strategy to compile for (default hip)"),
      llvm::cl::init(defaults.strategy.getValue()), getStrategyOptionValues(),
      llvm::cl::cat(category)};
  llvm::cl::opt<unsigned> groupSize{
      "sim-group-size",
      llvm::cl::desc("--sim-to-ptx: threads per thread group (default 256)"),
      llvm::cl::init(defaults.groupSize.getValue()), llvm::cl::cat(category)};
  llvm::cl::opt<std::string> chip{
      "sim-chip",
      llvm::cl::desc("The NVIDIA GPU to compile for (default sm_90)"),
      llvm::cl::init(defaults.chip.getValue()), llvm::cl::cat(category)};
  llvm::cl::opt<std::string> features{
      "sim-features",
      llvm::cl::desc("NVPTX features, e.g. +ptx80 (default: the chip's "
                     "oldest PTX ISA)"),
      llvm::cl::init(defaults.features.getValue()), llvm::cl::cat(category)};
  llvm::cl::opt<unsigned> optLevel{
      "sim-opt-level",
      llvm::cl::desc("LLVM optimization level of the kernels, 0 to 3 "
                     "(default 3)"),
      llvm::cl::init(defaults.optLevel.getValue()), llvm::cl::cat(category)};
  llvm::cl::opt<std::string> cudaPath{
      "sim-cuda-path",
      llvm::cl::desc("Root of the CUDA toolkit that provides libdevice "
                     "(default: $CUDA_ROOT, $CUDA_HOME, $CUDA_PATH, then "
                     "/usr/local/cuda)"),
      llvm::cl::init(defaults.cudaPath.getValue()), llvm::cl::cat(category)};

  void copyTo(GPUTargetOptions &options) const {
    options.chip = chip.getValue();
    options.features = features.getValue();
    options.optLevel = optLevel.getValue();
    options.cudaPath = cudaPath.getValue();
  }
  void copyTo(SimToGPUOptions &options) const {
    options.strategy = strategy.getValue();
    options.groupSize = groupSize.getValue();
    options.chip = chip.getValue();
    options.features = features.getValue();
    options.optLevel = optLevel.getValue();
    options.cudaPath = cudaPath.getValue();
  }
};

/// mlirTranslateMain makes every context it creates print the whole failing
/// operation under each diagnostic, which buries a one-line message under a
/// dump of a lowered gpu.module. sim's tools print it only when asked
/// (--mlir-print-op-on-diagnostic). mlirTranslateMain sets the flag after
/// creating the context, so it can only be undone here, in the translation.
// TODO: use include/sim/Support/ToolDefaults.h once sim-opt's shared helper
// exists.
void applyDiagnosticDefaults(MLIRContext *context) {
  auto &options = llvm::cl::getRegisteredOptions();
  auto it = options.find("mlir-print-op-on-diagnostic");
  if (it == options.end() || it->second->getNumOccurrences() == 0)
    context->printOpOnDiagnostic(false);
}

/// Writes the PTX of every gpu.binary in `module`: one PTX module as is, or
/// several, each after a `// ----- @<gpu.module name>` line.
LogicalResult writePTX(ModuleOp module, raw_ostream &os) {
  SmallVector<std::pair<StringRef, StringRef>> ptx;
  for (auto binary : module.getOps<gpu::BinaryOp>()) {
    for (Attribute attr : binary.getObjectsAttr()) {
      auto object = dyn_cast<gpu::ObjectAttr>(attr);
      if (!object || object.getFormat() != gpu::CompilationTarget::Assembly)
        return binary.emitError()
               << "expected PTX (an object in assembly format), got " << attr;
      ptx.emplace_back(binary.getName(), object.getObject().getValue());
    }
  }
  if (ptx.empty())
    return module.emitError("the pipeline produced no GPU kernels");
  for (auto [name, text] : ptx) {
    if (ptx.size() > 1)
      os << "// ----- @" << name << "\n";
    os << text;
  }
  return success();
}

/// Reports every operation of type `OpTy` in `module`: `what` it should have
/// been or had.
template <typename OpTy>
LogicalResult reportEach(ModuleOp module, StringRef what) {
  bool found = false;
  for (OpTy op : module.getOps<OpTy>()) {
    op.emitOpError(what);
    found = true;
  }
  return failure(found);
}

/// Parses the input, checks that it holds an `InputOpTy` to compile, runs the
/// pipeline `build` adds, checks that it lowered every `InputOpTy` and writes
/// the PTX.
template <typename InputOpTy>
LogicalResult
translateToPTX(const std::shared_ptr<llvm::SourceMgr> &sourceMgr,
               raw_ostream &os, MLIRContext *context,
               function_ref<void(DialectRegistry &)> registerDialects,
               function_ref<void(OpPassManager &)> build) {
  applyDiagnosticDefaults(context);
  // Some upstream passes report an error and still succeed (e.g.
  // gpu-module-to-binary when $CUDA_HOME names no CUDA toolkit); any error
  // fails the translation.
  bool reportedError = false;
  ScopedDiagnosticHandler errorTracker(context, [&](Diagnostic &diag) {
    reportedError |= diag.getSeverity() == DiagnosticSeverity::Error;
    return failure(); // Not handled: the tool's handler prints it.
  });

  DialectRegistry registry;
  registry.insert<arith::ArithDialect, math::MathDialect, scf::SCFDialect,
                  vector::VectorDialect>();
  registerGPUToPTXDependencies(registry);
  registerDialects(registry);
  context->appendDialectRegistry(registry);

  OwningOpRef<ModuleOp> module =
      parseSourceFile<ModuleOp>(sourceMgr, ParserConfig(context));
  if (!module)
    return failure();
  if (module->getOps<InputOpTy>().empty())
    return module->emitError()
           << "there is no " << InputOpTy::getOperationName()
           << " to compile to PTX";

  PassManager pm(context, ModuleOp::getOperationName());
  if (failed(applyPassManagerCLOptions(pm)))
    return failure();
  build(pm);
  if (failed(pm.run(*module)) ||
      failed(reportEach<InputOpTy>(
          *module, "was not compiled to GPU kernels by the pipeline")) ||
      reportedError)
    return failure();
  return writePTX(*module, os);
}

} // namespace

void mlir::sim::registerToPTXTranslations() {
  static PTXTranslationOptions options;

  TranslateRegistration simToPTX(
      "sim-to-ptx",
      "Compile a scene to the PTX of its GPU kernels (options --sim-*)",
      [](const std::shared_ptr<llvm::SourceMgr> &sourceMgr, raw_ostream &os,
         MLIRContext *context) {
        return translateToPTX<SimulationOp>(
            sourceMgr, os, context,
            [](DialectRegistry &registry) { registry.insert<SimDialect>(); },
            [](OpPassManager &pm) {
              SimToGPUOptions pipeline;
              options.copyTo(pipeline);
              buildSimToGPUPipeline(pm, pipeline);
            });
      });

  TranslateRegistration gpuToPTX(
      "gpu-to-ptx",
      "Compile gpu.modules to PTX (options --sim-chip, --sim-features, "
      "--sim-opt-level, --sim-cuda-path)",
      [](const std::shared_ptr<llvm::SourceMgr> &sourceMgr, raw_ostream &os,
         MLIRContext *context) {
        return translateToPTX<gpu::GPUModuleOp>(
            sourceMgr, os, context, [](DialectRegistry &) {},
            [](OpPassManager &pm) {
              GPUTargetOptions pipeline;
              options.copyTo(pipeline);
              buildSimGPUToPTXPipeline(pm, pipeline);
            });
      });
}
