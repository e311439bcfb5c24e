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
  mlir::sim::registerSimToolPasses();

  mlir::DialectRegistry registry;
  mlir::sim::registerSimToolDialects(registry);
  mlir::sim::registerSimReductionPatterns(registry);
  mlir::MLIRContext context(registry);
  return mlir::failed(mlir::mlirReduceMain(argc, argv, context));
}
