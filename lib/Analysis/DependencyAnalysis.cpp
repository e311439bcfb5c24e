//===- DependencyAnalysis.cpp - who reads and writes what -----------------===//
//
// Classifies every view read by how its index relates to the body's item
// argument `%i`. An index is a window when it decomposes into `%i + c` through
// additions, subtractions and index casts, where every other term has a range
// that upstream IntegerRangeAnalysis can bound (constants, loop induction
// variables with constant bounds, values derived from them) and that does not
// depend on a sim.get_param (a run-time value). Anything else is a gather.
// Being conservative matters: a read classified as a window that is really a
// gather would make a shared-memory cache or a legality verdict wrong; the
// reverse only costs performance.
//
//===----------------------------------------------------------------------===//

#include "sim/Analysis/DependencyAnalysis.h"

#include "mlir/Analysis/DataFlow/ConstantPropagationAnalysis.h"
#include "mlir/Analysis/DataFlow/DeadCodeAnalysis.h"
#include "mlir/Analysis/DataFlow/IntegerRangeAnalysis.h"
#include "mlir/Analysis/DataFlowFramework.h"
#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/Utils/StaticValueUtils.h"
#include "mlir/Interfaces/LoopLikeInterface.h"
#include "llvm/ADT/SetVector.h"
#include "llvm/Support/Debug.h"
#include "llvm/Support/MathExtras.h"

#define DEBUG_TYPE "sim-dependency-analysis"

using namespace mlir;
using namespace mlir::sim;

//===----------------------------------------------------------------------===//
// AccessPattern
//===----------------------------------------------------------------------===//

AccessPattern AccessPattern::window(int64_t minOffset, int64_t maxOffset) {
  if (minOffset == 0 && maxOffset == 0)
    return own();
  return AccessPattern(Kind::Window, minOffset, maxOffset);
}

AccessPattern AccessPattern::join(const AccessPattern &other) const {
  if (isGather() || other.isGather())
    return gather();
  return window(std::min(minOffset, other.minOffset),
                std::max(maxOffset, other.maxOffset));
}

static void printOffset(llvm::raw_ostream &os, int64_t offset) {
  os << "i";
  if (offset > 0)
    os << "+" << offset;
  else if (offset < 0)
    os << offset;
}

void AccessPattern::print(llvm::raw_ostream &os) const {
  switch (kind) {
  case Kind::Own:
    os << "i";
    return;
  case Kind::Window:
    printOffset(os, minOffset);
    if (maxOffset != minOffset) {
      os << "..";
      printOffset(os, maxOffset);
    }
    return;
  case Kind::Gather:
    os << "gather";
    return;
  }
}

std::string AccessPattern::str() const {
  std::string text;
  llvm::raw_string_ostream os(text);
  print(os);
  return text;
}

//===----------------------------------------------------------------------===//
// Index classification
//===----------------------------------------------------------------------===//

namespace {
/// Offsets larger than this are treated as unbounded: no scene reads that
/// far, and the bound keeps offset arithmetic far from overflow.
constexpr int64_t kMaxOffset = int64_t(1) << 40;

using OffsetRange = std::pair<int64_t, int64_t>;

/// Appends what the values an operation defines depend on: its operands and
/// the values its regions yield (loop-carried values, results of
/// conditionals).
void appendInputs(Operation *op, SmallVectorImpl<Value> &worklist) {
  llvm::append_range(worklist, op->getOperands());
  for (Region &region : op->getRegions())
    for (Block &block : region)
      if (!block.empty() && block.back().hasTrait<OpTrait::IsTerminator>())
        llvm::append_range(worklist, block.back().getOperands());
}

/// True when `root` depends on a `sim.get_param`. Parameters are run-time
/// values (`--sim-set-params` or the runtime change them after compilation),
/// so a range IntegerRangeAnalysis derives through one (from the type of an
/// index_cast, for example) is not a bound the item index keeps. A loop
/// induction variable depends on the loop's bounds and step only; any other
/// block argument of a nested region depends on its op's inputs.
bool dependsOnParam(Value root) {
  SmallVector<Value> worklist = {root};
  llvm::DenseSet<Value> seen;
  while (!worklist.empty()) {
    Value value = worklist.pop_back_val();
    if (!seen.insert(value).second)
      continue;
    if (Operation *def = value.getDefiningOp()) {
      if (isa<GetParamOp>(def))
        return true;
      appendInputs(def, worklist);
      continue;
    }
    Operation *owner = cast<BlockArgument>(value).getOwner()->getParentOp();
    if (!owner || isa<ComponentOp, BufferOp>(owner))
      continue; // A body argument: %i, %t, %n, %dt.
    auto loop = dyn_cast<LoopLikeOpInterface>(owner);
    std::optional<SmallVector<Value>> inductionVars =
        loop ? loop.getLoopInductionVars() : std::nullopt;
    if (inductionVars && llvm::is_contained(*inductionVars, value)) {
      for (auto bounds : {loop.getLoopLowerBounds(), loop.getLoopUpperBounds(),
                          loop.getLoopSteps()})
        if (bounds)
          for (OpFoldResult bound : *bounds)
            if (auto boundValue = dyn_cast<Value>(bound))
              worklist.push_back(boundValue);
      continue;
    }
    appendInputs(owner, worklist);
  }
  return false;
}

/// Decomposes read indices into `%item + c` and bounds `c`.
class IndexClassifier {
public:
  IndexClassifier(DataFlowSolver &solver) : solver(solver) {}

