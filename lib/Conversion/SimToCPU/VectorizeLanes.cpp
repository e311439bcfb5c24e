//===- VectorizeLanes.cpp - a group's lanes in SIMD registers -------------===//
//
// SPMD on SIMD for the CPU kernels. A phase of a group is a loop over its
// lanes whose iterations are independent (GPU threads between barriers;
// SimToCPU marks it `simplan.lanes`), and the body of one lane is scalar code
// with loops and branches of its own, so LLVM's loop vectoriser, which only
// takes innermost loops, cannot run lanes side by side. This pass does: it
// re-emits the body once for a chunk of `width` lanes, each lane-dependent
// ("varying") value a vector whose lane l belongs to item l of the chunk.
// A value of type vector<N x T> per lane becomes N vectors of `width` T (one
// per element), so that the component's own vec4 arithmetic becomes four
// full-width SIMD operations instead of one item's four lanes in one
// register. Lane-independent ("uniform") values stay as they are.
//
// Every lane executes exactly the scalar operations of the original loop, in
// the same order, so the results are bit for bit the scalar ones: elementwise
// ops are the same ops on vectors, libm functions are called per element,
// reductions combine in the order the scalar lowering does. Lanes a branch
// does not take still compute its values (discarded by a select), but they
// never touch memory they would not have touched: loads use the address of
// an active lane, stores are masked, integer divisions divide by one.
//
//===----------------------------------------------------------------------===//

#include "sim/Conversion/Passes.h"

#include "mlir/Dialect/LLVMIR/LLVMDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Dominance.h"
#include "mlir/IR/IRMapping.h"
#include "mlir/Interfaces/SideEffectInterfaces.h"
#include "mlir/Transforms/ControlFlowSinkUtils.h"

#include "llvm/ADT/EquivalenceClasses.h"
#include "llvm/ADT/Sequence.h"
#include "llvm/Support/Debug.h"

#define DEBUG_TYPE "sim-vectorize-lanes"

namespace mlir::sim {
#define GEN_PASS_DEF_SIMVECTORIZELANES
#include "sim/Conversion/Passes.h.inc"
} // namespace mlir::sim

using namespace mlir;

namespace {

/// The largest vector<N x T> of one lane that is split into N vectors.
constexpr int64_t kMaxElements = 64;

/// A value of the widened loop: uniform (`parts` is the one scalar value of
/// the original type) or varying (one vector<width x T> per element of the
/// original: one part for a scalar, N for a vector<N x T>).
struct Wide {
  SmallVector<Value, 4> parts;
  bool varying = false;
  /// A varying vector<N x T> may also be held as the elements of its lanes
  /// side by side, as memory holds them: one vector<width * stride x T>
  /// whose element `lane * stride + k` is element k of lane `lane` (a
  /// wide load before its de-interleaving shuffles). Elementwise ops on
  /// such values stay in that form, so that a value computed from loads
  /// (an interpolation of two halves) is de-interleaved once, not each
  /// load. `parts` are made from it on demand, right after `definedBy`
  /// (null for a loop-carried value: at the start of its loop's body).
  Value interleaved;
  int64_t stride = 0;
  Operation *definedBy = nullptr;
  /// For an interleaved result of an elementwise op (widenInterleaved): the
  /// original op, whose parts can be computed from its operands' parts
  /// instead of de-interleaving its result (LaneVectorizer::lanePart).
  Operation *elementwiseOf = nullptr;
};

/// Whether `type` can be held per lane: an integer, index or float scalar, or
/// a one-dimensional fixed vector of those.
static bool isLaneType(Type type) {
  auto scalarOk = [](Type t) { return t.isIntOrIndexOrFloat(); };
  if (auto vector = dyn_cast<VectorType>(type))
    return vector.getRank() == 1 && !vector.isScalable() &&
           vector.getNumElements() <= kMaxElements &&
           scalarOk(vector.getElementType());
  return scalarOk(type);
}

static int64_t elementCount(Type type) {
  if (auto vector = dyn_cast<VectorType>(type))
    return vector.getNumElements();
  return 1;
}

static Type elementType(Type type) { return getElementTypeOrSelf(type); }

/// The distance in scalars between consecutive elements of a memref of
/// `type`. LLVM's x86-64 data layout gives a vector its size rounded up to a
/// power of two (vector<3xf32> takes 16 bytes), and the memref lowering
/// indexes elements by that size.
static int64_t elementStride(Type type) {
  return llvm::PowerOf2Ceil(elementCount(type));
}

/// Whether a varying value of `type` can be held interleaved (Wide): a
/// vector of at least two elements, a power of two of them (no padding
/// between lanes), not of i1 (masks are made per part).
static bool holdsInterleaved(Type type) {
  auto vector = dyn_cast<VectorType>(type);
  return vector && vector.getNumElements() >= 2 &&
         llvm::isPowerOf2_64(vector.getNumElements()) &&
         !vector.getElementType().isInteger(1);
}

/// A memref the widened loop can address element by element through a
/// pointer: rank 1, identity layout (offset 0, stride 1), and elements that
/// are whole bytes (no i1, no index).
static bool isAddressable(Value memref) {
  auto type = dyn_cast<MemRefType>(memref.getType());
  if (!type || type.getRank() != 1 || !type.getLayout().isIdentity() ||
      !isLaneType(type.getElementType()))
    return false;
  Type scalar = elementType(type.getElementType());
  return !scalar.isIndex() && scalar.getIntOrFloatBitWidth() % 8 == 0;
}

/// A builder at the end of `block` after removing the terminator a builder of
/// scf.if or scf.for may have put there (the caller yields its own).
static OpBuilder emptyBody(Block *block) {
  if (!block->empty() && block->mightHaveTerminator())
    block->getTerminator()->erase();
  return OpBuilder::atBlockEnd(block);
}

static bool isIntegerDivision(Operation *op) {
  return isa<arith::DivSIOp, arith::DivUIOp, arith::RemSIOp, arith::RemUIOp,
             arith::CeilDivSIOp, arith::CeilDivUIOp, arith::FloorDivSIOp>(op);
}

/// Whether the integer division `op` by `divisor` cannot trap in any lane: a
/// constant divisor other than 0 (and, for a signed division, -1, which traps
/// on INT_MIN / -1). Such a division needs no mask, and LLVM turns it into a
/// multiplication by the divisor's reciprocal instead of one `div` per lane.
static bool divisorCannotTrap(Operation *op, Value divisor) {
  APInt value;
  if (!matchPattern(divisor, m_ConstantInt(&value)))
    return false;
  bool isUnsigned = isa<arith::DivUIOp, arith::RemUIOp, arith::CeilDivUIOp>(op);
  return !value.isZero() && (isUnsigned || !value.isAllOnes());
}

/// The divisor of a 64-bit unsigned remainder by a constant that the widened
/// loop computes in 32-bit halves, or 0. x86 has no vector instruction for
/// the high half of a 64-bit product, so LLVM computes `x % c` on a vector of
/// i64 with one scalar `mul` per lane; the same remainder from 32-bit
/// remainders, which x86 does have in vector form (`pmuludq`), is exact when
/// `(c - 1)^2 + c - 1 < 2^32`. Powers of two are a mask already.
static uint64_t narrowRemainderDivisor(Operation *op) {
  if (!isa<arith::RemUIOp>(op) ||
      !elementType(op->getResultTypes()[0]).isInteger(64))
    return 0;
  APInt value;
  if (!matchPattern(op->getOperand(1), m_ConstantInt(&value)) ||
      value.getActiveBits() > 16 || value.ult(3) || value.isPowerOf2())
    return 0;
  return value.getZExtValue();
}

/// Whether the widened loop computes the integer division `op` in f64 lanes.
/// x86 has no SIMD integer division, so LLVM divides lane by lane (`idiv`,
/// tens of cycles each); but for |x| < 2^53 and 0 < |d| < 2^53 the quotient
/// truncated from the correctly rounded f64 x / d is exact: one that is not
/// an integer lies at least 1 / |d| from the nearest integer, further than
/// the rounding error |x / d| 2^-53 (and an integer quotient is exact).
/// 32-bit operands always qualify; 64-bit ones where every lane of a chunk
/// is in range (checked; else the chunk divides as before; the range is
/// 2^51 or 2^53 by how the lanes convert, see divideThroughDouble); index
/// ones (the wrap of a window read) as 64-bit ones. A constant divisor is
/// left to LLVM, which multiplies by its reciprocal.
static bool dividesThroughDouble(Operation *op) {
  if (!isa<arith::DivSIOp, arith::DivUIOp, arith::RemSIOp, arith::RemUIOp>(op))
    return false;
  Type scalar = elementType(op->getResultTypes()[0]);
  return (scalar.isInteger(32) || scalar.isInteger(64) || scalar.isIndex()) &&
         !matchPattern(op->getOperand(1), m_Constant());
}

/// Ops that compute per element: arith, math, vector.fma and the
/// llvm.intr.fma that --sim-fused-multiply-add makes of it.
static bool isElementwise(Operation *op) {
  return op->getNumRegions() == 0 && op->getNumResults() == 1 &&
         (op->hasTrait<OpTrait::Elementwise>() ||
          isa<vector::FMAOp, LLVM::FMAOp>(op));
}

class LaneVectorizer {
public:
  LaneVectorizer(scf::ForOp loop, int64_t width, bool wideConversions,
                 bool chainsApart)
      : loop(loop), width(width), wideConversions(wideConversions),
        chainsApart(chainsApart) {}

  /// Finds the varying values and checks that every op can be widened; on
  /// failure `why` names the first op that cannot.
  LogicalResult analyze(std::string &why);
  /// Emits the widened loop for the whole chunks before the original loop,
  /// which keeps the remaining lanes.
  void rewrite();
  /// After `analyze`: turns every select on a lane-independent condition
  /// whose operand costs an integer division into a branch that computes
  /// only the chosen operand. Returns whether it changed the loop (then the
  /// analysis must run again).
  bool branchCostlySelects();

private:
  bool isVarying(Value value) const { return varying.contains(value); }
  /// Whether operand `index` of `op` is a select's condition that is one
  /// scalar for every lane: the widened select keeps it as it is.
  bool isUniformCondition(Operation *op, unsigned index) const {
    Value operand = op->getOperand(index);
    return index == 0 && isa<arith::SelectOp>(op) && !isVarying(operand) &&
           !isa<VectorType>(operand.getType());
  }
  LogicalResult check(Operation *op, std::string &why);

  // Emission.
  void widenBlock(OpBuilder &b, Block &block, Value mask);
  void widenOp(OpBuilder &b, Operation *op, Value mask);
  void widenIf(OpBuilder &b, scf::IfOp op, Value mask);
  void widenFor(OpBuilder &b, scf::ForOp op, Value mask);
  void widenElementwise(OpBuilder &b, Operation *op, Value mask);
  /// `lanes % divisor` for a vector of i64 lanes and a divisor that
  /// narrowRemainderDivisor accepts, from 32-bit remainders.
  Value remainderByHalves(OpBuilder &b, Value lanes, uint64_t divisor);
  /// Whether `op` divides a consecutive dividend (`uniform + lane`) by a
  /// uniform divisor, which divideConsecutive computes from one scalar
  /// division per chunk.
  bool dividesConsecutive(Operation *op) const;
  /// `op` (dividesConsecutive): where the divisor is at least the chunk's
  /// lanes and the dividend's lanes neither wrap nor (signed) go below 0,
  /// at most one multiple of the divisor lies among them, so one scalar
  /// division of the first lane and a compare give every lane's quotient
  /// and remainder; elsewhere the chunk divides as widenElementPart does.
  /// With `partner`, the division or remainder of the same operands later
  /// in the block (a grid's row and column), computed in the same branch
  /// from the same scalar division; its lanes are kept for when it widens.
  Value divideConsecutive(OpBuilder &b, Operation *op, Operation *partner,
                          Value mask);
  /// Part `k` of the elementwise `op` widened, masked by `mask` (null: all
  /// lanes).
  Value widenElementPart(OpBuilder &b, Operation *op, int64_t k, Value mask);
  /// `op` (dividesThroughDouble) on the lane vectors `dividend` and
  /// `divisor`; `mask`: the lanes that run it, or null for all.
  Value divideThroughDouble(OpBuilder &b, Operation *op, Value dividend,
                            Value divisor, Value mask);
  void widenLoad(OpBuilder &b, memref::LoadOp op, Value mask);
  void widenStore(OpBuilder &b, memref::StoreOp op, Value mask);
  void widenReduction(OpBuilder &b, vector::ReductionOp op);
  void cloneUniform(OpBuilder &b, Operation *op);

