//===- BundleVerifier.cpp - what a bundle's schema cannot say -------------===//
//
// FlatBuffers' verifier proves that every offset and length of a bundle lies
// inside it; this file proves what the executors rely on beyond that, once,
// so that they never check again:
//
// - every enum value is one the schema declares, every index names an
//   entry of the table it points into, names are unique where they are
//   looked up by name, and kernel names are identifiers;
// - the scene's range, dt and max_steps are in their domains;
// - every plan's clock holds its fixed slots, evaluation counters, sub-step
//   clocks and histogram without overlaps;
// - every launch matches the signature its kernel records: as many
//   arguments as parameters, memory where the kernel takes a memref (with
//   the element type and stride of the buffer passed), scalars of the type
//   the kernel takes, the same dynamic shared memory, and a kernel made for
//   the plan's clock;
// - phases unroll to a bounded number of launches;
// - distributed plans: halos within the plan's, exchanges of buffers (and
//   snapshots) the plan has, all-reduces of clock slots it has and of the
//   levels of LocalSteps components; First and
//   Extent arguments, halos, replicated buffers, exchanges and all-reduces
//   only there; no halo on a replicated buffer;
// - the reference model resolves against the scene;
// - every shared object's ELF headers lie inside its bytes
//   (SharedObject.h), checked before anything is loaded.
//
// Every message names the table and entry it is about.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "SharedObject.h"
#include "sim/Runtime/BundleFormat.h"

#include <cmath>
#include <set>