  AccessPattern classify(Value index, Value item) {
    Reach reach = reachFromItem(index, item, 0);
    // An offset beyond 2^62 is no neighbourhood: `%i + c` may wrap around
    // the 64-bit index, and the halos, caches and level reaches sized from
    // the window (hi - lo and more) would overflow. A gather computes the
    // index as the scalar code does, on every backend. (Ranges stop at
    // 2^40, so every offset that can reach another item stays a window.)
    constexpr int64_t kLargestOffset = int64_t(1) << 62;
    if (!reach.lo || !reach.hi || *reach.lo < -kLargestOffset ||
        *reach.hi > kLargestOffset)
      return AccessPattern::gather();
    return AccessPattern::window(*reach.lo, *reach.hi);
  }

private:
  /// The offsets `value - %i` can take, each side bounded or not. A read is
  /// a window when both are: `%i + c`, but also an index a body clamps
  /// around its own item, `min(max(%j, %i - w), %i + w)` with any `%j` (a
  /// neighbour list's entry given a reach), which is how a scene bounds a
  /// gather so that halos, caches and local time steps can be planned.
  struct Reach {
    std::optional<int64_t> lo, hi;
  };

  /// The range of an integer value, when IntegerRangeAnalysis bounds it and
  /// it does not depend on a run-time parameter.
  std::optional<OffsetRange> rangeOf(Value value) {
    if (dependsOnParam(value))
      return std::nullopt;
    auto *lattice =
        solver.lookupState<dataflow::IntegerValueRangeLattice>(value);
    if (!lattice || lattice->getValue().isUninitialized())
      return std::nullopt;
    const ConstantIntRanges &range = lattice->getValue().getValue();
    if (range.smin().getBitWidth() > 64)
      return std::nullopt;
    int64_t lo = range.smin().getSExtValue();
    int64_t hi = range.smax().getSExtValue();
    if (lo < -kMaxOffset || hi > kMaxOffset)
      return std::nullopt;
    return OffsetRange{lo, hi};
  }

  static std::optional<int64_t> shifted(std::optional<int64_t> bound,
                                        int64_t term) {
    return bound ? std::optional<int64_t>(*bound + term) : std::nullopt;
  }
  /// The tighter of two lower (`lower`) or upper bounds, either optional.
  static std::optional<int64_t> tighter(std::optional<int64_t> a,
                                        std::optional<int64_t> b, bool lower) {
    if (!a || !b)
      return a ? a : b;
    return lower ? std::max(*a, *b) : std::min(*a, *b);
  }
  /// The looser of two bounds: unbounded when either is.
  static std::optional<int64_t> looser(std::optional<int64_t> a,
                                       std::optional<int64_t> b, bool lower) {
    if (!a || !b)
      return std::nullopt;
    return lower ? std::min(*a, *b) : std::max(*a, *b);
  }