  Wide lookup(Value value) const;
  /// Element `k` of `value` as a vector of lanes (broadcast if uniform).
  Value lanePart(OpBuilder &b, Value value, int64_t k);
  /// How many de-interleavings making the parts of `value` costs at least
  /// (0: it has them or is uniform; 1: its own or one of its operands';
  /// 2: more, or a loop-carried value, whose parts would undo its
  /// interleaved loop).
  unsigned freshDeinterleavings(Value value, unsigned depth) const;
  /// The sum of freshDeinterleavings over the varying operands of the
  /// elementwise `op` (not a select's lane-independent condition).
  unsigned operandDeinterleavings(Operation *op, unsigned depth) const;
  /// `value` in the interleaved form of a result with `stride` (an
  /// interleaved value as it is, a uniform one spread), or null.
  Value interleavedOf(OpBuilder &b, Value value, int64_t stride);
  /// Widens an elementwise op in the interleaved form when an operand has
  /// it and every other one can take it; returns whether it did.
  bool widenInterleaved(OpBuilder &b, Operation *op);
  /// All parts of `value` as vectors of lanes.
  SmallVector<Value> laneParts(OpBuilder &b, Value value);
  VectorType laneType(Type scalar) const {
    return VectorType::get({width}, scalar);
  }
  /// The types `value` is held in: its own if uniform, else N lane vectors.
  void heldTypes(Value value, SmallVectorImpl<Type> &types) const;
  /// `results` from a flat list of held values.
  void assign(ValueRange results, ValueRange flat);
  /// `results` from a flat list of held values, those marked in
  /// `interleaved` as one interleaved value each (defined by `definedBy`,
  /// or null for a loop's block arguments).
  void holdResults(ValueRange results, ValueRange flat,
                   ArrayRef<bool> interleaved, Operation *definedBy);
  /// The held values of `value` (lane vectors where `value` is varying in the
  /// widened loop but `source` may be uniform).
  void appendHeld(OpBuilder &b, Value target, Value source,
                  SmallVectorImpl<Value> &flat);

  Value constantIndex(OpBuilder &b, int64_t value);
  Value anyLane(OpBuilder &b, Value mask);
  Value allLanes(OpBuilder &b, Value mask);
  Value basePointer(OpBuilder &b, Value memref);
  /// A constant vector of lanes all equal to `value`.
  Value splat(OpBuilder &b, Type scalar, Attribute value);
  /// The address of element `index[0]` (`stride` scalars each) of `pointer`.
  Value firstAddress(OpBuilder &b, Value pointer, Type scalar, Value index,
                     int64_t stride);
  /// Per element k < count of the lanes' elements `index` (i64 lanes), the
  /// vector of their addresses.
  SmallVector<Value> laneAddresses(OpBuilder &b, Value pointer, Type scalar,
                                   Value index, int64_t stride, int64_t count);
  /// Whether one wide access serves the chunk at the lanes' element
  /// indices `index` (i64 lanes) of the original index `original`: from
  /// two scalar compares when `original` is a bounded run of consecutive
  /// indices, else by comparing every lane with the first lane's + lane.
  Value contiguousCheck(OpBuilder &b, Value original, Value index, Value mask);
  bool likelyUniform(Value index) const;
  void findBoundedRuns();

  scf::ForOp loop;
  int64_t width;
  /// The target converts vectors of i64 to and from f64 (AVX-512DQ).
  bool wideConversions;
  /// Loop bodies of pure ops are ordered chain by chain
  /// (clusterIndependentChains).
  bool chainsApart;
  Location loc = loop.getLoc();
  DenseSet<Value> varying;
  /// Values proven to be `uniform + lane` (consecutive items of the chunk).
  DenseSet<Value> consecutive;
  /// A value equal to the consecutive value `run` (give or take a uniform
  /// offset) wherever every lane of `run` lies between `low` (uniform; null:
  /// 0) and `high` (uniform; inclusive or not): the boundary rules' clamp,
  /// wrap and zero applied to `item + offset`. One wide access serves such
  /// an index whenever the chunk's first and last lanes lie inside.
  struct BoundedRun {
    Value run, low, high;
    bool highInclusive;
  };
  DenseMap<Value, BoundedRun> boundedRuns;
  DenseMap<Value, Wide> values;
  /// Lanes of a consecutive division's partner, computed with it.
  DenseMap<Value, Value> partnerLanes;
  DenseMap<Value, Value> pointers;
  Value iota;
  OpBuilder::InsertPoint preheader;
};

} // namespace

//===----------------------------------------------------------------------===//
// Analysis
//===----------------------------------------------------------------------===//

LogicalResult LaneVectorizer::analyze(std::string &why) {
  if (!loop.getInitArgs().empty()) {
    why = "the lane loop carries values";
    return failure();
  }
  std::optional<int64_t> step = getConstantIntValue(loop.getStep());
  if (!step || *step != 1) {
    why = "the lane loop's step is not 1";
    return failure();
  }
  varying.insert(loop.getInductionVar());
  consecutive.insert(loop.getInductionVar());
  // Lane dependence flows along operands, branch conditions and loop-carried
  // values; iterate until nothing changes (loop-carried values may become
  // varying through their yields).
  bool changed = true;
  auto mark = [&](Value value) {
    if (varying.insert(value).second)
      changed = true;
  };
  while (changed) {
    changed = false;
    loop.getBody()->walk([&](Operation *op) {
      if (auto ifOp = dyn_cast<scf::IfOp>(op)) {
        bool laneCondition = isVarying(ifOp.getCondition());
        for (auto [index, result] : llvm::enumerate(ifOp.getResults())) {
          bool fromBranch = isVarying(ifOp.thenYield().getOperand(index)) ||
                            (ifOp.elseBlock() &&
                             isVarying(ifOp.elseYield().getOperand(index)));
          if (laneCondition || fromBranch)
            mark(result);
        }
        return;
      }
      if (auto forOp = dyn_cast<scf::ForOp>(op)) {
        auto yield = cast<scf::YieldOp>(forOp.getBody()->getTerminator());
        for (auto [index, result] : llvm::enumerate(forOp.getResults())) {
          if (isVarying(forOp.getInitArgs()[index]) ||
              isVarying(yield.getOperand(index))) {
            mark(result);
            mark(forOp.getRegionIterArg(index));
          }
        }
        return;
      }
      if (op->getNumRegions() != 0)
        return;
      if (llvm::any_of(op->getOperands(),
                       [&](Value v) { return isVarying(v); }))
        for (Value result : op->getResults())
          mark(result);
    });
  }
  // `uniform + lane` values: their lanes are consecutive integers.
  loop.getBody()->walk([&](Operation *op) {
    if (auto add = dyn_cast<arith::AddIOp>(op)) {
      Value lhs = add.getLhs(), rhs = add.getRhs();
      if ((consecutive.contains(lhs) && !isVarying(rhs)) ||
          (consecutive.contains(rhs) && !isVarying(lhs)))
        consecutive.insert(add.getResult());
    } else if (auto subtract = dyn_cast<arith::SubIOp>(op)) {
      if (consecutive.contains(subtract.getLhs()) &&
          !isVarying(subtract.getRhs()))
        consecutive.insert(subtract.getResult());
    } else if (isa<arith::IndexCastOp, arith::IndexCastUIOp>(op)) {
      // Lanes consecutive in a narrower integer may wrap inside a chunk
      // (i8 lanes 127, -128): widened, they are not consecutive.
      Type source = elementType(op->getOperand(0).getType());
      bool widens = !source.isIndex() && source.getIntOrFloatBitWidth() < 64;
      if (consecutive.contains(op->getOperand(0)) && !widens)
        consecutive.insert(op->getResult(0));
    }
  });
  findBoundedRuns();

  WalkResult result = loop.getBody()->walk([&](Operation *op) {
    if (failed(check(op, why)))
      return WalkResult::interrupt();
    return WalkResult::advance();
  });
  return failure(result.wasInterrupted());
}

/// The boundary rules (SimAttrs.cpp, buildBoundaryItem) on a consecutive
/// `item + offset`, and uniform shifts of their results:
///   clamp  minsi(maxsi(x, low), high)
///   zero   select(cmpi ult(x, end), x, c)
///   wrap   scf.if (cmpi ult(x, end)) { yield x } else { ... }
void LaneVectorizer::findBoundedRuns() {
  auto uniform = [&](Value value) { return !isVarying(value); };
  // x < end, unsigned, with x consecutive and end uniform: the run of x
  // within [0, end).
  auto unsignedBelow = [&](Value condition, Value &run, Value &end) {
    auto compare = condition.getDefiningOp<arith::CmpIOp>();
    if (!compare || compare.getPredicate() != arith::CmpIPredicate::ult ||
        !consecutive.contains(compare.getLhs()) || !uniform(compare.getRhs()))
      return false;
    run = compare.getLhs();
    end = compare.getRhs();
    return true;
  };
  loop.getBody()->walk([&](Operation *op) {
    if (auto minimum = dyn_cast<arith::MinSIOp>(op)) {
      auto maximum = minimum.getLhs().getDefiningOp<arith::MaxSIOp>();
      if (maximum && uniform(minimum.getRhs()) &&
          consecutive.contains(maximum.getLhs()) && uniform(maximum.getRhs()))
        boundedRuns[minimum.getResult()] = {maximum.getLhs(), maximum.getRhs(),
                                            minimum.getRhs(),
                                            /*highInclusive=*/true};
      return;
    }
    if (auto select = dyn_cast<arith::SelectOp>(op)) {
      Value run, end;
      if (unsignedBelow(select.getCondition(), run, end) &&
          select.getTrueValue() == run && uniform(select.getFalseValue()))
        boundedRuns[select.getResult()] = {run, Value(), end,
                                           /*highInclusive=*/false};
      return;
    }
    if (auto branch = dyn_cast<scf::IfOp>(op)) {
      Value run, end;
      if (branch.getNumResults() == 1 && branch.elseBlock() &&
          unsignedBelow(branch.getCondition(), run, end) &&
          branch.thenYield().getOperand(0) == run)
        boundedRuns[branch.getResult(0)] = {run, Value(), end,
                                            /*highInclusive=*/false};
      return;
    }
    // Uniform shifts and casts keep the run and its bounds. The run is
    // copied before the new entry is made: inserting may grow the map and
    // move the entry it was copied from (a use after free that valgrind
    // found on a scene with 21 window reads).
    auto keepRun = [&](Value from, Value to) {
      auto it = boundedRuns.find(from);
      if (it == boundedRuns.end())
        return false;
      BoundedRun run = it->second;
      boundedRuns[to] = run;
      return true;
    };
    if (isa<arith::AddIOp, arith::SubIOp>(op)) {
      Value lhs = op->getOperand(0), rhs = op->getOperand(1);
      if (uniform(rhs) && keepRun(lhs, op->getResult(0)))
        return;
      if (isa<arith::AddIOp>(op) && uniform(lhs))
        keepRun(rhs, op->getResult(0));
      return;
    }
    if (isa<arith::IndexCastOp, arith::IndexCastUIOp>(op))
      keepRun(op->getOperand(0), op->getResult(0));
  });
}

