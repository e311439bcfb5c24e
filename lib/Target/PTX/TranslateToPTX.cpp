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
// The options are translation options (--sim-chip=...,
// sim/Target/TranslationOptions.h), since mlir-translate-style tools have no
// pipeline syntax. Failures are diagnostics at the input's locations.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/TranslateToPTX.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Support/ToolDefaults.h"
#include "sim/Target/TranslationOptions.h"

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
#include "llvm/Support/SourceMgr.h"

using namespace mlir;
using namespace mlir::sim;

namespace {

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

/// Parses the input, checks that it holds an `InputOpTy` to compile and that
/// `checkInput` accepts each, runs the pipeline `build` adds, checks that it
/// lowered every `InputOpTy` and writes the PTX.
template <typename InputOpTy>
LogicalResult
translateToPTX(const std::shared_ptr<llvm::SourceMgr> &sourceMgr,
               raw_ostream &os, MLIRContext *context,
               function_ref<void(DialectRegistry &)> registerDialects,
               function_ref<void(OpPassManager &)> build,
               function_ref<LogicalResult(InputOpTy)> checkInput = nullptr) {
  applyPrintOpOnDiagnosticOption(context);
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
  // What --sim-lower-to-gpu leaves next to its gpu.modules (the host plan),
  // so that its output translates as sim-opt --sim-gpu-to-ptx takes it.
  registry.insert<simplan::PlanDialect>();
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
  if (checkInput)
    for (InputOpTy input : module->getOps<InputOpTy>())
      if (failed(checkInput(input)))
        return failure();

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
  // Registers the --sim-* options.
  (void)getTranslationOptions();

  TranslateRegistration simToPTX(
      "sim-to-ptx",
      "Compile a scene to the PTX of its GPU kernels (options --sim-*)",
      [](const std::shared_ptr<llvm::SourceMgr> &sourceMgr, raw_ostream &os,
         MLIRContext *context) -> LogicalResult {
        return translateToPTX<SimulationOp>(
            sourceMgr, os, context,
            [](DialectRegistry &registry) { registry.insert<SimDialect>(); },
            [](OpPassManager &pm) {
              const TranslationOptions &flags = getTranslationOptions();
              flags.addSetParams(pm);
              buildSimToGPUPipeline(pm, flags.strategy, flags.groupSize,
                                    flags.getGPUTarget());
            },
            [](SimulationOp simulation) -> LogicalResult {
              // PTX alone runs only on a GPU, where a group is whole warps of
              // 32 threads and at most 1024 (a bundle's group size may be
              // larger: its CPU kernels take any, and sim-run chooses
              // another for a GPU run).
              int64_t groupSize = getTranslationOptions().groupSize;
              if (groupSize >= 32 && groupSize <= 1024 && groupSize % 32 == 0)
                return success();
              return emitError(simulation.getLoc())
                     << "--sim-group-size must be a multiple of 32 (a GPU "
                        "warp) from 32 to 1024 (a CUDA group), not "
                     << groupSize;
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
              buildSimGPUToPTXPipeline(pm,
                                       getTranslationOptions().getGPUTarget());
            });
      });
}
