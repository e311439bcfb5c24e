//===- SimOps.h - sim dialect operations ------------------------*- C++ -*-===//
//
// Declares the sim operations and the helpers that classify the bodies they
// hold.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_DIALECT_SIM_IR_SIMOPS_H
#define SIM_DIALECT_SIM_IR_SIMOPS_H

#include "mlir/Bytecode/BytecodeOpInterface.h"
#include "mlir/IR/OpDefinition.h"
#include "mlir/IR/OpImplementation.h"
#include "mlir/IR/RegionKindInterface.h"
#include "mlir/IR/SymbolTable.h"
#include "mlir/Interfaces/ControlFlowInterfaces.h"
#include "mlir/Interfaces/SideEffectInterfaces.h"

#include "sim/Dialect/Sim/IR/SimAttrs.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"

namespace mlir::sim {

/// The memory-effect resource that stands for the whole simulation state.
struct StateResource : public SideEffects::Resource::Base<StateResource> {
  StringRef getName() final { return "SimState"; }
};

/// The memory-effect resource of the shared-memory caches of hip-cache.
struct CacheResource : public SideEffects::Resource::Base<CacheResource> {
  StringRef getName() final { return "SimCache"; }
};

/// The kinds of bodies that may read state.
enum class BodyKind { NumSteps, Evaluate, Init, Exact, Total };

/// Returns a printable name ("num_steps", "evaluate", "init", "exact",
/// "total").
StringRef stringifyBodyKind(BodyKind kind);

/// Returns true when `type` can be a buffer element: f32, f64, or a vector of
/// 1 to 16 of them.
bool isValidElementType(Type type);

} // namespace mlir::sim

#define GET_OP_CLASSES
#include "sim/Dialect/Sim/IR/SimOps.h.inc"

namespace mlir::sim {

/// Where an operation nested in a body sits: the body kind, and the component
/// or buffer that owns the body. Returns std::nullopt outside any body.
struct BodyLocation {
  BodyKind kind;
  /// The component for num_steps and evaluate bodies, else null.
  ComponentOp component;
  /// The buffer for init and exact bodies, else null.
  BufferOp buffer;
  /// The total for a total body, else null.
  TotalOp total = nullptr;
};
std::optional<BodyLocation> getEnclosingBody(Operation *op);

/// The sim.fill_cache of `buffer` in the evaluate body that holds `op`, or
/// null.
FillCacheOp findFillCache(Operation *op, FlatSymbolRefAttr buffer);

} // namespace mlir::sim

#endif // SIM_DIALECT_SIM_IR_SIMOPS_H
