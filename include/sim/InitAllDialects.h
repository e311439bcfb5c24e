//===- InitAllDialects.h - dialects and passes of sim's tools ---*- C++ -*-===//
//
// What the tools that read scenes as text (sim-opt, sim-lsp-server,
// sim-reduce) register: the dialects a scene may use (sim and the upstream
// dialects of its bodies) and those of its lowering and GPU back end (plan,
// gpu, memref, func, and what the PTX pipeline loads), and the passes that
// matter for scenes and for the back end. A scene that one of the tools
// accepts, the others accept too, and sim-reduce's --opt-reduction-pass runs
// the passes sim-opt runs.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_INITALLDIALECTS_H
#define SIM_INITALLDIALECTS_H

#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/Transforms/Passes.h"
#include "sim/Pipelines/Pipelines.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Func/IR/FuncOps.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/MemRef/IR/MemRef.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/DialectRegistry.h"
#include "mlir/Transforms/Passes.h"

namespace mlir::sim {

/// Adds the dialects of scenes, of their lowering and of the GPU back end
/// to `registry`.
inline void registerSimToolDialects(DialectRegistry &registry) {
  registry.insert<SimDialect, arith::ArithDialect, math::MathDialect,
                  scf::SCFDialect, vector::VectorDialect, simplan::PlanDialect,
                  gpu::GPUDialect, memref::MemRefDialect, func::FuncDialect>();
  registerGPUToPTXDependencies(registry);
}

/// Registers sim's passes and pipelines and the upstream passes that are
/// useful on scenes, with the global pass registry.
inline void registerSimToolPasses() {
  static bool initOnce = [] {
    registerSimPasses();
    registerSimConversionPasses();
    registerSimPipelines();
    registerGPUToPTXPasses();
    registerCanonicalizerPass();
    registerCSEPass();
    registerSymbolDCEPass();
    registerInlinerPass();
    registerLoopInvariantCodeMotionPass();
    return true;
  }();
  (void)initOnce;
}

} // namespace mlir::sim

#endif // SIM_INITALLDIALECTS_H
