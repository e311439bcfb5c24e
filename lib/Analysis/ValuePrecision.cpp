//===- ValuePrecision.cpp - the float width a value derives from ----------===//
//
// See ValuePrecision.h.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/ValuePrecision.h"

#include "mlir/IR/BuiltinTypes.h"
#include "llvm/ADT/STLExtras.h"
#include "llvm/ADT/StringMap.h"

#include <algorithm>
#include <limits>

using namespace mlir;
using namespace mlir::sim;

namespace {

constexpr unsigned kNoFloat = std::numeric_limits<unsigned>::max();

/// The width of a float type, or of the float elements of a vector or
/// shaped type; kNoFloat for any other type.
unsigned floatBits(Type type) {
  if (auto shaped = dyn_cast<ShapedType>(type))
    type = shaped.getElementType();
  if (auto floatType = dyn_cast<FloatType>(type))
    return floatType.getWidth();
  return kNoFloat;
}

/// What one body computes through: its own narrowest float width and the
/// buffers it reads (any symbol reference to a buffer of the scene).
struct BodyUse {
  unsigned bits = kNoFloat;
  SmallVector<BufferOp> reads;
};

void addBody(Region &region, const llvm::StringMap<BufferOp> &buffers,
             BodyUse &use) {
  region.walk([&](Block *block) {
    for (BlockArgument argument : block->getArguments())
      use.bits = std::min(use.bits, floatBits(argument.getType()));
  });
  region.walk([&](Operation *op) {
    for (Type type : op->getOperandTypes())
      use.bits = std::min(use.bits, floatBits(type));
    for (Type type : op->getResultTypes())
      use.bits = std::min(use.bits, floatBits(type));
    for (NamedAttribute attribute : op->getAttrs())
      if (auto symbol = dyn_cast<FlatSymbolRefAttr>(attribute.getValue()))
        if (BufferOp read = buffers.lookup(symbol.getValue()))
          use.reads.push_back(read);
  });
}

} // namespace

ValuePrecision::ValuePrecision(SimulationOp simulation) {
  llvm::StringMap<BufferOp> buffers;
  for (BufferOp buffer : simulation.getBuffers())
    buffers[buffer.getSymName()] = buffer;

  // Each buffer's and total's own width and reads, then the fixpoint.
  llvm::DenseMap<Operation *, BodyUse> uses;
  for (BufferOp buffer : simulation.getBuffers()) {
    BodyUse &use = uses[buffer];
    use.bits = floatBits(buffer.getElementType());
    addBody(buffer.getInit(), buffers, use);
    if (ComponentOp writer = simulation.getWriter(buffer)) {
      addBody(writer.getNumSteps(), buffers, use);
      addBody(writer.getEvaluate(), buffers, use);
    }
  }
  for (TotalOp total : simulation.getTotals()) {
    BodyUse &use = uses[total];
    use.bits = floatBits(total.getValueType());
    addBody(total.getBody(), buffers, use);
  }
  // A Hermite read also reads the derivative it interpolates with.
  for (auto &[op, use] : uses)
    for (size_t i = 0; i < use.reads.size(); ++i)
      if (auto hermite =
              dyn_cast<HermiteInterpAttr>(use.reads[i].getInterpolation()))
        if (BufferOp derivative =
                buffers.lookup(hermite.getDerivative().getValue()))
          if (!llvm::is_contained(use.reads, derivative))
            use.reads.push_back(derivative);

  for (auto &[op, use] : uses)
    bits[op] = use.bits;
  for (bool changed = true; changed;) {
    changed = false;
    for (auto &[op, use] : uses)
      for (BufferOp read : use.reads) {
        unsigned readBits = bits.lookup(read);
        if (readBits < bits[op]) {
          bits[op] = readBits;
          changed = true;
        }
      }
  }
}

unsigned ValuePrecision::getBits(BufferOp buffer) const {
  return bits.lookup(buffer);
}

unsigned ValuePrecision::getBits(TotalOp total) const {
  return bits.lookup(total);
}