namespace sim::rt {

namespace {

/// The largest number of clock slots a plan may ask for (the clock is
/// allocated and reset every run).
constexpr uint64_t kMaxClockSlots = uint64_t(1) << 24;
/// The most lanes of a vector element, and the largest element stride.
constexpr uint32_t kMaxLanes = 64;
constexpr uint32_t kMaxStride = 1 << 16;

[[noreturn]] void bad(const std::string &message) {
  fail(SIM_ERROR_BUNDLE, message);
}

template <typename Enum> bool valid(Enum value) {
  return uint32_t(value) <= uint32_t(Enum::MAX);
}

std::string quoted(const std::string &name) { return "'" + name + "'"; }

/// A C identifier: what a PTX entry and a dlsym'ed function may be named.
bool isIdentifier(const std::string &name) {
  if (name.empty() || name.size() > 1024 ||
      !(std::isalpha((unsigned char)name[0]) || name[0] == '_'))
    return false;
  for (char c : name)
    if (!(std::isalnum((unsigned char)c) || c == '_'))
      return false;
  return true;
}

/// Buffer and Total precision_bytes: 0 (a bundle before the field), 4 or 8.
void checkPrecision(int32_t bytes, const std::string &what) {
  if (bytes != 0 && bytes != 4 && bytes != 8)
    bad(what + " derives from floats of " + std::to_string(bytes) +
        " bytes, not 4 or 8");
}

void checkElement(const schema::Element *element, const std::string &what) {
  if (!element)
    bad(what + " has no element type");
  if (element->scalar() != schema::ScalarType::F32 &&
      element->scalar() != schema::ScalarType::F64)
    bad(what + " has element scalar type " +
        std::to_string(int(element->scalar())) + ", not f32 or f64");
  if (element->lanes() < 1 || element->lanes() > kMaxLanes)
    bad(what + " has " + std::to_string(element->lanes()) +
        " lanes, not 1 to " + std::to_string(kMaxLanes));
}

/// Rejects a repeated name among `names`.
template <typename Entries>
void checkUniqueNames(const Entries &entries, const std::string &what) {
  std::set<std::string> seen;
  for (const auto &entry : entries)
    if (!seen.insert(entry->name).second)
      bad(what + " " + quoted(entry->name) + " is declared twice");
}

template <typename Index>
void checkIndex(Index index, size_t size, const std::string &what) {
  if (index < 0 || uint64_t(index) >= size)
    bad(what + " is " + std::to_string(index) + ", but there are only " +
        std::to_string(size));
}

/// Checks that every index of `indices` names one of `entries`, each at
/// most once; `where` names the list, `kind` its entries.
template <typename Entries>
void checkUniqueIndices(const std::vector<uint32_t> &indices,
                        const Entries &entries, const std::string &where,
                        const std::string &kind) {
  std::set<uint32_t> seen;
  for (uint32_t index : indices) {
    checkIndex(index, entries.size(), where + ": a " + kind);
    if (!seen.insert(index).second)
      bad(where + " lists " + kind + " " + quoted(entries[index]->name) +
          " twice");
  }
}

//===----------------------------------------------------------------------===//
// Scene
//===----------------------------------------------------------------------===//

void verifyScene(const schema::SceneT &scene) {
  std::string what = "scene " + quoted(scene.name);
  if (scene.range < 1 || scene.range > (int64_t(1) << 40))
    bad(what + " has a range of " + std::to_string(scene.range) +
        " items, not 1 to 2^40");
  if (!scene.dt)
    bad(what + " has no dt");
  Value dt = Value::of(*scene.dt);
  if (dt.type != ScalarType::F32 && dt.type != ScalarType::F64)
    bad(what + " has a dt of type " + std::to_string(int(dt.type)) +
        ", not f32 or f64");
  double used = dt.type == ScalarType::F32 ? double(float(dt.f)) : dt.f;
  if (!std::isfinite(used) || !(used > 0))
    bad(what + " has dt " + dt.text() + ", not a positive finite number");
  // As sim_session_set refuses one: a subnormal dt is no time step.
  if (dt.type == ScalarType::F32 ? !std::isnormal(float(dt.f))
                                 : !std::isnormal(dt.f))
    bad(what + " has dt " + dt.text() + ", which is subnormal in " +
        (dt.type == ScalarType::F32 ? "f32" : "f64"));
  if (scene.max_steps < 1 || scene.max_steps > (1 << 20))
    bad(what + " has max_steps " + std::to_string(scene.max_steps) +
        ", not 1 to 2^20");

  checkUniqueNames(scene.params, what + ": parameter");
  for (const auto &param : scene.params) {
    std::string about = what + ": parameter " + quoted(param->name);
    if (param->name == "range" || param->name == "dt" ||
        param->name == "max_steps")
      bad(about + " clashes with the scene's own " + param->name);
    if (!param->value || !valid(param->value->type()))
      bad(about + " has no value of a known type");
    if (param->value->type() == ScalarType::I32 &&
        (param->value->int_value() < INT32_MIN ||
         param->value->int_value() > INT32_MAX))
      bad(about + " has the i32 value " +
          std::to_string(param->value->int_value()) + ", which does not fit");
  }

  checkUniqueNames(scene.buffers, what + ": buffer");
  for (const auto &buffer : scene.buffers) {
    std::string about = what + ": buffer " + quoted(buffer->name);
    checkElement(buffer->element.get(), about);
    if (!valid(buffer->interp))
      bad(about + " has interpolation " + std::to_string(int(buffer->interp)) +
          ", which is not linear, cubic, hermite, none or flux");
    if (!valid(buffer->boundary))
      bad(about + " has boundary rule " +
          std::to_string(int(buffer->boundary)) +
          ", which is not clamp, wrap or zero");
    checkPrecision(buffer->precision_bytes, about);
    if (buffer->interp != Interp::Hermite) {
      if (buffer->derivative != -1)
        bad(about + " names a derivative but is not interpolated by hermite");
      continue;
    }
    checkIndex(buffer->derivative, scene.buffers.size(),
               about + ": its hermite derivative");
    const auto &derivative = scene.buffers[size_t(buffer->derivative)];
    if (derivative->element && *derivative->element != *buffer->element)
      bad(about + " interpolates with the derivative " +
          quoted(derivative->name) + ", whose element type differs");
  }

  checkUniqueNames(scene.totals, what + ": total");
  for (const auto &total : scene.totals) {
    if (total->type != ScalarType::F32 && total->type != ScalarType::F64)
      bad(what + ": total " + quoted(total->name) + " has type " +
          std::to_string(int(total->type)) + ", not f32 or f64");
    checkPrecision(total->precision_bytes,
                   what + ": total " + quoted(total->name));
  }
}

//===----------------------------------------------------------------------===//
// Plans
//===----------------------------------------------------------------------===//

class PlanVerifier {
public:
  PlanVerifier(const schema::SceneT &scene, const schema::PlanT &plan)
      : scene(scene), plan(plan), what(std::string("the plan of strategy '") +
                                       strategyName(plan.strategy) + "'") {}

