//===- PlanOps.cpp - simplan dialect
//---------------------------------------===//
//
// The plan's verifiers make sure that a runtime can execute a plan without
// guessing: every launch names a kernel that exists and takes exactly the
// arguments listed (memrefs where the runtime passes memory, scalars
// elsewhere), and every symbol an argument names is a buffer or parameter of
// the plan.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Plan/IR/PlanOps.h"

#include "mlir/IR/BuiltinTypes.h"
#include "mlir/IR/DialectImplementation.h"
#include "mlir/Interfaces/FunctionInterfaces.h"
#include "llvm/ADT/TypeSwitch.h"

using namespace mlir;
using namespace mlir::simplan;

#include "sim/Dialect/Plan/IR/PlanDialect.cpp.inc"
#include "sim/Dialect/Plan/IR/PlanEnums.cpp.inc"

#define GET_ATTRDEF_CLASSES
#include "sim/Dialect/Plan/IR/PlanAttrs.cpp.inc"

/// Enum attributes print as a bare keyword in the custom op syntax
/// (`simplan.phase init`); the generic form keeps `#simplan<phase init>`.
template <typename EnumAttrTy>
static ParseResult parseEnumKeyword(OpAsmParser &parser, EnumAttrTy &attr) {
  using Enum = decltype(std::declval<EnumAttrTy>().getValue());
  StringRef keyword;
  SMLoc loc = parser.getCurrentLocation();
  if (parser.parseKeyword(&keyword))
    return failure();
  std::optional<Enum> value = symbolizeEnum<Enum>(keyword);
  if (!value)
    return parser.emitError(loc) << "unknown keyword '" << keyword << "'";
  attr = EnumAttrTy::get(parser.getContext(), *value);
  return success();
}

template <typename EnumAttrTy>
static void printEnumKeyword(OpAsmPrinter &printer, Operation *,
                             EnumAttrTy attr) {
  printer << stringifyEnum(attr.getValue());
}

#define GET_OP_CLASSES
#include "sim/Dialect/Plan/IR/PlanOps.cpp.inc"

void PlanDialect::initialize() {
  addOperations<
#define GET_OP_LIST
#include "sim/Dialect/Plan/IR/PlanOps.cpp.inc"
      >();
  registerAttributes();
}

void PlanDialect::registerAttributes() {
  addAttributes<
#define GET_ATTRDEF_LIST
#include "sim/Dialect/Plan/IR/PlanAttrs.cpp.inc"
      >();
}

/// Kinds that name a symbol of the plan.
static bool needsName(ArgKind kind) {
  return kind == ArgKind::buffer || kind == ArgKind::snapshot ||
         kind == ArgKind::exact || kind == ArgKind::param ||
         kind == ArgKind::total;
}

/// Kinds that the runtime passes as memory (a memref descriptor).
static bool isMemory(ArgKind kind) {
  return kind == ArgKind::clock || kind == ArgKind::buffer ||
         kind == ArgKind::snapshot || kind == ArgKind::exact ||
         kind == ArgKind::total;
}

LogicalResult ArgAttr::verify(function_ref<InFlightDiagnostic()> emitError,
                              ArgKind kind, FlatSymbolRefAttr name) {
  if (needsName(kind) && !name)
    return emitError() << "a '" << stringifyArgKind(kind)
                       << "' argument names a symbol";
  if (!needsName(kind) && name)
    return emitError() << "a '" << stringifyArgKind(kind)
                       << "' argument takes no symbol";
  return success();
}

/// `#simplan.arg<kind>` or `#simplan.arg<kind @symbol>`.
Attribute ArgAttr::parse(AsmParser &parser, Type) {
  StringRef keyword;
  SMLoc loc = parser.getCurrentLocation();
  if (parser.parseLess() || parser.parseKeyword(&keyword))
    return {};
  std::optional<ArgKind> kind = symbolizeArgKind(keyword);
  if (!kind) {
    parser.emitError(loc) << "unknown launch argument kind '" << keyword << "'";
    return {};
  }
  FlatSymbolRefAttr name;
  Attribute symbol;
  OptionalParseResult hasSymbol = parser.parseOptionalAttribute(symbol);
  if (hasSymbol.has_value()) {
    if (failed(*hasSymbol))
      return {};
    name = dyn_cast<FlatSymbolRefAttr>(symbol);
    if (!name) {
      parser.emitError(loc) << "expected a symbol after the argument kind";
      return {};
    }
  }
  if (parser.parseGreater())
    return {};
  return ArgAttr::getChecked([&] { return parser.emitError(loc); },
                             parser.getContext(), *kind, name);
}

