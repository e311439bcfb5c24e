//===- SimOps.cpp - sim dialect operations and verifiers ------------------===//
//
// Verifiers check everything a scene must satisfy before any analysis runs:
// body signatures and yields, symbol references, element types, that every
// buffer has exactly one writer, that initial states do not depend on each
// other in a cycle, and that bodies make no poison values. Checks that need
// symbol lookups live in verifySymbolUses so that the symbol table is built
// once per simulation.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Support/Cycles.h"

#include "mlir/Dialect/UB/IR/UBOps.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Builders.h"
#include "mlir/IR/BuiltinOps.h"
#include "mlir/IR/BuiltinTypes.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/IR/Matchers.h"
#include "mlir/IR/OpImplementation.h"
#include "mlir/IR/TypeUtilities.h"

#include "llvm/ADT/DenseMap.h"
#include "llvm/ADT/STLExtras.h"
#include "llvm/ADT/SetVector.h"
#include "llvm/ADT/SmallPtrSet.h"
#include <limits>

using namespace mlir;
using namespace mlir::sim;

//===----------------------------------------------------------------------===//
// Helpers
//===----------------------------------------------------------------------===//

StringRef mlir::sim::stringifyBodyKind(BodyKind kind) {
  switch (kind) {
  case BodyKind::NumSteps:
    return "num_steps";
  case BodyKind::Evaluate:
    return "evaluate";
  case BodyKind::Init:
    return "init";
  case BodyKind::Exact:
    return "exact";
  case BodyKind::Total:
    return "total";
  }
  llvm_unreachable("unknown body kind");
}

bool mlir::sim::isValidElementType(Type type) {
  auto isScalar = [](Type t) { return t.isF32() || t.isF64(); };
  if (isScalar(type))
    return true;
  auto vector = dyn_cast<VectorType>(type);
  return vector && vector.getRank() == 1 && !vector.isScalable() &&
         vector.getNumElements() >= 1 && vector.getNumElements() <= 16 &&
         isScalar(vector.getElementType());
}

std::optional<BodyLocation> mlir::sim::getEnclosingBody(Operation *op) {
  for (Region *region = op->getParentRegion(); region;) {
    Operation *parent = region->getParentOp();
    if (!parent)
      return std::nullopt;
    if (auto component = dyn_cast<ComponentOp>(parent)) {
      BodyKind kind = region == &component.getNumSteps() ? BodyKind::NumSteps
                                                         : BodyKind::Evaluate;
      return BodyLocation{kind, component, nullptr};
    }
    if (auto buffer = dyn_cast<BufferOp>(parent)) {
      BodyKind kind =
          region == &buffer.getInit() ? BodyKind::Init : BodyKind::Exact;
      return BodyLocation{kind, nullptr, buffer};
    }
    if (auto total = dyn_cast<TotalOp>(parent))
      return BodyLocation{BodyKind::Total, nullptr, nullptr, total};
    region = parent->getParentRegion();
  }
  return std::nullopt;
}

/// Prints a type list as "'f32', 'i64'" for diagnostics.
static std::string formatTypes(TypeRange types) {
  std::string text;
  llvm::raw_string_ostream os(text);
  llvm::interleaveComma(types, os, [&](Type t) { os << "'" << t << "'"; });
  return text;
}

/// Verifies that `region` (a body of `op` named `bodyName`) has one block with
/// arguments of `argTypes` (named in `argSpelling` for the message) and ends
/// in a sim.yield. Returns that yield, or null after emitting an error.
static YieldOp verifyBodySignature(Operation *op, Region &region,
                                   StringRef bodyName, TypeRange argTypes,
                                   StringRef argSpelling) {
  Block &block = region.front();
  if (block.getArgumentTypes() != argTypes) {
    op->emitOpError() << "expects the " << bodyName
                      << " body to have arguments " << argSpelling
                      << ", but it has ("
                      << formatTypes(block.getArgumentTypes()) << ")";
    return nullptr;
  }
  // The body may not end in a terminator at all (an empty block, or one whose
  // last operation is not a terminator): the generic block checks run only
  // after this verifier, so Block::getTerminator() cannot be used here.
  auto yield = block.empty() ? nullptr : dyn_cast<YieldOp>(block.back());
  if (!yield) {
    op->emitOpError() << "expects the " << bodyName
                      << " body to end in 'sim.yield'";
    return nullptr;
  }
  // This verifier runs before the generic checks of the body's operations,
  // and a tool that erases operations through the C++ API (sim-reduce's
  // reduction tree) leaves their uses null: the yielded types cannot be
  // read then.
  if (llvm::is_contained(yield->getOperands(), Value())) {
    op->emitOpError() << "expects the " << bodyName
                      << " body to yield values, but an operand of its "
                         "'sim.yield' is null (its definition was erased)";
    return nullptr;
  }
  return yield;
}

/// Looks up `name` as a buffer of the simulation that encloses `user`.
static BufferOp lookupBuffer(SymbolTableCollection &symbolTable,
                             Operation *user, FlatSymbolRefAttr name) {
  return symbolTable.lookupNearestSymbolFrom<BufferOp>(user, name.getAttr());
}

//===----------------------------------------------------------------------===//
// Custom directives
//===----------------------------------------------------------------------===//

/// `(@a, @b)`: a parenthesised, non-empty list of flat symbol references.
static ParseResult parseSymbolList(OpAsmParser &parser, ArrayAttr &list) {
  SmallVector<Attribute> symbols;
  auto parseOne = [&]() -> ParseResult {
    StringAttr name;
    if (parser.parseSymbolName(name))
      return failure();
    symbols.push_back(FlatSymbolRefAttr::get(name));
    return success();
  };
  if (parser.parseCommaSeparatedList(OpAsmParser::Delimiter::Paren, parseOne))
    return failure();
  list = parser.getBuilder().getArrayAttr(symbols);
  return success();
}

static void printSymbolList(OpAsmPrinter &printer, Operation *,
                            ArrayAttr list) {
  printer << '(';
  llvm::interleaveComma(list, printer, [&](Attribute symbol) {
    printer.printSymbolName(cast<FlatSymbolRefAttr>(symbol).getValue());
  });
  printer << ')';
}

/// The integer of `max_steps(...)`, parsed as a signed 64-bit value so that
/// 3000000000 is not read as the i32 -1294967296: a value outside i32 gets
/// the verifier's message here, at its location.
static ParseResult parseMaxSteps(OpAsmParser &parser, IntegerAttr &maxSteps) {
  SMLoc loc = parser.getCurrentLocation();
  int64_t value = 0;
  if (parser.parseInteger(value))
    return failure();
  if (value < std::numeric_limits<int32_t>::min() ||
      value > std::numeric_limits<int32_t>::max())
    return parser.emitError(loc) << "expects max_steps to be "
                                 << (value < 1 ? "at least 1" : "at most 2^20")
                                 << ", but got " << value;
  maxSteps = parser.getBuilder().getI32IntegerAttr(value);
  return success();
}

static void printMaxSteps(OpAsmPrinter &printer, Operation *,
                          IntegerAttr maxSteps) {
  printer << maxSteps.getInt();
}