  void verify() {
    verifyHeader();
    verifyBuffers();
    verifyComponents();
    verifyTotals();
    verifyKernels();
    verifyPhases();
    verifyCode();
  }

private:
  void verifyHeader() {
    if (plan.group_size < 1 || plan.group_size > bundle::kMaxGroupSize)
      bad(what + " is made for groups of " + std::to_string(plan.group_size) +
          ", not 1 to " + std::to_string(bundle::kMaxGroupSize));
    // The cap is the front end's decision; a big step is still 1 to
    // max_steps base steps (the clock counts them up to max_steps).
    if (plan.step_cap < 1 || plan.step_cap > uint32_t(scene.max_steps))
      bad(what + " caps big steps at " + std::to_string(plan.step_cap) +
          " base steps, not 1 to max_steps (" +
          std::to_string(scene.max_steps) + ")");
    if (plan.clock_slots > kMaxClockSlots)
      bad(what + " asks for a clock of " + std::to_string(plan.clock_slots) +
          " slots, more than " + std::to_string(kMaxClockSlots));
    if (plan.distributed && plan.distributed->halo > bundle::kMaxHalo)
      bad(what + " is distributed with a halo of " +
          std::to_string(plan.distributed->halo) + " items, more than " +
          std::to_string(bundle::kMaxHalo));
    if (plan.histogram < kFirstFreeSlot ||
        uint64_t(plan.histogram) + uint64_t(scene.max_steps) + 1 >
            plan.clock_slots)
      bad(what + " puts the histogram of big-step sizes at slot " +
          std::to_string(plan.histogram) + ", which with max_steps " +
          std::to_string(scene.max_steps) +
          " does not fit between the fixed slots and the end of its clock of " +
          std::to_string(plan.clock_slots) + " slots");
  }

  /// Claims clock slots [first, first + count) for `owner`.
  void claimSlots(uint64_t first, uint64_t count, const std::string &owner) {
    if (first < uint64_t(kFirstFreeSlot) || first + count > plan.histogram)
      bad(what + ": " + owner + " uses clock slot " + std::to_string(first) +
          (count > 1 ? " to " + std::to_string(first + count - 1) : "") +
          ", outside the free slots " + std::to_string(kFirstFreeSlot) +
          " to " + std::to_string(int64_t(plan.histogram) - 1));
    for (uint64_t slot = first; slot < first + count; ++slot)
      if (!claimed.insert(slot).second)
        bad(what + ": " + owner + " uses clock slot " + std::to_string(slot) +
            ", which another counter uses too");
  }

  void verifyBuffers() {
    std::set<uint32_t> seen;
    for (const auto &buffer : plan.buffers) {
      checkIndex(buffer->buffer, scene.buffers.size(),
                 what + ": a buffer's scene buffer");
      const auto &sceneBuffer = *scene.buffers[buffer->buffer];
      std::string about = what + ": buffer " + quoted(sceneBuffer.name);
      if (!seen.insert(buffer->buffer).second)
        bad(about + " is listed twice");
      int64_t packed = packedBytes(*sceneBuffer.element);
      if (buffer->stride < packed || buffer->stride > kMaxStride ||
          buffer->stride % scalarBytes(*sceneBuffer.element) != 0)
        bad(about + " has a stride of " + std::to_string(buffer->stride) +
            " bytes, which cannot hold its elements (" +
            elementText(*sceneBuffer.element) + ")");
      uint32_t halo = plan.distributed ? plan.distributed->halo : 0;
      if (!plan.distributed && (buffer->halo_below || buffer->halo_above))
        bad(about + " has a halo (" + std::to_string(buffer->halo_below) +
            " below, " + std::to_string(buffer->halo_above) +
            " above), but the plan is not distributed");
      if (buffer->replicated && !plan.distributed)
        bad(about + " is replicated, but the plan is not distributed");
      // A replicated buffer is whole on every rank: nothing is a ghost.
      if (buffer->replicated && (buffer->halo_below || buffer->halo_above))
        bad(about + " is replicated and has a halo (" +
            std::to_string(buffer->halo_below) + " below, " +
            std::to_string(buffer->halo_above) + " above)");
      if (buffer->halo_below > halo || buffer->halo_above > halo)
        bad(about + " has a halo of " + std::to_string(buffer->halo_below) +
            " below and " + std::to_string(buffer->halo_above) +
            " above, wider than the plan's halo of " + std::to_string(halo));
    }
  }

