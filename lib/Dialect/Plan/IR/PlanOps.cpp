//===- PlanOps.cpp - simplan dialect --------------------------------------===//
//
// The plan's verifiers make sure that a runtime can execute a plan without
// guessing: every launch names a kernel that exists and takes exactly the
// arguments listed (memrefs where the runtime passes memory, scalars
// elsewhere) with the shared memory and clock the kernel was made for, every
// symbol an argument names is a buffer or parameter of the plan, and every
// clock slot the plan names is inside the clock.
//
//===----------------------------------------------------------------------===//

#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Runtime/bundle_generated.h"

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
  // The enum's own namespace declares its symbolizeEnum (advance is the sim
  // dialect's).
  std::optional<Enum> value;
  if constexpr (std::is_same_v<Enum, mlir::sim::Advance>)
    value = mlir::sim::symbolizeEnum<Enum>(keyword);
  else
    value = symbolizeEnum<Enum>(keyword);
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

// The launch arguments are the bundle schema's, number for number.
static constexpr bool sameArgKind(ArgKind kind, ::sim::bundle::ArgKind other) {
  return uint32_t(kind) == uint32_t(other);
}
static_assert(
    sameArgKind(ArgKind::clock, ::sim::bundle::ArgKind::Clock) &&
        sameArgKind(ArgKind::buffer, ::sim::bundle::ArgKind::Buffer) &&
        sameArgKind(ArgKind::snapshot, ::sim::bundle::ArgKind::Snapshot) &&
        sameArgKind(ArgKind::exact, ::sim::bundle::ArgKind::Exact) &&
        sameArgKind(ArgKind::param, ::sim::bundle::ArgKind::Param) &&
        sameArgKind(ArgKind::range, ::sim::bundle::ArgKind::Range) &&
        sameArgKind(ArgKind::dt, ::sim::bundle::ArgKind::Dt) &&
        sameArgKind(ArgKind::time, ::sim::bundle::ArgKind::Time) &&
        sameArgKind(ArgKind::total, ::sim::bundle::ArgKind::Total) &&
        sameArgKind(ArgKind::first, ::sim::bundle::ArgKind::First) &&
        sameArgKind(ArgKind::extent, ::sim::bundle::ArgKind::Extent) &&
        sameArgKind(ArgKind::levels, ::sim::bundle::ArgKind::Levels),
    "simplan's ArgKind and the bundle schema's differ");

static_assert(int64_t(::sim::bundle::SubClockWidth::GridSubSteps) ==
                      int64_t(::sim::bundle::SubClockSlot::Estimate) + 1 &&
                  int64_t(::sim::bundle::SubClockWidth::LocalSteps) ==
                      int64_t(::sim::bundle::SubClockSlot::UnitRequest) + 1,
              "the schema's SubClockWidth and SubClockSlot disagree");

int64_t mlir::simplan::subClockSlots(mlir::sim::Advance advance) {
  return int64_t(advance == mlir::sim::Advance::local_steps
                     ? ::sim::bundle::SubClockWidth::LocalSteps
                     : ::sim::bundle::SubClockWidth::GridSubSteps);
}

void PlanDialect::registerAttributes() {
  addAttributes<
#define GET_ATTRDEF_LIST
#include "sim/Dialect/Plan/IR/PlanAttrs.cpp.inc"
      >();
}

/// The records a kernel function carries for its launches (`simplan.shared`,
/// `simplan.clock_slots`, `simplan.group_arguments`); no other `simplan.`
/// attribute may appear outside the dialect's own operations.
LogicalResult PlanDialect::verifyOperationAttribute(Operation *op,
                                                    NamedAttribute attribute) {
  StringRef name = attribute.getName().getValue();
  Attribute value = attribute.getValue();
  if (name == getLanesAttrName()) {
    if (!isa<UnitAttr>(value))
      return op->emitError() << "'" << name << "' must be a unit attribute";
    if (op->getName().getStringRef() != "scf.for")
      return op->emitError()
             << "'" << name << "' marks the loop over a group's lanes, but '"
             << op->getName() << "' is not an scf.for";
    return success();
  }
  if (name == getSharedAttrName()) {
    auto shared = dyn_cast<DenseI64ArrayAttr>(value);
    if (!shared || shared.size() != 2 || shared[0] < 0 || shared[1] < 0)
      return op->emitError()
             << "'" << name
             << "' must be array<i64: per_thread, fixed> of two byte counts "
                "of at least 0, not "
             << value;
  } else if (name == getClockSlotsAttrName()) {
    auto slots = dyn_cast<IntegerAttr>(value);
    if (!slots || !slots.getType().isInteger(64) || slots.getInt() < 1)
      return op->emitError()
             << "'" << name << "' must be a positive i64 slot count, not "
             << value;
  } else if (name == getUnevenGroupsAttrName()) {
    if (!isa<UnitAttr>(value))
      return op->emitError() << "'" << name << "' must be a unit attribute";
  } else if (name == getGroupArgumentsAttrName()) {
    auto count = dyn_cast<IntegerAttr>(value);
    if (!count || !count.getType().isInteger(64) || count.getInt() < 0)
      return op->emitError()
             << "'" << name
             << "' must be an i64 count of trailing arguments, not " << value;
  } else {
    return op->emitError() << "'" << name
                           << "' is not an attribute of the simplan dialect";
  }
  if (!isa<FunctionOpInterface>(op))
    return op->emitError() << "'" << name
                           << "' is a record of a kernel function, but '"
                           << op->getName() << "' is not a function";
  return success();
}