/// An optional bare read-role keyword (`own`, `interpolate`, `back_edge`).
static ParseResult parseOptionalReadRole(OpAsmParser &parser,
                                         ReadRoleAttr &role) {
  StringRef keyword;
  SMLoc loc = parser.getCurrentLocation();
  if (failed(parser.parseOptionalKeyword(&keyword)))
    return success();
  std::optional<ReadRole> value = symbolizeReadRole(keyword);
  if (!value)
    return parser.emitError(loc)
           << "expected a read role (own, interpolate or back_edge), but got '"
           << keyword << "'";
  role = ReadRoleAttr::get(parser.getContext(), *value);
  return success();
}

static void printOptionalReadRole(OpAsmPrinter &printer, Operation *,
                                  ReadRoleAttr role) {
  if (role)
    printer << ' ' << stringifyReadRole(role.getValue());
}

/// An optional `interp(<attribute>)` clause; the attribute must implement
/// InterpolationAttrInterface. `interp(none)` is #sim.none.
/// `(...)` after `interp`.
static ParseResult parseInterpClause(OpAsmParser &parser,
                                     InterpolationAttrInterface &interp) {
  if (parser.parseLParen())
    return failure();
  if (succeeded(parser.parseOptionalKeyword("none"))) {
    interp = cast<InterpolationAttrInterface>(
        NoneInterpAttr::get(parser.getContext()));
    return parser.parseRParen();
  }
  Attribute attr;
  SMLoc loc = parser.getCurrentLocation();
  if (parser.parseAttribute(attr))
    return failure();
  interp = dyn_cast<InterpolationAttrInterface>(attr);
  if (!interp)
    return parser.emitError(loc)
           << "expected an interpolation function such as #sim.linear, "
              "#sim.cubic or #sim.hermite<@derivative>, or none, but got "
           << attr;
  return parser.parseRParen();
}

static void printInterpClause(OpAsmPrinter &printer, Operation *,
                              InterpolationAttrInterface interp) {
  if (!interp)
    return;
  if (isa<NoneInterpAttr>(interp))
    printer << " interp(none)";
  else
    printer << " interp(" << Attribute(interp) << ")";
}

/// The version keyword of a sim.load.
static ParseResult parseLoadVersion(OpAsmParser &parser, VersionAttr &version) {
  StringRef keyword;
  SMLoc loc = parser.getCurrentLocation();
  if (failed(parser.parseOptionalKeyword(&keyword)))
    return parser.emitError(loc) << "expected the copy to load (source, "
                                    "snapshot, target or local)";
  std::optional<Version> value = symbolizeVersion(keyword);
  if (!value)
    return parser.emitError(loc)
           << "expected the copy to load (source, snapshot, target or "
              "local), but got '"
           << keyword << "'";
  version = VersionAttr::get(parser.getContext(), *value);
  return success();
}

static void printLoadVersion(OpAsmPrinter &printer, Operation *,
                             VersionAttr version) {
  printer << stringifyVersion(version.getValue());
}

/// An optional `boundary(<rule>)` clause; `clamp` (the default) is elided.
/// `(...)` after `boundary`.
static ParseResult parseBoundaryClause(OpAsmParser &parser,
                                       BoundaryAttr &boundary) {
  if (parser.parseLParen())
    return failure();
  StringRef keyword;
  SMLoc loc = parser.getCurrentLocation();
  if (failed(parser.parseOptionalKeyword(&keyword)))
    return parser.emitError(loc)
           << "expected a boundary rule (clamp, wrap or zero)";
  std::optional<Boundary> value = symbolizeBoundary(keyword);
  if (!value)
    return parser.emitError(loc)
           << "expected a boundary rule (clamp, wrap or zero), but got '"
           << keyword << "'";
  boundary = BoundaryAttr::get(parser.getContext(), *value);
  return parser.parseRParen();
}

static void printBoundaryClause(OpAsmPrinter &printer, Operation *,
                                BoundaryAttr boundary) {
  if (boundary && boundary.getValue() != Boundary::clamp)
    printer << " boundary(" << stringifyBoundary(boundary.getValue()) << ")";
}

/// A buffer's optional `constant`, `interp(...)` and `boundary(...)`, in
/// any order, each at most once; printed in that order.
static ParseResult parseBufferClauses(OpAsmParser &parser,
                                      InterpolationAttrInterface &interp,
                                      BoundaryAttr &boundary,
                                      UnitAttr &constant) {
  bool seenInterp = false, seenBoundary = false;
  while (true) {
    SMLoc loc = parser.getCurrentLocation();
    if (succeeded(parser.parseOptionalKeyword("constant"))) {
      if (constant)
        return parser.emitError(loc) << "the buffer is declared constant twice";
      constant = UnitAttr::get(parser.getContext());
    } else if (succeeded(parser.parseOptionalKeyword("interp"))) {
      if (seenInterp)
        return parser.emitError(loc) << "the buffer has two interp clauses";
      seenInterp = true;
      if (parseInterpClause(parser, interp))
        return failure();
    } else if (succeeded(parser.parseOptionalKeyword("boundary"))) {
      if (seenBoundary)
        return parser.emitError(loc) << "the buffer has two boundary clauses";
      seenBoundary = true;
      if (parseBoundaryClause(parser, boundary))
        return failure();
    } else {
      return success();
    }
  }
}

static void printBufferClauses(OpAsmPrinter &printer, Operation *op,
                               InterpolationAttrInterface interp,
                               BoundaryAttr boundary, UnitAttr constant) {
  if (constant)
    printer << " constant";
  printInterpClause(printer, op, interp);
  printBoundaryClause(printer, op, boundary);
}

/// Drops every use of the values `region` defines. The parser resolves a
/// name that was used before its definition wherever the definition is
/// found, even inside an isolated region (where the verifier would reject
/// the use later). When a later part of the op then fails to parse, the
/// op's regions are freed while such a use outside them still points into
/// them: the parser's cleanup then wrote to freed memory (a scene with a
/// deleted line and a typo further down crashed sim-opt). Cut first.
static void dropUsesOfDefinitions(Region &region) {
  for (Block &block : region) {
    for (BlockArgument argument : block.getArguments())
      argument.dropAllUses();
    block.walk([](Operation *op) {
      for (Value result : op->getResults())
        result.dropAllUses();
    });
  }
}

/// Parses `keyword region` into `region`; on failure drops the uses of
/// what `parsed` (the op's regions so far, `region` included) define.
static ParseResult parseBody(OpAsmParser &parser, StringRef keyword,
                             Region &region, ArrayRef<Region *> parsed) {
  if ((keyword.empty() || succeeded(parser.parseKeyword(keyword))) &&
      succeeded(parser.parseRegion(region)))
    return success();
  for (Region *earlier : parsed)
    dropUsesOfDefinitions(*earlier);
  return failure();
}

/// A buffer's `init {...}` and optional `exact {...}`.
static ParseResult parseBufferBodies(OpAsmParser &parser, Region &init,
                                     Region &exact) {
  if (parseBody(parser, "init", init, {&init}))
    return failure();
  if (failed(parser.parseOptionalKeyword("exact")))
    return success();
  return parseBody(parser, "", exact, {&init, &exact});
}

static void printBufferBodies(OpAsmPrinter &printer, BufferOp, Region &init,
                              Region &exact) {
  printer << "init ";
  printer.printRegion(init);
  if (!exact.empty()) {
    printer << " exact ";
    printer.printRegion(exact);
  }
}