LogicalResult LaneVectorizer::check(Operation *op, std::string &why) {
  auto fail = [&](StringRef reason) {
    why = (reason + ": " + op->getName().getStringRef()).str();
    return failure();
  };
  for (Value result : op->getResults())
    if (isVarying(result) && !isLaneType(result.getType()))
      return fail("a lane-dependent value of a type without lanes");
  if (isa<scf::YieldOp>(op))
    return success();
  if (auto forOp = dyn_cast<scf::ForOp>(op)) {
    if (isVarying(forOp.getLowerBound()) || isVarying(forOp.getUpperBound()) ||
        isVarying(forOp.getStep()))
      return fail("a loop with lane-dependent bounds");
    for (BlockArgument arg : forOp.getRegionIterArgs())
      if (isVarying(arg) && !isLaneType(arg.getType()))
        return fail("a lane-dependent loop value of a type without lanes");
    return success();
  }
  if (isa<scf::IfOp>(op))
    return success();
  if (auto load = dyn_cast<memref::LoadOp>(op)) {
    if (load.getIndices().size() == 1 && !isVarying(load.getIndices()[0]))
      return success();
    if (!isAddressable(load.getMemRef()) ||
        loop->isAncestor(load.getMemRef().getParentRegion()->getParentOp()))
      return fail("a lane-dependent load from a memref it cannot address");
    return success();
  }
  if (auto store = dyn_cast<memref::StoreOp>(op)) {
    if (store.getIndices().size() != 1)
      return fail("a store to a memref of rank other than 1");
    bool laneIndex = isVarying(store.getIndices()[0]);
    if (!laneIndex && isVarying(store.getValueToStore()))
      return fail("lanes that store different values to one element");
    if (laneIndex &&
        (!isAddressable(store.getMemRef()) ||
         loop->isAncestor(store.getMemRef().getParentRegion()->getParentOp())))
      return fail("a lane-dependent store to a memref it cannot address");
    return success();
  }
  bool anyVarying =
      llvm::any_of(op->getResults(), [&](Value v) { return isVarying(v); });
  if (!anyVarying) {
    // Uniform: cloned as it is, once for all lanes, which only holds for an
    // op without effects (a repeated store of one value is handled above).
    if (op->getNumRegions() == 0 && isMemoryEffectFree(op))
      return success();
    return fail("an op with effects or regions");
  }
  if (isElementwise(op)) {
    Type resultType = op->getResult(0).getType();
    for (Value operand : op->getOperands()) {
      if (!isLaneType(operand.getType()))
        return fail("an operand without lanes");
      if (isa<VectorType>(operand.getType()) &&
          elementCount(operand.getType()) != elementCount(resultType))
        return fail("operands of different shapes");
    }
    return success();
  }
  if (auto broadcast = dyn_cast<vector::BroadcastOp>(op)) {
    if (isa<VectorType>(broadcast.getSourceType()))
      return fail("a broadcast of a vector");
    return success();
  }
  if (auto extract = dyn_cast<vector::ExtractOp>(op)) {
    if (!extract.getDynamicPosition().empty() ||
        extract.getStaticPosition().size() != 1 ||
        extract.getStaticPosition()[0] < 0)
      return fail("an extract at a dynamic position");
    return success();
  }
  if (auto insert = dyn_cast<vector::InsertOp>(op)) {
    if (!insert.getDynamicPosition().empty() ||
        insert.getStaticPosition().size() != 1 ||
        insert.getStaticPosition()[0] < 0 ||
        isa<VectorType>(insert.getValueToStoreType()))
      return fail("an insert at a dynamic position");
    return success();
  }
  if (isa<vector::ShuffleOp, vector::FromElementsOp>(op))
    return success();
  if (auto reduction = dyn_cast<vector::ReductionOp>(op)) {
    // A reassociating reduction may be lowered in another order.
    if (auto fastmath = reduction.getFastmathAttr();
        fastmath &&
        bitEnumContainsAny(fastmath.getValue(), arith::FastMathFlags::reassoc))
      return fail("a reassociating reduction");
    switch (reduction.getKind()) {
    case vector::CombiningKind::ADD:
    case vector::CombiningKind::MUL:
    case vector::CombiningKind::MINUI:
    case vector::CombiningKind::MINSI:
    case vector::CombiningKind::MAXUI:
    case vector::CombiningKind::MAXSI:
    case vector::CombiningKind::AND:
    case vector::CombiningKind::OR:
    case vector::CombiningKind::XOR:
    case vector::CombiningKind::MINIMUMF:
    case vector::CombiningKind::MAXIMUMF:
      return success();
    default:
      return fail("a reduction of an unsupported kind");
    }
  }
  return fail("an op it cannot widen");
}

//===----------------------------------------------------------------------===//
// Emission helpers
//===----------------------------------------------------------------------===//

Wide LaneVectorizer::lookup(Value value) const {
  auto it = values.find(value);
  if (it != values.end())
    return it->second;
  // Defined outside the loop: uniform, used as it is.
  Wide wide;
  wide.parts.push_back(value);
  return wide;
}

Value LaneVectorizer::constantIndex(OpBuilder &b, int64_t value) {
  return arith::ConstantIndexOp::create(b, loc, value);
}

unsigned LaneVectorizer::freshDeinterleavings(Value value,
                                              unsigned depth) const {
  Wide wide = lookup(value);
  if (!wide.varying || !wide.parts.empty())
    return 0;
  if (!wide.definedBy)
    return 2;
  if (!wide.elementwiseOf || depth == 0)
    return 1;
  return std::min(operandDeinterleavings(wide.elementwiseOf, depth - 1), 1u);
}

unsigned LaneVectorizer::operandDeinterleavings(Operation *op,
                                                unsigned depth) const {
  unsigned operands = 0;
  for (auto [index, operand] : llvm::enumerate(op->getOperands()))
    if (!isUniformCondition(op, index))
      operands += freshDeinterleavings(operand, depth);
  return operands;
}

Value LaneVectorizer::lanePart(OpBuilder &b, Value value, int64_t k) {
  Wide wide = lookup(value);
  if (wide.varying && wide.parts.empty() && wide.interleaved &&
      wide.elementwiseOf) {
    // An elementwise op on interleaved values costs as many instructions in
    // parts as interleaved, and its parts from its operands' parts cost no
    // de-interleaving where they have them, or one where one operand does
    // not yet: then the operand's parts, often needed elsewhere too (the
    // rows of a vec4 product built from the same two loads, and each row
    // also read as a whole), are made once instead of each result's.
    Operation *op = wide.elementwiseOf;
    if (operandDeinterleavings(op, /*depth=*/4) <= 1) {
      OpBuilder at(b.getContext());
      at.setInsertionPointAfter(wide.definedBy);
      SmallVector<Value, 4> parts;
      for (int64_t e = 0, n = elementCount(value.getType()); e < n; ++e)
        parts.push_back(widenElementPart(at, op, e, /*mask=*/Value()));
      values[value].parts.assign(parts.begin(), parts.end());
      wide = values[value];
    }
  }
  if (wide.varying && wide.parts.empty() && wide.interleaved) {
    // The de-interleaving shuffles, once, where the value is defined.
    OpBuilder at(b.getContext());
    if (wide.definedBy)
      at.setInsertionPointAfter(wide.definedBy);
    else // a loop-carried value: at the start of its loop's body
      at.setInsertionPointToStart(
          cast<BlockArgument>(wide.interleaved).getOwner());
    Wide &held = values[value];
    for (int64_t e = 0, n = elementCount(value.getType()); e < n; ++e) {
      SmallVector<int64_t> positions;
      for (int64_t lane = 0; lane < width; ++lane)
        positions.push_back(lane * wide.stride + e);
      held.parts.push_back(vector::ShuffleOp::create(
          at, loc, wide.interleaved, wide.interleaved, positions));
    }
    wide = held;
  }
  if (wide.varying)
    return wide.parts[isa<VectorType>(value.getType()) ? k : 0];
  Value scalar = wide.parts[0];
  if (isa<VectorType>(value.getType()))
    scalar = vector::ExtractOp::create(b, loc, scalar, k);
  return vector::BroadcastOp::create(b, loc, laneType(scalar.getType()),
                                     scalar);
}

Value LaneVectorizer::interleavedOf(OpBuilder &b, Value value, int64_t stride) {
  auto type = dyn_cast<VectorType>(value.getType());
  if (!type)
    return Value();
  Wide wide = lookup(value);
  if (wide.varying)
    return wide.interleaved && wide.stride == stride ? wide.interleaved
                                                     : Value();
  // A uniform vector<N x T>: element k in every lane's position k
  // (interleaved values have no padding: stride == N).
  Value uniform = wide.parts[0];
  if (type.getNumElements() != stride)
    return Value();
  SmallVector<int64_t> positions;
  for (int64_t lane = 0; lane < width; ++lane)
    for (int64_t e = 0; e < stride; ++e)
      positions.push_back(e);
  return vector::ShuffleOp::create(b, loc, uniform, uniform, positions);
}

bool LaneVectorizer::widenInterleaved(OpBuilder &b, Operation *op) {
  Value result = op->getResult(0);
  auto type = dyn_cast<VectorType>(result.getType());
  // Integer divisions keep their per-part masks (a lane a branch does not
  // take divides by one); comparisons make their masks per part (a shuffle
  // of i1 vectors costs more on x86 than the compares it would save).
  if (!type || type.getNumElements() < 2 || isIntegerDivision(op) ||
      type.getElementType().isInteger(1))
    return false;
  int64_t stride = 0;
  for (Value operand : op->getOperands()) {
    Wide wide = lookup(operand);
    if (wide.varying && wide.interleaved) {
      stride = wide.stride;
      break;
    }
  }
  if (!stride)
    return false;
  SmallVector<Value> operands;
  for (auto [index, operand] : llvm::enumerate(op->getOperands())) {
    if (isUniformCondition(op, index)) {
      operands.push_back(lookup(operand).parts[0]);
      continue;
    }
    if (isVarying(operand) && !lookup(operand).interleaved)
      return false;
    Value held = interleavedOf(b, operand, stride);
    if (!held)
      return false;
    operands.push_back(held);
  }
  OperationState state(loc, op->getName());
  state.addOperands(operands);
  state.addTypes(VectorType::get({width * stride}, type.getElementType()));
  state.addAttributes(op->getAttrs());
  Operation *widened = b.create(state);
  Wide wide;
  wide.varying = true;
  wide.interleaved = widened->getResult(0);
  wide.stride = stride;
  wide.definedBy = widened;
  wide.elementwiseOf = op;
  values[result] = wide;
  return true;
}

SmallVector<Value> LaneVectorizer::laneParts(OpBuilder &b, Value value) {
  SmallVector<Value> parts;
  for (int64_t k = 0, e = elementCount(value.getType()); k < e; ++k)
    parts.push_back(lanePart(b, value, k));
  return parts;
}

void LaneVectorizer::heldTypes(Value value,
                               SmallVectorImpl<Type> &types) const {
  if (!isVarying(value)) {
    types.push_back(value.getType());
    return;
  }
  types.append(elementCount(value.getType()),
               laneType(elementType(value.getType())));
}

void LaneVectorizer::assign(ValueRange results, ValueRange flat) {
  holdResults(results, flat, SmallVector<bool>(results.size(), false), nullptr);
}

void LaneVectorizer::holdResults(ValueRange results, ValueRange flat,
                                 ArrayRef<bool> interleaved,
                                 Operation *definedBy) {
  unsigned position = 0;
  for (auto [index, result] : llvm::enumerate(results)) {
    Wide wide;
    wide.varying = isVarying(result);
    if (interleaved[index]) {
      wide.interleaved = flat[position++];
      wide.stride = elementCount(result.getType());
      wide.definedBy = definedBy;
    } else {
      unsigned count = wide.varying ? elementCount(result.getType()) : 1;
      for (unsigned k = 0; k < count; ++k)
        wide.parts.push_back(flat[position++]);
    }
    values[result] = wide;
  }
}