/// Kinds that name a symbol of the plan.
static bool needsName(ArgKind kind) {
  return kind == ArgKind::buffer || kind == ArgKind::snapshot ||
         kind == ArgKind::exact || kind == ArgKind::param ||
         kind == ArgKind::total || kind == ArgKind::levels;
}

/// Kinds that the runtime passes as memory (a memref descriptor).
static bool isMemory(ArgKind kind) {
  return kind == ArgKind::clock || kind == ArgKind::buffer ||
         kind == ArgKind::snapshot || kind == ArgKind::exact ||
         kind == ArgKind::total || kind == ArgKind::levels;
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
  // Halos are counts of ghost items below and above a rank's block.
  if (std::optional<int64_t> halo = getDistributedHalo(); halo && *halo < 0)
    return emitOpError() << "has a distributed halo of " << *halo
                         << " items; it must be 0 or more";
  for (BufferOp buffer : getBlock().getOps<BufferOp>())
    if (std::optional<ArrayRef<int64_t>> halo = buffer.getHalo();
        halo && (halo->size() != 2 ||
                 llvm::any_of(*halo, [](int64_t items) { return items < 0; })))
      return buffer.emitOpError()
             << "expects a halo of two counts of items (below and above), "
                "0 or more";
  if (getStepCap() < 1 || getStepCap() > getMaxSteps())
    return emitOpError() << "has a step cap of " << getStepCap()
                         << ", which is not between 1 and max_steps ("
                         << getMaxSteps() << ")";
  // The fixed slots come first; a component's counters sit between them and
  // the histogram.
  int64_t firstFree = int64_t(::sim::bundle::ClockSlot::FirstFree);
  for (ComponentOp component : getBlock().getOps<ComponentOp>()) {
    int64_t slot = component.getEvaluations();
    int64_t histogram = getHistogramSlot();
    if (slot < firstFree || slot >= histogram)
      return component.emitOpError()
             << "counts its evaluations in clock slot " << slot
             << ", which is not between the fixed slots and the histogram ["
             << firstFree << ", " << getHistogramSlot() << ")";
    std::optional<int64_t> largest = component.getLargestEstimate();
    int64_t largestSlots = int64_t(::sim::bundle::LargestEstimateSlot::Slots);
    if (largest &&
        (*largest < firstFree || *largest + largestSlots > histogram))
      return component.emitOpError()
             << "keeps its largest estimate in clock slots " << *largest
             << " to " << *largest + largestSlots - 1
             << ", which are not between the fixed slots and the histogram ["
             << firstFree << ", " << getHistogramSlot() << ")";
    std::optional<int64_t> subClock = component.getSubClock();
    int64_t subClockWidth = subClockSlots(component.getAdvance());
    if (subClock &&
        (*subClock < firstFree || *subClock + subClockWidth > histogram))
      return component.emitOpError()
             << "has a sub-step clock at slots " << *subClock << " to "
             << *subClock + subClockWidth - 1
             << ", which are not between the fixed slots and the histogram ["
             << firstFree << ", " << getHistogramSlot() << ")";
  }
  return success();
}