void ArgAttr::print(AsmPrinter &printer) const {
  printer << '<' << stringifyArgKind(getKind());
  if (getName())
    printer << ' ' << getName();
  printer << '>';
}

LogicalResult PlanOp::verifyRegions() {
  for (Operation &op : getBlock()) {
    if (!isa<ParamOp, BufferOp, ComponentOp, TotalOp, PhaseOp>(op))
      return op.emitOpError() << "cannot appear directly in a plan";
  }
  llvm::SmallDenseSet<PhaseKind> phases;
  for (PhaseOp phase : getBlock().getOps<PhaseOp>())
    if (!phases.insert(phase.getKind()).second)
      return phase.emitOpError()
             << "repeats phase '" << stringifyPhaseKind(phase.getKind())
             << "' of the plan";
  if (getHistogramSlot() + getMaxSteps() + 1 > getClockSlots())
    return emitOpError() << "has a clock of " << getClockSlots()
                         << " slots, too small for its histogram";
  return success();
}

LogicalResult LaunchOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  auto plan = (*this)->getParentOfType<PlanOp>();
  Operation *container = symbolTable.lookupSymbolIn(
      plan->getParentOp(), getKernel().getRootReference());
  if (!container)
    return emitOpError() << "launches " << getKernel()
                         << ", but there is no kernel container "
                         << getKernel().getRootReference();
  // Once the kernels are compiled (a gpu.binary), there is no function left
  // to compare the arguments with.
  if (!container->hasTrait<OpTrait::SymbolTable>())
    return success();
  Operation *kernel =
      symbolTable.lookupSymbolIn(plan->getParentOp(), getKernel());
  auto function = dyn_cast_or_null<FunctionOpInterface>(kernel);
  if (!function)
    return emitOpError() << "launches " << getKernel()
                         << ", which is not a kernel function";
  // CPU kernels take the groups to run as trailing arguments of their own.
  ArrayRef<Type> inputs = function.getArgumentTypes();
  if (auto extra = function->getAttrOfType<IntegerAttr>(
          PlanDialect::getGroupArgumentsAttrName()))
    inputs =
        inputs.drop_back(std::min<uint64_t>(extra.getInt(), inputs.size()));
  if (inputs.size() != getArgs().size())
    return emitOpError() << "passes " << getArgs().size() << " arguments to "
                         << getKernel() << ", which takes " << inputs.size();
  if (FlatSymbolRefAttr component = getComponentAttr())
    if (!isa_and_nonnull<ComponentOp>(
            symbolTable.lookupSymbolIn(plan, component)))
      return emitOpError() << "is for " << component
                           << ", which is not a component of the plan";
  for (auto [index, attr, type] :
       llvm::enumerate(getArgs().getAsRange<ArgAttr>(), inputs)) {
    if (isMemory(attr.getKind()) != isa<MemRefType>(type))
      return emitOpError() << "passes " << attr << " as argument " << index
                           << " of type " << type;
    if (!attr.getName())
      continue;
    Operation *symbol = symbolTable.lookupSymbolIn(plan, attr.getName());
    if (attr.getKind() == ArgKind::total) {
      if (!isa_and_nonnull<TotalOp>(symbol))
        return emitOpError()
               << "passes " << attr << ", but the plan has no total "
               << attr.getName();
      continue;
    }
    bool isParam = attr.getKind() == ArgKind::param;
    auto buffer = dyn_cast_or_null<BufferOp>(symbol);
    if (isParam ? !isa_and_nonnull<ParamOp>(symbol) : !buffer)
      return emitOpError() << "passes " << attr << ", but the plan has no "
                           << (isParam ? "parameter " : "buffer ")
                           << attr.getName();
    if (attr.getKind() == ArgKind::snapshot && !buffer.getSnapshot())
      return emitOpError() << "passes " << attr << ", but buffer "
                           << attr.getName() << " has no snapshot";
    if (attr.getKind() == ArgKind::exact && !buffer.getExact())
      return emitOpError() << "passes " << attr << ", but buffer "
                           << attr.getName() << " has no exact solution";
  }
  return success();
}
