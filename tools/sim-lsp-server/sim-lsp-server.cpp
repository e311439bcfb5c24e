//===- sim-lsp-server.cpp - the sim language server -----------------------===//
//
// mlir-lsp-server for sim: diagnostics, definitions, references, hovers and
// outlines of scenes in an editor (VS Code's MLIR extension, or any LSP
// client told to run sim-lsp-server for .mlir files). It knows the dialects
// sim-opt knows (sim/InitAllDialects.h), so a scene that sim-opt parses and
// verifies shows no error here, and one that it rejects shows the same error
// at the same place.
//
//===----------------------------------------------------------------------===//

#include "sim/InitAllDialects.h"
#include "sim/Support/ToolDefaults.h"

#include "mlir/IR/DialectRegistry.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/Tools/mlir-lsp-server/MlirLspServerMain.h"

int main(int argc, char **argv) {
  // An error in a component would otherwise carry a dump of the whole
  // sim.simulation as a note: the option sim-opt defaults to false.
  mlir::registerMLIRContextCLOptions();
  mlir::sim::setToolDefaults();

  mlir::DialectRegistry registry;
  mlir::sim::registerSimToolDialects(registry);
  return mlir::failed(mlir::MlirLspServerMain(argc, argv, registry));
}