/// A component's optional `num_steps {...}` and `evaluate {...}`.
static ParseResult parseComponentBodies(OpAsmParser &parser, Region &numSteps,
                                        Region &evaluate) {
  if (succeeded(parser.parseOptionalKeyword("num_steps")) &&
      parseBody(parser, "", numSteps, {&numSteps}))
    return failure();
  return parseBody(parser, "evaluate", evaluate, {&numSteps, &evaluate});
}

static void printComponentBodies(OpAsmPrinter &printer, ComponentOp,
                                 Region &numSteps, Region &evaluate) {
  if (!numSteps.empty()) {
    printer << "num_steps ";
    printer.printRegion(numSteps);
    printer << " ";
  }
  printer << "evaluate ";
  printer.printRegion(evaluate);
}

#define GET_OP_CLASSES
#include "sim/Dialect/Sim/IR/SimOps.cpp.inc"

//===----------------------------------------------------------------------===//
// Poison in bodies
//===----------------------------------------------------------------------===//

/// Checks one index of a vector op: a static position, or a dynamic one that
/// is a constant. -1 is upstream's poison index (the vector dialect's
/// kPoisonIndex, which folding turns into `ub.poison`), not the last
/// element, and any index outside the dimension makes the result undefined.
/// A scalable dimension has no size known here: only a negative index is an
/// error there.
static LogicalResult verifyVectorIndex(Operation *op, int64_t index,
                                       int64_t size, bool scalable,
                                       StringRef what) {
  if (index >= 0 && (scalable || index < size))
    return success();
  InFlightDiagnostic diag = op->emitOpError();
  if (index == vector::ExtractOp::kPoisonIndex)
    diag << "uses the poison " << what
         << " -1, so its result is undefined (-1 is not the last element)";
  else
    diag << "uses the " << what << " " << index
         << ", which is out of range, so its result is undefined";
  diag << "; use " << (what == "index" ? "an " : "a ") << what;
  if (scalable)
    diag << " from 0 up";
  else
    diag << " from 0 to " << size - 1;
  return diag;
}

/// Checks the static and constant positions of a vector.extract or
/// vector.insert into a vector of `type`. A position computed at run time
/// is lowered only in the innermost dimension (an element of a 1-D LLVM
/// vector); an n-D vector is an LLVM array of those, whose index must be a
/// constant.
static LogicalResult verifyVectorPosition(Operation *op,
                                          ArrayRef<int64_t> staticPosition,
                                          ValueRange dynamicPosition,
                                          VectorType type) {
  auto dynamic = dynamicPosition.begin();
  std::optional<size_t> computedOuter;
  for (auto [d, index, dimension, scalable] : llvm::enumerate(
           staticPosition, type.getShape(), type.getScalableDims())) {
    int64_t value = index;
    if (ShapedType::isDynamic(index)) {
      if (dynamic == dynamicPosition.end())
        return success(); // Reported by the op's own verifier.
      APInt constant;
      if (!matchPattern(*dynamic++, m_ConstantInt(&constant))) {
        if (int64_t(d) + 1 < type.getRank() && !computedOuter)
          computedOuter = d;
        continue;
      }
      value = constant.getSExtValue();
    }
    if (failed(verifyVectorIndex(op, value, dimension, scalable, "index")))
      return failure();
  }
  if (computedOuter)
    return op->emitOpError()
           << "indexes dimension " << *computedOuter << " of " << type
           << " with a value computed at run time, which no backend "
              "lowers; only the innermost dimension may be indexed so: "
              "vector.shape_cast the vector to 1-D and index the element "
              "there";
  return success();
}

/// A body is compiled into kernels of its own, without the module's
/// functions. Checked when the op holding the body is verified, before the
/// symbol uses: `sim.simulation` is a symbol table, so a call's own
/// verifier would say that the function does not exist.
///
/// Nor can it hold the GPU's own operations (thread ids, barriers,
/// shuffles): a body computes one item, and each backend maps items to
/// threads, lanes and groups itself (a CPU kernel has no GPU thread, and on
/// a GPU the result would depend on the group size).
static LogicalResult verifyNoCalls(Operation *holder) {
  WalkResult result = holder->walk([&](Operation *op) {
    StringRef dialect = op->getName().getDialectNamespace();
    if (op != holder && (dialect == "gpu" || dialect == "nvvm")) {
      op->emitOpError() << "is a GPU operation, which a body cannot hold: "
                           "a body computes one item, and each backend maps "
                           "items to threads and groups itself";
      return WalkResult::interrupt();
    }
    if (!llvm::is_contained({"func.call", "func.call_indirect", "llvm.call"},
                            op->getName().getStringRef()))
      return WalkResult::advance();
    op->emitOpError() << "calls a function, which a body cannot: its "
                         "kernels are compiled without the module's "
                         "functions; write the function's operations in the "
                         "body itself";
    return WalkResult::interrupt();
  });
  return failure(result.wasInterrupted());
}

/// The scalar types every backend computes with: integers of at most 64
/// bits (and index), f16, f32 and f64. Wider integers and other floats
/// (f80, f128, the 8-bit floats) make LLVM's back ends stop with a fatal
/// error, and bf16 conversions need compiler-rt routines that the CPU
/// kernels do not link. So does a scalable vector (`vector<[4]xf32>`): its
/// length is the hardware's, which neither a GPU lane nor the CPU kernels
/// have.
static LogicalResult verifyScalarTypes(Region &body) {
  auto unsupported = [](Type type) -> Type {
    Type scalar = getElementTypeOrSelf(type);
    if (auto integer = dyn_cast<IntegerType>(scalar))
      return integer.getWidth() > 64 ? scalar : Type();
    if (isa<FloatType>(scalar) &&
        !isa<Float16Type, Float32Type, Float64Type>(scalar))
      return scalar;
    return Type();
  };
  WalkResult result = body.walk([&](Operation *op) {
    // LLVM's powi takes a C int exponent: x86's back end stops with "POWI
    // exponent does not match sizeof(int)" on another width. (Matched by
    // name: the sim dialect does not depend on the math dialect.)
    if (op->getName().getStringRef() == "math.fpowi" &&
        op->getNumOperands() == 2) {
      Type exponent = getElementTypeOrSelf(op->getOperand(1).getType());
      if (!exponent.isInteger(32)) {
        op->emitOpError() << "raises to an exponent of type " << exponent
                          << ", which no backend lowers (LLVM's powi takes "
                             "an i32 exponent); convert the exponent to i32 "
                             "with arith.trunci or arith.extsi";
        return WalkResult::interrupt();
      }
    }
    for (TypeRange types :
         {TypeRange(op->getResultTypes()), TypeRange(op->getOperandTypes())})
      for (Type type : types) {
        if (auto vector = dyn_cast<VectorType>(type);
            vector && vector.isScalable()) {
          op->emitOpError() << "computes with the scalable vector type " << type
                            << ", which no backend supports; use a vector "
                               "of fixed length";
          return WalkResult::interrupt();
        }
        if (Type scalar = unsupported(type)) {
          op->emitOpError() << "computes with " << scalar
                            << ", which no backend supports; use integers "
                               "of at most 64 bits, f16, f32 or f64";
          return WalkResult::interrupt();
        }
      }
    return WalkResult::advance();
  });
  return failure(result.wasInterrupted());
}

