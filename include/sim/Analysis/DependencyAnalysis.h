//===- DependencyAnalysis.h - who reads and writes what ---------*- C++ -*-===//
//
// The static program analysis the paper's method rests on (Section 4, Fig. 5):
// for every component and buffer body, which buffers it reads, and how each
// read is indexed relative to the item being computed (the own item, a window
// i+c with bounded c, or a gather). Passes get it with
// getAnalysis<DependencyAnalysis>() on a sim.simulation; unit tests construct
// it directly.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_ANALYSIS_DEPENDENCYANALYSIS_H
#define SIM_ANALYSIS_DEPENDENCYANALYSIS_H

#include "sim/Dialect/Sim/IR/SimOps.h"

#include "llvm/ADT/DenseMap.h"
#include "llvm/ADT/SmallVector.h"

namespace mlir::sim {

/// How the index of a read relates to the item `%i` that the body computes.
class AccessPattern {
public:
  enum class Kind {
    /// Exactly the own item `%i`.
    Own,
    /// `%i + c` with `c` in [minOffset, maxOffset] (not both zero).
    Window,
    /// Anything else: the analysis cannot bound the item read.
    Gather,
  };

  static AccessPattern own() { return AccessPattern(Kind::Own, 0, 0); }
  /// A window; [0, 0] is the own item.
  static AccessPattern window(int64_t minOffset, int64_t maxOffset);
  static AccessPattern gather() { return AccessPattern(Kind::Gather, 0, 0); }

  Kind getKind() const { return kind; }
  bool isOwn() const { return kind == Kind::Own; }
  bool isGather() const { return kind == Kind::Gather; }
  /// The offsets relative to `%i` (both 0 for Own; meaningless for Gather).
  int64_t getMinOffset() const { return minOffset; }
  int64_t getMaxOffset() const { return maxOffset; }

  /// The smallest pattern that covers both: own and window join to a window
  /// that includes offset 0, anything joined with a gather is a gather.
  AccessPattern join(const AccessPattern &other) const;

  bool operator==(const AccessPattern &other) const {
    return kind == other.kind && minOffset == other.minOffset &&
           maxOffset == other.maxOffset;
  }

  /// Prints `i`, `i-4..i+4`, `i+1` or `gather`.
  void print(llvm::raw_ostream &os) const;
  std::string str() const;

private:
  AccessPattern(Kind kind, int64_t minOffset, int64_t maxOffset)
      : kind(kind), minOffset(minOffset), maxOffset(maxOffset) {}

  Kind kind;
  int64_t minOffset, maxOffset;
};

// The op handles below are `mutable`: a handle is a pointer to an operation,
// so a const handle protects nothing, and passes must be able to annotate the
// operations the (const) analysis results point to.

/// One `sim.read` and what the analysis found about it.
struct ReadInfo {
  mutable ReadOp read;
  /// The buffer read.
  mutable BufferOp buffer;
  /// The body the read sits in.
  BodyKind body;
  /// The component that owns the body (num_steps and evaluate), else null.
  mutable ComponentOp component;
  /// The buffer that owns the body (init and exact), else null.
  mutable BufferOp owner;
  AccessPattern pattern;
};

/// All reads of one buffer from one body, with their joined pattern.
struct BufferAccess {
  mutable BufferOp buffer;
  BodyKind body;
  AccessPattern pattern;
  mutable SmallVector<ReadOp, 2> reads;
};

/// Reads and writes of every component and buffer body of a simulation.
class DependencyAnalysis {
public:
  /// Analyses `op`, which must be a sim.simulation.
  explicit DependencyAnalysis(Operation *op);

  SimulationOp getSimulation() const { return simulation; }

  /// Components and buffers in the order they appear in the simulation.
  ArrayRef<ComponentOp> getComponents() const { return components; }
  ArrayRef<BufferOp> getBuffers() const { return buffers; }

  /// The component that writes `buffer` (verified IR has exactly one):
  /// SimulationOp::getWriter, the one place writers are looked up.
  ComponentOp getWriter(BufferOp buffer) const {
    return SimulationOp(simulation).getWriter(buffer);
  }
  /// The buffers `component` writes, in `writes` order.
  SmallVector<BufferOp> getWrittenBuffers(ComponentOp component) const;

  /// Every read of the simulation's components and buffers, in program
  /// order.
  ArrayRef<ReadInfo> getReads() const { return reads; }
  /// Every read of its totals' bodies, with its pattern. Totals are
  /// outputs, not components: no schedule or memory plan sees them.
  ArrayRef<std::pair<ReadOp, AccessPattern>> getTotalReads() const {
    return totalReads;
  }
  /// The pattern of one read.
  AccessPattern getPattern(ReadOp read) const;
  /// The pattern of one explicit load in a component body (what
  /// --sim-insert-interpolation made of a read), classified as reads are:
  /// the lowerings check the recorded decisions against it.
  AccessPattern getPattern(LoadOp load) const;

  /// Reads of the num_steps and evaluate bodies of `component`, one entry per
  /// (body, buffer) in first-read order.
  ArrayRef<BufferAccess> getAccesses(ComponentOp component) const;
  /// Reads of the init and exact bodies of `buffer`.
  ArrayRef<BufferAccess> getAccesses(BufferOp buffer) const;

  /// The joined pattern of every read of `buffer` by `component` in either
  /// body, or std::nullopt when the component never reads it.
  std::optional<AccessPattern> getReadPattern(ComponentOp component,
                                              BufferOp buffer) const;

  /// The other components whose buffers `component` reads (in num_steps or
  /// evaluate): its producers, in first-read order.
  SmallVector<ComponentOp> getProducers(ComponentOp component) const;

  /// Sub-stepping inside one kernel is race-free only when the component
  /// reads the buffers it writes at its own item: then each thread owns its
  /// item's state. Returns the first read (in either body) of a written
  /// buffer at another item, which forces a grid-wide barrier between
  /// sub-steps, or null when there is none.
  const BufferAccess *findSubStepHazard(ComponentOp component) const;

  /// The buffers `component` reads that `producer` writes.
  SmallVector<BufferOp> getBuffersReadFrom(ComponentOp component,
                                           ComponentOp producer) const;

private:
  void analyzeReads();

  SimulationOp simulation;
  SmallVector<ComponentOp> components;
  SmallVector<BufferOp> buffers;
  SmallVector<ReadInfo> reads;
  SmallVector<std::pair<ReadOp, AccessPattern>> totalReads;
  llvm::DenseMap<Operation *, unsigned> readIndex;
  llvm::DenseMap<Operation *, AccessPattern> loadPatterns;
  llvm::DenseMap<Operation *, SmallVector<BufferAccess>> accesses;
};

/// For a gather `read` that wraps its body's item plus a constant around
/// by hand, `(%i + c) mod n` (`arith.remsi` or `arith.remui`, the sum
/// perhaps with `n` added first, `(%i - 1 + n) mod n`, so that it is never
/// below zero), what to write instead, for a remark after "; ": the window
/// `@B[%i + c]` that the buffer's `boundary(wrap)` gives. Otherwise an
/// empty string. (The analysis keeps such a read a gather: `n` need not be
/// the range.)
std::string describeHandWrappedRead(ReadOp read, BufferOp buffer);

} // namespace mlir::sim

#endif // SIM_ANALYSIS_DEPENDENCYANALYSIS_H
