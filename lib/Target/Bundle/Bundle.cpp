//===- Bundle.cpp - scenes to .simb bundles -------------------------------===//
//
// The bundle writer (docs/Bundle.md). A bundle is a 32-byte header
// (runtime/include/sim/Runtime/BundleFormat.h) and one FlatBuffer of the
// schema runtime/schema/bundle.fbs, built here with the schema's object API
// from the IR. Per strategy the writer clones the scene, runs the front end,
// and from that one result makes both kernel sets:
//
//   front end ─┬─ --sim-lower-to-gpu ── Plan (from the simplan.plan and the
//              │                    │   kernel functions' signatures)
//              │                    └─ buildSimGPUToPTXPipeline ── ptx
//              └─ --sim-lower-to-cpu ── the same Plan ── compileCPUKernels
//                                                        ── cpu
//
// The two lowerings must make the same plan, since the runtime runs the one
// plan with either kernel set; the writer builds the Plan of each and checks
// that they are equal. The scene comes from the simulation as written
// (before pruning), so it lists every parameter and buffer a user can name;
// the reference model from the reference lowering's `sim.reference_model`.
// Everything that refers to something else is an index: plan buffers name
// scene buffers, launches kernels, arguments plan buffers, scene
// parameters or plan totals.
//
//===----------------------------------------------------------------------===//

#include "sim/Target/Bundle.h"
#include "sim/Analysis/ValuePrecision.h"
#include "sim/Conversion/Passes.h"
#include "sim/Dialect/Plan/IR/PlanOps.h"
#include "sim/Dialect/Sim/IR/SimDialect.h"
#include "sim/Dialect/Sim/IR/SimOps.h"
#include "sim/Pipelines/Pipelines.h"
#include "sim/Runtime/BundleFormat.h"
#include "sim/Runtime/bundle_generated.h"
#include "sim/Target/CPUKernels.h"

#include "mlir/Dialect/Arith/IR/Arith.h"
#include "mlir/Dialect/GPU/IR/GPUDialect.h"
#include "mlir/Dialect/Math/IR/Math.h"
#include "mlir/Dialect/SCF/IR/SCF.h"
#include "mlir/Dialect/Vector/IR/VectorOps.h"
#include "mlir/IR/Diagnostics.h"
#include "mlir/Interfaces/FunctionInterfaces.h"
#include "mlir/Pass/PassManager.h"
#include "llvm/ADT/SetVector.h"
#include "llvm/ADT/StringMap.h"
#include "llvm/ADT/StringSet.h"
#include "llvm/Config/llvm-config.h"
#include "llvm/Support/CRC.h"
#include "llvm/Support/MathExtras.h"

#include <map>

using namespace mlir;
using namespace mlir::sim;

namespace fb = ::sim::bundle;