LogicalResult ComponentOp::verify() {
  bool grid = getAdvance() == mlir::sim::Advance::grid_substeps ||
              getAdvance() == mlir::sim::Advance::local_steps;
  if (grid && !getSubClock())
    return emitOpError() << "advances in "
                         << mlir::sim::stringifyAdvance(getAdvance())
                         << " but has no sub_clock";
  if (!grid && getSubClock())
    return emitOpError() << "has a sub_clock but advances in "
                         << mlir::sim::stringifyAdvance(getAdvance())
                         << "; only grid_substeps and local_steps components "
                            "have one";
  if (std::optional<int64_t> reach = getLevelReach()) {
    if (getAdvance() != mlir::sim::Advance::local_steps)
      return emitOpError() << "has a level_reach but advances in "
                           << mlir::sim::stringifyAdvance(getAdvance())
                           << "; only local_steps components have levels";
    if (*reach < 1)
      return emitOpError() << "has a level_reach of " << *reach
                           << "; it must be at least 1";
    if (!(*this)->getParentOfType<PlanOp>().getDistributedHalo())
      return emitOpError() << "has a level_reach in a plan that is not "
                              "distributed";
  }
  if (getKeepsLevels() && getAdvance() != mlir::sim::Advance::local_steps)
    return emitOpError() << "keeps levels but advances in "
                         << mlir::sim::stringifyAdvance(getAdvance())
                         << "; only local_steps components have levels";
  bool pairWriter = getAdvance() == mlir::sim::Advance::local_flux;
  if (getLargestEstimate() && (!pairWriter || !getEstimates())) {
    InFlightDiagnostic diag = emitOpError() << "has a largest_estimate but ";
    if (!getEstimates())
      diag << "does not estimate";
    else
      diag << "advances in " << mlir::sim::stringifyAdvance(getAdvance());
    return diag << "; only a pair's writer (local_flux) that estimates "
                   "bounds the big step by its largest num_steps";
  }
  if (getEstimates() && pairWriter && !getLargestEstimate())
    return emitOpError() << "estimates and advances in local_flux but has no "
                            "largest_estimate slots";
  if (getKeepsEstimate() && !getLargestEstimate())
    return emitOpError() << "keeps its estimate but has no largest_estimate";
  return success();
}

/// What only a distributed plan has (its `first` and `extent` arguments,
/// all-reduces and exchanges), and that those name what the plan has.
LogicalResult
LaunchOp::verifyCommunication(PlanOp plan, SymbolTableCollection &symbolTable) {
  bool distributed = plan.getDistributedHalo().has_value();
  for (auto arg : getArgs().getAsRange<ArgAttr>())
    if ((arg.getKind() == ArgKind::first || arg.getKind() == ArgKind::extent) &&
        !distributed)
      return emitOpError() << "passes " << arg
                           << ", which only a distributed plan has";
  if (!distributed &&
      (getReduceMin() || getExchange() || getExchangeSnapshots() ||
       getReduceMaxLevels() || getExchangeTargets() || getExchangeSubStep() ||
       getExchangeLocalStep() || getExchangeLocalFlux()))
    return emitOpError() << "communicates between ranks in a plan that is not "
                            "distributed";
  if (std::optional<ArrayRef<int64_t>> slots = getReduceMin())
    for (int64_t slot : *slots)
      if (slot < 0 || slot >= int64_t(plan.getClockSlots()))
        return emitOpError()
               << "all-reduces clock slot " << slot << ", but the clock has "
               << plan.getClockSlots() << " slots";
  for (auto [names, snapshot] : {std::pair(getExchangeAttr(), false),
                                 std::pair(getExchangeTargetsAttr(), false),
                                 std::pair(getExchangeSubStepAttr(), false),
                                 std::pair(getExchangeLocalStepAttr(), false),
                                 std::pair(getExchangeLocalFluxAttr(), false),
                                 std::pair(getExchangeSnapshotsAttr(), true)}) {
    if (!names)
      continue;
    for (auto name : names.getAsRange<FlatSymbolRefAttr>()) {
      auto buffer =
          dyn_cast_or_null<BufferOp>(symbolTable.lookupSymbolIn(plan, name));
      if (!buffer)
        return emitOpError()
               << "exchanges " << name << ", which is not a buffer of the plan";
      if (snapshot && !buffer.getSnapshot())
        return emitOpError()
               << "exchanges the snapshot of " << name << ", which has none";
    }
  }
  // A buffer travels one way after a launch.
  ArrayAttr ways[] = {getExchangeAttr(), getExchangeTargetsAttr(),
                      getExchangeSubStepAttr(), getExchangeLocalStepAttr(),
                      getExchangeLocalFluxAttr()};
  const char *wayNames[] = {"whole", "by its target half",
                            "by the half its sub-step wrote",
                            "by the blocks and halves its slot wrote",
                            "by the blocks its slot's fluxes are due in"};
  constexpr int kWays = std::size(ways);
  for (int one = 0; one < kWays; ++one)
    for (int other = one + 1; other < kWays; ++other)
      if (ways[one] && ways[other])
        for (Attribute name : ways[other])
          if (llvm::is_contained(ways[one], name))
            return emitOpError() << "exchanges " << name << " both "
                                 << wayNames[one] << " and " << wayNames[other];
  // The launch's component advancing by `advance`, or null.
  auto componentAdvancing = [&](mlir::sim::Advance advance) {
    auto component =
        getComponentAttr()
            ? dyn_cast_or_null<ComponentOp>(
                  symbolTable.lookupSymbolIn(plan, getComponentAttr()))
            : ComponentOp();
    return component && component.getAdvance() == advance ? component
                                                          : ComponentOp();
  };
  if (ArrayAttr names = getExchangeSubStepAttr()) {
    // The half comes from the sub-step clock of the launch's component.
    if (!componentAdvancing(mlir::sim::Advance::grid_substeps))
      return emitOpError()
             << "exchanges " << names[0]
             << " by the half its sub-step wrote, but the launch is not for a "
                "grid_substeps component, whose sub-step clock says which";
  }
  if (ArrayAttr names = getExchangeLocalStepAttr()) {
    // The blocks and halves come from the levels and the sub-step clock of
    // the launch's component, which the launch must pass.
    if (!componentAdvancing(mlir::sim::Advance::local_steps))
      return emitOpError()
             << "exchanges " << names[0]
             << " by the blocks and halves its slot wrote, but the launch is "
                "not for a local_steps component, whose levels say which";
    bool passesLevels =
        llvm::any_of(getArgs().getAsRange<ArgAttr>(), [&](ArgAttr arg) {
          return arg.getKind() == ArgKind::levels &&
                 arg.getName() == getComponentAttr();
        });
    if (!passesLevels)
      return emitOpError() << "exchanges " << names[0]
                           << " by the blocks and halves its slot wrote, but "
                              "does not pass the levels of "
                           << getComponentAttr() << ", which say which";
  }
  if (ArrayAttr names = getExchangeLocalFluxAttr()) {
    // The blocks come from the levels and the sub-step clock of the flux
    // pair's reader, the one component whose levels the launch passes.
    if (!componentAdvancing(mlir::sim::Advance::local_flux))
      return emitOpError()
             << "exchanges " << names[0]
             << " by the blocks its slot's fluxes are due in, but the launch "
                "is not for a local_flux component";
    SmallVector<FlatSymbolRefAttr> levels;
    for (auto arg : getArgs().getAsRange<ArgAttr>())
      if (arg.getKind() == ArgKind::levels)
        levels.push_back(arg.getName());
    if (levels.size() != 1)
      return emitOpError()
             << "exchanges " << names[0]
             << " by the blocks its slot's fluxes are due in, but passes the "
                "levels of "
             << levels.size()
             << " components instead of those of the flux pair's reader";
  }
  if (ArrayAttr names = getReduceMaxLevelsAttr())
    for (auto name : names.getAsRange<FlatSymbolRefAttr>()) {
      auto component =
          dyn_cast_or_null<ComponentOp>(symbolTable.lookupSymbolIn(plan, name));
      if (!component)
        return emitOpError() << "all-reduces the levels of " << name
                             << ", which is not a component of the plan";
      if (component.getAdvance() != mlir::sim::Advance::local_steps)
        return emitOpError()
               << "all-reduces the levels of " << name << ", which advances in "
               << mlir::sim::stringifyAdvance(component.getAdvance())
               << "; only local_steps components have levels";
      if (!component.getLevelReach())
        return emitOpError()
               << "reduces the levels of " << name
               << ", which has no level_reach to say which blocks";
    }
  return success();
}