  void verifyComponents() {
    checkUniqueNames(plan.components, what + ": component");
    std::vector<int> writer(plan.buffers.size(), -1);
    for (size_t c = 0; c < plan.components.size(); ++c) {
      const schema::ComponentT &component = *plan.components[c];
      std::string about = "component " + quoted(component.name);
      if (component.writes.empty())
        bad(what + ": " + about + " writes no buffer");
      for (uint32_t write : component.writes) {
        checkIndex(write, plan.buffers.size(),
                   what + ": a buffer " + about + " writes");
        if (writer[write] >= 0)
          bad(what + ": buffer " + quoted(bufferName(write)) +
              " is written by both " +
              quoted(plan.components[size_t(writer[write])]->name) + " and " +
              quoted(component.name));
        writer[write] = int(c);
      }
      if (!valid(component.advance))
        bad(what + ": " + about + " advances in an unknown way (" +
            std::to_string(int(component.advance)) + ")");
      claimSlots(component.evaluations, 1, about + "'s evaluation counter");
      if (component.advance == Advance::GridSubSteps ||
          component.advance == Advance::LocalSteps)
        claimSlots(component.sub_clock,
                   uint64_t(component.advance == Advance::LocalSteps
                                ? schema::SubClockWidth::LocalSteps
                                : schema::SubClockWidth::GridSubSteps),
                   about + "'s sub-step clock");
      if (component.level_reach != 0 &&
          (component.advance != Advance::LocalSteps || !plan.distributed))
        bad(what + ": " + about +
            " has a level reach, but only a component that takes local time "
            "steps in a distributed plan has one");
      if (component.keeps_levels && component.advance != Advance::LocalSteps)
        bad(what + ": " + about +
            " keeps its levels, but only a component that takes local time "
            "steps has levels");
      if (component.largest_estimate != 0) {
        if (component.advance != Advance::LocalFlux || !component.estimates)
          bad(what + ": " + about +
              " has a largest estimate, but only a pair's writer that "
              "estimates the big step has one");
        claimSlots(component.largest_estimate,
                   uint64_t(schema::LargestEstimateSlot::Slots),
                   about + "'s largest estimate");
      } else if (component.advance == Advance::LocalFlux &&
                 component.estimates) {
        bad(what + ": " + about +
            " estimates the big step as a pair's writer, but has no clock "
            "slots for its largest estimate");
      }
      if (component.keeps_estimate && component.largest_estimate == 0)
        bad(what + ": " + about +
            " keeps its estimate, but has no largest estimate");
    }
  }

  void verifyTotals() {
    checkUniqueIndices(plan.totals, scene.totals, what, "total");
  }

  void verifyKernels() {
    checkUniqueNames(plan.kernels, what + ": kernel");
    for (const auto &kernel : plan.kernels) {
      std::string about = what + ": kernel " + quoted(kernel->name);
      if (!isIdentifier(kernel->name))
        bad(about + " is not named by an identifier");
      if (kernel->clock_slots != plan.clock_slots)
        bad(about + " was made for a clock of " +
            std::to_string(kernel->clock_slots) +
            " slots, but the plan's has " + std::to_string(plan.clock_slots));
      if (kernel->params.size() > 4096)
        bad(about + " takes " + std::to_string(kernel->params.size()) +
            " parameters, more than any kernel does");
      for (size_t p = 0; p < kernel->params.size(); ++p) {
        const schema::KernelParam &param = kernel->params[p];
        std::string which = about + ": parameter " + std::to_string(p);
        if (!valid(param.type()))
          bad(which + " has unknown type " + std::to_string(int(param.type())));
        if (param.type() != ParamType::Memref)
          continue;
        // The clock is a memref of i64; everything else of f32 or f64.
        if (param.element().scalar() != ScalarType::I64)
          checkElement(&param.element(), which);
        if (param.stride() < 1 || param.stride() > kMaxStride)
          bad(which + " has a stride of " + std::to_string(param.stride()) +
              " bytes");
      }
    }
  }

  /// The scene buffer behind plan buffer `index`.
  const schema::BufferT &sceneBuffer(uint32_t index) const {
    return *scene.buffers[plan.buffers[index]->buffer];
  }
  const std::string &bufferName(uint32_t index) const {
    return sceneBuffer(index).name;
  }

  static std::string typeName(const schema::KernelParam &param) {
    switch (param.type()) {
    case ParamType::Memref:
      return "memref<?x" +
             (param.element().scalar() == ScalarType::I64
                  ? std::string("i64")
                  : elementText(param.element())) +
             "> (stride " + std::to_string(param.stride()) + ")";
    case ParamType::I32:
      return "i32";
    case ParamType::I64:
      return "i64";
    case ParamType::F32:
      return "f32";
    case ParamType::F64:
      return "f64";
    }
    return "?";
  }