namespace {

/// The instruction-set level of the reference functions: the portable one
/// (they are the oracle, not the fast path).
constexpr StringLiteral kReferenceIsa = "x86-64";
/// What wrote the bundle.
constexpr StringLiteral kProducer =
    "sim-translate (LLVM " LLVM_VERSION_STRING ")";

//===----------------------------------------------------------------------===//
// Enumerations, values and types
//===----------------------------------------------------------------------===//

fb::Strategy getStrategy(Strategy strategy) {
  switch (strategy) {
  case Strategy::simple:
    return fb::Strategy::Simple;
  case Strategy::traditional:
    return fb::Strategy::Traditional;
  case Strategy::hip:
    return fb::Strategy::Hip;
  case Strategy::hip_cache:
    return fb::Strategy::HipCache;
  case Strategy::lts:
    return fb::Strategy::Lts;
  }
  llvm_unreachable("unknown strategy");
}

fb::Advance getAdvance(Advance advance) {
  switch (advance) {
  case Advance::whole_step:
    return fb::Advance::WholeStep;
  case Advance::group_substeps:
    return fb::Advance::GroupSubSteps;
  case Advance::grid_substeps:
    return fb::Advance::GridSubSteps;
  case Advance::local_steps:
    return fb::Advance::LocalSteps;
  case Advance::local_flux:
    return fb::Advance::LocalFlux;
  }
  llvm_unreachable("unknown advance");
}

fb::SubStepping getSubStepping(SubStepping subStepping) {
  switch (subStepping) {
  case SubStepping::in_kernel:
    return fb::SubStepping::InKernel;
  case SubStepping::grid_sync:
    return fb::SubStepping::GridSync;
  }
  llvm_unreachable("unknown sub-stepping");
}

fb::Boundary getBoundary(Boundary boundary) {
  switch (boundary) {
  case Boundary::clamp:
    return fb::Boundary::Clamp;
  case Boundary::wrap:
    return fb::Boundary::Wrap;
  case Boundary::zero:
    return fb::Boundary::Zero;
  }
  llvm_unreachable("unknown boundary");
}

fb::PhaseKind getPhaseKind(simplan::PhaseKind kind) {
  switch (kind) {
  case simplan::PhaseKind::init:
    return fb::PhaseKind::Init;
  case simplan::PhaseKind::step:
    return fb::PhaseKind::Step;
  case simplan::PhaseKind::finish:
    return fb::PhaseKind::Finish;
  case simplan::PhaseKind::exact:
    return fb::PhaseKind::Exact;
  case simplan::PhaseKind::total:
    return fb::PhaseKind::Total;
  }
  llvm_unreachable("unknown phase");
}

fb::LaunchShape getLaunchShape(simplan::LaunchShape shape) {
  switch (shape) {
  case simplan::LaunchShape::items:
    return fb::LaunchShape::Items;
  case simplan::LaunchShape::single:
    return fb::LaunchShape::Single;
  }
  llvm_unreachable("unknown launch shape");
}

fb::ArgKind getArgKind(simplan::ArgKind kind) {
  switch (kind) {
  case simplan::ArgKind::clock:
    return fb::ArgKind::Clock;
  case simplan::ArgKind::buffer:
    return fb::ArgKind::Buffer;
  case simplan::ArgKind::snapshot:
    return fb::ArgKind::Snapshot;
  case simplan::ArgKind::exact:
    return fb::ArgKind::Exact;
  case simplan::ArgKind::param:
    return fb::ArgKind::Param;
  case simplan::ArgKind::range:
    return fb::ArgKind::Range;
  case simplan::ArgKind::dt:
    return fb::ArgKind::Dt;
  case simplan::ArgKind::time:
    return fb::ArgKind::Time;
  case simplan::ArgKind::total:
    return fb::ArgKind::Total;
  case simplan::ArgKind::first:
    return fb::ArgKind::First;
  case simplan::ArgKind::extent:
    return fb::ArgKind::Extent;
  case simplan::ArgKind::levels:
    return fb::ArgKind::Levels;
  }
  llvm_unreachable("unknown launch argument kind");
}

/// The schema's scalar type of `type`: i32, i64, index, f32 or f64.
std::optional<fb::ScalarType> getScalarType(Type type) {
  if (type.isInteger(32))
    return fb::ScalarType::I32;
  if (type.isInteger(64))
    return fb::ScalarType::I64;
  if (type.isIndex())
    return fb::ScalarType::Index;
  if (type.isF32())
    return fb::ScalarType::F32;
  if (type.isF64())
    return fb::ScalarType::F64;
  return std::nullopt;
}

/// `attr` as a Value of its type, when the schema has the type.
std::optional<fb::Value> getValue(TypedAttr attr) {
  std::optional<fb::ScalarType> type = getScalarType(attr.getType());
  if (!type)
    return std::nullopt;
  if (auto integer = dyn_cast<IntegerAttr>(attr))
    return fb::Value(integer.getValue().getSExtValue(), 0.0, *type);
  if (auto real = dyn_cast<FloatAttr>(attr))
    return fb::Value(0, real.getValueAsDouble(), *type);
  return std::nullopt;
}

/// `type` (a scalar the schema has, or a vector of one) as an Element.
std::optional<fb::Element> getElement(Type type) {
  int64_t lanes = 1;
  if (auto vector = dyn_cast<VectorType>(type)) {
    if (vector.getRank() != 1 || vector.isScalable() ||
        vector.getNumElements() > std::numeric_limits<uint16_t>::max())
      return std::nullopt;
    lanes = vector.getNumElements();
    type = vector.getElementType();
  }
  std::optional<fb::ScalarType> scalar = getScalarType(type);
  if (!scalar)
    return std::nullopt;
  return fb::Element(*scalar, static_cast<uint16_t>(lanes));
}

/// The bytes one element of `type` takes as the kernels address it: LLVM's
/// alloc size, vectors padded to a power of two (vector<3xf32>: 16).
uint32_t getElementStride(Type type) {
  Type scalar = getElementTypeOrSelf(type);
  uint64_t bytes = scalar.isIndex() ? 8 : scalar.getIntOrFloatBitWidth() / 8;
  if (auto vector = dyn_cast<VectorType>(type))
    bytes = llvm::PowerOf2Ceil(bytes * vector.getNumElements());
  return static_cast<uint32_t>(bytes);
}

/// Positions of the scene's parameters, buffers and totals by name.
struct SceneIndex {
  llvm::StringMap<uint32_t> params, buffers, totals;
};

//===----------------------------------------------------------------------===//
// The scene
//===----------------------------------------------------------------------===//

/// The schema's Scene of `simulation` as written (before pruning), and the
/// positions of its symbols. Fails with an error at the offending op for
/// what the schema cannot hold.
LogicalResult buildScene(SimulationOp simulation, fb::SceneT &scene,
                         SceneIndex &index) {
  scene.name = simulation.getSymName().str();
  scene.range = simulation.getRange();
  std::optional<fb::Value> dt = getValue(cast<TypedAttr>(simulation.getDt()));
  if (!dt ||
      (dt->type() != fb::ScalarType::F32 && dt->type() != fb::ScalarType::F64))
    return simulation.emitOpError()
           << "has a time step of type " << simulation.getTimeStepType()
           << ", which a bundle cannot hold (f32 or f64)";
  scene.dt = std::make_unique<fb::Value>(*dt);
  scene.max_steps = simulation.getMaxSteps();

  for (ParamOp param : simulation.getParams()) {
    auto value = cast<TypedAttr>(param.getValue());
    std::optional<fb::Value> converted = getValue(value);
    if (!converted)
      return param.emitOpError()
             << "has type " << value.getType()
             << ", which a bundle cannot hold (parameters are i32, i64, "
                "index, f32 or f64)";
    index.params[param.getSymName()] = scene.params.size();
    auto record = std::make_unique<fb::ParamT>();
    record->name = param.getSymName().str();
    record->value = std::make_unique<fb::Value>(*converted);
    scene.params.push_back(std::move(record));
  }

  // Positions first: a Hermite derivative may come after its buffer.
  for (auto [position, buffer] : llvm::enumerate(simulation.getBuffers()))
    index.buffers[buffer.getSymName()] = position;
  llvm::SmallDenseSet<StringRef> observed;
  if (ObserveOp observe = simulation.getObserveOp())
    for (auto name : observe.getBuffers().getAsRange<FlatSymbolRefAttr>())
      observed.insert(name.getValue());
  ValuePrecision precision(simulation);
  // The bundle's precision_bytes: f32 and narrower floats count as f32.
  auto precisionBytes = [](unsigned bits) { return bits <= 32 ? 4 : 8; };
  for (BufferOp buffer : simulation.getBuffers()) {
    auto record = std::make_unique<fb::BufferT>();
    record->name = buffer.getSymName().str();
    std::optional<fb::Element> element = getElement(buffer.getElementType());
    if (!element || (element->scalar() != fb::ScalarType::F32 &&
                     element->scalar() != fb::ScalarType::F64))
      return buffer.emitOpError()
             << "has elements of type " << buffer.getElementType()
             << ", which a bundle cannot hold (f32, f64 or a vector of them)";
    record->element = std::make_unique<fb::Element>(*element);
    InterpolationAttrInterface interp = buffer.getInterpolation();
    if (isa<LinearInterpAttr>(interp)) {
      record->interp = fb::Interp::Linear;
    } else if (isa<CubicInterpAttr>(interp)) {
      record->interp = fb::Interp::Cubic;
    } else if (isa<NoneInterpAttr>(interp)) {
      record->interp = fb::Interp::None;
    } else if (isa<FluxInterpAttr>(interp)) {
      record->interp = fb::Interp::Flux;
    } else if (auto hermite = dyn_cast<HermiteInterpAttr>(interp)) {
      auto derivative = index.buffers.find(hermite.getDerivative().getValue());
      if (derivative == index.buffers.end())
        return buffer.emitOpError()
               << "interpolates with the derivative " << hermite.getDerivative()
               << ", which is not a buffer of the scene";
      record->interp = fb::Interp::Hermite;
      record->derivative = derivative->second;
    } else {
      return buffer.emitOpError()
             << "interpolates with " << interp
             << ", which the bundle format has no value for (linear, cubic, "
                "hermite, flux or none)";
    }
    record->boundary = getBoundary(buffer.getBoundary());
    record->observed = observed.contains(buffer.getSymName());
    record->exact = !buffer.getExact().empty();
    record->precision_bytes = precisionBytes(precision.getBits(buffer));
    scene.buffers.push_back(std::move(record));
  }

  for (TotalOp total : simulation.getTotals()) {
    std::optional<fb::ScalarType> type = getScalarType(total.getValueType());
    if (!type || (*type != fb::ScalarType::F32 && *type != fb::ScalarType::F64))
      return total.emitOpError()
             << "has type " << total.getValueType()
             << ", which a bundle cannot hold (totals are f32 or f64)";
    index.totals[total.getSymName()] = scene.totals.size();
    auto record = std::make_unique<fb::TotalT>();
    record->name = total.getSymName().str();
    record->type = *type;
    record->precision_bytes = precisionBytes(precision.getBits(total));
    scene.totals.push_back(std::move(record));
  }
  return success();
}

//===----------------------------------------------------------------------===//
// Plans
//===----------------------------------------------------------------------===//

/// Builds the schema's Plan of one simplan.plan, without its code: the
/// plan's symbols by position, every distinct kernel its launches call with
/// the signature of the kernel function (in the module the lowering made)
/// and its records, and the phases.
class PlanReader {
public:
  PlanReader(const SceneIndex &scene, ModuleOp module)
      : scene(scene), module(module) {}