LogicalResult LaunchOp::verifySymbolUses(SymbolTableCollection &symbolTable) {
  auto plan = (*this)->getParentOfType<PlanOp>();
  if (failed(verifyCommunication(plan, symbolTable)))
    return failure();
  Operation *container = symbolTable.lookupSymbolIn(
      plan->getParentOp(), getKernel().getRootReference());
  if (!container)
    return emitOpError() << "launches " << getKernel()
                         << ", but there is no kernel container "
                         << FlatSymbolRefAttr::get(
                                getKernel().getRootReference());
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
  // What the kernel was made for, where it says so.
  if (auto shared = function->getAttrOfType<DenseI64ArrayAttr>(
          PlanDialect::getSharedAttrName());
      shared && shared.size() == 2 &&
      (shared[0] != int64_t(getSharedPerThread()) ||
       shared[1] != int64_t(getSharedFixed())))
    return emitOpError() << "asks for shared(" << getSharedPerThread() << ", "
                         << getSharedFixed() << "), but " << getKernel()
                         << " records shared(" << shared[0] << ", " << shared[1]
                         << ")";
  if (auto slots = function->getAttrOfType<IntegerAttr>(
          PlanDialect::getClockSlotsAttrName());
      slots && slots.getInt() != int64_t(plan.getClockSlots()))
    return emitOpError() << "launches " << getKernel()
                         << ", which was made for a clock of " << slots.getInt()
                         << " slots, in a plan whose clock has "
                         << plan.getClockSlots();
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
    if (attr.getKind() == ArgKind::levels) {
      auto component = dyn_cast_or_null<ComponentOp>(symbol);
      if (!component ||
          component.getAdvance() != mlir::sim::Advance::local_steps)
        return emitOpError()
               << "passes " << attr << ", but the plan has no component "
               << attr.getName() << " that advances in "
               << "local_steps";
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