  /// The reach of `value` from `item`.
  Reach reachFromItem(Value value, Value item, unsigned depth) {
    if (value == item)
      return Reach{0, 0};
    // A value that does not follow the item: the item is in [0, range), so
    // `value - %i` is at most the value's largest, and unbounded below
    // (the range is a run-time parameter).
    Reach unrelated;
    if (std::optional<OffsetRange> range = rangeOf(value))
      unrelated.hi = range->second;
    // Index expressions in scenes are short; the bound only protects
    // against pathological inputs.
    if (depth > 32)
      return unrelated;
    Operation *def = value.getDefiningOp();
    if (!def)
      return unrelated;
    if (isa<arith::IndexCastOp, arith::IndexCastUIOp>(def)) {
      // A narrower integer extended to an index is `%i + c` only where the
      // narrow sum did not wrap, which depends on the range: `index_cast
      // (i8(%i) + 1)` is -128 at item 127, and `index_castui (i32(%i) - 1)`
      // 2^32 - 1 at item 0, neighbours of neither.
      Type source = def->getOperand(0).getType();
      if (!source.isIndex() && source.getIntOrFloatBitWidth() < 64)
        return unrelated;
      return reachFromItem(def->getOperand(0), item, depth + 1);
    }
    if (auto add = dyn_cast<arith::AddIOp>(def)) {
      // `base + term` with a bounded term, either way round; both bounds
      // hold, so the tighter of the two is kept.
      Reach sum;
      bool any = false;
      for (auto [base, term] : {std::pair(add.getLhs(), add.getRhs()),
                                std::pair(add.getRhs(), add.getLhs())}) {
        std::optional<OffsetRange> termRange = rangeOf(term);
        if (!termRange)
          continue;
        Reach baseReach = reachFromItem(base, item, depth + 1);
        Reach candidate{shifted(baseReach.lo, termRange->first),
                        shifted(baseReach.hi, termRange->second)};
        sum = any ? Reach{tighter(sum.lo, candidate.lo, true),
                          tighter(sum.hi, candidate.hi, false)}
                  : candidate;
        any = true;
      }
      return any ? sum : unrelated;
    }
    if (auto sub = dyn_cast<arith::SubIOp>(def)) {
      std::optional<OffsetRange> termRange = rangeOf(sub.getRhs());
      if (!termRange)
        return unrelated;
      Reach baseReach = reachFromItem(sub.getLhs(), item, depth + 1);
      return Reach{shifted(baseReach.lo, -termRange->second),
                   shifted(baseReach.hi, -termRange->first)};
    }
    // Signed minimum and maximum: a clamp around the item. (The unsigned
    // ones order a negative offset's index above every item.)
    if (isa<arith::MinSIOp, arith::MaxSIOp>(def)) {
      Reach lhs = reachFromItem(def->getOperand(0), item, depth + 1);
      Reach rhs = reachFromItem(def->getOperand(1), item, depth + 1);
      if (isa<arith::MinSIOp>(def))
        return Reach{looser(lhs.lo, rhs.lo, true),
                     tighter(lhs.hi, rhs.hi, false)};
      return Reach{tighter(lhs.lo, rhs.lo, true),
                   looser(lhs.hi, rhs.hi, false)};
    }
    // Either of two indices: both reaches.
    if (auto select = dyn_cast<arith::SelectOp>(def)) {
      Reach lhs = reachFromItem(select.getTrueValue(), item, depth + 1);
      Reach rhs = reachFromItem(select.getFalseValue(), item, depth + 1);
      return Reach{looser(lhs.lo, rhs.lo, true), looser(lhs.hi, rhs.hi, false)};
    }
    return unrelated;
  }

  DataFlowSolver &solver;
};
} // namespace

/// The `c` of an index `(%i + c) mod n` that describeHandWrappedRead
/// recognises, taken between `-n/2` and `n/2` where `n` is a constant.
static std::optional<int64_t> getHandWrappedOffset(Value index, Value item) {
  Operation *rem = index.getDefiningOp();
  if (!isa_and_nonnull<arith::RemSIOp, arith::RemUIOp>(rem))
    return std::nullopt;
  Value sum = rem->getOperand(0), modulus = rem->getOperand(1);
  std::optional<int64_t> period = getConstantIntValue(modulus);
  auto isModulus = [&](Value value) {
    if (value == modulus)
      return true;
    std::optional<int64_t> constant = getConstantIntValue(value);
    return period && constant && *constant == *period;
  };
  // `(%i + c + n) mod n`: the n keeps the sum from going below zero.
  bool lifted = false;
  if (auto add = sum.getDefiningOp<arith::AddIOp>()) {
    lifted = true;
    if (isModulus(add.getRhs()))
      sum = add.getLhs();
    else if (isModulus(add.getLhs()))
      sum = add.getRhs();
    else
      lifted = false;
  }
  int64_t offset = 0;
  if (sum != item) {
    Operation *def = sum.getDefiningOp();
    if (!isa_and_nonnull<arith::AddIOp, arith::SubIOp>(def))
      return std::nullopt;
    Value lhs = def->getOperand(0), rhs = def->getOperand(1);
    if (isa<arith::AddIOp>(def) && rhs == item)
      std::swap(lhs, rhs);
    std::optional<int64_t> constant = getConstantIntValue(rhs);
    if (lhs != item || !constant || *constant <= -kMaxOffset ||
        *constant >= kMaxOffset)
      return std::nullopt;
    offset = isa<arith::AddIOp>(def) ? *constant : -*constant;
  }
  // A sum below zero is no wrap: remsi keeps its sign (the buffer's
  // boundary rule reads it), remui reads 2^64 - 1 mod n at item 0.
  if (offset < 0 && (!lifted || (period && offset + *period < 0)))
    return std::nullopt;
  if (period) {
    if (*period <= 0)
      return std::nullopt;
    offset %= *period;
    if (offset > *period / 2)
      offset -= *period;
    else if (offset < -(*period / 2))
      offset += *period;
  }
  if (offset == 0)
    return std::nullopt;
  return offset;
}