void LaneVectorizer::appendHeld(OpBuilder &b, Value target, Value source,
                                SmallVectorImpl<Value> &flat) {
  if (!isVarying(target)) {
    flat.push_back(lookup(source).parts[0]);
    return;
  }
  llvm::append_range(flat, laneParts(b, source));
}

Value LaneVectorizer::anyLane(OpBuilder &b, Value mask) {
  return vector::ReductionOp::create(b, loc, vector::CombiningKind::OR, mask);
}

Value LaneVectorizer::allLanes(OpBuilder &b, Value mask) {
  return vector::ReductionOp::create(b, loc, vector::CombiningKind::AND, mask);
}

/// The aligned pointer of `memref` as an !llvm.ptr, made once before the
/// widened loop (every memref it addresses is defined outside the loop).
Value LaneVectorizer::basePointer(OpBuilder &b, Value memref) {
  auto it = pointers.find(memref);
  if (it != pointers.end())
    return it->second;
  OpBuilder::InsertionGuard guard(b);
  b.restoreInsertionPoint(preheader);
  Value address =
      memref::ExtractAlignedPointerAsIndexOp::create(b, loc, memref);
  Value integer = arith::IndexCastOp::create(b, loc, b.getI64Type(), address);
  Value pointer = LLVM::IntToPtrOp::create(
      b, loc, LLVM::LLVMPointerType::get(b.getContext()), integer);
  preheader = b.saveInsertionPoint();
  pointers[memref] = pointer;
  return pointer;
}

Value LaneVectorizer::splat(OpBuilder &b, Type scalar, Attribute value) {
  VectorType type = laneType(scalar);
  return arith::ConstantOp::create(b, loc, type,
                                   DenseElementsAttr::get(type, value));
}

Value LaneVectorizer::firstAddress(OpBuilder &b, Value pointer, Type scalar,
                                   Value index, int64_t stride) {
  Value offset = vector::ExtractOp::create(b, loc, index, 0);
  if (stride != 1)
    offset = arith::MulIOp::create(
        b, loc, offset,
        arith::ConstantIntOp::create(b, loc, b.getI64Type(), stride));
  return LLVM::GEPOp::create(b, loc, LLVM::LLVMPointerType::get(b.getContext()),
                             scalar, pointer, ValueRange{offset});
}

SmallVector<Value> LaneVectorizer::laneAddresses(OpBuilder &b, Value pointer,
                                                 Type scalar, Value index,
                                                 int64_t stride,
                                                 int64_t count) {
  Value base = index;
  if (stride != 1)
    base = arith::MulIOp::create(
        b, loc, index, splat(b, b.getI64Type(), b.getI64IntegerAttr(stride)));
  VectorType pointers =
      VectorType::get({width}, LLVM::LLVMPointerType::get(b.getContext()));
  SmallVector<Value> addresses;
  for (int64_t k = 0; k < count; ++k) {
    Value offsets = base;
    if (k != 0)
      offsets = arith::AddIOp::create(
          b, loc, base, splat(b, b.getI64Type(), b.getI64IntegerAttr(k)));
    addresses.push_back(LLVM::GEPOp::create(b, loc, pointers, scalar, pointer,
                                            ValueRange{offsets}));
  }
  return addresses;
}

/// True (i1) when the lanes of `index` (i64 lanes) are consecutive and every
/// lane is active, so that one wide access serves the chunk.
Value LaneVectorizer::contiguousCheck(OpBuilder &b, Value original, Value index,
                                      Value mask) {
  // Consecutive lanes (under a branch's mask): whether every lane runs.
  if (mask && consecutive.contains(original))
    return allLanes(b, mask);
  auto bounded = boundedRuns.find(original);
  if (bounded != boundedRuns.end()) {
    // The run's first lane x0 and last x0 + width - 1 inside the bounds:
    // then every lane's index is its run value shifted alike.
    const BoundedRun &run = bounded->second;
    // An index or integer value (scalar or lanes) as i64.
    auto toI64 = [&](Value value) -> Value {
      Type type = value.getType();
      auto vector = dyn_cast<VectorType>(type);
      Type element = vector ? vector.getElementType() : type;
      Type i64 = vector ? Type(laneType(b.getI64Type())) : b.getI64Type();
      if (element.isIndex())
        return arith::IndexCastOp::create(b, loc, i64, value);
      if (element.getIntOrFloatBitWidth() < 64)
        return arith::ExtSIOp::create(b, loc, i64, value);
      return value;
    };
    auto scalar = [&](Value uniformValue) {
      return toI64(lookup(uniformValue).parts[0]);
    };
    Value runLanes = toI64(lookup(run.run).parts[0]);
    Value first = vector::ExtractOp::create(b, loc, runLanes, 0);
    Value last = arith::AddIOp::create(
        b, loc, first,
        arith::ConstantIntOp::create(b, loc, b.getI64Type(), width - 1));
    Value low = run.low
                    ? scalar(run.low)
                    : arith::ConstantIntOp::create(b, loc, b.getI64Type(), 0)
                          .getResult();
    Value above =
        arith::CmpIOp::create(b, loc, arith::CmpIPredicate::sge, first, low);
    Value below =
        arith::CmpIOp::create(b, loc,
                              run.highInclusive ? arith::CmpIPredicate::sle
                                                : arith::CmpIPredicate::slt,
                              last, scalar(run.high));
    Value inside = arith::AndIOp::create(b, loc, above, below);
    // The run does not wrap around the 64-bit integers inside the chunk
    // (`%i + c` near the largest index): else the lanes past the wrap are
    // far below the first, however the ends compare.
    Value noWrap =
        arith::CmpIOp::create(b, loc, arith::CmpIPredicate::sge, last, first);
    inside = arith::AndIOp::create(b, loc, inside, noWrap);
    if (mask)
      inside = arith::AndIOp::create(b, loc, inside, allLanes(b, mask));
    return inside;
  }
  Value first = vector::ExtractOp::create(b, loc, index, 0);
  Value firsts = vector::BroadcastOp::create(b, loc, index.getType(), first);
  Value iota64 = arith::IndexCastOp::create(b, loc, index.getType(), iota);
  Value expected = arith::AddIOp::create(b, loc, firsts, iota64);
  Value equal =
      arith::CmpIOp::create(b, loc, arith::CmpIPredicate::eq, index, expected);
  Value all = allLanes(b, equal);
  if (mask)
    all = arith::AndIOp::create(b, loc, all, allLanes(b, mask));
  return all;
}

/// True when `index` is an item divided by a constant of at least a chunk's
/// lanes (a block's levels: item / 32), give or take uniform offsets and
/// clamps: then most chunks read one element, which a scalar load and a
/// broadcast serve at a fraction of a gather's cost, and the others two
/// (a chunk crosses at most one multiple of the divisor), which two such
/// loads and a select serve.
bool LaneVectorizer::likelyUniform(Value index) const {
  auto constantAtLeast = [](Value value, int64_t bound) {
    APInt constant;
    return matchPattern(value, m_ConstantInt(&constant)) &&
           constant.getActiveBits() < 63 && constant.getSExtValue() >= bound;
  };
  while (Operation *op = index.getDefiningOp()) {
    if (isa<arith::IndexCastOp, arith::IndexCastUIOp, arith::ExtSIOp,
            arith::ExtUIOp>(op)) {
      index = op->getOperand(0);
      continue;
    }
    if (isa<arith::DivUIOp, arith::DivSIOp>(op))
      return constantAtLeast(op->getOperand(1), width);
    if (isa<arith::ShRUIOp, arith::ShRSIOp>(op)) {
      APInt shift;
      return matchPattern(op->getOperand(1), m_ConstantInt(&shift)) &&
             shift.getZExtValue() < 63 &&
             (int64_t(1) << shift.getZExtValue()) >= width;
    }
    // A uniform offset or clamp keeps lanes that were equal equal.
    if (isa<arith::AddIOp, arith::SubIOp, arith::MinSIOp, arith::MinUIOp,
            arith::MaxSIOp, arith::MaxUIOp>(op)) {
      Value lhs = op->getOperand(0), rhs = op->getOperand(1);
      if (isVarying(lhs) == isVarying(rhs))
        return false;
      index = isVarying(lhs) ? lhs : rhs;
      continue;
    }
    return false;
  }
  return false;
}

//===----------------------------------------------------------------------===//
// Emission
//===----------------------------------------------------------------------===//

void LaneVectorizer::widenBlock(OpBuilder &b, Block &block, Value mask) {
  for (Operation &op : block.without_terminator())
    widenOp(b, &op, mask);
}

void LaneVectorizer::cloneUniform(OpBuilder &b, Operation *op) {
  IRMapping mapping;
  for (Value operand : op->getOperands())
    mapping.map(operand, lookup(operand).parts[0]);
  Operation *clone = b.clone(*op, mapping);
  for (auto [result, cloned] :
       llvm::zip(op->getResults(), clone->getResults())) {
    Wide wide;
    wide.parts.push_back(cloned);
    values[result] = wide;
  }
}

void LaneVectorizer::widenOp(OpBuilder &b, Operation *op, Value mask) {
  if (auto ifOp = dyn_cast<scf::IfOp>(op))
    return widenIf(b, ifOp, mask);
  if (auto forOp = dyn_cast<scf::ForOp>(op))
    return widenFor(b, forOp, mask);
  if (auto load = dyn_cast<memref::LoadOp>(op)) {
    if (isVarying(load.getIndices()[0]))
      return widenLoad(b, load, mask);
    return cloneUniform(b, op);
  }
  if (auto store = dyn_cast<memref::StoreOp>(op)) {
    if (isVarying(store.getIndices()[0]))
      return widenStore(b, store, mask);
    // Every active lane stores the same value to one element: once (the
    // enclosing branches already run only when a lane is active).
    return cloneUniform(b, op);
  }
  if (!llvm::any_of(op->getResults(), [&](Value v) { return isVarying(v); }))
    return cloneUniform(b, op);

  Wide wide;
  wide.varying = true;
  if (auto broadcast = dyn_cast<vector::BroadcastOp>(op)) {
    Value lanes = lanePart(b, broadcast.getSource(), 0);
    wide.parts.append(elementCount(broadcast.getResultVectorType()), lanes);
  } else if (auto extract = dyn_cast<vector::ExtractOp>(op)) {
    wide.parts.push_back(
        lanePart(b, extract.getSource(), extract.getStaticPosition()[0]));
  } else if (auto insert = dyn_cast<vector::InsertOp>(op)) {
    wide.parts = laneParts(b, insert.getDest());
    wide.parts[insert.getStaticPosition()[0]] =
        lanePart(b, insert.getValueToStore(), 0);
  } else if (auto shuffle = dyn_cast<vector::ShuffleOp>(op)) {
    SmallVector<Value> both = laneParts(b, shuffle.getV1());
    llvm::append_range(both, laneParts(b, shuffle.getV2()));
    Type scalar = elementType(shuffle.getResultVectorType());
    for (int64_t position : shuffle.getMask()) {
      if (position < 0 || position >= static_cast<int64_t>(both.size()))
        wide.parts.push_back(arith::ConstantOp::create(
            b, loc, laneType(scalar), b.getZeroAttr(laneType(scalar))));
      else
        wide.parts.push_back(both[position]);
    }
  } else if (auto fromElements = dyn_cast<vector::FromElementsOp>(op)) {
    for (Value element : fromElements.getElements())
      wide.parts.push_back(lanePart(b, element, 0));
  } else if (auto reduction = dyn_cast<vector::ReductionOp>(op)) {
    return widenReduction(b, reduction);
  } else {
    return widenElementwise(b, op, mask);
  }
  values[op->getResult(0)] = wide;
}