  FailureOr<std::unique_ptr<fb::PlanT>> read(simplan::PlanOp op);

private:
  LogicalResult readSteps(Block &block,
                          std::vector<std::unique_ptr<fb::StepT>> &steps);
  FailureOr<std::unique_ptr<fb::LaunchT>> readLaunch(simplan::LaunchOp launch);
  FailureOr<uint32_t> getKernel(simplan::LaunchOp launch);

  const SceneIndex &scene;
  ModuleOp module;
  fb::PlanT *plan = nullptr;
  llvm::StringMap<uint32_t> buffers, components, totals, kernels;
};

FailureOr<std::unique_ptr<fb::PlanT>> PlanReader::read(simplan::PlanOp op) {
  auto result = std::make_unique<fb::PlanT>();
  plan = result.get();
  std::optional<Strategy> strategy = symbolizeStrategy(op.getStrategy());
  if (!strategy)
    return op.emitOpError() << "has the strategy '" << op.getStrategy()
                            << "', which is not a strategy of the bundle";
  plan->strategy = getStrategy(*strategy);
  plan->group_size = op.getGroupSize();
  plan->step_cap = op.getStepCap();
  plan->clock_slots = op.getClockSlots();
  plan->histogram = op.getHistogramSlot();

  for (Operation &child : op.getBlock()) {
    if (isa<simplan::ParamOp>(child))
      continue; // The scene lists every parameter; arguments name them there.
    if (auto buffer = dyn_cast<simplan::BufferOp>(child)) {
      auto found = scene.buffers.find(buffer.getSymName());
      if (found == scene.buffers.end())
        return buffer.emitOpError() << "is not a buffer of the scene";
      buffers[buffer.getSymName()] = plan->buffers.size();
      auto record = std::make_unique<fb::PlanBufferT>();
      record->buffer = found->second;
      record->stride = buffer.getStride();
      record->snapshot = buffer.getSnapshot();
      if (std::optional<ArrayRef<int64_t>> halo = buffer.getHalo();
          halo && halo->size() == 2) {
        for (int64_t width : *halo)
          if (width < 0 || width > int64_t(::sim::bundle::kMaxHalo))
            return emitError(buffer.getLoc())
                   << "@" << buffer.getSymName() << " is read " << width
                   << " items away from the reading item, and a distributed "
                      "run holds at most "
                   << ::sim::bundle::kMaxHalo
                   << " ghost items on each side of a rank's block: narrow "
                      "the window, or compile without --sim-distributed";
        record->halo_below = uint32_t((*halo)[0]);
        record->halo_above = uint32_t((*halo)[1]);
      }
      record->replicated = buffer.getReplicated();
      plan->buffers.push_back(std::move(record));
    } else if (auto component = dyn_cast<simplan::ComponentOp>(child)) {
      components[component.getSymName()] = plan->components.size();
      auto record = std::make_unique<fb::ComponentT>();
      record->name = component.getSymName().str();
      for (auto name : component.getWrites().getAsRange<FlatSymbolRefAttr>()) {
        auto found = buffers.find(name.getValue());
        if (found == buffers.end())
          return component.emitOpError()
                 << "writes " << name
                 << ", which is not a buffer of the plan before it";
        record->writes.push_back(found->second);
      }
      record->evaluations = component.getEvaluations();
      record->advance = getAdvance(component.getAdvance());
      record->estimates = component.getEstimates();
      record->sub_clock = component.getSubClock().value_or(0);
      record->level_reach = uint64_t(component.getLevelReach().value_or(0));
      record->keeps_levels = component.getKeepsLevels();
      record->largest_estimate =
          uint32_t(component.getLargestEstimate().value_or(0));
      record->keeps_estimate = component.getKeepsEstimate();
      plan->components.push_back(std::move(record));
    } else if (auto total = dyn_cast<simplan::TotalOp>(child)) {
      auto found = scene.totals.find(total.getSymName());
      if (found == scene.totals.end())
        return total.emitOpError() << "is not a total of the scene";
      totals[total.getSymName()] = plan->totals.size();
      plan->totals.push_back(found->second);
    } else if (auto phase = dyn_cast<simplan::PhaseOp>(child)) {
      auto record = std::make_unique<fb::PhaseT>();
      record->kind = getPhaseKind(phase.getKind());
      if (failed(readSteps(phase.getBody().front(), record->body)))
        return failure();
      plan->phases.push_back(std::move(record));
    } else {
      return child.emitOpError("cannot be written to a bundle's plan");
    }
  }
  // The plan's halo is the largest of its buffers', checked above at the
  // buffer; this catches a plan written by hand.
  if (std::optional<int64_t> halo = op.getDistributedHalo()) {
    if (*halo < 0 || *halo > int64_t(::sim::bundle::kMaxHalo))
      return op.emitOpError()
             << "is distributed with a halo of " << *halo
             << " items; a rank holds at most " << ::sim::bundle::kMaxHalo
             << " ghost items on each side of its block";
    plan->distributed = std::make_unique<fb::DistributionT>();
    plan->distributed->halo = uint32_t(*halo);
  }
  return result;
}

LogicalResult
PlanReader::readSteps(Block &block,
                      std::vector<std::unique_ptr<fb::StepT>> &steps) {
  for (Operation &op : block) {
    auto step = std::make_unique<fb::StepT>();
    if (auto repeat = dyn_cast<simplan::RepeatOp>(op)) {
      step->repeat = std::make_unique<fb::RepeatT>();
      step->repeat->count = repeat.getCount();
      if (failed(readSteps(repeat.getBody().front(), step->repeat->body)))
        return failure();
    } else if (auto launch = dyn_cast<simplan::LaunchOp>(op)) {
      FailureOr<std::unique_ptr<fb::LaunchT>> read = readLaunch(launch);
      if (failed(read))
        return failure();
      step->launch = std::move(*read);
    } else {
      return op.emitOpError("cannot be written to a bundle's plan");
    }
    steps.push_back(std::move(step));
  }
  return success();
}

FailureOr<std::unique_ptr<fb::LaunchT>>
PlanReader::readLaunch(simplan::LaunchOp launch) {
  auto record = std::make_unique<fb::LaunchT>();
  FailureOr<uint32_t> kernel = getKernel(launch);
  if (failed(kernel))
    return failure();
  record->kernel = *kernel;
  record->shape = getLaunchShape(launch.getShape());
  if (FlatSymbolRefAttr component = launch.getComponentAttr()) {
    auto found = components.find(component.getValue());
    if (found == components.end())
      return launch.emitOpError()
             << "is for " << component << ", which is not a component of "
             << "the plan";
    record->component = found->second;
  }
  record->shared_per_thread = launch.getSharedPerThread();
  record->shared_fixed = launch.getSharedFixed();
  for (auto arg : launch.getArgs().getAsRange<simplan::ArgAttr>()) {
    uint32_t index = 0;
    if (FlatSymbolRefAttr name = arg.getName()) {
      const llvm::StringMap<uint32_t> &symbols =
          arg.getKind() == simplan::ArgKind::param    ? scene.params
          : arg.getKind() == simplan::ArgKind::total  ? totals
          : arg.getKind() == simplan::ArgKind::levels ? components
                                                      : buffers;
      auto found = symbols.find(name.getValue());
      if (found == symbols.end())
        return launch.emitOpError()
               << "passes " << arg << ", whose symbol the bundle cannot "
               << "resolve";
      index = found->second;
    }
    record->args.emplace_back(getArgKind(arg.getKind()), index);
  }
  if (std::optional<ArrayRef<int64_t>> slots = launch.getReduceMin())
    for (int64_t slot : *slots)
      record->reduce_min.push_back(uint32_t(slot));
  // Where a buffer's ghost items travel: both halves (or its snapshot),
  // the target half, the half the sub-step wrote, the blocks a local time
  // step's slot started in the halves they wrote, or the target half of
  // the blocks where a flux pair's fluxes may be due at the slot.
  enum class Half { Both, Target, SubStep, LocalStep, LocalFlux };
  auto exchange = [&](ArrayAttr names, bool snapshot,
                      Half half = Half::Both) -> LogicalResult {
    if (!names)
      return success();
    for (auto name : names.getAsRange<FlatSymbolRefAttr>()) {
      auto found = buffers.find(name.getValue());
      if (found == buffers.end())
        return launch.emitOpError()
               << "exchanges " << name << ", which is not a buffer of the plan";
      if (half == Half::Target)
        record->exchange_targets.push_back(found->second);
      else if (half == Half::SubStep)
        record->exchange_sub_step.push_back(found->second);
      else if (half == Half::LocalStep)
        record->exchange_local_step.push_back(found->second);
      else if (half == Half::LocalFlux)
        record->exchange_local_flux.push_back(found->second);
      else
        record->exchange.emplace_back(found->second, snapshot);
    }
    return success();
  };
  if (failed(exchange(launch.getExchangeAttr(), false)) ||
      failed(exchange(launch.getExchangeSnapshotsAttr(), true)) ||
      failed(exchange(launch.getExchangeTargetsAttr(), false, Half::Target)) ||
      failed(exchange(launch.getExchangeSubStepAttr(), false, Half::SubStep)) ||
      failed(exchange(launch.getExchangeLocalStepAttr(), false,
                      Half::LocalStep)) ||
      failed(
          exchange(launch.getExchangeLocalFluxAttr(), false, Half::LocalFlux)))
    return failure();
  if (ArrayAttr names = launch.getReduceMaxLevelsAttr())
    for (auto name : names.getAsRange<FlatSymbolRefAttr>()) {
      auto found = components.find(name.getValue());
      if (found == components.end())
        return launch.emitOpError() << "all-reduces the levels of " << name
                                    << ", which is not a component of the plan";
      record->reduce_max_levels.push_back(found->second);
    }
  return record;
}

/// The position of the launch's kernel in the plan's kernels, adding it
/// with the signature and records of its function on its first launch.
FailureOr<uint32_t> PlanReader::getKernel(simplan::LaunchOp launch) {
  StringRef name = launch.getKernel().getLeafReference().getValue();
  if (auto found = kernels.find(name); found != kernels.end())
    return found->second;

  auto function = dyn_cast_or_null<FunctionOpInterface>(
      SymbolTable::lookupSymbolIn(module, launch.getKernel()));
  if (!function)
    return launch.emitOpError()
           << "launches " << launch.getKernel()
           << ", which is not a kernel function of the lowered module";
  auto shared = function->getAttrOfType<DenseI64ArrayAttr>(
      simplan::PlanDialect::getSharedAttrName());
  auto clockSlots = function->getAttrOfType<IntegerAttr>(
      simplan::PlanDialect::getClockSlotsAttrName());
  if (!shared || shared.size() != 2 || !clockSlots)
    return function->emitOpError()
           << "has no record of its shared memory and clock ('"
           << simplan::PlanDialect::getSharedAttrName() << "', '"
           << simplan::PlanDialect::getClockSlotsAttrName()
           << "'), which the bundle needs for every kernel";

  auto kernel = std::make_unique<fb::KernelT>();
  kernel->name = name.str();
  kernel->shared_per_thread = shared[0];
  kernel->shared_fixed = shared[1];
  kernel->clock_slots = clockSlots.getInt();
  kernel->uneven_groups =
      function->hasAttr(simplan::PlanDialect::getUnevenGroupsAttrName());
  ArrayRef<Type> inputs = function.getArgumentTypes();
  if (auto extra = function->getAttrOfType<IntegerAttr>(
          simplan::PlanDialect::getGroupArgumentsAttrName()))
    inputs =
        inputs.drop_back(std::min<uint64_t>(extra.getInt(), inputs.size()));
  for (auto [position, type] : llvm::enumerate(inputs)) {
    if (auto memref = dyn_cast<MemRefType>(type)) {
      std::optional<fb::Element> element = getElement(memref.getElementType());
      if (memref.getRank() == 1 && element) {
        kernel->params.emplace_back(fb::ParamType::Memref, *element,
                                    getElementStride(memref.getElementType()));
        continue;
      }
    } else if (std::optional<fb::ScalarType> scalar = getScalarType(type)) {
      fb::ParamType param = fb::ParamType::I64;
      switch (*scalar) {
      case fb::ScalarType::I32:
        param = fb::ParamType::I32;
        break;
      case fb::ScalarType::I64:
      case fb::ScalarType::Index:
        param = fb::ParamType::I64;
        break;
      case fb::ScalarType::F32:
        param = fb::ParamType::F32;
        break;
      case fb::ScalarType::F64:
        param = fb::ParamType::F64;
        break;
      }
      kernel->params.emplace_back(param, fb::Element(), 0);
      continue;
    }
    return function->emitOpError()
           << "takes argument " << position << " of type " << type
           << ", which the bundle format has no kernel parameter for "
              "(memref<?xT> of a scalar or vector, i32, i64, index, f32 or "
              "f64)";
  }
  uint32_t position = plan->kernels.size();
  kernels[name] = position;
  plan->kernels.push_back(std::move(kernel));
  return position;
}

/// The FlatBuffer of `plan` alone: plans with the same bytes are the same.
std::string packPlan(const fb::PlanT &plan) {
  flatbuffers::FlatBufferBuilder builder;
  builder.Finish(fb::Plan::Pack(builder, &plan));
  return std::string(reinterpret_cast<const char *>(builder.GetBufferPointer()),
                     builder.GetSize());
}

//===----------------------------------------------------------------------===//
// The reference model
//===----------------------------------------------------------------------===//

/// Reads the `sim.reference_model` dictionary of the reference module
/// (lib/Conversion/SimToReference) into `reference`, naming the scene's
/// parameters, buffers and totals by position.
LogicalResult readReferenceModel(ModuleOp module, const SceneIndex &scene,
                                 fb::ReferenceT &reference) {
  auto model = module->getAttrOfType<DictionaryAttr>(kReferenceModelAttrName);
  auto malformed = [&](StringRef what) {
    return module.emitError() << "has a malformed reference model ('"
                              << kReferenceModelAttrName << "'): " << what;
  };
  if (!model)
    return malformed("it is not a dictionary");

  // Model parameters and buffers by scene name.
  auto readNames = [&](StringRef key, StringRef what,
                       const llvm::StringMap<uint32_t> &index,
                       std::vector<uint32_t> &positions) -> LogicalResult {
    auto names = model.getAs<ArrayAttr>(key);
    if (!names)
      return malformed(("no '" + key + "' array of names").str());
    for (Attribute attr : names) {
      auto name = dyn_cast<StringAttr>(attr);
      if (!name)
        return malformed(
            ("'" + key + "' holds something other than a name").str());
      auto found = index.find(name.getValue());
      if (found == index.end())
        return module.emitError()
               << "has a reference model that names the " << what << " '"
               << name.getValue() << "', which the scene does not have";
      positions.push_back(found->second);
    }
    return success();
  };
  if (failed(
          readNames("params", "parameter", scene.params, reference.params)) ||
      failed(readNames("buffers", "buffer", scene.buffers, reference.buffers)))
    return failure();

  // Model buffer indices.
  auto readIndices = [&](DictionaryAttr entry, StringRef key,
                         std::vector<uint32_t> &indices) -> LogicalResult {
    auto array = entry.getAs<DenseI64ArrayAttr>(key);
    if (!array)
      return malformed(("an entry without a '" + key + "' array").str());
    for (int64_t index : array.asArrayRef()) {
      if (index < 0 || index >= int64_t(reference.buffers.size()))
        return malformed(
            ("'" + key + "' names a buffer outside the model").str());
      indices.push_back(index);
    }
    return success();
  };
  auto components = model.getAs<ArrayAttr>("components");
  if (!components)
    return malformed("no 'components' array");
  for (Attribute attr : components) {
    auto entry = dyn_cast<DictionaryAttr>(attr);
    if (!entry)
      return malformed("a component that is not a dictionary");
    auto name = entry.getAs<StringAttr>("name");
    auto subStepping = entry.getAs<SubSteppingAttr>("sub_stepping");
    auto numSteps = entry.getAs<BoolAttr>("num_steps");
    auto stepping = entry.getAs<DictionaryAttr>("stepping");
    if (!name || !subStepping || !numSteps || !stepping)
      return malformed("a component without a name, sub_stepping, num_steps "
                       "or stepping");
    auto record = std::make_unique<fb::RefComponentT>();
    record->name = name.getValue().str();
    record->sub_stepping = getSubStepping(subStepping.getValue());
    record->num_steps = numSteps.getValue();
    if (failed(readIndices(entry, "writes", record->writes)) ||
        failed(readIndices(entry, "reads", record->reads)))
      return failure();
    if (auto window = entry.getAs<DenseI64ArrayAttr>("local_window")) {
      if (window.size() != 2)
        return malformed("a 'local_window' that is not [lo, hi]");
      record->local_window.assign(window.asArrayRef().begin(),
                                  window.asArrayRef().end());
    }
    if (auto window = entry.getAs<DenseI64ArrayAttr>("flux_window")) {
      if (window.size() != 2)
        return malformed("a 'flux_window' that is not [lo, hi]");
      record->flux_window.assign(window.asArrayRef().begin(),
                                 window.asArrayRef().end());
    }
    // Indexed by the schema's Strategy, which is the sim dialect's order.
    for (uint32_t value = 0; value <= getMaxEnumValForStrategy(); ++value) {
      Strategy strategy = *symbolizeStrategy(value);
      auto decided =
          stepping.getAs<DictionaryAttr>(stringifyStrategy(strategy));
      auto advance = decided ? decided.getAs<AdvanceAttr>("advance") : nullptr;
      auto estimates = decided ? decided.getAs<BoolAttr>("estimates") : nullptr;
      if (!advance || !estimates)
        return malformed(("component '" + name.getValue() +
                          "' has no stepping for strategy '" +
                          stringifyStrategy(strategy) + "'")
                             .str());
      if (uint32_t(getStrategy(strategy)) != record->stepping.size())
        return malformed("the strategies are not in the schema's order");
      record->stepping.emplace_back(getAdvance(advance.getValue()),
                                    estimates.getValue());
    }
    reference.components.push_back(std::move(record));
  }

  auto stepCaps = model.getAs<DictionaryAttr>("step_caps");
  if (!stepCaps)
    return malformed("no 'step_caps' dictionary");
  for (uint32_t value = 0; value <= getMaxEnumValForStrategy(); ++value) {
    Strategy strategy = *symbolizeStrategy(value);
    auto cap = stepCaps.getAs<IntegerAttr>(stringifyStrategy(strategy));
    if (!cap)
      return malformed(
          ("no step cap for strategy '" + stringifyStrategy(strategy) + "'")
              .str());
    reference.step_caps.push_back(uint32_t(cap.getInt()));
  }

  auto totals = model.getAs<ArrayAttr>("totals");
  if (!totals)
    return malformed("no 'totals' array");
  for (Attribute attr : totals) {
    auto entry = dyn_cast<DictionaryAttr>(attr);
    auto name = entry ? entry.getAs<StringAttr>("name") : nullptr;
    if (!name)
      return malformed("a total without a name");
    auto found = scene.totals.find(name.getValue());
    if (found == scene.totals.end())
      return module.emitError()
             << "has a reference model that names the total '"
             << name.getValue() << "', which the scene does not have";
    auto record = std::make_unique<fb::RefTotalT>();
    record->total = found->second;
    if (failed(readIndices(entry, "reads", record->reads)))
      return failure();
    reference.totals.push_back(std::move(record));
  }
  return success();
}

//===----------------------------------------------------------------------===//
// Compiling one strategy
//===----------------------------------------------------------------------===//

/// What the check of the GPU back end says when a kernel calls a libdevice
/// function and there is no libdevice (lib/Target/PTX/Transforms/
/// CheckTarget.cpp).
constexpr StringLiteral kNeedsLibdevice =
    "this operation needs the libdevice function '";

/// The plan of one strategy with its code, and why it has no PTX when it
/// has none.
struct StrategyCode {
  std::unique_ptr<fb::PlanT> plan;
  /// The libdevice functions the kernels call when the PTX could not be
  /// made for want of libdevice, and where the first one is called.
  SmallVector<std::string> missingLibdevice;
  std::optional<Location> firstLibdeviceCall;
  /// The CPU kernels until they are compiled (BundleWriter::compileCPU).
  OwningOpRef<ModuleOp> cpuKernels;
};

class BundleWriter {
public:
  BundleWriter(ModuleOp module, SimulationOp simulation,
               const SceneIndex &scene, const BundleOptions &options)
      : module(module), simulation(simulation), scene(scene), options(options),
        context(module.getContext()) {}