/// The item argument `%i` of a body: of `component` for num_steps and
/// evaluate, of `buffer` for init and exact, of `total` for a total.
static Value getBodyItem(BodyKind kind, ComponentOp component, BufferOp buffer,
                         TotalOp total) {
  switch (kind) {
  case BodyKind::NumSteps:
    return component.getNumStepsItem();
  case BodyKind::Evaluate:
    return component.getEvaluateItem();
  case BodyKind::Init:
    return buffer.getInitItem();
  case BodyKind::Exact:
    return buffer.getExactItem();
  case BodyKind::Total:
    return total.getItem();
  }
  llvm_unreachable("unknown body kind");
}

std::string mlir::sim::describeHandWrappedRead(ReadOp read, BufferOp buffer) {
  std::optional<BodyLocation> body = getEnclosingBody(read);
  if (!body)
    return "";
  std::optional<int64_t> offset = getHandWrappedOffset(
      read.getIndex(),
      getBodyItem(body->kind, body->component, body->buffer, body->total));
  if (!offset)
    return "";
  std::string window = "%i " + std::string(*offset < 0 ? "- " : "+ ") +
                       std::to_string(*offset < 0 ? -*offset : *offset);
  std::string name = "@" + buffer.getSymName().str();
  std::string text =
      "the index wraps " + window + " around the range by hand: ";
  if (buffer.getBoundary() == Boundary::wrap)
    text += name + " is boundary(wrap), so ";
  else
    text += "with boundary(wrap) on " + name + ", ";
  return text + name + "[" + window +
         "] reads the same item (where the divisor is the range) as a window";
}

/// The item argument `%i` of the body a read sits in. (Total bodies are not
/// analysed, see analyzeReads.)
static Value getItemArgument(const ReadInfo &info) {
  assert(info.body != BodyKind::Total && "total bodies are not analysed");
  return getBodyItem(info.body, info.component, info.owner, nullptr);
}

//===----------------------------------------------------------------------===//
// DependencyAnalysis
//===----------------------------------------------------------------------===//

DependencyAnalysis::DependencyAnalysis(Operation *op)
    : simulation(cast<SimulationOp>(op)) {
  llvm::append_range(components, simulation.getComponents());
  llvm::append_range(buffers, simulation.getBuffers());
  analyzeReads();
}