/// A body must compute defined values: what a poison value turns into is up
/// to each backend, so strategies and backends could not be compared. The
/// constructs that visibly make one are errors at their operation:
/// `ub.poison`, the poison index -1 and constant out-of-range indices of
/// vector.extract and vector.insert, and the poison entry -1 of a
/// vector.shuffle mask. (An index that becomes -1 only by folding is lowered
/// to LLVM's poison by both back ends.)
static LogicalResult verifyNoPoison(Region &body) {
  WalkResult result = body.walk([](Operation *op) {
    LogicalResult verified = success();
    if (isa<ub::PoisonOp>(op)) {
      verified = op->emitOpError()
                 << "makes a poison value, which would leave what the body "
                    "computes undefined; compute a defined value instead";
    } else if (auto extract = dyn_cast<vector::ExtractOp>(op)) {
      verified = verifyVectorPosition(op, extract.getStaticPosition(),
                                      extract.getDynamicPosition(),
                                      extract.getSourceVectorType());
    } else if (auto insert = dyn_cast<vector::InsertOp>(op)) {
      verified = verifyVectorPosition(op, insert.getStaticPosition(),
                                      insert.getDynamicPosition(),
                                      insert.getDestVectorType());
    } else if (auto shuffle = dyn_cast<vector::ShuffleOp>(op)) {
      auto leading = [](VectorType type) {
        return type.getRank() == 0 ? int64_t(1) : type.getDimSize(0);
      };
      int64_t size = leading(shuffle.getV1VectorType()) +
                     leading(shuffle.getV2VectorType());
      for (int64_t entry : shuffle.getMask())
        if (failed(verified = verifyVectorIndex(
                       op, entry, size, /*scalable=*/false, "mask entry")))
          break;
    }
    return failed(verified) ? WalkResult::interrupt() : WalkResult::advance();
  });
  return failure(result.wasInterrupted());
}

//===----------------------------------------------------------------------===//
// SimulationOp
//===----------------------------------------------------------------------===//

ScheduleOp SimulationOp::getScheduleOp() {
  auto ops = getBody().front().getOps<ScheduleOp>();
  return ops.empty() ? nullptr : *ops.begin();
}

ObserveOp SimulationOp::getObserveOp() {
  auto ops = getBody().front().getOps<ObserveOp>();
  return ops.empty() ? nullptr : *ops.begin();
}

ComponentOp SimulationOp::getWriter(FlatSymbolRefAttr buffer) {
  for (ComponentOp component : getComponents())
    if (component.writesBuffer(buffer))
      return component;
  return nullptr;
}

ComponentOp SimulationOp::getWriter(BufferOp buffer) {
  return getWriter(FlatSymbolRefAttr::get(buffer.getSymNameAttr()));
}

std::optional<unsigned>
SimulationOp::getSchedulePosition(ComponentOp component) {
  ScheduleOp schedule = getScheduleOp();
  if (!schedule)
    return std::nullopt;
  auto order = schedule.getOrder().getAsRange<FlatSymbolRefAttr>();
  auto it =
      llvm::find(order, FlatSymbolRefAttr::get(component.getSymNameAttr()));
  if (it == order.end())
    return std::nullopt;
  return std::distance(order.begin(), it);
}

std::optional<SmallVector<ComponentOp>> SimulationOp::getScheduledOrder() {
  ScheduleOp schedule = getScheduleOp();
  if (!schedule ||
      schedule.getOrder().size() != llvm::range_size(getComponents()))
    return std::nullopt;
  SmallVector<ComponentOp> order;
  for (FlatSymbolRefAttr name :
       schedule.getOrder().getAsRange<FlatSymbolRefAttr>())
    order.push_back(lookupComponent(name));
  return order;
}

Operation *SimulationOp::findExplicitAccess() {
  Operation *found = nullptr;
  for (ComponentOp component : getComponents()) {
    component.walk<WalkOrder::PreOrder>([&](Operation *op) {
      if (!isa<LoadOp, BigStepOp>(op))
        return WalkResult::advance();
      found = op;
      return WalkResult::interrupt();
    });
    if (found)
      return found;
  }
  return nullptr;
}

LogicalResult SimulationOp::checkConstantsInlined(StringRef passArgument) {
  for (BufferOp buffer : getBuffers())
    if (buffer.getConstant()) {
      InFlightDiagnostic diag =
          emitOpError() << "has the constant buffer @" << buffer.getSymName()
                        << ", which no component writes; ";
      if (passArgument.empty())
        diag << "run the front end (--sim-front-end), whose first pass "
                "--sim-inline-constants replaces its reads, before lowering "
                "it";
      else
        diag << "run --sim-inline-constants before --" << passArgument;
      diag.attachNote(buffer.getLoc())
          << "@" << buffer.getSymName() << " is declared constant here";
      return diag;
    }
  return success();
}

Type SimulationOp::getBuiltinParamType(StringRef name) {
  Builder b(getContext());
  if (name == "range")
    return b.getI64Type();
  if (name == "dt")
    return getTimeStepType();
  if (name == "max_steps")
    return b.getI32Type();
  return nullptr;
}

LogicalResult
SimulationOp::checkLoweredNamesAreFree(ArrayRef<SimulationOp> simulations,
                                       StringRef suffix, StringRef what,
                                       StringRef pass) {
  bool clashes = false;
  for (SimulationOp simulation : simulations) {
    Operation *parent = simulation->getParentOp();
    if (!parent)
      continue;
    std::string name = (simulation.getSymName() + suffix).str();
    Operation *clash = mlir::SymbolTable::lookupSymbolIn(
        parent, StringAttr::get(simulation.getContext(), name));
    if (!clash)
      continue;
    // Left to the lowering, the new module would be a second definition of
    // the name, reported by the symbol table as an error of the IR that
    // names neither the simulation nor the way out.
    clashes = true;
    clash->emitError()
            .append("simulation ",
                    SymbolRefAttr::get(simulation.getSymNameAttr()),
                    " needs the name '", name, "' for its ", what, " (--", pass,
                    " puts them in a module of that name); rename this symbol")
            .attachNote(simulation.getLoc())
        << "the simulation is here";
  }
  return failure(clashes);
}

/// Whether `op` is the top-level module: a builtin.module with no parent,
/// or the only op of one. The parser verifies what it read inside a
/// module of its own and, when that holds a single module, returns the
/// latter: `module @scenes { sim.simulation ... }` is verified one level
/// down, while beside other ops the same module is a nested one.
static bool isTopLevelModule(Operation *op) {
  if (!isa<ModuleOp>(op))
    return false;
  Operation *outer = op->getParentOp();
  return !outer || (isa<ModuleOp>(outer) && !outer->getParentOp() &&
                    llvm::hasSingleElement(
                        cast<ModuleOp>(outer).getBody()->getOperations()));
}