void LaneVectorizer::widenElementwise(OpBuilder &b, Operation *op, Value mask) {
  Value result = op->getResult(0);
  int64_t count = elementCount(result.getType());
  Wide wide;
  wide.varying = true;
  if (count == 1 && dividesConsecutive(op)) {
    if (Value lanes = partnerLanes.lookup(result)) {
      wide.parts.push_back(lanes);
      values[result] = wide;
      return;
    }
    // The remainder of a division of the same operands, or the division of
    // a remainder: the same signedness, the other kind.
    auto isSigned = [](Operation *of) {
      return isa<arith::DivSIOp, arith::RemSIOp>(of);
    };
    auto isRemainder = [](Operation *of) {
      return isa<arith::RemSIOp, arith::RemUIOp>(of);
    };
    Operation *partner = nullptr;
    for (Operation *next = op->getNextNode(); next && !partner;
         next = next->getNextNode())
      if (isa<arith::DivSIOp, arith::DivUIOp, arith::RemSIOp, arith::RemUIOp>(
              next) &&
          next->getOperands() == op->getOperands() &&
          isSigned(next) == isSigned(op) &&
          isRemainder(next) != isRemainder(op))
        partner = next;
    wide.parts.push_back(divideConsecutive(b, op, partner, mask));
    values[result] = wide;
    return;
  }
  if (!narrowRemainderDivisor(op) && widenInterleaved(b, op))
    return;
  for (int64_t k = 0; k < count; ++k)
    wide.parts.push_back(widenElementPart(b, op, k, mask));
  values[result] = wide;
}

Value LaneVectorizer::widenElementPart(OpBuilder &b, Operation *op, int64_t k,
                                       Value mask) {
  Type resultScalar = elementType(op->getResult(0).getType());
  if (uint64_t divisor = narrowRemainderDivisor(op))
    return remainderByHalves(b, lanePart(b, op->getOperand(0), k), divisor);
  SmallVector<Value> operands;
  for (auto [index, operand] : llvm::enumerate(op->getOperands())) {
    if (isUniformCondition(op, index)) {
      operands.push_back(lookup(operand).parts[0]);
      continue;
    }
    Value lanes = lanePart(b, operand, k);
    // Lanes that do not run this division divide by one: x86 traps on a
    // division by zero (and on INT_MIN / -1), whichever lane it is in.
    if (index == 1 && mask && isIntegerDivision(op) &&
        !divisorCannotTrap(op, operand)) {
      Type type = lanes.getType();
      Value one = arith::ConstantOp::create(
          b, loc, type,
          DenseElementsAttr::get(cast<ShapedType>(type),
                                 b.getIntegerAttr(elementType(type), 1)));
      lanes = arith::SelectOp::create(b, loc, mask, lanes, one);
    }
    operands.push_back(lanes);
  }
  if (dividesThroughDouble(op))
    return divideThroughDouble(b, op, operands[0], operands[1], mask);
  // A widened math.fpowi has an exponent per lane, which LLVM's powi (one
  // exponent for all) cannot take: --sim-lower-vector-ops, after this pass,
  // unrolls it into one scalar fpowi per lane.
  OperationState state(loc, op->getName());
  state.addOperands(operands);
  state.addTypes(laneType(resultScalar));
  state.addAttributes(op->getAttrs());
  return b.create(state)->getResult(0);
}

bool LaneVectorizer::dividesConsecutive(Operation *op) const {
  if (!isa<arith::DivSIOp, arith::DivUIOp, arith::RemSIOp, arith::RemUIOp>(
          op) ||
      !consecutive.contains(op->getOperand(0)) || isVarying(op->getOperand(1)))
    return false;
  Type scalar = elementType(op->getResultTypes()[0]);
  if (!scalar.isIndex() && !scalar.isInteger(32) && !scalar.isInteger(64))
    return false;
  // A constant divisor: LLVM shifts by a power of two and multiplies by the
  // reciprocal of any other, which x86 does in vector lanes for 32 bits
  // but lane by lane for 64; a constant below the lanes never qualifies.
  APInt value;
  if (matchPattern(op->getOperand(1), m_ConstantInt(&value)))
    return !scalar.isInteger(32) && !value.isPowerOf2() &&
           value.uge(static_cast<uint64_t>(width)) && !value.isNegative();
  return true;
}

Value LaneVectorizer::divideConsecutive(OpBuilder &b, Operation *op,
                                        Operation *partner, Value mask) {
  bool isSigned = isa<arith::DivSIOp, arith::RemSIOp>(op);
  bool isRemainder = isa<arith::RemSIOp, arith::RemUIOp>(op);
  Value dividend = lanePart(b, op->getOperand(0), 0);
  Value divisor = lookup(op->getOperand(1)).parts[0];
  auto type = cast<VectorType>(dividend.getType());
  Type scalar = type.getElementType();
  unsigned bits = scalar.isIndex() ? 64 : scalar.getIntOrFloatBitWidth();
  auto constant = [&](OpBuilder &at, const APInt &value) -> Value {
    return arith::ConstantOp::create(at, loc, scalar,
                                     at.getIntegerAttr(scalar, value));
  };
  APInt lanesMinusOne(bits, width - 1);
  // Lane k holds first + k: the last lane must not wrap, and for a signed
  // division every lane must be at least 0, so that all of them divide
  // alike; a divisor of at least the lanes is then crossed at most once.
  Value first = vector::ExtractOp::create(b, loc, dividend, 0);
  Value wideDivisor =
      isSigned
          ? arith::CmpIOp::create(b, loc, arith::CmpIPredicate::sge, divisor,
                                  constant(b, APInt(bits, width)))
          : arith::CmpIOp::create(b, loc, arith::CmpIPredicate::uge, divisor,
                                  constant(b, APInt(bits, width)));
  Value noWrap =
      isSigned
          ? arith::CmpIOp::create(
                b, loc, arith::CmpIPredicate::sle, first,
                constant(b, APInt::getSignedMaxValue(bits) - lanesMinusOne))
          : arith::CmpIOp::create(
                b, loc, arith::CmpIPredicate::ule, first,
                constant(b, APInt::getMaxValue(bits) - lanesMinusOne));
  Value fits = arith::AndIOp::create(b, loc, wideDivisor, noWrap);
  if (isSigned)
    fits = arith::AndIOp::create(
        b, loc, fits,
        arith::CmpIOp::create(b, loc, arith::CmpIPredicate::sge, first,
                              constant(b, APInt(bits, 0))));
  SmallVector<Type> types(partner ? 2 : 1, type);
  auto choice = scf::IfOp::create(b, loc, types, fits,
                                  /*withElseRegion=*/true);
  OpBuilder fast = emptyBody(choice.thenBlock());
  // Both operands are at least 0 here: an unsigned division is the signed
  // one.
  Value quotient = arith::DivUIOp::create(fast, loc, first, divisor);
  Value base = arith::MulIOp::create(fast, loc, quotient, divisor);
  auto spread = [&](Value value) -> Value {
    return vector::BroadcastOp::create(fast, loc, type, value);
  };
  // first + k - quotient * divisor = (first % divisor) + k, below twice the
  // divisor: one past it at most once.
  Value remainders = arith::SubIOp::create(fast, loc, dividend, spread(base));
  Value divisors = spread(divisor);
  Value past = arith::CmpIOp::create(fast, loc, arith::CmpIPredicate::uge,
                                     remainders, divisors);
  auto remainderLanes = [&]() -> Value {
    return arith::SelectOp::create(
        fast, loc, past, arith::SubIOp::create(fast, loc, remainders, divisors),
        remainders);
  };
  auto quotientLanes = [&]() -> Value {
    Value next = arith::AddIOp::create(fast, loc, quotient,
                                       constant(fast, APInt(bits, 1)));
    return arith::SelectOp::create(fast, loc, past, spread(next),
                                   spread(quotient));
  };
  SmallVector<Value> fastResults{isRemainder ? remainderLanes()
                                             : quotientLanes()};
  if (partner)
    fastResults.push_back(isRemainder ? quotientLanes() : remainderLanes());
  scf::YieldOp::create(fast, loc, fastResults);
  OpBuilder slow = emptyBody(choice.elseBlock());
  SmallVector<Value> slowResults{widenElementPart(slow, op, 0, mask)};
  if (partner)
    slowResults.push_back(widenElementPart(slow, partner, 0, mask));
  scf::YieldOp::create(slow, loc, slowResults);
  if (partner)
    partnerLanes[partner->getResult(0)] = choice.getResult(1);
  return choice.getResult(0);
}

Value LaneVectorizer::divideThroughDouble(OpBuilder &b, Operation *op,
                                          Value dividend, Value divisor,
                                          Value mask) {
  bool isSigned = isa<arith::DivSIOp, arith::RemSIOp>(op);
  bool isRemainder = isa<arith::RemSIOp, arith::RemUIOp>(op);
  if (elementType(dividend.getType()).isIndex()) {
    // As 64-bit integers (what index lowers to), and back.
    VectorType words = laneType(b.getI64Type());
    auto toWords = [&](Value value) -> Value {
      if (isSigned)
        return arith::IndexCastOp::create(b, loc, words, value);
      return arith::IndexCastUIOp::create(b, loc, words, value);
    };
    Value result =
        divideThroughDouble(b, op, toWords(dividend), toWords(divisor), mask);
    if (isSigned)
      return arith::IndexCastOp::create(b, loc, dividend.getType(), result);
    return arith::IndexCastUIOp::create(b, loc, dividend.getType(), result);
  }
  auto intType = cast<VectorType>(dividend.getType());
  VectorType doubles = laneType(b.getF64Type());
  auto remainderOf = [&](OpBuilder &at, Value quotient) -> Value {
    if (!isRemainder)
      return quotient;
    return arith::SubIOp::create(
        at, loc, dividend, arith::MulIOp::create(at, loc, quotient, divisor));
  };
  // The quotient by the target's conversions; fptosi and fptoui truncate
  // toward zero, as divsi and divui do.
  auto inDoubles = [&](OpBuilder &at) -> Value {
    auto toDouble = [&](Value value) -> Value {
      if (isSigned)
        return arith::SIToFPOp::create(at, loc, doubles, value);
      return arith::UIToFPOp::create(at, loc, doubles, value);
    };
    Value ratio =
        arith::DivFOp::create(at, loc, toDouble(dividend), toDouble(divisor));
    if (isSigned)
      return arith::FPToSIOp::create(at, loc, intType, ratio);
    return arith::FPToUIOp::create(at, loc, intType, ratio);
  };
  // Every 32-bit integer is a double, and x86 converts vectors of them both
  // ways.
  if (elementType(intType).isInteger(32))
    return remainderOf(b, inDoubles(b));

  // 64 bits: with AVX-512DQ (wideConversions) x86 converts vectors of them
  // to and from doubles, for lanes within 2^53 of zero; elsewhere LLVM would
  // convert lane by lane, so the lanes convert through the bits of
  // 1.5 * 2^52, whose doubles have a unit in the last place of 1: for
  // |v| < 2^51, bits(1.5 * 2^52) + v are the bits of 1.5 * 2^52 + v. Either
  // needs every lane that runs in range.
  Type i64 = b.getI64Type();
  // Made before the branch, whose builder `b` then stands after it.
  Value magicBits, magicDouble;
  if (!wideConversions) {
    const double magic = 6755399441055744.0; // 1.5 * 2^52
    magicBits = splat(b, i64, b.getI64IntegerAttr(0x4338000000000000));
    magicDouble = splat(b, b.getF64Type(), b.getF64FloatAttr(magic));
  }
  int64_t limit = int64_t(1) << (wideConversions ? 53 : 51);
  auto inRange = [&](Value value) -> Value {
    if (!isSigned)
      return arith::CmpIOp::create(b, loc, arith::CmpIPredicate::ult, value,
                                   splat(b, i64, b.getI64IntegerAttr(limit)));
    // -limit < v < limit <=> v + (limit - 1) <u 2 limit - 1 (a wrapped sum
    // is large).
    Value shifted = arith::AddIOp::create(
        b, loc, value, splat(b, i64, b.getI64IntegerAttr(limit - 1)));
    return arith::CmpIOp::create(
        b, loc, arith::CmpIPredicate::ult, shifted,
        splat(b, i64, b.getI64IntegerAttr(2 * limit - 1)));
  };
  Value lanesInRange =
      arith::AndIOp::create(b, loc, inRange(dividend), inRange(divisor));
  if (mask) {
    // Lanes that do not run this division may hold anything.
    lanesInRange =
        arith::SelectOp::create(b, loc, mask, lanesInRange,
                                splat(b, b.getI1Type(), b.getBoolAttr(true)));
  }
  Value chunkInRange = vector::ReductionOp::create(
      b, loc, vector::CombiningKind::AND, lanesInRange);
  auto choice = scf::IfOp::create(b, loc, TypeRange{intType}, chunkInRange,
                                  /*withElseRegion=*/true);
  OpBuilder fast = emptyBody(choice.thenBlock());
  Value quotient;
  if (wideConversions) {
    quotient = inDoubles(fast);
  } else {
    auto toDouble = [&](Value value) -> Value {
      Value bits = arith::AddIOp::create(fast, loc, value, magicBits);
      return arith::SubFOp::create(
          fast, loc, arith::BitcastOp::create(fast, loc, doubles, bits),
          magicDouble);
    };
    Value ratio =
        arith::DivFOp::create(fast, loc, toDouble(dividend), toDouble(divisor));
    // |quotient| <= |dividend| < 2^51: truncated, then back through the
    // bits.
    Value truncated = math::TruncOp::create(fast, loc, ratio);
    Value shiftedQuotient = arith::BitcastOp::create(
        fast, loc, intType,
        arith::AddFOp::create(fast, loc, truncated, magicDouble));
    quotient = arith::SubIOp::create(fast, loc, shiftedQuotient, magicBits);
  }
  scf::YieldOp::create(fast, loc, remainderOf(fast, quotient));
  OpBuilder slow = emptyBody(choice.elseBlock());
  OperationState state(loc, op->getName());
  state.addOperands({dividend, divisor});
  state.addTypes(intType);
  state.addAttributes(op->getAttrs());
  scf::YieldOp::create(slow, loc, slow.create(state)->getResult(0));
  return choice.getResult(0);
}