  /// Compiles `strategy` into `code`; any error carries a note that names
  /// the strategy.
  LogicalResult compile(Strategy strategy, StrategyCode &code) {
    ScopedDiagnosticHandler note(context, [&](Diagnostic &diag) {
      if (diag.getSeverity() == DiagnosticSeverity::Error)
        diag.attachNote(simulation.getLoc())
            << "while compiling the bundle's strategy '"
            << stringifyStrategy(strategy)
            << "' (--sim-strategies chooses the strategies)";
      return failure(); // Not handled: the next handler reports it.
    });

    OwningOpRef<ModuleOp> frontEnd(module.clone());
    {
      PassManager pm(context, ModuleOp::getOperationName());
      FrontEndOptions frontEndOptions;
      frontEndOptions.strategy = strategy;
      frontEndOptions.groupSize = options.groupSize;
      frontEndOptions.distributed = options.distributed;
      buildFrontEndPipeline(pm, frontEndOptions);
      if (failed(runPipeline(pm, *frontEnd)))
        return failure();
    }

    // GPU kernels and the plan (read before the back end turns the kernel
    // functions into a binary), then the PTX.
    OwningOpRef<ModuleOp> gpu(frontEnd->clone());
    simplan::PlanOp plan;
    {
      PassManager pm(context, ModuleOp::getOperationName());
      SimLowerToGPUOptions lowering;
      lowering.groupSize = options.groupSize;
      pm.addPass(createSimLowerToGPU(lowering));
      if (failed(runPipeline(pm, *gpu)))
        return failure();
      FailureOr<simplan::PlanOp> found = getPlan(*gpu);
      if (failed(found))
        return failure();
      plan = *found;
      FailureOr<std::unique_ptr<fb::PlanT>> read =
          PlanReader(scene, *gpu).read(plan);
      if (failed(read))
        return failure();
      code.plan = std::move(*read);
    }
    std::string gpuPlan = packPlan(*code.plan);
    if (failed(compilePTX(*gpu, plan, code)))
      return failure();

    // CPU kernels: the same plan, and a shared object.
    OwningOpRef<ModuleOp> cpu(frontEnd->clone());
    frontEnd = nullptr;
    {
      PassManager pm(context, ModuleOp::getOperationName());
      SimLowerToCPUOptions lowering;
      lowering.groupSize = options.groupSize;
      lowering.levelsPerLane = options.cpuLevelsPerLane;
      pm.addPass(createSimLowerToCPU(lowering));
      if (failed(runPipeline(pm, *cpu)))
        return failure();
    }
    FailureOr<simplan::PlanOp> cpuPlan = getPlan(*cpu);
    if (failed(cpuPlan))
      return failure();
    FailureOr<std::unique_ptr<fb::PlanT>> cpuRead =
        PlanReader(scene, *cpu).read(*cpuPlan);
    if (failed(cpuRead))
      return failure();
    if (packPlan(**cpuRead) != gpuPlan)
      return emitError(simulation.getLoc())
             << "the GPU and the CPU lowerings made different plans; the "
                "bundle needs one plan for both kernel sets";
    auto kernels = dyn_cast_or_null<ModuleOp>(
        SymbolTable::lookupSymbolIn(*cpu, cpuPlan->getKernelsAttr()));
    if (!kernels)
      return cpuPlan->emitOpError()
             << "names the kernels " << cpuPlan->getKernelsAttr()
             << ", which are not a module of CPU kernels";
    // The shared objects come later, for every strategy at once
    // (compileCPU).
    code.cpuKernels = cast<ModuleOp>(kernels->clone());
    return success();
  }

