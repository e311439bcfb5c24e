//===- LowerSubgroupReduce.cpp - warp reductions as shuffles --------------===//
//
// The kernels combine a warp's lanes with gpu.subgroup_reduce (minima of
// num_steps, sums of evaluation counts), which convert-gpu-to-nvvm lowers to
// `redux.sync`, an instruction of sm_80 and later. For older chips (sm_70
// Volta, sm_75 Turing) it refuses the operation instead, so no kernel
// compiled. This pass rewrites every gpu.subgroup_reduce into a butterfly of
// gpu.shuffle xor over the 32 lanes of a warp (shfl.sync, every chip), with
// upstream's patterns; integer minima and sums give the same value in any
// order. See the pass description in Passes.td.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/PTX/Passes.h"

#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/GPU/Transforms/Passes.h"
#include "mlir/Transforms/GreedyPatternRewriteDriver.h"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMGPULOWERSUBGROUPREDUCE
#include "sim/Target/PTX/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;
using namespace mlir::sim;

namespace {

/// The lanes of an NVIDIA warp, and the widest value shfl.sync moves.
constexpr unsigned kWarpLanes = 32;
constexpr unsigned kShuffleBits = 32;

struct LowerSubgroupReducePass
    : public sim::impl::SimGPULowerSubgroupReduceBase<LowerSubgroupReducePass> {
  void runOnOperation() override {
    RewritePatternSet patterns(&getContext());
    populateGpuBreakDownSubgroupReducePatterns(patterns, kShuffleBits);
    populateGpuLowerSubgroupReduceToShufflePatterns(patterns, kWarpLanes,
                                                    kShuffleBits);
    if (failed(applyPatternsGreedily(getOperation(), std::move(patterns))))
      return signalPassFailure();
    // A reduction of a type no pattern takes (wider than 32 bits) would
    // reach convert-gpu-to-nvvm and fail there without saying why.
    WalkResult result = getOperation()->walk([](gpu::SubgroupReduceOp op) {
      op.emitOpError() << "cannot become warp shuffles of at most "
                       << kShuffleBits
                       << " bits for a chip without redux.sync (before "
                          "sm_80); compile for sm_80 or later";
      return WalkResult::interrupt();
    });
    if (result.wasInterrupted())
      signalPassFailure();
  }
};

} // namespace
