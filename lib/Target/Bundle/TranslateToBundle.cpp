//===- TranslateToBundle.cpp - sim-translate --sim-to-bundle --------------===//
//
// The translation that writes a scene's bundle (Bundle.cpp) with the options
// every sim translation shares (--sim-group-size, --sim-chip,
// --sim-set-params, ...) and its own --sim-strategies.
//
//===----------------------------------------------------------------------===//

#include "sim/Support/ToolDefaults.h"
#include "sim/Target/Bundle.h"
#include "sim/Target/TranslationOptions.h"

#include "mlir/IR/BuiltinOps.h"
#include "mlir/Parser/Parser.h"
#include "mlir/Pass/PassManager.h"
#include "mlir/Tools/mlir-translate/Translation.h"
#include "llvm/Support/SourceMgr.h"

using namespace mlir;
using namespace mlir::sim;

void mlir::sim::registerToBundleTranslation() {
  // Registers the --sim-* options.
  (void)getTranslationOptions();

  TranslateRegistration toBundle(
      "sim-to-bundle",
      "Compile a scene for every strategy into a bundle (.simb) for the "
      "runtime (options --sim-*)",
      [](const std::shared_ptr<llvm::SourceMgr> &sourceMgr, raw_ostream &os,
         MLIRContext *context) {
        applyPrintOpOnDiagnosticOption(context);
        DialectRegistry registry;
        registerBundleDependencies(registry);
        context->appendDialectRegistry(registry);
        OwningOpRef<ModuleOp> module =
            parseSourceFile<ModuleOp>(sourceMgr, ParserConfig(context));
        if (!module)
          return failure();

        const TranslationOptions &flags = getTranslationOptions();
        // --sim-set-params=...: the scene as if it said so (max_steps is
        // compiled into the plans); errors are at the scene.
        if (!flags.setParams.empty()) {
          PassManager pm(context, ModuleOp::getOperationName());
          flags.addSetParams(pm);
          if (failed(pm.run(*module)))
            return failure();
        }
        BundleOptions options;
        if (!flags.strategies.empty())
          options.strategies.assign(flags.strategies.begin(),
                                    flags.strategies.end());
        options.groupSize = flags.groupSize;
        options.target = flags.getGPUTarget();
        options.flushSubnormals = flags.ftz;
        options.distributed = flags.distributed;
        options.cpuLevelsPerLane = flags.cpuLevelsPerLane;
        if (!flags.cpuIsas.empty()) {
          // `host`: the level a run on this machine would take (a bundle
          // compiled to run here, as sim-run compiles a .mlir scene); a
          // level it names twice that way is compiled once.
          options.cpuIsas.clear();
          for (const std::string &isa : flags.cpuIsas) {
            if (isa != "host") {
              options.cpuIsas.push_back(isa);
              continue;
            }
            std::string host = getHostCPUIsa();
            if (!llvm::is_contained(flags.cpuIsas, host) &&
                !llvm::is_contained(options.cpuIsas, host))
              options.cpuIsas.push_back(host);
          }
        }
        return writeBundle(*module, options, os);
      });
}
