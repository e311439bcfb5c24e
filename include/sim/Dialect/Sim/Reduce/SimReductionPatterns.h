//===- SimReductionPatterns.h - sim-reduce's patterns -----------*- C++ -*-===//
//
// The reduction patterns of the sim dialect (DialectReductionPatternInterface),
// which sim-reduce's reduction tree tries on a scene after deleting what it
// can delete alone.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_REDUCE_SIMREDUCTIONPATTERNS_H
#define SIM_DIALECT_SIM_REDUCE_SIMREDUCTIONPATTERNS_H

namespace mlir {
class DialectRegistry;
namespace sim {

/// Attaches the sim dialect's reduction patterns to `registry`.
void registerSimReductionPatterns(DialectRegistry &registry);

} // namespace sim
} // namespace mlir

#endif // SIM_DIALECT_SIM_REDUCE_SIMREDUCTIONPATTERNS_H