Value LaneVectorizer::remainderByHalves(OpBuilder &b, Value lanes,
                                        uint64_t divisor) {
  // x = hi * 2^32 + lo, so x % c = ((hi % c) * (2^32 % c) + lo % c) % c, and
  // with c < 2^16 every term fits in 32 bits.
  VectorType wide = laneType(b.getI64Type());
  VectorType narrow = laneType(b.getI32Type());
  Value c = splat(b, b.getI32Type(), b.getI32IntegerAttr(divisor));
  Value high = arith::TruncIOp::create(
      b, loc, narrow,
      arith::ShRUIOp::create(
          b, loc, lanes, splat(b, b.getI64Type(), b.getI64IntegerAttr(32))));
  Value low = arith::TruncIOp::create(b, loc, narrow, lanes);
  Value highRemainder = arith::RemUIOp::create(b, loc, high, c);
  Value lowRemainder = arith::RemUIOp::create(b, loc, low, c);
  uint64_t scale = (uint64_t(1) << 32) % divisor;
  Value scaled =
      scale == 1 ? highRemainder
                 : Value(arith::MulIOp::create(
                       b, loc, highRemainder,
                       splat(b, b.getI32Type(), b.getI32IntegerAttr(scale))));
  Value sum = arith::AddIOp::create(b, loc, scaled, lowRemainder);
  return arith::ExtUIOp::create(b, loc, wide,
                                arith::RemUIOp::create(b, loc, sum, c));
}

void LaneVectorizer::widenReduction(OpBuilder &b, vector::ReductionOp op) {
  SmallVector<Value> parts = laneParts(b, op.getVector());
  Type scalar = op.getDest().getType();
  VectorType lanes = laneType(scalar);
  // The op each kind combines with (upstream's), element by element.
  auto combine = [&](Value lhs, Value rhs) -> Value {
    return vector::makeArithReduction(b, loc, op.getKind(), lhs, rhs);
  };
  // The scalar lowering is an ordered llvm.vector.reduce.* from the
  // accumulator, or for fadd and fmul without one from +0.0 and 1.0
  // (convert-vector-to-llvm): the same chain here, element by element.
  Value total;
  if (op.getAcc()) {
    total = lanePart(b, op.getAcc(), 0);
  } else if (isa<FloatType>(scalar) &&
             (op.getKind() == vector::CombiningKind::ADD ||
              op.getKind() == vector::CombiningKind::MUL)) {
    double start = op.getKind() == vector::CombiningKind::ADD ? 0.0 : 1.0;
    total = arith::ConstantOp::create(
        b, loc, lanes,
        DenseElementsAttr::get(lanes, b.getFloatAttr(scalar, start)));
  }
  bool minMaxWithAcc =
      op.getAcc() && (op.getKind() != vector::CombiningKind::ADD &&
                      op.getKind() != vector::CombiningKind::MUL);
  if (minMaxWithAcc) {
    // Lowered as the reduction of the vector, then combined with the
    // accumulator (exact for these kinds in any order, but keep it).
    Value reduced = parts[0];
    for (Value part : ArrayRef(parts).drop_front())
      reduced = combine(reduced, part);
    total = combine(total, reduced);
  } else {
    for (Value part : parts)
      total = total ? combine(total, part) : part;
  }
  Wide wide;
  wide.varying = true;
  wide.parts.push_back(total);
  values[op.getDest()] = wide;
}

void LaneVectorizer::widenIf(OpBuilder &b, scf::IfOp op, Value mask) {
  SmallVector<Type> types;
  for (Value result : op.getResults())
    heldTypes(result, types);

  auto emitBranch = [&](OpBuilder &inner, Block *block, Value branchMask) {
    SmallVector<Value> flat;
    if (block) {
      widenBlock(inner, *block, branchMask);
      auto yield = cast<scf::YieldOp>(block->getTerminator());
      for (auto [result, yielded] :
           llvm::zip(op.getResults(), yield.getOperands()))
        appendHeld(inner, result, yielded, flat);
    }
    scf::YieldOp::create(inner, loc, flat);
  };

  if (!isVarying(op.getCondition())) {
    // One side for every lane. A varying vector that both sides compute
    // interleaved (a read from one of several halves, chosen by the clock)
    // is yielded as it is, so that its users (a window's sum) keep it
    // interleaved too; a result either side has only in parts is held in
    // parts, and the branch is widened again where that shows only then.
    Value condition = lookup(op.getCondition()).parts[0];
    SmallVector<bool> interleave;
    for (Value result : op.getResults())
      interleave.push_back(isVarying(result) &&
                           holdsInterleaved(result.getType()));
    while (true) {
      SmallVector<Type> held;
      for (auto [index, result] : llvm::enumerate(op.getResults())) {
        if (!interleave[index]) {
          heldTypes(result, held);
          continue;
        }
        auto type = cast<VectorType>(result.getType());
        held.push_back(VectorType::get({width * type.getNumElements()},
                                       type.getElementType()));
      }
      bool hasElse = op.elseBlock() != nullptr || !held.empty();
      auto newIf = scf::IfOp::create(b, loc, held, condition, hasElse);
      bool retry = false;
      auto emitSide = [&](Block *into, Block *from) {
        OpBuilder inner = emptyBody(into);
        SmallVector<Value> flat;
        if (from) {
          widenBlock(inner, *from, mask);
          auto yield = cast<scf::YieldOp>(from->getTerminator());
          for (auto [index, result, yielded] :
               llvm::enumerate(op.getResults(), yield.getOperands())) {
            if (!interleave[index]) {
              appendHeld(inner, result, yielded, flat);
              continue;
            }
            Value held =
                interleavedOf(inner, yielded, elementCount(result.getType()));
            if (!held) {
              interleave[index] = false;
              retry = true;
              continue;
            }
            flat.push_back(held);
          }
        }
        scf::YieldOp::create(inner, loc, flat);
      };
      emitSide(newIf.thenBlock(), op.thenBlock());
      if (hasElse)
        emitSide(newIf.elseBlock(), op.elseBlock());
      if (retry) {
        newIf.erase();
        continue;
      }
      holdResults(op.getResults(), newIf.getResults(), interleave, newIf);
      return;
    }
  }

  // A lane-dependent branch: each side runs under its lanes' mask, only when
  // one of them takes it; the results are selected per lane.
  Value condition = lookup(op.getCondition()).parts[0];
  Value ones = arith::ConstantOp::create(
      b, loc, condition.getType(),
      DenseElementsAttr::get(cast<ShapedType>(condition.getType()),
                             b.getBoolAttr(true)));
  Value negated = arith::XOrIOp::create(b, loc, condition, ones);
  auto side = [&](Block *block, Value sideMask) -> SmallVector<Value> {
    if (mask)
      sideMask = arith::AndIOp::create(b, loc, mask, sideMask);
    auto guard = scf::IfOp::create(b, loc, types, anyLane(b, sideMask),
                                   /*withElse=*/true);
    OpBuilder inner = emptyBody(guard.thenBlock());
    emitBranch(inner, block, sideMask);
    OpBuilder skipped = emptyBody(guard.elseBlock());
    SmallVector<Value> zeros;
    for (Type type : types)
      zeros.push_back(arith::ConstantOp::create(skipped, loc, type,
                                                skipped.getZeroAttr(type)));
    scf::YieldOp::create(skipped, loc, zeros);
    return SmallVector<Value>(guard.getResults());
  };
  SmallVector<Value> thenValues = side(op.thenBlock(), condition);
  SmallVector<Value> elseValues;
  if (op.elseBlock())
    elseValues = side(op.elseBlock(), negated);
  SmallVector<Value> selected;
  for (auto [index, type] : llvm::enumerate(types))
    selected.push_back(arith::SelectOp::create(
        b, loc, condition, thenValues[index], elseValues[index]));
  assign(op.getResults(), selected);
}

/// Whether every use of the loop-carried `arg` in its loop's body is an
/// elementwise op of the shape widenInterleaved takes (a vector of the same
/// elements, not i1, no integer division, not a select's condition): only
/// then can the value stay interleaved from one iteration to the next.
static bool carriesElementwise(BlockArgument arg) {
  if (!holdsInterleaved(arg.getType()))
    return false;
  Type type = arg.getType();
  for (OpOperand &use : arg.getUses()) {
    Operation *user = use.getOwner();
    if (isa<scf::YieldOp>(user) &&
        user->getParentOp() == arg.getOwner()->getParentOp())
      continue;
    if (!OpTrait::hasElementwiseMappableTraits(user) ||
        user->getNumResults() != 1 || isIntegerDivision(user) ||
        (isa<arith::SelectOp>(user) && use.getOperandNumber() == 0) ||
        user->getResult(0).getType() != type)
      return false;
  }
  return true;
}

