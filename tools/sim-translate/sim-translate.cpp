//===- sim-translate.cpp - the sim translation driver ---------------------===//
//
// mlir-translate for sim: translates scenes (and gpu.modules) to what leaves
// the compiler, e.g. `sim-translate scene.mlir --sim-to-ptx -o scene.ptx`.
// The translations live in lib/Target; this is registration plus
// mlirTranslateMain.
//
//===----------------------------------------------------------------------===//

#include "sim/InitAllTranslations.h"
#include "sim/Support/ToolDefaults.h"

#include "mlir/Pass/PassManager.h"
#include "mlir/Tools/mlir-translate/MlirTranslateMain.h"

int main(int argc, char **argv) {
  mlir::sim::setToolDefaults();
  std::string runtimeFile = mlir::sim::describeRuntimeFileInput(argc, argv);
  if (!runtimeFile.empty()) {
    llvm::errs() << "sim-translate: error: " << runtimeFile << "\n";
    return 1;
  }
  std::string overInput = mlir::sim::describeOutputOverInput(argc, argv);
  if (!overInput.empty()) {
    llvm::errs() << "sim-translate: error: " << overInput << "\n";
    return 1;
  }
  mlir::sim::registerSimTranslations();
  // The translations run pass pipelines: --mlir-print-ir-after-failure,
  // --mlir-timing and friends apply to them.
  mlir::registerPassManagerCLOptions();
  return mlir::failed(
      mlir::mlirTranslateMain(argc, argv, "sim translation driver\n"));
}