  /// What a launch passes for `arg`, as a kernel parameter.
  schema::KernelParam expected(const schema::Arg &arg,
                               const std::string &about) const {
    auto memref = [](ScalarType scalar, uint16_t lanes, uint32_t stride) {
      return schema::KernelParam(ParamType::Memref,
                                 schema::Element(scalar, lanes), stride);
    };
    auto scalar = [](ScalarType type) {
      ParamType param = type == ScalarType::I32   ? ParamType::I32
                        : type == ScalarType::F32 ? ParamType::F32
                        : type == ScalarType::F64 ? ParamType::F64
                                                  : ParamType::I64;
      return schema::KernelParam(param, schema::Element(), 0);
    };
    switch (arg.kind()) {
    case ArgKind::Clock:
      return memref(ScalarType::I64, 1, 8);
    case ArgKind::Buffer:
    case ArgKind::Snapshot:
    case ArgKind::Exact: {
      checkIndex(arg.index(), plan.buffers.size(), about + "'s buffer");
      const schema::BufferT &buffer = sceneBuffer(arg.index());
      if (arg.kind() == ArgKind::Snapshot &&
          !plan.buffers[arg.index()]->snapshot)
        bad(about + " passes the snapshot of buffer " + quoted(buffer.name) +
            ", which has none");
      if (arg.kind() == ArgKind::Exact && !buffer.exact)
        bad(about + " passes the exact solution of buffer " +
            quoted(buffer.name) + ", which has none");
      return memref(buffer.element->scalar(), buffer.element->lanes(),
                    plan.buffers[arg.index()]->stride);
    }
    case ArgKind::Total:
      checkIndex(arg.index(), plan.totals.size(), about + "'s total");
      return memref(ScalarType::F64, 1, 8);
    case ArgKind::Levels:
      checkIndex(arg.index(), plan.components.size(), about + "'s component");
      if (plan.components[arg.index()]->advance != Advance::LocalSteps)
        bad(about + " passes the levels of component " +
            quoted(plan.components[arg.index()]->name) +
            ", which does not take local time steps");
      return memref(ScalarType::I64, 1, 8);
    case ArgKind::Param:
      checkIndex(arg.index(), scene.params.size(), about + "'s parameter");
      return scalar(scene.params[arg.index()]->value->type());
    case ArgKind::Range:
      return scalar(ScalarType::I64);
    case ArgKind::Dt:
      return scalar(scene.dt->type());
    case ArgKind::Time:
      return scalar(ScalarType::F64);
    case ArgKind::First:
    case ArgKind::Extent:
      if (!plan.distributed)
        bad(about + " passes the block's " +
            (arg.kind() == ArgKind::First ? "first item" : "extent") +
            ", but the plan is not distributed");
      return scalar(ScalarType::I64);
    }
    bad(about + " has unknown kind " + std::to_string(int(arg.kind())));
  }