LogicalResult SimulationOp::verify() {
  // A simulation nested in a body (through an op that opens a symbol table)
  // would be walked as part of the outer one by every analysis.
  if (auto outer = (*this)->getParentOfType<SimulationOp>()) {
    InFlightDiagnostic diag = emitOpError()
                              << "cannot be nested inside another simulation";
    diag.attachNote(outer.getLoc()) << "the enclosing simulation is here";
    return diag;
  }
  // The passes nest on the top-level module's simulations and sim-translate
  // looks for them there: one in a nested module would be left as written
  // by every pass, without a word. (A simulation with no parent is one
  // being built on its own.)
  Operation *parent = (*this)->getParentOp();
  if (parent && !isTopLevelModule(parent)) {
    InFlightDiagnostic diag = emitOpError()
                              << "must be directly in the top-level module, "
                                 "where the passes and sim-translate look for "
                                 "simulations, not in a nested '"
                              << parent->getName() << "'";
    if (auto name = parent->getAttrOfType<StringAttr>(
            mlir::SymbolTable::getSymbolAttrName()))
      diag << " " << SymbolRefAttr::get(name);
    diag << "; move it to the top level";
    diag.attachNote(parent->getLoc()) << "the enclosing op is here";
    return diag;
  }
  // The generated getRange() and getMaxSteps() return unsigned values, which
  // would let range(-5) and max_steps(-3) through; compare as signed.
  int64_t range = getRangeAttr().getInt();
  if (range <= 0)
    return emitOpError() << "expects a positive item range, but got " << range;
  if (range > kMaxRange)
    return emitOpError() << "expects an item range of at most 2^40, but got "
                         << range;
  int64_t maxSteps = getMaxStepsAttr().getInt();
  if (maxSteps < 1)
    return emitOpError() << "expects max_steps to be at least 1, but got "
                         << maxSteps;
  if (maxSteps > kMaxMaxSteps)
    return emitOpError() << "expects max_steps to be at most 2^20, but got "
                         << maxSteps;
  if (IntegerAttr cap = getStepCapAttr()) {
    int64_t value = cap.getInt();
    if (value < 1 || value > maxSteps)
      return emitOpError() << "has a step_cap of " << value
                           << ", but a big step takes 1 to max_steps ("
                           << maxSteps << ") base steps";
  }
  double dt = getTimeStep();
  if (!(dt > 0.0) || !std::isfinite(dt))
    return emitOpError() << "expects a positive, finite base time step dt, "
                            "but got "
                         << dt;
  // A subnormal dt has fewer significant bits than its type, and a bundle
  // compiled with flush-to-zero would compute with 0; the runtime refuses
  // to set one as well (sim_session_set).
  if (cast<FloatAttr>(getDt()).getValue().isDenormal())
    return emitOpError() << "expects a base time step dt that is a normal "
                         << getTimeStepType() << " value, but got " << dt
                         << ", which is subnormal; give a larger dt";
  if (std::optional<int64_t> halo = getDistributedHalo(); halo && *halo < 0)
    return emitOpError() << "has a distributed_halo of " << *halo
                         << " items; it must be 0 or more";
  return success();
}

LogicalResult SimulationOp::verifyRegions() {
  Block &body = getBody().front();
  Operation *schedule = nullptr, *observe = nullptr;
  for (Operation &op : body) {
    if (isa<ScheduleOp>(op)) {
      if (schedule)
        return op.emitOpError()
                   .append("is the second schedule of this simulation; "
                           "a simulation has at most one")
                   .attachNote(schedule->getLoc())
               << "the first schedule is here";
      schedule = &op;
      continue;
    }
    if (isa<ObserveOp>(op)) {
      if (observe)
        return op.emitOpError()
                   .append("is the second observe list of this simulation; "
                           "list all observed buffers in one")
                   .attachNote(observe->getLoc())
               << "the first observe list is here";
      observe = &op;
      continue;
    }
    if (!isa<ParamOp, BufferOp, ComponentOp, TotalOp>(op))
      return op.emitError()
             << "'" << op.getName()
             << "' cannot appear directly in a simulation; it holds only "
                "sim.param, sim.buffer, sim.component, sim.total, "
                "sim.schedule and sim.observe";
  }

  // Every buffer is written by exactly one component.
  DenseMap<Operation *, ComponentOp> writerOf;
  for (ComponentOp component : getComponents()) {
    for (auto name : component.getWrites().getAsRange<FlatSymbolRefAttr>()) {
      BufferOp buffer = lookupBuffer(name);
      if (!buffer)
        continue; // Reported by the component's symbol verification.
      if (buffer.getConstant())
        return component.emitOpError()
                   .append("writes buffer ", name,
                           ", which is declared constant; remove 'constant' "
                           "from @",
                           buffer.getSymName(),
                           " or this component's writes entry")
                   .attachNote(buffer.getLoc())
               << name << " is declared constant here";
      auto [it, inserted] = writerOf.try_emplace(buffer, component);
      if (!inserted)
        return component.emitOpError()
               << "writes buffer " << name << ", which component @"
               << it->second.getSymName()
               << " already writes; every buffer has exactly one writer";
    }
  }
  for (BufferOp buffer : getBuffers())
    if (!buffer.getConstant() && !writerOf.count(buffer))
      return buffer.emitOpError()
             << "is not written by any component; every buffer needs exactly "
                "one writer, or is declared 'constant' when its init gives "
                "its value at every time";

  // Initial states may read other initial states, but not in a cycle.
  SmallVector<BufferOp> buffers(getBuffers());
  DenseMap<Operation *, SmallVector<BufferOp>> initReads;
  for (BufferOp buffer : buffers) {
    buffer.getInit().walk([&](ReadOp read) {
      if (BufferOp source = lookupBuffer(read.getBufferAttr()))
        initReads[buffer].push_back(source);
    });
  }
  SmallVector<BufferOp> cycle =
      findCycle(ArrayRef<BufferOp>(buffers),
                [&](BufferOp buffer) { return initReads.lookup(buffer); });
  if (!cycle.empty()) {
    InFlightDiagnostic diag =
        cycle.front().emitOpError()
        << "has an initial state that depends on itself through the init "
           "bodies of ";
    llvm::interleave(
        cycle, [&](BufferOp b) { diag << "@" << b.getSymName(); },
        [&] { diag << " -> "; });
    diag << " -> @" << cycle.front().getSymName();
    return diag;
  }

  // Bodies compute defined values, in types every backend has.
  for (Operation &op : body)
    for (Region &region : op.getRegions())
      if (failed(verifyScalarTypes(region)) || failed(verifyNoPoison(region)))
        return failure();
  return success();
}

//===----------------------------------------------------------------------===//
// ParamOp / GetParamOp
//===----------------------------------------------------------------------===//

LogicalResult ParamOp::verify() {
  // --sim-set-params reads these names as the simulation's own attributes, so
  // a parameter with one of them could never be overridden.
  if (SimulationOp::isBuiltinParamName(getSymName()))
    return emitOpError() << "cannot be named '" << getSymName()
                         << "': range, dt and max_steps name the "
                            "simulation's own attributes";
  Attribute value = getValue();
  bool isScalar = false;
  if (auto intAttr = dyn_cast<IntegerAttr>(value))
    isScalar =
        intAttr.getType().isSignlessInteger() || intAttr.getType().isIndex();
  else
    isScalar = isa<FloatAttr>(value);
  if (!isScalar)
    return emitOpError() << "expects an integer or float default value, but "
                            "got "
                         << value;
  return success();
}

bool GetParamOp::isBuiltin() {
  return SimulationOp::isBuiltinParamName(getParam());
}

LogicalResult GetParamOp::verify() {
  if (!getEnclosingBody(*this))
    return emitOpError() << "must be inside a num_steps, evaluate, init or "
                            "exact body";
  return success();
}