  /// Compiles the CPU kernels of every strategy of `codes` into their plans:
  /// one shared object per instruction-set level, the same kernels, the
  /// same bits (docs/Bundle.md), faster code where the CPU has more. Every
  /// pair of a strategy and a level compiles side by side, and strategies
  /// whose kernels are the same module (lts where no component takes local
  /// time steps makes hip's) share the objects of one compilation: the
  /// compilations are most of a bundle's compile time.
  LogicalResult compileCPU(MutableArrayRef<StrategyCode> codes) {
    ScopedDiagnosticHandler note(context, [&](Diagnostic &diag) {
      if (diag.getSeverity() == DiagnosticSeverity::Error)
        diag.attachNote(simulation.getLoc())
            << "while compiling the bundle's CPU kernels (--sim-cpu-isas "
               "chooses the instruction-set levels)";
      return failure(); // Not handled: the next handler reports it.
    });
    std::map<std::string, size_t> moduleOfText;
    SmallVector<ModuleOp> modules;
    SmallVector<size_t> moduleOfCode;
    for (StrategyCode &code : codes) {
      std::string text;
      llvm::raw_string_ostream os(text);
      code.cpuKernels->print(os);
      auto [found, inserted] =
          moduleOfText.try_emplace(std::move(text), modules.size());
      if (inserted)
        modules.push_back(*code.cpuKernels);
      moduleOfCode.push_back(found->second);
    }
    CPUKernelOptions cpuOptions;
    cpuOptions.optLevel = options.target.optLevel;
    cpuOptions.flushSubnormals = options.flushSubnormals;
    FailureOr<SmallVector<SmallVector<std::string>>> libraries =
        compileCPUKernels(modules, options.cpuIsas, cpuOptions);
    if (failed(libraries))
      return failure();
    for (auto [code, module] : llvm::zip_equal(codes, moduleOfCode)) {
      for (auto [isa, library] :
           llvm::zip_equal(options.cpuIsas, (*libraries)[module])) {
        auto object = std::make_unique<fb::CpuCodeT>();
        object->isa = isa;
        object->object.assign(library.begin(), library.end());
        code.plan->cpu.push_back(std::move(object));
      }
      code.cpuKernels = nullptr;
    }
    return success();
  }

