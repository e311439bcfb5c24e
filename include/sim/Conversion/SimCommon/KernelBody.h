//===- KernelBody.h - inlining sim bodies into kernels ----------*- C++ -*-===//
//
// The part of lowering a simulation that the GPU and the CPU conversion
// share: turning one `sim` body (init, exact, num_steps, evaluate) into
// plain arith/memref code at a given point of a kernel. A conversion says,
// for one kernel, where every copy of every buffer lives and what the time
// and parameter ops stand for (KernelValues); the body's own arithmetic is
// cloned unchanged. Addressing, boundary rules and initial-state reads are
// written once, here.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CONVERSION_SIMCOMMON_KERNELBODY_H
#define SIM_CONVERSION_SIMCOMMON_KERNELBODY_H

#include "sim/Dialect/Sim/IR/SimOps.h"

#include "mlir/IR/Builders.h"
#include "llvm/ADT/StringMap.h"

namespace mlir::sim {

/// A group's shared-memory cache of one buffer: the interpolated values of
/// items `first .. first + size - 1`.
struct CacheView {
  Value memory;
  Value first, size;
};

/// What the sim ops of a body stand for in one kernel.
struct KernelValues {
  /// The number of items (index).
  Value range;
  /// Elements of one half of a buffer (index): `range` on one process; in a
  /// distributed plan the rank's block plus `2 * halo` ghost items.
  Value extent;
  /// Distributed plans: the first item of the rank's block (index) and the
  /// ghost items on each side of it; item `i` is element `i - first +
  /// halo`. Null on one process, where item `i` is element `i`.
  Value first;
  int64_t halo = 0;
  /// Distributed plans: the buffers every rank holds whole (a gather reads
  /// them), addressed as on one process: item `i` at element `i`, halves
  /// `range` apart.
  llvm::DenseSet<StringAttr> replicated;
  /// Parameter values by name, including the builtins `range` (i64), `dt`
  /// and `max_steps` (i64). `sim.get_param` converts to the type it asks for.
  llvm::StringMap<Value> params;
  /// Per buffer name: its storage of both halves (`2 * range` elements).
  llvm::DenseMap<StringAttr, Value> buffers;
  /// Per buffer name: its snapshot (`range` elements), if planned.
  llvm::DenseMap<StringAttr, Value> snapshots;
  /// Element offsets of the half that `source`, `target` and (without
  /// registers) `local` loads read, and the parities (i64) they are for
  /// (a replicated buffer's halves are `range` elements apart, not
  /// `extent`).
  Value sourceBase, targetBase, localBase;
  Value sourceParity, targetParity, localParity;
  /// Own state kept in registers: `local` loads of these buffers return the
  /// value instead of reading memory. Only valid for components that read
  /// their own buffers at their own item (`sub_stepping = in_kernel`).
  llvm::DenseMap<StringAttr, Value> registers;
  /// The item the body runs for; loads at exactly this index skip the
  /// boundary rule.
  Value item;
  /// `sim.big_step` (i64 values); null where a body cannot ask for it.
  Value bigStepBegin, bigStepSize;
  /// Per buffer name: the group's cache that `sim.load cache` reads inside
  /// its items. Without one (a CPU, or outside the items) a cache load
  /// computes the body's `sim.fill_cache` region at the read item. A load
  /// at `item` plus offsets bounded inside the fill's window needs no
  /// check: `item` is one of the group's items.
  llvm::DenseMap<StringAttr, CacheView> caches;
  /// Local time steps (a component that advances in `local_steps`, in the
  /// sub-step of slot `levelSlot`, i64, counted in the big step's unit
  /// `levelUnit` of base steps): a `local` load of another item reads the
  /// two stored time levels of that item's block (32 items). `levels`
  /// holds every block's sub-step in units (a power of two, i64) from
  /// element `levelBase`; the block of sub-step `s` has taken
  /// `ceil(levelSlot / s)` sub-steps, so its latest level is at
  /// `ceil(levelSlot / s) * s` units after `T` (or at `levelEnd`, the big
  /// step's `m` in base steps, where the block's last sub-step ends with
  /// the big step), in the half `sourceParity` xor that count's parity,
  /// and its previous one at `ceil(levelSlot / s) * s - s` units in the
  /// other half. Null outside such a sub-step.
  Value levels, levelSlot, levelEnd, levelBase, levelUnit;
  /// The flux writer of a flux pair reads its reader's state from the time
  /// levels at every item, its own included (it writes none of it).
  bool levelsAtItem = false;
  /// The writer of a pair that keeps state of its own (docs/Model.md,
  /// "Item pairs"): its `local` loads of these buffers, at its own item,
  /// read the item's latest value from the half at `latestBase` and
  /// `latestParity` instead of the time levels.
  llvm::DenseSet<StringAttr> latestOwn;
  Value latestBase, latestParity;
  /// Such a read loads the item from both halves and selects per item
  /// (KernelTarget::readsLevelsFromBothHalves) instead of loading from the
  /// half that the item's block says.
  bool levelsFromBothHalves = false;
};

/// Local time steps: the items of a block that chooses one level (the
/// bundle schema's LocalStepBlock, which the runtime reads too;
/// SimulationLowering.h checks that they agree).
constexpr int64_t kLevelBlock = 32;

/// The element of item `item` in a half, a snapshot, an exact or a total
/// array: `item` itself on one process, `item - first + halo` in a
/// distributed plan.
Value getElementIndex(OpBuilder &builder, Location loc,
                      const KernelValues &values, Value item,
                      StringAttr buffer = {});

/// The element offset of the half of `buffer` that `parity` selects:
/// `blockBase` (`parity * extent`), or `parity * range` for a replicated
/// buffer.
Value getHalfOffset(OpBuilder &builder, Location loc,
                    const KernelValues &values, StringAttr buffer,
                    Value blockBase, Value parity);

/// Returns the zero element of `type` (a float or a vector of floats).
Value buildZeroElement(OpBuilder &builder, Location loc, Type type);

/// Clones the single block of `body` at the builder's insertion point with
/// its arguments replaced by `arguments`, lowers every sim op in the clone
/// with `values`, and returns the values the body yields. `sim.read` (in init
/// and exact bodies) reads initial states: the read buffer's init body is
/// inlined at the read item. Emits an error at the offending op and fails
/// when a sim op has no meaning in this kernel (for example `sim.big_step`
/// where `values` has none).
FailureOr<SmallVector<Value>> inlineBody(OpBuilder &builder,
                                         SimulationOp simulation, Region &body,
                                         ValueRange arguments,
                                         const KernelValues &values);

/// The value that `buffer`'s `sim.fill_cache` in the evaluate body `body`
/// gives item `index`, for a body run with `arguments`: clones the fill's
/// region and the body's ops it depends on (its time values) at the
/// builder's insertion point.
FailureOr<Value> inlineCacheFill(OpBuilder &builder, SimulationOp simulation,
                                 Region &body, ValueRange arguments,
                                 FlatSymbolRefAttr buffer, Value index,
                                 const KernelValues &values);

} // namespace mlir::sim

#endif // SIM_CONVERSION_SIMCOMMON_KERNELBODY_H