  void verifyLaunch(const schema::LaunchT &launch, const std::string &where) {
    checkIndex(launch.kernel, plan.kernels.size(),
               where + ": a launch's kernel");
    const schema::KernelT &kernel = *plan.kernels[launch.kernel];
    std::string about = where + ": the launch of " + quoted(kernel.name);
    if (!valid(launch.shape))
      bad(about + " has unknown shape " + std::to_string(int(launch.shape)));
    if (launch.component != -1)
      checkIndex(launch.component, plan.components.size(),
                 about + ": its component");
    if (launch.shared_per_thread != kernel.shared_per_thread ||
        launch.shared_fixed != kernel.shared_fixed)
      bad(about + " asks for " + std::to_string(launch.shared_per_thread) +
          " bytes of shared memory per thread and " +
          std::to_string(launch.shared_fixed) +
          " fixed, but the kernel needs " +
          std::to_string(kernel.shared_per_thread) + " and " +
          std::to_string(kernel.shared_fixed));
    if (launch.args.size() != kernel.params.size())
      bad(about + " passes " + std::to_string(launch.args.size()) +
          " arguments, but the kernel takes " +
          std::to_string(kernel.params.size()));
    for (size_t a = 0; a < launch.args.size(); ++a) {
      std::string argument = about + ": argument " + std::to_string(a);
      schema::KernelParam want = expected(launch.args[a], argument);
      const schema::KernelParam &have = kernel.params[a];
      bool same = want.type() == have.type();
      if (same && want.type() == ParamType::Memref)
        same =
            want.element() == have.element() && want.stride() == have.stride();
      if (!same)
        bad(argument + " passes " + typeName(want) +
            ", but the kernel's parameter is " + typeName(have));
    }
    if (!plan.distributed &&
        (!launch.reduce_min.empty() || !launch.exchange.empty() ||
         !launch.exchange_targets.empty() ||
         !launch.exchange_sub_step.empty() ||
         !launch.exchange_local_step.empty() ||
         !launch.exchange_local_flux.empty() ||
         !launch.reduce_max_levels.empty()))
      bad(about + " has " +
          (launch.exchange.empty() && launch.exchange_targets.empty() &&
                   launch.exchange_sub_step.empty() &&
                   launch.exchange_local_step.empty() &&
                   launch.exchange_local_flux.empty()
               ? "all-reduces"
               : "exchanges") +
          ", but the plan is not distributed");
    std::set<uint32_t> reducedLevels;
    for (uint32_t c : launch.reduce_max_levels) {
      checkIndex(c, plan.components.size(),
                 about + ": a component whose levels it all-reduces");
      if (plan.components[c]->advance != Advance::LocalSteps)
        bad(about + " all-reduces the levels of component " +
            quoted(plan.components[c]->name) +
            ", which does not take local time steps");
      else if (plan.components[c]->level_reach == 0)
        bad(about + " all-reduces the levels of component " +
            quoted(plan.components[c]->name) +
            ", which has no level reach to say which blocks");
      else if (plan.components[c]->level_reach > (uint64_t(1) << 62))
        bad(about + " all-reduces the levels of component " +
            quoted(plan.components[c]->name) + ", whose level reach " +
            std::to_string(plan.components[c]->level_reach) +
            " is out of range");
      if (!reducedLevels.insert(c).second)
        bad(about + " all-reduces the levels of component " +
            quoted(plan.components[c]->name) + " twice");
    }
    std::set<uint32_t> reduced;
    for (uint32_t slot : launch.reduce_min) {
      if (slot >= plan.clock_slots)
        bad(about + " all-reduces clock slot " + std::to_string(slot) +
            ", but the plan's clock has " + std::to_string(plan.clock_slots) +
            " slots");
      if (!reduced.insert(slot).second)
        bad(about + " all-reduces clock slot " + std::to_string(slot) +
            " twice");
    }
    std::set<std::pair<uint32_t, bool>> exchanged;
    for (const schema::Exchange &entry : launch.exchange) {
      checkIndex(entry.buffer(), plan.buffers.size(),
                 about + ": an exchanged buffer");
      if (entry.snapshot() && !plan.buffers[entry.buffer()]->snapshot)
        bad(about + " exchanges the snapshot of buffer " +
            quoted(bufferName(entry.buffer())) + ", which has none");
      if (!exchanged.insert({entry.buffer(), entry.snapshot()}).second)
        bad(about + " exchanges " +
            (entry.snapshot() ? "the snapshot of buffer " : "buffer ") +
            quoted(bufferName(entry.buffer())) + " twice");
    }
    // Buffers whose ghost items travel one half (or part) of them: each
    // the plan has, and each once after the launch.
    auto checkExchanged = [&](const std::vector<uint32_t> &list,
                              const std::string &what) {
      for (uint32_t b : list) {
        checkIndex(b, plan.buffers.size(), about + ": a buffer " + what);
        if (!exchanged.insert({b, false}).second)
          bad(about + " exchanges buffer " + quoted(bufferName(b)) + " twice");
      }
    };
    checkExchanged(launch.exchange_targets, "whose target half it exchanges");
    if (!launch.exchange_sub_step.empty() &&
        (launch.component < 0 ||
         size_t(launch.component) >= plan.components.size() ||
         plan.components[size_t(launch.component)]->advance !=
             Advance::GridSubSteps))
      bad(about +
          " exchanges the half a sub-step wrote, but it is not a launch of a "
          "component that takes grid-wide sub-steps (whose sub-step clock "
          "says which half)");
    checkExchanged(launch.exchange_sub_step,
                   "whose sub-step's half it exchanges");
    if (!launch.exchange_local_step.empty()) {
      // The runtime reads the slot from the component's sub-step clock
      // (a repeat's) and the blocks' sub-steps from its levels.
      bool localSteps = launch.component >= 0 &&
                        size_t(launch.component) < plan.components.size() &&
                        plan.components[size_t(launch.component)]->advance ==
                            Advance::LocalSteps;
      bool passesLevels = std::any_of(
          launch.args.begin(), launch.args.end(), [&](const schema::Arg &a) {
            return a.kind() == ArgKind::Levels &&
                   int64_t(a.index()) == int64_t(launch.component);
          });
      if (!localSteps || !passesLevels || !insideRepeat)
        bad(about +
            " exchanges the blocks a slot wrote, but it is not a slot launch "
            "(in a repeat) of a component that takes local time steps, "
            "passing its levels (which say which blocks and halves)");
    }
    checkExchanged(launch.exchange_local_step,
                   "whose slot's blocks it exchanges");
    if (!launch.exchange_local_flux.empty()) {
      // The runtime reads the slot from the sub-step clock of the flux
      // pair's reader and its blocks' sub-steps from its levels: the one
      // Levels argument of the writer's slot launch.
      bool fluxWriter = launch.component >= 0 &&
                        size_t(launch.component) < plan.components.size() &&
                        plan.components[size_t(launch.component)]->advance ==
                            Advance::LocalFlux;
      int levels = 0;
      bool readerTakesLocalSteps = true;
      for (const schema::Arg &a : launch.args)
        if (a.kind() == ArgKind::Levels) {
          ++levels;
          readerTakesLocalSteps =
              readerTakesLocalSteps && a.index() < plan.components.size() &&
              plan.components[a.index()]->advance == Advance::LocalSteps;
        }
      if (!fluxWriter || levels != 1 || !readerTakesLocalSteps || !insideRepeat)
        bad(about +
            " exchanges the blocks a slot's fluxes are due in, but it is not "
            "a slot launch (in a repeat) of a flux writer passing the levels "
            "of one component that takes local time steps (which say which "
            "blocks)");
    }
    checkExchanged(launch.exchange_local_flux,
                   "whose slot's due fluxes it exchanges");
  }

