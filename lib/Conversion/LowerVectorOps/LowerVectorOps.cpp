//===- LowerVectorOps.cpp - high-level vector ops to the ones we lower ----===//
//
// A component body may use the vector dialect's high-level ops:
// vector.contract (a dot product), vector.outerproduct,
// vector.multi_reduction, vector.transpose, vector.step, vector.shape_cast,
// vector.scan, broadcasts to n-D vectors and masks (vector.create_mask,
// vector.constant_mask). The GPU's convert-gpu-to-nvvm lowers only the 1-D
// ops (extract, insert, reduction, fma, shuffle, ...), and the CPU
// pipeline's convert-vector-to-llvm not all of these, so they compiled for
// no backend; nor did a math.fpowi of vectors (LLVM's powi takes one
// integer exponent). This pass rewrites them with upstream's progressive
// lowering patterns into those ops, and fpowi element by element; the CPU
// kernels, the reference functions and the GPU kernels all run it, so they
// compute the same operations in the same order.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Dialect/Vector/Transforms/LoweringPatterns.h"
#include "mlir/Dialect/Vector/Transforms/VectorRewritePatterns.h"
#include "mlir/Transforms/GreedyPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMLOWERVECTOROPS
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

/// A vector fpowi as one scalar fpowi per element.
struct UnrollVectorPower : OpRewritePattern<math::FPowIOp> {
  using OpRewritePattern::OpRewritePattern;

  LogicalResult matchAndRewrite(math::FPowIOp op,
                                PatternRewriter &rewriter) const override {
    auto type = dyn_cast<VectorType>(op.getType());
    if (!type || type.getRank() != 1 || type.isScalable())
      return failure();
    Location loc = op.getLoc();
    Value result = arith::ConstantOp::create(
        rewriter, loc, type, cast<TypedAttr>(rewriter.getZeroAttr(type)));
    for (int64_t k = 0; k < type.getNumElements(); ++k) {
      Value base = vector::ExtractOp::create(rewriter, loc, op.getLhs(), k);
      Value exponent = vector::ExtractOp::create(rewriter, loc, op.getRhs(), k);
      Value power = math::FPowIOp::create(rewriter, loc, base, exponent);
      result = vector::InsertOp::create(rewriter, loc, power, result, k);
    }
    rewriter.replaceOp(op, result);
    return success();
  }
};

struct SimLowerVectorOpsPass
    : sim::impl::SimLowerVectorOpsBase<SimLowerVectorOpsPass> {
  void runOnOperation() override {
    // Nothing to do (and no folding of other ops) without such an op.
    Operation *found = nullptr;
    getOperation()->walk([&](Operation *op) {
      bool vectorPower =
          isa<math::FPowIOp>(op) && isa<VectorType>(op->getResultTypes()[0]);
      auto broadcast = dyn_cast<vector::BroadcastOp>(op);
      bool nDBroadcast =
          broadcast && broadcast.getResultVectorType().getRank() > 1;
      if (!vectorPower && !nDBroadcast &&
          !isa<vector::ContractionOp, vector::OuterProductOp,
               vector::MultiDimReductionOp, vector::TransposeOp, vector::StepOp,
               vector::InsertStridedSliceOp, vector::ExtractStridedSliceOp,
               vector::ShapeCastOp, vector::CreateMaskOp,
               vector::ConstantMaskOp, vector::ScanOp>(op))
        return WalkResult::advance();
      found = op;
      return op->getParentOfType<sim::SimulationOp>() ? WalkResult::interrupt()
                                                      : WalkResult::advance();
    });
    if (!found)
      return;
    // The lowerings start their vectors from ub.poison, which the bodies of
    // a scene cannot hold; the kernels and reference functions that the
    // lowerings of a scene make can.
    if (found->getParentOfType<sim::SimulationOp>()) {
      found->emitOpError()
          << "is in a body of a sim.simulation, whose vector ops "
             "--sim-lower-vector-ops does not lower (it lowers those of "
             "kernels); run it after --sim-lower-to-cpu, --sim-lower-to-gpu "
             "or --sim-lower-to-reference";
      return signalPassFailure();
    }
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
    // n-D broadcasts as 1-D ones inserted row by row; masks as comparisons
    // of vector.step with the bound (1-D) and inserts of those (n-D).
    vector::populateVectorBroadcastLoweringPatterns(patterns);
    // Scans as element-wise operations on slices, in order.
    vector::populateVectorScanLoweringPatterns(patterns);
    vector::populateVectorMaskOpLoweringPatterns(patterns);
    vector::populateVectorMaskMaterializationPatterns(
        patterns, /*force32BitVectorIndices=*/false);
    // Strided slices (which the multi-reduction lowering makes) as
    // shuffles, extracts and inserts.
    vector::populateVectorInsertExtractStridedSliceTransforms(patterns);
    patterns.add<UnrollVectorPower>(&getContext());
    if (failed(applyPatternsGreedily(getOperation(), std::move(patterns))))
      return signalPassFailure();
  }
};

} // namespace