/// Reorders a loop body made of pure ops only (a scene's load: rounds of a
/// matrix product on vec4 values) so that the ops of each independent
/// computation in it run one after another: widened, element k of a vec4
/// is computed from elements k only, so the body holds one chain of ops per
/// element, and emitted op by op the chains interleave and keep every
/// element's operands and results live at once (32 vectors for a 4x4
/// product, twice what AVX2 has in registers: LLVM spills half of them in
/// every round). Chain by chain, an element's operands die before the next
/// chain starts. Only the order changes, not an operation, so the results
/// are the same bits.
static void clusterIndependentChains(Block &body) {
  SmallVector<Operation *> ops;
  for (Operation &op : body.without_terminator()) {
    if (op.getNumRegions() != 0 || !isMemoryEffectFree(&op))
      return;
    ops.push_back(&op);
  }
  if (ops.size() < 4)
    return;
  // Ops joined along the operands defined in the body; each chain in its
  // order, the chains in the order they start.
  llvm::EquivalenceClasses<Operation *> chains;
  for (Operation *op : ops) {
    chains.insert(op);
    for (Value operand : op->getOperands())
      if (Operation *def = operand.getDefiningOp();
          def && def->getBlock() == &body)
        chains.unionSets(op, def);
  }
  DenseMap<Operation *, unsigned> start;
  SmallVector<unsigned> chain;
  for (auto [index, op] : llvm::enumerate(ops))
    chain.push_back(
        start.try_emplace(chains.getLeaderValue(op), index).first->second);
  if (llvm::all_equal(chain))
    return;
  auto order = llvm::to_vector(llvm::seq<unsigned>(0, ops.size()));
  llvm::sort(order, [&](unsigned a, unsigned b) {
    return std::make_pair(chain[a], a) < std::make_pair(chain[b], b);
  });
  Operation *terminator = body.getTerminator();
  for (unsigned index : order)
    ops[index]->moveBefore(terminator);
}

void LaneVectorizer::widenFor(OpBuilder &b, scf::ForOp op, Value mask) {
  // A varying vector carried from one iteration to the next (a window's
  // sum) stays interleaved, as loads give it, where the body computes it
  // from interleaved values by elementwise ops only: then its loads are
  // not de-interleaved in every iteration, the sum once after the loop.
  // Whether the body computes it that way shows only once it is widened,
  // so a loop whose carried value turns out to need its parts is widened
  // again without that value interleaved.
  auto iterArgs = op.getRegionIterArgs();
  SmallVector<bool> interleave;
  for (auto [arg, init] : llvm::zip(iterArgs, op.getInitArgs())) {
    int64_t count = elementCount(arg.getType());
    Wide start = lookup(init);
    interleave.push_back(
        isVarying(arg) && carriesElementwise(arg) &&
        (start.varying ? start.interleaved && start.stride == count : true));
  }
  while (true) {
    SmallVector<Value> inits;
    for (auto [index, arg, init] :
         llvm::enumerate(iterArgs, op.getInitArgs())) {
      if (interleave[index])
        inits.push_back(interleavedOf(b, init, elementCount(arg.getType())));
      else
        appendHeld(b, arg, init, inits);
    }
    auto newFor =
        scf::ForOp::create(b, loc, lookup(op.getLowerBound()).parts[0],
                           lookup(op.getUpperBound()).parts[0],
                           lookup(op.getStep()).parts[0], inits);
    Block *body = newFor.getBody();
    Wide iv;
    iv.parts.push_back(newFor.getInductionVar());
    values[op.getInductionVar()] = iv;
    holdResults(iterArgs, newFor.getRegionIterArgs(), interleave, nullptr);
    OpBuilder inner = emptyBody(body);
    widenBlock(inner, *op.getBody(), mask);
    auto yield = cast<scf::YieldOp>(op.getBody()->getTerminator());
    // A carried value stays interleaved where nothing in the body took its
    // parts and the body computes the next one interleaved.
    bool retry = false;
    SmallVector<Value> flat;
    for (auto [index, arg, yielded] :
         llvm::enumerate(iterArgs, yield.getOperands())) {
      if (!interleave[index]) {
        appendHeld(inner, arg, yielded, flat);
        continue;
      }
      Value next =
          values[arg].parts.empty()
              ? interleavedOf(inner, yielded, elementCount(arg.getType()))
              : Value();
      if (!next) {
        interleave[index] = false;
        retry = true;
        continue;
      }
      flat.push_back(next);
    }
    if (retry) {
      newFor.erase();
      continue;
    }
    scf::YieldOp::create(inner, loc, flat);
    if (chainsApart)
      clusterIndependentChains(*body);
    holdResults(op.getResults(), newFor.getResults(), interleave, newFor);
    return;
  }
}

/// Interleaves `parts` (count a power of two) into one vector whose element
/// `lane * count + k` is lane `lane` of part k.
static Value interleaveLanes(OpBuilder &b, Location loc,
                             ArrayRef<Value> parts) {
  if (parts.size() == 1)
    return parts[0];
  SmallVector<Value> even, odd;
  for (auto [k, part] : llvm::enumerate(parts))
    (k % 2 ? odd : even).push_back(part);
  Value lhs = interleaveLanes(b, loc, even), rhs = interleaveLanes(b, loc, odd);
  int64_t length = cast<VectorType>(lhs.getType()).getNumElements();
  SmallVector<int64_t> positions;
  for (int64_t i = 0; i < length; ++i) {
    positions.push_back(i);
    positions.push_back(length + i);
  }
  return vector::ShuffleOp::create(b, loc, lhs, rhs, positions);
}

void LaneVectorizer::widenLoad(OpBuilder &b, memref::LoadOp op, Value mask) {
  Type element = op.getMemRefType().getElementType();
  int64_t count = elementCount(element);
  int64_t stride = elementStride(element);
  Type scalar = elementType(element);
  VectorType lanes = laneType(scalar);
  VectorType i64Lanes = laneType(b.getI64Type());
  Value pointer = basePointer(b, op.getMemRef());
  Value indexLanes = lookup(op.getIndices()[0]).parts[0];
  Value index = arith::IndexCastOp::create(b, loc, i64Lanes, indexLanes);
  int64_t alignment = scalar.getIntOrFloatBitWidth() / 8;

  // One load of `width * stride` scalars from the first lane's element, as
  // memory holds them.
  auto raw = [&](OpBuilder &at) {
    Value address = firstAddress(at, pointer, scalar, index, stride);
    return LLVM::LoadOp::create(
        at, loc, VectorType::get({width * stride}, scalar), address, alignment);
  };
  // The same, split into one vector per element.
  auto wideLoad = [&](OpBuilder &at) {
    Value all = raw(at);
    SmallVector<Value> parts;
    if (count == 1) {
      parts.push_back(all);
      return parts;
    }
    for (int64_t k = 0; k < count; ++k) {
      SmallVector<int64_t> positions;
      for (int64_t lane = 0; lane < width; ++lane)
        positions.push_back(lane * stride + k);
      parts.push_back(vector::ShuffleOp::create(at, loc, all, all, positions));
    }
    return parts;
  };
  // The lanes' indices where every lane may read: lanes a branch does not
  // take read an active lane's element.
  auto safeIndex = [&](OpBuilder &at) {
    if (!mask)
      return index;
    Value largest =
        splat(at, at.getI64Type(),
              at.getI64IntegerAttr(std::numeric_limits<int64_t>::max()));
    Value active = arith::SelectOp::create(at, loc, mask, index, largest);
    Value lowest = vector::ReductionOp::create(
        at, loc, vector::CombiningKind::MINSI, active);
    Value lowests = vector::BroadcastOp::create(at, loc, i64Lanes, lowest);
    return arith::SelectOp::create(at, loc, mask, index, lowests).getResult();
  };
  // Gathers, one per element, at the safe indices `safe`.
  auto gatherAt = [&](OpBuilder &at, Value safe) {
    Value everyLane = splat(at, at.getI1Type(), at.getBoolAttr(true));
    Value zero =
        arith::ConstantOp::create(at, loc, lanes, at.getZeroAttr(lanes));
    SmallVector<Value> parts;
    for (Value addresses :
         laneAddresses(at, pointer, scalar, safe, stride, count)) {
      parts.push_back(LLVM::masked_gather::create(
          at, loc, lanes, addresses, everyLane, ValueRange{zero},
          at.getI32IntegerAttr(alignment)));
    }
    return parts;
  };
  auto gather = [&](OpBuilder &at) { return gatherAt(at, safeIndex(at)); };
  // The elements of the item at element index `itemIndex` (i64), each loaded
  // once and broadcast to every lane.
  auto broadcastItem = [&](OpBuilder &at, Value itemIndex) {
    Value offset = itemIndex;
    if (stride != 1)
      offset = arith::MulIOp::create(
          at, loc, offset,
          arith::ConstantIntOp::create(at, loc, at.getI64Type(), stride));
    SmallVector<Value> broadcasts;
    for (int64_t k = 0; k < count; ++k) {
      Value element = LLVM::GEPOp::create(
          at, loc, LLVM::LLVMPointerType::get(at.getContext()), scalar, pointer,
          ValueRange{offset});
      if (k != 0)
        element = LLVM::GEPOp::create(
            at, loc, LLVM::LLVMPointerType::get(at.getContext()), scalar,
            element, ArrayRef<LLVM::GEPArg>{k});
      Value value = LLVM::LoadOp::create(at, loc, scalar, element, alignment);
      broadcasts.push_back(vector::BroadcastOp::create(at, loc, lanes, value));
    }
    return broadcasts;
  };
  // One scalar load per element, to every lane, when the lanes' indices are
  // all the same; two and a select per lane when they are those of the
  // first and the last lane (an item divided by the items of a block, read
  // at an offset, crosses a block at most once in a chunk); else the
  // gathers.
  auto uniformOrGatherAt = [&](OpBuilder &at,
                               Value safe) -> SmallVector<Value> {
    Value first = vector::ExtractOp::create(at, loc, safe, 0);
    Value firsts = vector::BroadcastOp::create(at, loc, i64Lanes, first);
    Value isFirst =
        arith::CmpIOp::create(at, loc, arith::CmpIPredicate::eq, safe, firsts);
    SmallVector<Type> types(count, lanes);
    auto choice =
        scf::IfOp::create(at, loc, types, allLanes(at, isFirst), true);
    OpBuilder one = emptyBody(choice.thenBlock());
    scf::YieldOp::create(one, loc, broadcastItem(one, first));
    OpBuilder many = emptyBody(choice.elseBlock());
    Value last = vector::ExtractOp::create(many, loc, safe, width - 1);
    Value lasts = vector::BroadcastOp::create(many, loc, i64Lanes, last);
    Value firstOrLast = arith::OrIOp::create(
        many, loc, isFirst,
        arith::CmpIOp::create(many, loc, arith::CmpIPredicate::eq, safe,
                              lasts));
    auto pair =
        scf::IfOp::create(many, loc, types, allLanes(many, firstOrLast), true);
    OpBuilder two = emptyBody(pair.thenBlock());
    SmallVector<Value> ofFirst = broadcastItem(two, first);
    SmallVector<Value> ofLast = broadcastItem(two, last);
    SmallVector<Value> selected;
    for (int64_t k = 0; k < count; ++k)
      selected.push_back(
          arith::SelectOp::create(two, loc, isFirst, ofFirst[k], ofLast[k]));
    scf::YieldOp::create(two, loc, selected);
    OpBuilder other = emptyBody(pair.elseBlock());
    scf::YieldOp::create(other, loc, gatherAt(other, safe));
    scf::YieldOp::create(many, loc, pair.getResults());
    return SmallVector<Value>(choice.getResults());
  };
  // Under a mask, a chunk whose every lane runs (all but the last of a
  // range guarded by `item < range`) reads at its own indices; only the
  // others pay for the safe ones (a reduction across the lanes).
  auto uniformOrGather = [&](OpBuilder &at) -> SmallVector<Value> {
    if (!mask)
      return uniformOrGatherAt(at, index);
    SmallVector<Type> types(count, lanes);
    auto choice = scf::IfOp::create(at, loc, types, allLanes(at, mask), true);
    OpBuilder every = emptyBody(choice.thenBlock());
    scf::YieldOp::create(every, loc, uniformOrGatherAt(every, index));
    OpBuilder some = emptyBody(choice.elseBlock());
    scf::YieldOp::create(some, loc, uniformOrGatherAt(some, safeIndex(some)));
    return SmallVector<Value>(choice.getResults());
  };

  // Elements of several scalars without padding are held interleaved, as
  // loaded (the gathers' parts interleaved in the slow path), and
  // de-interleaved only where something needs them apart.
  bool interleave = count > 1 && stride == count && llvm::isPowerOf2_64(count);
  bool contiguous = !mask && consecutive.contains(op.getIndices()[0]);
  Wide wide;
  wide.varying = true;
  if (interleave) {
    if (contiguous) {
      auto load = raw(b);
      wide.interleaved = load;
      wide.definedBy = load;
    } else {
      auto choice = scf::IfOp::create(
          b, loc, TypeRange{VectorType::get({width * stride}, scalar)},
          contiguousCheck(b, op.getIndices()[0], index, mask), true);
      OpBuilder fast = emptyBody(choice.thenBlock());
      scf::YieldOp::create(fast, loc, ValueRange{raw(fast).getResult()});
      OpBuilder slow = emptyBody(choice.elseBlock());
      scf::YieldOp::create(
          slow, loc, ValueRange{interleaveLanes(slow, loc, gather(slow))});
      wide.interleaved = choice.getResult(0);
      wide.definedBy = choice;
    }
    wide.stride = stride;
    values[op.getResult()] = wide;
    return;
  }
  SmallVector<Value> parts;
  if (contiguous) {
    parts = wideLoad(b);
  } else if (likelyUniform(op.getIndices()[0])) {
    // An item divided by at least the lanes is never consecutive across a
    // chunk wider than two lanes: no contiguity check.
    parts = uniformOrGather(b);
  } else {
    SmallVector<Type> types(count, lanes);
    auto choice = scf::IfOp::create(
        b, loc, types, contiguousCheck(b, op.getIndices()[0], index, mask),
        true);
    OpBuilder fast = emptyBody(choice.thenBlock());
    scf::YieldOp::create(fast, loc, wideLoad(fast));
    OpBuilder slow = emptyBody(choice.elseBlock());
    scf::YieldOp::create(slow, loc, gather(slow));
    parts = SmallVector<Value>(choice.getResults());
  }
  wide.parts.assign(parts.begin(), parts.end());
  values[op.getResult()] = wide;
}