LogicalResult GetParamOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  if (isBuiltin()) {
    auto simulation = (*this)->getParentOfType<SimulationOp>();
    if (!simulation)
      return failure(); // Reported by verify().
    Type expected = simulation.getBuiltinParamType(getParam());
    if (getType() != expected)
      return emitOpError() << "result type " << getType()
                           << " does not match the type " << expected
                           << " of the simulation's " << getParam();
    return success();
  }
  auto param =
      symbolTable.lookupNearestSymbolFrom<ParamOp>(*this, getParamAttr());
  if (!param)
    return emitOpError() << getParamAttr()
                         << " does not name a sim.param of the enclosing "
                            "simulation";
  Type paramType = cast<TypedAttr>(param.getValue()).getType();
  if (paramType != getType())
    return emitOpError() << "result type " << getType()
                         << " does not match the type " << paramType
                         << " of parameter " << getParamAttr();
  return success();
}

//===----------------------------------------------------------------------===//
// BufferOp
//===----------------------------------------------------------------------===//

InterpolationAttrInterface BufferOp::getInterpolation() {
  if (auto interp = getInterpAttr())
    return interp;
  return cast<InterpolationAttrInterface>(LinearInterpAttr::get(getContext()));
}

FloatType BufferOp::getScalarType() {
  Type type = getElementType();
  if (auto vector = dyn_cast<VectorType>(type))
    type = vector.getElementType();
  return cast<FloatType>(type);
}

int64_t BufferOp::getElementBytes() {
  Type type = getElementType();
  int64_t count = 1;
  if (auto vector = dyn_cast<VectorType>(type))
    count = vector.getNumElements();
  return count * getScalarType().getWidth() / 8;
}

/// Names the block arguments of `region` after `names` in printed IR.
static void nameBodyArguments(Region &region, ArrayRef<StringRef> names,
                              OpAsmSetValueNameFn setNameFn) {
  if (region.empty())
    return;
  for (auto [arg, name] : llvm::zip(region.front().getArguments(), names))
    setNameFn(arg, name);
}

void BufferOp::getAsmBlockArgumentNames(Region &region,
                                        OpAsmSetValueNameFn setNameFn) {
  nameBodyArguments(region, {"i", "t"}, setNameFn);
}

LogicalResult BufferOp::verify() {
  if (failed(verifyNoCalls(*this)))
    return failure();
  // Counts of ghost items below and above a rank's block (--sim-plan-halos).
  if (std::optional<ArrayRef<int64_t>> halo = getHalo();
      halo && (halo->size() != 2 ||
               llvm::any_of(*halo, [](int64_t items) { return items < 0; })))
    return emitOpError() << "expects a halo of two counts of items (below "
                            "and above), 0 or more";
  Type elementType = getElementType();
  if (!isValidElementType(elementType))
    return emitOpError() << "expects an element type of f32, f64, or a vector "
                            "of 1 to 16 of them, but got "
                         << elementType;

  Builder b(getContext());
  YieldOp initYield = verifyBodySignature(*this, getInit(), "init",
                                          {b.getIndexType()}, "(index)");
  if (!initYield)
    return failure();
  if (initYield.getValues().getTypes() != TypeRange(elementType))
    return emitOpError() << "expects the init body to yield one value of the "
                            "element type "
                         << elementType << ", but it yields ("
                         << formatTypes(initYield.getValues().getTypes())
                         << ")";

  // A constant buffer is never interpolated or measured: its init is its
  // value at every time.
  if (getConstant() && getInterp())
    return emitOpError() << "is constant, so it takes no interp(...) clause: "
                            "its value is its init at every time, with "
                            "nothing to interpolate";
  if (getConstant() && !getExact().empty())
    return emitOpError() << "is constant, so it takes no exact body: its "
                            "init is its value at every time";
  if (!getExact().empty()) {
    YieldOp exactYield =
        verifyBodySignature(*this, getExact(), "exact",
                            {b.getIndexType(), b.getF64Type()}, "(index, f64)");
    if (!exactYield)
      return failure();
    if (exactYield.getValues().getTypes() != TypeRange(elementType))
      return emitOpError() << "expects the exact body to yield one value of "
                              "the element type "
                           << elementType << ", but it yields ("
                           << formatTypes(exactYield.getValues().getTypes())
                           << ")";
  }
  return success();
}

//===----------------------------------------------------------------------===//
// TotalOp
//===----------------------------------------------------------------------===//

void TotalOp::getAsmBlockArgumentNames(Region &region,
                                       OpAsmSetValueNameFn setNameFn) {
  nameBodyArguments(region, {"i"}, setNameFn);
}

LogicalResult TotalOp::verify() {
  if (failed(verifyNoCalls(*this)))
    return failure();
  Type type = getValueType();
  if (!type.isF32() && !type.isF64())
    return emitOpError() << "expects a total of type f32 or f64, but got "
                         << type;
  Builder b(getContext());
  YieldOp yield = verifyBodySignature(*this, getBody(), "total",
                                      {b.getIndexType()}, "(index)");
  if (!yield)
    return failure();
  if (yield.getValues().getTypes() != TypeRange(type))
    return emitOpError() << "expects the total body to yield one value of "
                            "the total's type "
                         << type << ", but it yields ("
                         << formatTypes(yield.getValues().getTypes()) << ")";
  return success();
}

LogicalResult BufferOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  InterpolationAttrInterface interp = getInterpolation();
  for (auto [index, name] : llvm::enumerate(interp.getAuxiliaryBuffers())) {
    StringRef role = interp.getAuxiliaryBufferRole(index);
    if (name.getValue() == getSymName())
      return emitOpError() << "cannot be its own " << role
                           << " buffer in its interpolation " << interp;
    BufferOp aux = lookupBuffer(symbolTable, *this, name);
    if (!aux)
      return emitOpError() << "names " << name << " as the " << role
                           << " buffer of its interpolation, but the "
                              "simulation has no such buffer";
    if (aux.getConstant())
      return emitOpError() << "names the constant buffer " << name << " as the "
                           << role << " buffer of its interpolation; the "
                           << role
                           << " of a buffer a component writes changes with "
                              "it: write "
                           << name << " in the same component";
    if (aux.getElementType() != getElementType())
      return emitOpError() << "has element type " << getElementType()
                           << ", but its " << role << " buffer " << name
                           << " has element type " << aux.getElementType()
                           << "; they must match";
  }
  return success();
}

//===----------------------------------------------------------------------===//
// ComponentOp
//===----------------------------------------------------------------------===//

void ComponentOp::getAsmBlockArgumentNames(Region &region,
                                           OpAsmSetValueNameFn setNameFn) {
  nameBodyArguments(region, {"i", "t", "n", "dt"}, setNameFn);
}

bool ComponentOp::writesBuffer(FlatSymbolRefAttr buffer) {
  return llvm::is_contained(getWrites().getAsRange<FlatSymbolRefAttr>(),
                            buffer);
}

