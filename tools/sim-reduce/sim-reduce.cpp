//===- sim-reduce.cpp - the sim test case reducer -------------------------===//
//
// mlir-reduce for sim: shrinks a scene while a test script still calls it
// interesting, e.g. a scene that makes a pass fail or a backend disagree
// with the reference executor, down to what a bug report needs:
//
//   sim-reduce scene.mlir \
//     --reduction-tree='traversal-mode=0 test=still-fails.sh' -o small.mlir
//
// The script gets the candidate's path as its first argument and, as for
// mlir-reduce, calls it interesting by exiting with a status other than 0
// (test/Tools/sim-reduce/Inputs has one). Candidates that do not verify are
// never interesting and never reach the script. The reduction
// tree deletes operations (parameters, totals, the operations of bodies),
// then tries the sim dialect's reduction patterns (a component with the
// buffers it writes, reads as zeros, parameters as their values, a smaller
// range: lib/Dialect/Sim/Reduce); --opt-reduction-pass='opt-pass=... test=...'
// keeps what a pass pipeline of sim-opt's (sim/InitAllDialects.h), e.g.
// sim-prune, makes of the scene when it is still interesting.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/Reduce/SimReductionPatterns.h"
#include "sim/InitAllDialects.h"
#include "sim/Support/ToolDefaults.h"

#include "mlir/IR/DialectRegistry.h"
#include "mlir/IR/MLIRContext.h"
#include "mlir/Tools/mlir-reduce/MlirReduceMain.h"

int main(int argc, char **argv) {
  std::string overInput = mlir::sim::describeOutputOverInput(argc, argv);
  if (!overInput.empty()) {
    llvm::errs() << "sim-reduce: error: " << overInput << "\n";
    return 1;
  }
  mlir::sim::registerSimToolPasses();

  mlir::DialectRegistry registry;
  mlir::sim::registerSimToolDialects(registry);
  mlir::sim::registerSimReductionPatterns(registry);
  mlir::MLIRContext context(registry);
  // The reducer verifies every candidate it makes, and most fail (an op
  // whose operand was removed, a component that writes a removed buffer):
  // their errors are no news and buried the one message that is, the
  // warning that the input itself is not interesting (the test script
  // exits 0 on it, the reverse of what mlir-reduce wants), which the
  // context's default handler does not print at all. The input's parse
  // errors go through the main's own handler.
  context.getDiagEngine().registerHandler([](mlir::Diagnostic &diagnostic) {
    if (diagnostic.getSeverity() != mlir::DiagnosticSeverity::Warning)
      return mlir::success();
    std::string message = diagnostic.str();
    if (llvm::StringRef(message).starts_with("uninterested module"))
      message = "the input is not interesting, so nothing was reduced: the "
                "test script exits with status 0 on it, and a candidate is "
                "interesting when it exits with another";
    llvm::errs() << "sim-reduce: warning: " << message << "\n";
    return mlir::success();
  });
  return mlir::failed(mlir::mlirReduceMain(argc, argv, context));
}