void LaneVectorizer::widenStore(OpBuilder &b, memref::StoreOp op, Value mask) {
  Type element = op.getMemRefType().getElementType();
  int64_t count = elementCount(element);
  int64_t stride = elementStride(element);
  Type scalar = elementType(element);
  VectorType i64Lanes = laneType(b.getI64Type());
  Value pointer = basePointer(b, op.getMemRef());
  Value indexLanes = lookup(op.getIndices()[0]).parts[0];
  Value index = arith::IndexCastOp::create(b, loc, i64Lanes, indexLanes);
  Value stored = op.getValueToStore();
  int64_t alignment = scalar.getIntOrFloatBitWidth() / 8;
  // A wide store writes whole elements; of a vector<3 x T> that includes its
  // padding, which the scatter leaves alone.
  bool wideOk = stride == count;
  // A value held interleaved is stored as it is (loaded, computed and
  // stored without a shuffle).
  Wide held = lookup(stored);
  Value interleaved = wideOk && held.varying && held.stride == stride
                          ? held.interleaved
                          : Value();

  auto wideStore = [&](OpBuilder &at) {
    Value address = firstAddress(at, pointer, scalar, index, stride);
    Value all = interleaved ? interleaved
                            : interleaveLanes(at, loc, laneParts(at, stored));
    LLVM::StoreOp::create(at, loc, all, address, alignment);
  };
  auto scatter = [&](OpBuilder &at) {
    SmallVector<Value> parts = laneParts(at, stored);
    Value lanesMask =
        mask ? mask : splat(at, at.getI1Type(), at.getBoolAttr(true));
    SmallVector<Value> addresses =
        laneAddresses(at, pointer, scalar, index, stride, count);
    for (int64_t k = 0; k < count; ++k) {
      LLVM::masked_scatter::create(
          at, loc, TypeRange{}, ValueRange{parts[k], addresses[k], lanesMask},
          {at.getNamedAttr("alignment", at.getI32IntegerAttr(alignment))});
    }
  };

  if (wideOk && !mask && consecutive.contains(op.getIndices()[0])) {
    wideStore(b);
    return;
  }
  if (!wideOk) {
    scatter(b);
    return;
  }
  auto choice = scf::IfOp::create(
      b, loc, TypeRange{}, contiguousCheck(b, op.getIndices()[0], index, mask),
      true);
  OpBuilder fast = OpBuilder::atBlockBegin(choice.thenBlock());
  if (!choice.thenBlock()->empty() && choice.thenBlock()->mightHaveTerminator())
    fast.setInsertionPoint(choice.thenBlock()->getTerminator());
  wideStore(fast);
  OpBuilder slow = OpBuilder::atBlockBegin(choice.elseBlock());
  if (!choice.elseBlock()->empty() && choice.elseBlock()->mightHaveTerminator())
    slow.setInsertionPoint(choice.elseBlock()->getTerminator());
  scatter(slow);
}

//===----------------------------------------------------------------------===//
// Selects that would divide in every lane
//===----------------------------------------------------------------------===//

/// Whether `value` is computed, through ops of `block` whose results nothing
/// else uses, by an integer division: work that a branch on the select's
/// condition would skip. x86 has no SIMD integer division, so a widened one
/// is a `div` per lane (tens of cycles each), and a select computes both of
/// its operands in every lane.
static bool costsDivision(Value value, Block *block, int depth = 0) {
  Operation *def = value.getDefiningOp();
  if (!def || def->getBlock() != block || !value.hasOneUse() ||
      def->getNumRegions() != 0 || !isMemoryEffectFree(def) || depth > 8)
    return false;
  if (isIntegerDivision(def) && !divisorCannotTrap(def, def->getOperand(1)))
    return true;
  return llvm::any_of(def->getOperands(), [&](Value operand) {
    return costsDivision(operand, block, depth + 1);
  });
}

bool LaneVectorizer::branchCostlySelects() {
  // A scene's num_steps picks its key with selects on scene parameters
  // (`i / @group` or `i`): the same choice in every lane, so a branch costs
  // one predictable jump where the select pays the division in every lane.
  SmallVector<arith::SelectOp> selects;
  loop.getBody()->walk([&](arith::SelectOp select) {
    Value condition = select.getCondition();
    if (isVarying(condition) || isa<VectorType>(condition.getType()))
      return;
    Block *block = select->getBlock();
    if (costsDivision(select.getTrueValue(), block) ||
        costsDivision(select.getFalseValue(), block))
      selects.push_back(select);
  });
  if (selects.empty())
    return false;
  DominanceInfo dominance;
  for (arith::SelectOp select : selects) {
    OpBuilder b(select);
    auto branch = scf::IfOp::create(b, select.getLoc(), select.getType(),
                                    select.getCondition(), /*withElse=*/true);
    OpBuilder thenBuilder = emptyBody(branch.thenBlock());
    scf::YieldOp::create(thenBuilder, select.getLoc(), select.getTrueValue());
    OpBuilder elseBuilder = emptyBody(branch.elseBlock());
    scf::YieldOp::create(elseBuilder, select.getLoc(), select.getFalseValue());
    select.replaceAllUsesWith(branch.getResult(0));
    select.erase();
    // Each operand's computation moves into the branch that uses it.
    controlFlowSink(
        branch->getRegions(), dominance,
        [](Operation *op, Region *) {
          return op->getNumRegions() == 0 && isMemoryEffectFree(op);
        },
        [](Operation *op, Region *region) {
          op->moveBefore(&region->front(), region->front().begin());
        });
  }
  return true;
}

void LaneVectorizer::rewrite() {
  OpBuilder b(loop);
  Value lower = loop.getLowerBound(), upper = loop.getUpperBound();
  // Whole chunks: [lower, lower + (upper - lower) / width * width).
  Value count = arith::SubIOp::create(b, loc, upper, lower);
  Value widthValue = constantIndex(b, width);
  Value chunks = arith::DivUIOp::create(b, loc, count, widthValue);
  Value whole = arith::MulIOp::create(b, loc, chunks, widthValue);
  Value end = arith::AddIOp::create(b, loc, lower, whole);
  SmallVector<APInt> positions;
  for (int64_t lane = 0; lane < width; ++lane)
    positions.push_back(APInt(64, lane));
  VectorType indexLanes = laneType(b.getIndexType());
  iota = arith::ConstantOp::create(
      b, loc, indexLanes, DenseElementsAttr::get(indexLanes, positions));

  auto chunkLoop = scf::ForOp::create(b, loc, lower, end, widthValue);
  // Base pointers are made before the chunk loop.
  preheader =
      OpBuilder::InsertPoint(chunkLoop->getBlock(), Block::iterator(chunkLoop));
  OpBuilder inner = OpBuilder::atBlockBegin(chunkLoop.getBody());
  inner.setInsertionPoint(chunkLoop.getBody()->getTerminator());
  Value firsts = vector::BroadcastOp::create(inner, loc, indexLanes,
                                             chunkLoop.getInductionVar());
  Wide lanes;
  lanes.varying = true;
  lanes.parts.push_back(arith::AddIOp::create(inner, loc, firsts, iota));
  values[loop.getInductionVar()] = lanes;
  widenBlock(inner, *loop.getBody(), /*mask=*/Value());

  // The original loop keeps the lanes after the last whole chunk.
  loop.getLowerBoundMutable().assign(end);
  loop->removeAttr(simplan::PlanDialect::getLanesAttrName());
}

namespace {

struct SimVectorizeLanesPass
    : sim::impl::SimVectorizeLanesBase<SimVectorizeLanesPass> {
  using Base::Base;

  void runOnOperation() override {
    if (width < 2 || width > 64 || !llvm::isPowerOf2_64(width)) {
      // A file's top module has no location of its own ("file:0:0"): at its
      // first operation then.
      Operation *at = getOperation();
      if (auto module = dyn_cast<ModuleOp>(at);
          module && !module.getBody()->empty())
        at = &module.getBody()->front();
      at->emitError()
          << "--sim-vectorize-lanes: width must be a power of two from 2 to "
             "64, not "
          << static_cast<int64_t>(width);
      return signalPassFailure();
    }
    SmallVector<scf::ForOp> loops;
    getOperation()->walk([&](scf::ForOp loop) {
      if (loop->hasAttr(simplan::PlanDialect::getLanesAttrName()))
        loops.push_back(loop);
    });
    for (scf::ForOp loop : loops) {
      std::optional<LaneVectorizer> vectorizer;
      vectorizer.emplace(loop, width, wideIntConversions, chainsApart);
      std::string why;
      LogicalResult analyzed = vectorizer->analyze(why);
      if (succeeded(analyzed) && vectorizer->branchCostlySelects()) {
        vectorizer.emplace(loop, width, wideIntConversions, chainsApart);
        analyzed = vectorizer->analyze(why);
      }
      if (failed(analyzed)) {
        // The scalar loop stays; it computes the same results.
        LLVM_DEBUG(llvm::dbgs() << "lanes stay scalar (" << why << ") at "
                                << loop.getLoc() << "\n");
        if (report)
          loop.emitRemark() << "lanes stay scalar: " << why;
        loop->removeAttr(simplan::PlanDialect::getLanesAttrName());
        ++numScalar;
        continue;
      }
      if (report)
        loop.emitRemark() << "lanes run " << static_cast<int64_t>(width)
                          << " at a time";
      vectorizer->rewrite();
      ++numWidened;
    }
  }
};

} // namespace
