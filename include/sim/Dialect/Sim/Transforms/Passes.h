//===- Passes.h - sim dialect passes ----------------------------*- C++ -*-===//
//
// Declares the sim passes and their registration.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_TRANSFORMS_PASSES_H
#define SIM_DIALECT_SIM_TRANSFORMS_PASSES_H

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/Pass/Pass.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "llvm/Support/CommandLine.h"

namespace mlir::sim {

/// Output formats of --sim-print-dependency-graph.
enum class GraphFormat { text, dot };

/// Output formats of --sim-report-memory.
enum class ReportFormat { text, json };

/// The values of every `strategy` option (--sim-plan-memory and
/// --sim-front-end): one list, spelled as the IR prints the Strategy enum.
inline llvm::cl::ValuesClass getStrategyOptionValues() {
  return llvm::cl::values(
      clEnumValN(Strategy::simple, stringifyStrategy(Strategy::simple),
                 "one base step per big step"),
      clEnumValN(Strategy::traditional,
                 stringifyStrategy(Strategy::traditional),
                 "global minimum step, one evaluation per component"),
      clEnumValN(Strategy::hip, stringifyStrategy(Strategy::hip),
                 "the paper's method: interpolated sub-steps"),
      clEnumValN(Strategy::hip_cache, stringifyStrategy(Strategy::hip_cache),
                 "hip with shared-memory caches of window reads"),
      clEnumValN(Strategy::lts, stringifyStrategy(Strategy::lts),
                 "hip with local time steps for stencil components"));
}

/// True for the strategies that sub-step and interpolate inside a big step
/// (`hip`, `hip-cache`, `lts`); `simple` and `traditional` evaluate every
/// component once per big step.
inline bool isSubSteppingStrategy(Strategy strategy) {
  return strategy == Strategy::hip || strategy == Strategy::hip_cache ||
         strategy == Strategy::lts;
}

/// Fails with an error on `simulation` when it is past
/// --sim-insert-interpolation (it holds sim.load or sim.big_step), naming
/// the pass that cannot run on it and what it would re-decide, e.g.
/// ("sim-plan-memory", "its memory plan is").
LogicalResult checkBeforeInterpolation(SimulationOp simulation,
                                       StringRef passArgument,
                                       StringRef decisions);

/// Fails with an error at `read` (an `interpolate` read in `component`'s
/// body of `kind`) when its buffer is declared interp(none) and `strategy`
/// sub-steps (hip, hip-cache): the read would need a value at an
/// intermediate time of the big step, which such a buffer does not have.
LogicalResult checkInterpolable(ReadOp read, BufferOp buffer,
                                ComponentOp component, BodyKind kind,
                                Strategy strategy);

#define GEN_PASS_DECL
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"

#define GEN_PASS_REGISTRATION
#include "sim/Dialect/Sim/Transforms/Passes.h.inc"

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_TRANSFORMS_PASSES_H
