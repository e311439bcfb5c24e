//===- ValuePrecision.h - the float width a value derives from --*- C++ -*-===//
//
// The narrowest floating-point width each buffer's and each total's values
// are computed through: a buffer of f64 elements whose writer reads an f32
// buffer, converts to f32 or calls an f32 math function is only as precise
// as f32, whatever its element type. sim-run's --check compares a backend
// with the reference executor at a tolerance for that width, not for the
// element type (an f32 `math.sin` on CUDA is libdevice's, an ulp or two from
// libm's, and an f64 value computed from it inherits that difference).
//
// A body's own width is the narrowest float type among its block arguments
// and the operands and results of its operations (vector and shaped types by
// their element type); a buffer's width is the narrowest of its element
// type, its init body, its writer's num_steps and evaluate bodies and the
// widths of the buffers those bodies read (a Hermite read reads the
// derivative buffer too); a total's, of its type, its body and what it
// reads. Reads through the back edge count like any other: the widths are a
// fixpoint over the scene's buffers.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_ANALYSIS_VALUEPRECISION_H
#define SIM_ANALYSIS_VALUEPRECISION_H

#include "sim/Dialect/Sim/IR/SimOps.h"

#include "llvm/ADT/DenseMap.h"

namespace mlir::sim {

class ValuePrecision {
public:
  explicit ValuePrecision(SimulationOp simulation);

  /// The narrowest float width, in bits, the buffer's values derive from.
  unsigned getBits(BufferOp buffer) const;
  /// The narrowest float width, in bits, the total's values derive from.
  unsigned getBits(TotalOp total) const;

private:
  llvm::DenseMap<Operation *, unsigned> bits;
};

} // namespace mlir::sim

#endif // SIM_ANALYSIS_VALUEPRECISION_H