  /// Compiles the reference executor's part (docs/Reference.md): the model
  /// and the shared object of the body functions, from the scheduled IR. It
  /// shares no lowering with the strategies' kernels.
  LogicalResult compileReference(fb::ReferenceT &reference) {
    ScopedDiagnosticHandler note(context, [&](Diagnostic &diag) {
      if (diag.getSeverity() == DiagnosticSeverity::Error)
        diag.attachNote(simulation.getLoc())
            << "while compiling the bundle's reference functions";
      return failure();
    });
    OwningOpRef<ModuleOp> scheduled(module.clone());
    PassManager pm(context, ModuleOp::getOperationName());
    // The strategies' front ends explain the verdicts where they matter.
    ReferenceOptions referenceOptions;
    referenceOptions.remarks = false;
    buildReferencePipeline(pm, referenceOptions);
    if (failed(runPipeline(pm, *scheduled)))
      return failure();
    auto modules = scheduled->getOps<ModuleOp>();
    if (modules.empty() || std::next(modules.begin()) != modules.end())
      return emitError(simulation.getLoc())
             << "the reference lowering made no single module of functions";
    ModuleOp functions = *modules.begin();
    if (failed(readReferenceModel(functions, scene, reference)))
      return failure();
    CPUKernelOptions cpuOptions;
    cpuOptions.optLevel = options.target.optLevel;
    cpuOptions.flushSubnormals = options.flushSubnormals;
    FailureOr<std::string> compiled =
        compileReferenceFunctions(functions, cpuOptions);
    if (failed(compiled))
      return failure();
    reference.isa = kReferenceIsa.str();
    reference.object.assign(compiled->begin(), compiled->end());
    return success();
  }

private:
  /// Runs `pm` on `op`. Some upstream passes report an error and still
  /// succeed (gpu-module-to-binary without a toolkit), so any error fails.
  LogicalResult runPipeline(PassManager &pm, ModuleOp op) {
    bool reportedError = false;
    ScopedDiagnosticHandler errors(context, [&](Diagnostic &diag) {
      reportedError |= diag.getSeverity() == DiagnosticSeverity::Error;
      return failure();
    });
    if (failed(applyPassManagerCLOptions(pm)))
      return failure();
    return failure(failed(pm.run(op)) || reportedError);
  }