void DependencyAnalysis::analyzeReads() {
  DataFlowSolver solver;
  solver.load<dataflow::DeadCodeAnalysis>();
  solver.load<dataflow::SparseConstantPropagation>();
  solver.load<dataflow::IntegerRangeAnalysis>();
  // Without ranges every neighbour read degrades to a gather, which is
  // correct but pessimistic; a solver failure is therefore not fatal.
  if (failed(solver.initializeAndRun(simulation)))
    LLVM_DEBUG(llvm::dbgs() << "integer range analysis failed\n");
  IndexClassifier classifier(solver);

  llvm::DenseMap<StringAttr, BufferOp> bufferByName;
  for (BufferOp buffer : buffers)
    bufferByName[buffer.getSymNameAttr()] = buffer;

  simulation.walk([&](ReadOp read) {
    std::optional<BodyLocation> location = getEnclosingBody(read);
    BufferOp buffer = bufferByName.lookup(read.getBufferAttr().getAttr());
    if (!location || !buffer)
      return; // Not in verified IR.
    // A total reads the state at T after a run; it is an output, not a
    // component, so it takes no part in the schedule or the memory plan.
    if (location->kind == BodyKind::Total) {
      auto total = read->getParentOfType<TotalOp>();
      totalReads.emplace_back(
          read, classifier.classify(read.getIndex(),
                                    total.getBody().front().getArgument(0)));
      return;
    }
    ReadInfo info{read,
                  buffer,
                  location->kind,
                  location->component,
                  location->buffer,
                  AccessPattern::gather()};
    info.pattern = classifier.classify(read.getIndex(), getItemArgument(info));
    LLVM_DEBUG(llvm::dbgs() << "read of @" << buffer.getSymName() << " in "
                            << stringifyBodyKind(info.body) << ": "
                            << info.pattern.str() << "\n");
    readIndex[read] = reads.size();
    reads.push_back(info);

    Operation *owner = info.component ? info.component.getOperation()
                                      : info.owner.getOperation();
    SmallVector<BufferAccess> &list = accesses[owner];
    auto it = llvm::find_if(list, [&](const BufferAccess &access) {
      return access.buffer == buffer && access.body == info.body;
    });
    if (it == list.end()) {
      list.push_back(BufferAccess{buffer, info.body, info.pattern, {read}});
    } else {
      it->pattern = it->pattern.join(info.pattern);
      it->reads.push_back(read);
    }
  });

  simulation.walk([&](LoadOp load) {
    std::optional<BodyLocation> location = getEnclosingBody(load);
    if (!location || !location->component)
      return;
    Value item = location->kind == BodyKind::Evaluate
                     ? location->component.getEvaluateItem()
                     : location->component.getNumStepsItem();
    loadPatterns.try_emplace(load, classifier.classify(load.getIndex(), item));
  });
}

SmallVector<BufferOp>
DependencyAnalysis::getWrittenBuffers(ComponentOp component) const {
  SmallVector<BufferOp> result;
  for (auto name : component.getWrites().getAsRange<FlatSymbolRefAttr>())
    for (BufferOp buffer : buffers)
      if (buffer.getSymNameAttr() == name.getAttr())
        result.push_back(buffer);
  return result;
}

AccessPattern DependencyAnalysis::getPattern(ReadOp read) const {
  auto it = readIndex.find(read);
  if (it == readIndex.end())
    return AccessPattern::gather();
  return reads[it->second].pattern;
}

AccessPattern DependencyAnalysis::getPattern(LoadOp load) const {
  auto it = loadPatterns.find(load);
  return it == loadPatterns.end() ? AccessPattern::gather() : it->second;
}

ArrayRef<BufferAccess>
DependencyAnalysis::getAccesses(ComponentOp component) const {
  auto it = accesses.find(component);
  return it == accesses.end() ? ArrayRef<BufferAccess>() : it->second;
}

ArrayRef<BufferAccess> DependencyAnalysis::getAccesses(BufferOp buffer) const {
  auto it = accesses.find(buffer);
  return it == accesses.end() ? ArrayRef<BufferAccess>() : it->second;
}

std::optional<AccessPattern>
DependencyAnalysis::getReadPattern(ComponentOp component,
                                   BufferOp buffer) const {
  std::optional<AccessPattern> result;
  for (const BufferAccess &access : getAccesses(component))
    if (access.buffer == buffer)
      result = result ? result->join(access.pattern) : access.pattern;
  return result;
}

SmallVector<ComponentOp>
DependencyAnalysis::getProducers(ComponentOp component) const {
  llvm::SetVector<Operation *> producers;
  for (const BufferAccess &access : getAccesses(component)) {
    ComponentOp writer = getWriter(access.buffer);
    if (writer && writer != component)
      producers.insert(writer);
  }
  return llvm::map_to_vector(
      producers, [](Operation *op) { return cast<ComponentOp>(op); });
}

SmallVector<BufferOp>
DependencyAnalysis::getBuffersReadFrom(ComponentOp component,
                                       ComponentOp producer) const {
  llvm::SetVector<Operation *> result;
  for (const BufferAccess &access : getAccesses(component))
    if (getWriter(access.buffer) == producer)
      result.insert(access.buffer);
  return llvm::map_to_vector(result,
                             [](Operation *op) { return cast<BufferOp>(op); });
}

const BufferAccess *
DependencyAnalysis::findSubStepHazard(ComponentOp component) const {
  for (const BufferAccess &access : getAccesses(component))
    if (getWriter(access.buffer) == component && !access.pattern.isOwn())
      return &access;
  return nullptr;
}
