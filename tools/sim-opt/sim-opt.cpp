//===- sim-opt.cpp - the sim optimizer driver -----------------------------===//
//
// mlir-opt for sim: parses, verifies, transforms and prints sim scenes. It
// registers only the dialects a scene body may use, those of the lowering and
// the GPU back end (gpu, nvvm, llvm, ...) and the passes that matter for
// scenes and for the back end (sim/InitAllDialects.h, shared with
// sim-lsp-server and sim-reduce), so `--help` stays readable, and sets the
// sim tools' option defaults (sim/Support/ToolDefaults.h).
//
//===----------------------------------------------------------------------===//

#include "sim/InitAllDialects.h"
#include "sim/Support/ToolDefaults.h"

#include "mlir/IR/DialectRegistry.h"
#include "mlir/Tools/mlir-opt/MlirOptMain.h"

int main(int argc, char **argv) {
  // Errors name the operation and location; no dump of the whole simulation
  // unless --mlir-print-op-on-diagnostic asks for it.
  mlir::sim::setToolDefaults();
  std::string runtimeFile = mlir::sim::describeRuntimeFileInput(argc, argv);
  if (!runtimeFile.empty()) {
    llvm::errs() << "sim-opt: error: " << runtimeFile << "\n";
    return 1;
  }
  std::string overInput = mlir::sim::describeOutputOverInput(argc, argv);
  if (!overInput.empty()) {
    llvm::errs() << "sim-opt: error: " << overInput << "\n";
    return 1;
  }

  mlir::DialectRegistry registry;
  mlir::sim::registerSimToolDialects(registry);

  mlir::sim::registerSimToolPasses();

  return mlir::asMainReturnCode(mlir::MlirOptMain(
      argc, argv, "sim optimizer driver: scenes in the sim dialect\n",
      registry));
}