  /// The one plan a lowering made of the one simulation.
  FailureOr<simplan::PlanOp> getPlan(ModuleOp lowered) {
    auto plans = lowered.getOps<simplan::PlanOp>();
    if (plans.empty() || std::next(plans.begin()) != plans.end())
      return emitError(simulation.getLoc())
             << "the lowering made no single simplan.plan of the simulation";
    return *plans.begin();
  }

  /// Runs the GPU back end on the lowered module `gpu` and takes the PTX of
  /// the plan's kernels. Without libdevice, kernels that call math functions
  /// cannot be made: that leaves the strategy without PTX (the caller
  /// warns), any other error fails.
  LogicalResult compilePTX(ModuleOp gpu, simplan::PlanOp plan,
                           StrategyCode &code) {
    PassManager pm(context, ModuleOp::getOperationName());
    GPUTargetOptions target = options.target;
    target.flushSubnormals = options.flushSubnormals;
    buildSimGPUToPTXPipeline(pm, target);

    // Held back until it is known whether they are only libdevice's.
    SmallVector<Diagnostic> held;
    LogicalResult result = success();
    {
      ScopedDiagnosticHandler hold(context, [&](Diagnostic &diag) {
        held.push_back(std::move(diag));
        return success();
      });
      result = runPipeline(pm, gpu);
    }
    bool onlyLibdevice = failed(result) && !held.empty();
    for (Diagnostic &diag : held)
      if (diag.getSeverity() == DiagnosticSeverity::Error &&
          !StringRef(diag.str()).starts_with(kNeedsLibdevice))
        onlyLibdevice = false;
    if (onlyLibdevice) {
      for (Diagnostic &diag : held) {
        // diag.str() is a temporary: keep the message while it is read.
        std::string message = diag.str();
        StringRef function =
            StringRef(message).drop_front(kNeedsLibdevice.size());
        code.missingLibdevice.push_back(
            function.take_until([](char c) { return c == '\''; }).str());
        if (!code.firstLibdeviceCall)
          code.firstLibdeviceCall = diag.getLocation();
      }
      return success();
    }
    for (Diagnostic &diag : held)
      context->getDiagEngine().emit(std::move(diag));
    if (failed(result))
      return failure();

    auto binary = dyn_cast_or_null<gpu::BinaryOp>(
        SymbolTable::lookupSymbolIn(gpu, plan.getKernelsAttr()));
    if (!binary || binary.getObjectsAttr().size() != 1)
      return plan.emitOpError()
             << "names the kernels " << plan.getKernelsAttr()
             << ", which the GPU back end did not compile to one gpu.binary";
    auto object = dyn_cast<gpu::ObjectAttr>(binary.getObjectsAttr()[0]);
    if (!object || object.getFormat() != gpu::CompilationTarget::Assembly)
      return binary.emitError()
             << "expected PTX (an object in assembly format), got "
             << binary.getObjectsAttr()[0];
    code.plan->ptx = object.getObject().getValue().str();
    code.plan->ptx_chip = options.target.chip;
    return success();
  }

  ModuleOp module;
  SimulationOp simulation;
  const SceneIndex &scene;
  const BundleOptions &options;
  MLIRContext *context;
};

} // namespace

//===----------------------------------------------------------------------===//
// The bundle
//===----------------------------------------------------------------------===//

void mlir::sim::registerBundleDependencies(DialectRegistry &registry) {
  registry.insert<SimDialect, simplan::PlanDialect, arith::ArithDialect,
                  math::MathDialect, scf::SCFDialect, vector::VectorDialect>();
  registerGPUToPTXDependencies(registry);
  registerCPUKernelDialects(registry);
}

