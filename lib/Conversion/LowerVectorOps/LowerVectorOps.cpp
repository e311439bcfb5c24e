//===- LowerVectorOps.cpp - high-level vector ops to the ones we lower ----===//
//
// A component body may use the vector dialect's high-level ops:
// vector.contract (a dot product), vector.outerproduct,
// vector.multi_reduction, vector.transpose, vector.step. The CPU pipeline's
// convert-vector-to-llvm and the GPU's convert-gpu-to-nvvm lower only the
// 1-D ops (extract, insert, reduction, fma, shuffle, ...), so these compiled
// for no backend. This pass rewrites them with upstream's progressive
// lowering patterns into those ops; the CPU kernels, the reference
// functions and the GPU kernels all run it, so they compute the same
// operations in the same order.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Dialect/Vector/Transforms/LoweringPatterns.h"
#include "mlir/Transforms/GreedyPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERVECTOROPS
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

struct SimLowerVectorOpsPass
    : sim::impl::SimLowerVectorOpsBase<SimLowerVectorOpsPass> {
  void runOnOperation() override {
    // Nothing to do (and no folding of other ops) without such an op.
    WalkResult found = getOperation()->walk([](Operation *op) {
      return isa<vector::ContractionOp, vector::OuterProductOp,
                 vector::MultiDimReductionOp, vector::TransposeOp,
                 vector::StepOp>(op)
                 ? WalkResult::interrupt()
                 : WalkResult::advance();
    });
    if (!found.wasInterrupted())
      return;
    RewritePatternSet patterns(&getContext());
    // A contraction as multiplications and reductions in program order
    // (ParallelArith), not llvm.matrix intrinsics that only the CPU has.
    vector::populateVectorContractLoweringPatterns(
        patterns, vector::VectorContractLowering::ParallelArith);
    vector::populateVectorOuterProductLoweringPatterns(patterns);
    vector::populateVectorMultiReductionLoweringPatterns(
        patterns, vector::VectorMultiReductionLowering::InnerReduction);
    vector::populateVectorTransposeLoweringPatterns(
        patterns, vector::VectorTransposeLowering::EltWise);
    vector::populateVectorStepLoweringPatterns(patterns);
    vector::populateVectorShapeCastLoweringPatterns(patterns);
    if (failed(applyPatternsGreedily(getOperation(), std::move(patterns))))
      return signalPassFailure();
  }
};

} // namespace