  /// Verifies `steps` and counts the launches they unroll to into `count`.
  void verifySteps(const std::vector<std::unique_ptr<schema::StepT>> &steps,
                   const std::string &where, uint64_t times, uint64_t &count) {
    for (const auto &step : steps) {
      if (bool(step->launch) == bool(step->repeat))
        bad(where + " has a step that is not exactly one of a launch and a "
                    "repeat");
      if (step->launch) {
        verifyLaunch(*step->launch, where);
        count += times;
      } else {
        if (step->repeat->count < 1)
          bad(where + " repeats a block 0 times");
        uint64_t inner = times * uint64_t(step->repeat->count);
        if (inner > uint64_t(kMaxPhaseLaunches))
          bad(where + " repeats its launches more than " +
              std::to_string(kMaxPhaseLaunches) + " times");
        bool outer = insideRepeat;
        insideRepeat = true;
        verifySteps(step->repeat->body, where, inner, count);
        insideRepeat = outer;
      }
      if (count > uint64_t(kMaxPhaseLaunches))
        bad(where + " unrolls to more than " +
            std::to_string(kMaxPhaseLaunches) + " launches");
    }
  }

  void verifyPhases() {
    std::set<PhaseKind> seen;
    for (const auto &phase : plan.phases) {
      if (!valid(phase->kind))
        bad(what + " has a phase of unknown kind " +
            std::to_string(int(phase->kind)));
      std::string where = what + ", phase " + phaseName(phase->kind);
      if (!seen.insert(phase->kind).second)
        bad(what + " has two " + phaseName(phase->kind) + " phases");
      uint64_t count = 0;
      verifySteps(phase->body, where, 1, count);
      if (phase->kind == PhaseKind::Step && count == 0)
        bad(where + " launches nothing");
    }
    for (PhaseKind required :
         {PhaseKind::Init, PhaseKind::Step, PhaseKind::Finish})
      if (!seen.count(required))
        bad(what + " has no " + phaseName(required) + " phase");
  }

  void verifyCode() {
    if (plan.ptx.empty() && !plan.ptx_chip.empty())
      bad(what + " names the chip " + quoted(plan.ptx_chip) +
          " of PTX it does not have");
    std::set<std::string> isas;
    for (const auto &code : plan.cpu) {
      if (!isas.insert(code->isa).second)
        bad(what + " has two CPU objects for " + quoted(code->isa));
      checkElfImage(code->object,
                    "the CPU kernels (" + code->isa + ") of " + what);
    }
  }