LogicalResult mlir::sim::writeBundle(ModuleOp module,
                                     const BundleOptions &options,
                                     raw_ostream &os) {
  DialectRegistry registry;
  registerBundleDependencies(registry);
  module.getContext()->appendDialectRegistry(registry);

  auto simulations = module.getOps<SimulationOp>();
  if (simulations.empty())
    return module.emitError()
           << "there is no sim.simulation to write to a bundle";
  if (std::next(simulations.begin()) != simulations.end()) {
    InFlightDiagnostic diag =
        (*std::next(simulations.begin())).emitError()
        << "a bundle holds one scene; this is a second sim.simulation";
    diag.attachNote((*simulations.begin()).getLoc()) << "the first one";
    return diag;
  }
  SimulationOp simulation = *simulations.begin();

  if (options.strategies.empty())
    return emitError(simulation.getLoc())
           << "a bundle needs at least one strategy";
  for (auto [index, strategy] : llvm::enumerate(options.strategies))
    if (llvm::is_contained(ArrayRef(options.strategies).take_front(index),
                           strategy))
      return emitError(simulation.getLoc())
             << "strategy '" << stringifyStrategy(strategy)
             << "' is asked for twice";
  // The bundle's GPU kernels run a group's items in warps of 32 (sim-run
  // --group-size chooses another size for a run, any size on a CPU).
  if (options.groupSize <= 0 || options.groupSize % 32 != 0 ||
      options.groupSize > int64_t(::sim::bundle::kMaxGroupSize))
    return emitError(simulation.getLoc())
           << "the group size must be a multiple of 32 (a GPU warp) from 32 "
              "to "
           << ::sim::bundle::kMaxGroupSize << ", not " << options.groupSize;
  if (options.cpuIsas.empty())
    return emitError(simulation.getLoc())
           << "a bundle needs CPU kernels for at least one instruction-set "
              "level";
  for (auto [index, isa] : llvm::enumerate(options.cpuIsas)) {
    if (!llvm::is_contained(getCPUIsaLevels(), isa))
      return emitError(simulation.getLoc())
             << "unknown CPU instruction-set level '" << isa
             << "' (known: " << llvm::join(getCPUIsaLevels(), ", ") << ")";
    if (llvm::is_contained(ArrayRef(options.cpuIsas).take_front(index), isa))
      return emitError(simulation.getLoc())
             << "CPU instruction-set level '" << isa << "' is asked for twice";
  }

  fb::BundleT bundle;
  bundle.producer = kProducer.str();
  bundle.subnormals = options.flushSubnormals ? fb::Subnormals::FlushToZero
                                              : fb::Subnormals::Keep;
  bundle.scene = std::make_unique<fb::SceneT>();
  SceneIndex scene;
  if (failed(buildScene(simulation, *bundle.scene, scene)))
    return failure();

  // Every strategy runs the front end, and both lowerings run after it: a
  // remark or warning about the scene would come up to eight times. Each is
  // reported once, and so is an error that the CPU levels compiling side
  // by side each meet (no linker).
  llvm::StringSet<> reported;
  ScopedDiagnosticHandler once(module.getContext(), [&](Diagnostic &diag) {
    std::string key;
    llvm::raw_string_ostream os(key);
    os << diag.getLocation() << ": " << diag;
    for (const Diagnostic &note : diag.getNotes())
      os << "\n" << note.getLocation() << ": " << note;
    // Handled (dropped) when it was reported before.
    return success(!reported.insert(key).second);
  });

  BundleWriter writer(module, simulation, scene, options);
  SmallVector<Strategy> withoutPTX;
  llvm::SetVector<StringRef> missingLibdevice;
  std::optional<Location> firstLibdeviceCall;
  SmallVector<StrategyCode> codes(options.strategies.size());
  for (auto [strategy, code] : llvm::zip_equal(options.strategies, codes)) {
    if (failed(writer.compile(strategy, code)))
      return failure();
    if (code.plan->ptx.empty()) {
      withoutPTX.push_back(strategy);
      missingLibdevice.insert(code.missingLibdevice.begin(),
                              code.missingLibdevice.end());
      if (!firstLibdeviceCall)
        firstLibdeviceCall = code.firstLibdeviceCall;
    }
  }

  if (failed(writer.compileCPU(codes)))
    return failure();

  bundle.reference = std::make_unique<fb::ReferenceT>();
  if (failed(writer.compileReference(*bundle.reference)))
    return failure();

  if (!withoutPTX.empty()) {
    InFlightDiagnostic warning =
        emitWarning(firstLibdeviceCall.value_or(simulation.getLoc()))
        << "the bundle has no PTX for strateg"
        << (withoutPTX.size() == 1 ? "y " : "ies ");
    llvm::interleaveComma(withoutPTX, warning, [&](Strategy strategy) {
      warning << "'" << stringifyStrategy(strategy) << "'";
    });
    warning << ": the kernels call the libdevice function"
            << (missingLibdevice.size() == 1 ? " " : "s ");
    llvm::interleaveComma(missingLibdevice, warning);
    warning << ", but there is no libdevice at '"
            << getLibdevicePath(options.target.cudaPath)
            << "'; they run on the CPU only (give the CUDA toolkit's root "
               "with --sim-cuda-path or $CUDA_HOME)";
  }

  for (StrategyCode &code : codes)
    bundle.plans.push_back(std::move(code.plan));

  // The header's CRC covers every byte after it: the FlatBuffer.
  flatbuffers::FlatBufferBuilder builder;
  fb::FinishBundleBuffer(builder, fb::Bundle::Pack(builder, &bundle));
  ArrayRef<uint8_t> payload(builder.GetBufferPointer(), builder.GetSize());
  // What a runtime verifies first; a bundle that fails it is a writer bug
  // (a required field left out), never a file to write.
  flatbuffers::Verifier verifier(payload.data(), payload.size());
  if (!fb::VerifyBundleBuffer(verifier))
    return emitError(simulation.getLoc())
           << "the bundle's FlatBuffer fails the schema's verifier; this is "
              "a bug of the bundle writer";
  fb::Header header;
  header.checksum = llvm::crc32(payload);
  header.size = fb::kHeaderSize + payload.size();
  if (header.size > fb::kMaxBundleBytes)
    return emitError(simulation.getLoc())
           << "the bundle would take " << header.size
           << " bytes, more than a runtime reads (" << fb::kMaxBundleBytes
           << ")";
  os << fb::encodeHeader(header);
  os.write(reinterpret_cast<const char *>(payload.data()), payload.size());
  return success();
}
