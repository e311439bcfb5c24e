//===- FusedMultiplyAdd.cpp - vector.fma to llvm.intr.fma -----------------===//
//
// `vector.fma` rounds once. Upstream lowers it to `llvm.intr.fmuladd`, which
// a target without FMA (generic x86-64) splits into a multiply and an add;
// `llvm.intr.fma` is fused on every target, so the CPU kernels, the
// reference functions and the PTX compute the same bits.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Dialect/Vector/Transforms/LoweringPatterns.h"
#include "mlir/IR/PatternMatch.h"
#include "mlir/Transforms/GreedyPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMFUSEDMULTIPLYADD
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

/// `vector.fma %a, %b, %c` to `llvm.intr.fma` on the same vector type. The
/// LLVM dialect takes builtin vectors of floats, so the op stays valid for
/// the conversions that follow and none of them touches it again.
struct FMAToLLVMIntrinsic : OpRewritePattern<vector::FMAOp> {
  using OpRewritePattern::OpRewritePattern;

  LogicalResult matchAndRewrite(vector::FMAOp op,
                                PatternRewriter &rewriter) const override {
    VectorType type = op.getVectorType();
    // llvm.intr.fma takes one-dimensional vectors (and scalable ones).
    if (type.getRank() != 1)
      return rewriter.notifyMatchFailure(op, "not a one-dimensional vector");
    rewriter.replaceOpWithNewOp<LLVM::FMAOp>(op, op.getLhs(), op.getRhs(),
                                             op.getAcc());
    return success();
  }
};

struct SimFusedMultiplyAddPass
    : sim::impl::SimFusedMultiplyAddBase<SimFusedMultiplyAddPass> {
  void runOnOperation() override {
    RewritePatternSet patterns(&getContext());
    // n-D fmas become 1-D ones first (upstream's pattern, which keeps them
    // vector.fma), then each becomes the intrinsic.
    vector::populateVectorRankReducingFMAPattern(patterns);
    patterns.add<FMAToLLVMIntrinsic>(&getContext());
    // Only these rewrites: no folding, no constant CSE, no region
    // simplification, so the kernels keep every other op as they were.
    GreedyRewriteConfig config;
    config.enableFolding(false).enableConstantCSE(false);
    config.setRegionSimplificationLevel(GreedySimplifyRegionLevel::Disabled);
    if (failed(
            applyPatternsGreedily(getOperation(), std::move(patterns), config)))
      signalPassFailure();
  }
};

} // namespace