LogicalResult ComponentOp::verify() {
  if (failed(verifyNoCalls(*this)))
    return failure();
  ArrayAttr writes = getWrites();
  if (writes.empty())
    return emitOpError() << "expects to write at least one buffer";
  llvm::SmallDenseSet<Attribute> seen;
  for (Attribute name : writes)
    if (!seen.insert(name).second)
      return emitOpError() << "lists buffer " << name << " twice in writes";

  // Sub-steps and estimates are sized by num_steps (a pair writer's steps
  // by its reader's, a pair reader's by its writer's where it has none).
  if (!hasNumSteps()) {
    if (std::optional<Advance> advance = getAdvance();
        advance && *advance != Advance::whole_step &&
        *advance != Advance::local_flux && *advance != Advance::local_steps)
      return emitOpError() << "advances by " << stringifyAdvance(*advance)
                           << " but has no num_steps body to size them";
    if (getEstimates())
      return emitOpError()
             << "estimates the big step but has no num_steps body";
  }

  Builder b(getContext());
  if (hasNumSteps()) {
    YieldOp yield =
        verifyBodySignature(*this, getNumSteps(), "num_steps",
                            {b.getIndexType(), b.getI64Type()}, "(index, i64)");
    if (!yield)
      return failure();
    if (yield.getValues().getTypes() != TypeRange(b.getI32Type()))
      return emitOpError() << "expects the num_steps body to yield one 'i32', "
                              "but it yields ("
                           << formatTypes(yield.getValues().getTypes()) << ")";
  }

  auto simulation = (*this)->getParentOfType<SimulationOp>();
  Type dtType = simulation.getTimeStepType();
  std::string spelling;
  llvm::raw_string_ostream(spelling) << "(index, i64, i32, " << dtType << ")";
  YieldOp yield = verifyBodySignature(
      *this, getEvaluate(), "evaluate",
      {b.getIndexType(), b.getI64Type(), b.getI32Type(), dtType}, spelling);
  if (!yield)
    return failure();
  if (yield.getValues().size() != writes.size())
    return emitOpError() << "expects the evaluate body to yield one value per "
                            "written buffer ("
                         << writes.size() << "), but it yields "
                         << yield.getValues().size();
  if (getCachesAttr() && simulation.getStrategy() != Strategy::hip_cache)
    return emitOpError() << "has shared-memory caches, but the simulation's "
                            "memory plan is not for the hip-cache strategy";
  if (DenseI64ArrayAttr window = getLocalWindowAttr()) {
    if (window.size() != 2 || window[0] > 0 || window[1] < 0)
      return emitOpError() << "has a local_window that is not [lo, hi] with "
                              "lo <= 0 <= hi";
  }
  if (getAdvance() == Advance::local_steps &&
      (!getLocalWindowAttr() || simulation.getStrategy() != Strategy::lts))
    return emitOpError() << "advances in local_steps, which needs a "
                            "local_window and the lts strategy";
  if (getInvariantLevels()) {
    if (getAdvance() != Advance::local_steps)
      return emitOpError() << "has invariant_levels but does not advance in "
                              "local_steps";
    // The kernels keep the levels on this word: a num_steps that reads
    // the time or a buffer would give other levels later. (A pair's reader
    // may have no num_steps: then its writer's is checked by the pass.)
    if (hasNumSteps() && !getNumStepsTime().use_empty())
      return emitOpError() << "has invariant_levels, but its num_steps "
                              "reads its local time";
    ReadOp read;
    getNumSteps().walk([&](ReadOp found) {
      read = found;
      return WalkResult::interrupt();
    });
    if (read)
      return emitOpError() << "has invariant_levels, but its num_steps reads "
                           << read.getBufferAttr();
  }
  if (getInvariantEstimate()) {
    if (getAdvance() != Advance::grid_substeps || !hasNumSteps())
      return emitOpError() << "has invariant_estimate but does not advance in "
                              "grid_substeps with a num_steps";
    // The sub-step kernels keep the first round's minimum on this word:
    // a num_steps that reads the time or a buffer (as sim.read, or as the
    // sim.load the interpolation pass made of it) would give another.
    if (!getNumStepsTime().use_empty())
      return emitOpError() << "has invariant_estimate, but its num_steps "
                              "reads its local time";
    FlatSymbolRefAttr buffer;
    getNumSteps().walk([&](Operation *op) {
      if (auto read = dyn_cast<ReadOp>(op))
        buffer = read.getBufferAttr();
      else if (auto load = dyn_cast<LoadOp>(op))
        buffer = load.getBufferAttr();
      return buffer ? WalkResult::interrupt() : WalkResult::advance();
    });
    if (buffer)
      return emitOpError() << "has invariant_estimate, but its num_steps "
                              "reads "
                           << buffer;
  }
  if (DenseI64ArrayAttr window = getFluxWindowAttr()) {
    if (window.size() != 2 || window[0] > window[1])
      return emitOpError() << "has a flux_window that is not [lo, hi] with "
                              "lo <= hi";
  }
  if (getAdvance() == Advance::local_flux &&
      (!getFluxWindowAttr() || simulation.getStrategy() != Strategy::lts))
    return emitOpError() << "advances in local_flux, which needs a "
                            "flux_window and the lts strategy";
  return success();
}

LogicalResult
ComponentOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  auto yield = cast<YieldOp>(getEvaluate().front().getTerminator());
  for (auto [index, name] :
       llvm::enumerate(getWrites().getAsRange<FlatSymbolRefAttr>())) {
    BufferOp buffer = lookupBuffer(symbolTable, *this, name);
    if (!buffer)
      return emitOpError() << "writes " << name
                           << ", which is not a sim.buffer of this simulation";
    Type yielded = yield.getValues()[index].getType();
    if (yielded != buffer.getElementType())
      return emitOpError() << "yields " << yielded << " for " << name
                           << " (result #" << index
                           << " of evaluate), but the buffer's element type "
                              "is "
                           << buffer.getElementType();
  }
  if (ArrayAttr caches = getCachesAttr()) {
    llvm::SmallDenseSet<Attribute> seen;
    for (auto cache : caches.getAsRange<CacheAttr>()) {
      FlatSymbolRefAttr name = cache.getBuffer();
      if (!lookupBuffer(symbolTable, *this, name))
        return emitOpError() << "caches " << name
                             << ", which is not a sim.buffer of this "
                                "simulation";
      if (writesBuffer(name))
        return emitOpError() << "caches " << name
                             << ", which it writes; a cache holds "
                                "interpolated values of another "
                                "component's buffer";
      if (!seen.insert(name).second)
        return emitOpError() << "caches " << name
                             << " twice; one cache covers all window reads "
                                "of a buffer";
    }
  }
  return success();
}

//===----------------------------------------------------------------------===//
// ScheduleOp / ObserveOp
//===----------------------------------------------------------------------===//

/// Verifies that `list` names distinct symbols of kind `OpTy`.
template <typename OpTy>
static LogicalResult
verifySymbolArray(Operation *user, SymbolTableCollection &symbolTable,
                  ArrayAttr list, StringRef listName, StringRef kindName) {
  llvm::SmallDenseSet<Attribute> seen;
  for (auto name : list.getAsRange<FlatSymbolRefAttr>()) {
    if (!symbolTable.lookupNearestSymbolFrom<OpTy>(user, name.getAttr()))
      return user->emitOpError()
             << "lists " << name << " in " << listName << ", but it is not a "
             << kindName << " of this simulation";
    if (!seen.insert(name).second)
      return user->emitOpError()
             << "lists " << name << " twice in " << listName;
  }
  return success();
}