  const schema::SceneT &scene;
  const schema::PlanT &plan;
  std::string what;
  std::set<uint64_t> claimed;
  /// Whether verifySteps is inside a repeat (a slot or a round).
  bool insideRepeat = false;
};

//===----------------------------------------------------------------------===//
// Reference model
//===----------------------------------------------------------------------===//

void verifyReference(const schema::SceneT &scene,
                     const schema::ReferenceT &reference) {
  const std::string what = "the reference model";
  checkUniqueIndices(reference.params, scene.params, what, "parameter");
  checkUniqueIndices(reference.buffers, scene.buffers, what, "buffer");
  // Scene buffer -> model buffer, to resolve Hermite derivatives.
  std::vector<int> modelBuffer(scene.buffers.size(), -1);
  for (size_t b = 0; b < reference.buffers.size(); ++b)
    modelBuffer[reference.buffers[b]] = int(b);
  for (uint32_t buffer : reference.buffers) {
    const schema::BufferT &info = *scene.buffers[buffer];
    if (info.interp == Interp::Hermite &&
        modelBuffer[size_t(info.derivative)] < 0)
      bad(what + ": buffer " + quoted(info.name) +
          " interpolates with the derivative " +
          quoted(scene.buffers[size_t(info.derivative)]->name) +
          ", which is not a buffer of the model");
  }
  checkUniqueNames(reference.components, what + ": component");
  std::vector<int> writer(reference.buffers.size(), -1);
  for (size_t c = 0; c < reference.components.size(); ++c) {
    const schema::RefComponentT &component = *reference.components[c];
    std::string about = what + ": component " + quoted(component.name);
    if (!valid(component.sub_stepping))
      bad(about + " has an unknown sub-stepping verdict");
    if (component.writes.empty())
      bad(about + " writes no buffer");
    for (uint32_t write : component.writes) {
      checkIndex(write, reference.buffers.size(),
                 about + ": a buffer it writes");
      if (writer[write] >= 0)
        bad(what + ": buffer " +
            quoted(scene.buffers[reference.buffers[write]]->name) +
            " is written by both " +
            quoted(reference.components[size_t(writer[write])]->name) +
            " and " + quoted(component.name));
      writer[write] = int(c);
    }
    std::set<uint32_t> reads;
    for (uint32_t read : component.reads) {
      checkIndex(read, reference.buffers.size(), about + ": a buffer it reads");
      if (!reads.insert(read).second)
        bad(about + " lists a read of " +
            quoted(scene.buffers[reference.buffers[read]]->name) + " twice");
    }
    if (component.stepping.size() != size_t(kNumStrategies))
      bad(about + " says how it steps under " +
          std::to_string(component.stepping.size()) + " strategies, not " +
          std::to_string(kNumStrategies));
    for (int s = 0; s < kNumStrategies; ++s) {
      const schema::Stepping &stepping = component.stepping[size_t(s)];
      std::string under = about + " under " + strategyName(Strategy(s));
      if (!valid(stepping.advance()))
        bad(under + " advances in an unknown way");
      // A pair's reader without num_steps takes its blocks' steps from
      // the writer's.
      if (!component.num_steps &&
          (stepping.estimates() || (stepping.advance() != Advance::WholeStep &&
                                    stepping.advance() != Advance::LocalFlux &&
                                    stepping.advance() != Advance::LocalSteps)))
        bad(under + " estimates or sub-steps, but it has no num_steps");
      if (stepping.advance() == Advance::LocalSteps &&
          (component.local_window.size() != 2 ||
           component.local_window[0] > 0 || component.local_window[1] < 0))
        bad(under + " takes local time steps without a window [lo, hi] "
                    "with lo <= 0 <= hi");
      if (stepping.advance() == Advance::LocalFlux &&
          (component.flux_window.size() != 2 ||
           component.flux_window[0] > component.flux_window[1]))
        bad(under + " writes the fluxes of a flux pair without a window "
                    "[lo, hi] with lo <= hi");
    }
  }
  if (reference.step_caps.size() != size_t(kNumStrategies))
    bad(what + " gives the largest big step of " +
        std::to_string(reference.step_caps.size()) + " strategies, not " +
        std::to_string(kNumStrategies));
  for (int s = 0; s < kNumStrategies; ++s) {
    uint32_t cap = reference.step_caps[size_t(s)];
    if (cap < 1 || cap > uint32_t(scene.max_steps))
      bad(what + " caps big steps under " + strategyName(Strategy(s)) + " at " +
          std::to_string(cap) + " base steps, not 1 to max_steps (" +
          std::to_string(scene.max_steps) + ")");
  }
  for (const auto &total : reference.totals) {
    checkIndex(total->total, scene.totals.size(), what + ": a total");
    for (uint32_t read : total->reads)
      checkIndex(read, reference.buffers.size(),
                 what + ": a buffer total " +
                     quoted(scene.totals[total->total]->name) + " reads");
  }
  checkElfImage(reference.object, "the reference functions");
}

} // namespace

void verifyBundle(const schema::BundleT &contents) {
  if (!contents.scene)
    bad("there is no scene");
  const schema::SceneT &scene = *contents.scene;
  verifyScene(scene);
  if (contents.subnormals != schema::Subnormals::Keep &&
      contents.subnormals != schema::Subnormals::FlushToZero)
    bad("the bundle has unknown floating-point mode " +
        std::to_string(int(contents.subnormals)));
  std::set<Strategy> strategies;
  for (const auto &plan : contents.plans) {
    if (!valid(plan->strategy))
      bad("a plan has unknown strategy " + std::to_string(int(plan->strategy)));
    if (!strategies.insert(plan->strategy).second)
      bad(std::string("there are two plans of strategy '") +
          strategyName(plan->strategy) + "'");
    PlanVerifier(scene, *plan).verify();
  }
  if (contents.reference)
    verifyReference(scene, *contents.reference);
}

} // namespace sim::rt
