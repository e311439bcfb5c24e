//===- sim-opt.cpp - the sim optimizer driver -----------------------------===//
//
// mlir-opt for sim: parses, verifies, transforms and prints sim scenes. It
// registers only the dialects a scene body may use, those of the lowering and
// the GPU back end (gpu, nvvm, llvm, ...) and the passes that matter for
// scenes and for the back end, so `--help` stays readable, and sets the sim
// tools' option defaults (sim/Support/ToolDefaults.h).
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Support/ToolDefaults.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/DialectRegistry.h"
#include "mlir/Tools/mlir-opt/MlirOptMain.h"
#include "mlir/Transforms/Passes.h"

int main(int argc, char **argv) {
  // Errors name the operation and location; no dump of the whole simulation
  // unless --mlir-print-op-on-diagnostic asks for it.
  mlir::sim::setToolDefaults();
  std::string runtimeFile = mlir::sim::describeRuntimeFileInput(argc, argv);
  if (!runtimeFile.empty()) {
    llvm::errs() << "sim-opt: error: " << runtimeFile << "\n";
    return 1;
  }

  mlir::DialectRegistry registry;
  registry.insert<mlir::sim::SimDialect, mlir::arith::ArithDialect,
                  mlir::math::MathDialect, mlir::scf::SCFDialect,
                  mlir::vector::VectorDialect, mlir::simplan::PlanDialect,
                  mlir::gpu::GPUDialect, mlir::memref::MemRefDialect,
                  mlir::func::FuncDialect>();
  mlir::sim::registerGPUToPTXDependencies(registry);

  mlir::sim::registerSimPasses();
  mlir::sim::registerSimConversionPasses();
  mlir::sim::registerSimPipelines();
  mlir::sim::registerGPUToPTXPasses();
  // Upstream passes that are useful on scenes.
  mlir::registerCanonicalizerPass();
  mlir::registerCSEPass();
  mlir::registerSymbolDCEPass();
  mlir::registerInlinerPass();
  mlir::registerLoopInvariantCodeMotionPass();

  return mlir::asMainReturnCode(mlir::MlirOptMain(
      argc, argv, "sim optimizer driver: scenes in the sim dialect\n",
      registry));
}