LogicalResult ScheduleOp::verifySymbolUses(SymbolTableCollection &table) {
  if (getOrder().empty())
    return emitOpError() << "expects at least the component that starts a "
                            "step";
  if (failed(verifySymbolArray<ComponentOp>(*this, table, getOrder(), "order",
                                            "sim.component")))
    return failure();
  ArrayAttr bounds = getBoundedByAttr();
  if (!bounds)
    return success();
  if (failed(verifySymbolArray<ComponentOp>(*this, table, bounds, "bounded_by",
                                            "sim.component")))
    return failure();
  for (auto name : bounds.getAsRange<FlatSymbolRefAttr>()) {
    auto component =
        table.lookupNearestSymbolFrom<ComponentOp>(*this, name.getAttr());
    if (!component.hasNumSteps())
      return emitOpError() << "lists " << name
                           << " in bounded_by, but it has no num_steps body, "
                              "so it never bounds a step";
  }
  return success();
}

LogicalResult ObserveOp::verifySymbolUses(SymbolTableCollection &table) {
  if (getBuffers().empty())
    return emitOpError() << "expects at least one observed buffer";
  if (failed(verifySymbolArray<BufferOp>(*this, table, getBuffers(), "observe",
                                         "sim.buffer")))
    return failure();
  for (auto name : getBuffers().getAsRange<FlatSymbolRefAttr>())
    if (BufferOp buffer = lookupBuffer(table, *this, name);
        buffer && buffer.getConstant())
      return emitOpError()
                 .append("observes ", name,
                         ", which is constant: no run changes it, and no "
                         "backend stores it (its init is computed where it "
                         "is read); observe the buffers components write, or "
                         "a sim.total")
                 .attachNote(buffer.getLoc())
             << name << " is declared constant here";
  return success();
}

//===----------------------------------------------------------------------===//
// ReadOp / LoadOp / BigStepOp
//===----------------------------------------------------------------------===//

LogicalResult ReadOp::verify() {
  std::optional<BodyLocation> body = getEnclosingBody(*this);
  if (!body)
    return emitOpError() << "must be inside a num_steps, evaluate, init or "
                            "exact body";
  if (getRoleAttr() && !body->component)
    return emitOpError() << "has a read role, but roles only apply to reads "
                            "in component bodies";
  return success();
}

/// Shared symbol checks of sim.read and sim.load: the buffer exists and the
/// result has its element type.
static LogicalResult verifyBufferAccess(Operation *op,
                                        SymbolTableCollection &symbolTable,
                                        FlatSymbolRefAttr name, Type resultType,
                                        BufferOp &buffer) {
  buffer = lookupBuffer(symbolTable, op, name);
  if (!buffer)
    return op->emitOpError() << "reads " << name
                             << ", which is not a sim.buffer of this "
                                "simulation";
  if (buffer.getElementType() != resultType)
    return op->emitOpError()
           << "result type " << resultType
           << " does not match the element type " << buffer.getElementType()
           << " of buffer " << name;
  return success();
}

LogicalResult ReadOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  BufferOp buffer;
  if (failed(verifyBufferAccess(*this, symbolTable, getBufferAttr(), getType(),
                                buffer)))
    return failure();
  std::optional<BodyLocation> body = getEnclosingBody(*this);
  if (body->kind == BodyKind::Init && body->buffer == buffer)
    return emitOpError() << "reads " << getBufferAttr()
                         << " in its own init body; the initial state cannot "
                            "depend on itself";
  return success();
}

LogicalResult LoadOp::verify() {
  if (getInWindow() && getVersion() != Version::cache)
    return emitOpError() << "is marked in_window, but loads the "
                         << stringifyVersion(getVersion())
                         << " copy; only a cache load has a fill window";
  std::optional<BodyLocation> body = getEnclosingBody(*this);
  if (body && body->total) {
    if (getVersion() != Version::source)
      return emitOpError() << "loads the " << stringifyVersion(getVersion())
                           << " copy in a total body; a total reads the "
                              "state at T, the source copy";
    return success();
  }
  if (!body || !body->component)
    return emitOpError() << "must be inside a component's num_steps or "
                            "evaluate body, or a total body";
  return success();
}

LogicalResult LoadOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  BufferOp buffer;
  if (failed(verifyBufferAccess(*this, symbolTable, getBufferAttr(), getType(),
                                buffer)))
    return failure();
  if (getVersion() == Version::snapshot && !buffer.getSnapshot())
    return emitOpError() << "loads the snapshot of " << getBufferAttr()
                         << ", but the memory plan keeps none: the buffer is "
                            "not marked 'snapshot'";
  ComponentOp component = getEnclosingBody(*this)->component;
  if (!component)
    return success(); // A total body's source load (checked by verify()).
  if (getVersion() == Version::cache && !findFillCache(*this, getBufferAttr()))
    return emitOpError() << "loads the cache of " << getBufferAttr()
                         << ", but the body fills no cache of it "
                            "(sim.fill_cache)";
  // A flux writer reads its reader's state at its local time (the
  // reader's time levels).
  if (getVersion() == Version::local &&
      !component.writesBuffer(getBufferAttr()) &&
      component.getAdvance() != Advance::local_flux)
    return emitOpError() << "loads the local state of " << getBufferAttr()
                         << ", but component @" << component.getSymName()
                         << " does not write it";
  return success();
}

FillCacheOp mlir::sim::findFillCache(Operation *op, FlatSymbolRefAttr buffer) {
  std::optional<BodyLocation> body = getEnclosingBody(op);
  if (!body || !body->component || body->kind != BodyKind::Evaluate)
    return nullptr;
  for (auto fill : body->component.getEvaluate().front().getOps<FillCacheOp>())
    if (fill.getBufferAttr() == buffer)
      return fill;
  return nullptr;
}

LogicalResult FillCacheOp::verifyRegions() {
  std::optional<BodyLocation> body = getEnclosingBody(*this);
  if (!body || !body->component || body->kind != BodyKind::Evaluate ||
      (*this)->getParentRegion() != &body->component.getEvaluate())
    return emitOpError() << "must be at the top of a component's evaluate "
                            "body";
  Block &block = getBody().front();
  if (block.getNumArguments() != 1 || !block.getArgument(0).getType().isIndex())
    return emitOpError() << "expects one index argument (the item)";
  int64_t lo = getMinOffsetAttr().getInt(), hi = getMaxOffsetAttr().getInt();
  if (lo >= hi)
    return emitOpError() << "expects a window of more than one offset, but "
                            "got "
                         << lo << ", " << hi;
  if (uint64_t(hi) - uint64_t(lo) > uint64_t(kMaxCacheWindow))
    return emitOpError() << "expects a window of at most " << kMaxCacheWindow
                         << " offsets, but got " << lo << ", " << hi;
  return success();
}

LogicalResult
FillCacheOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  auto buffer =
      symbolTable.lookupNearestSymbolFrom<BufferOp>(*this, getBufferAttr());
  if (!buffer)
    return emitOpError() << getBufferAttr()
                         << " does not name a sim.buffer of the simulation";
  auto yield = cast<YieldOp>(getBody().front().getTerminator());
  if (yield.getValues().size() != 1 ||
      yield.getValues().front().getType() != buffer.getElementType())
    return emitOpError() << "must yield one " << buffer.getElementType()
                         << ", the element of " << getBufferAttr();
  return success();
}

LogicalResult BigStepOp::verify() {
  std::optional<BodyLocation> body = getEnclosingBody(*this);
  if (!body || !body->component)
    return emitOpError() << "must be inside a component's num_steps or "
                            "evaluate body";
  return success();
}
