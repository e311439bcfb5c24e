//===- Session.cpp - the plan executor ------------------------------------===//
//
// Executes docs/Plan.md. The host never decides a step size: it writes the
// end of a run into clock slot 3, launches the step phase K times ahead
// (K = remaining base steps / the mean big step seen so far, starting from
// the largest possible one), reads T + m once per batch, and stops when the
// clock reaches the end. Kernels of big steps past the end do nothing, so
// launching ahead is safe.
//
//===----------------------------------------------------------------------===//

#include "Session.h"
#include "Error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <set>

namespace sim::rt {

namespace {

/// Step phases launched between two looks at the clock, at most: enough to
/// hide the host round trip, few enough to keep progress reports and the
/// driver's launch queue reasonable.
constexpr int64_t kMaxBatch = 256;
/// With a progress callback, a batch takes about this long at most (the
/// first, whose time is not known yet, this many step phases), so that the
/// callback comes that often however long a big step takes.
constexpr double kProgressBatchSeconds = 0.25;
constexpr int64_t kFirstProgressBatch = 8;

/// Calls `copy(first, count)` for each run of consecutive elements in
/// `elements`, in order: ghost lists are mostly a few runs, and each run is
/// one backend copy.
template <typename Copy>
void forEachRun(const std::vector<int64_t> &elements, Copy copy) {
  size_t i = 0;
  while (i < elements.size()) {
    size_t j = i + 1;
    while (j < elements.size() && elements[j] == elements[j - 1] + 1)
      ++j;
    copy(elements[i], int64_t(j - i));
    i = j;
  }
}

} // namespace

Session::Session(std::shared_ptr<const Bundle> bundleIn,
                 const sim_session_options &optionsIn)
    : bundle(std::move(bundleIn)), options(optionsIn), settings(*bundle) {
  if (uint32_t(options.strategy) >= kNumStrategies)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "unknown strategy " + std::to_string(int(options.strategy)));
  // Before the backend is chosen: a bad value is refused wherever the
  // session would land (auto on CUDA included).
  checkCpuThreads(options.cpu_threads);
  Strategy strategy = Strategy(options.strategy);
  std::string name = strategyName(strategy);
  plan_ = bundle->plan(strategy);
  if (!plan_) {
    std::vector<std::string> present;
    for (Strategy s : bundle->strategies())
      present.push_back(strategyName(s));
    // The strategy is the caller's choice among those the bundle has.
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "bundle '" + bundle->name + "' has no plan for strategy '" + name +
             "' (it has: " + listNames(present) + ")");
  }
  bool hasPtx = !plan_->ptx.empty();
  const schema::CpuCodeT *cpu = bundle->cpuCode(*plan_);

  // Distributed plans run on every rank with the same code, on either
  // backend: the ghost items move through the backend's reads and writes.
  if (options.communicator && !plan_->distributed)
    fail(SIM_ERROR_BUNDLE,
         "bundle '" + bundle->name +
             "' was not compiled for distributed runs: compile it with "
             "sim-translate --sim-distributed");
  if (plan_->distributed) {
    comm = std::make_unique<Communicator>(options.communicator);
    halo = int64_t(plan_->distributed->halo);
  }

  auto noCode = [&](const char *what, const char *backendName) {
    fail(SIM_ERROR_BUNDLE, "bundle '" + bundle->name + "' has no " + what +
                               " for strategy '" + name + "'; the " +
                               backendName + " backend needs it");
  };
  switch (options.backend) {
  case SIM_BACKEND_CUDA:
    if (!hasPtx)
      noCode("PTX", "CUDA");
    backend = createCudaBackend(options.cuda_device);
    break;
  case SIM_BACKEND_AUTO:
    if (!hasPtx) {
      note = "the bundle has no PTX for strategy '" + name + "'";
    } else {
      try {
        backend = createCudaBackend(options.cuda_device);
      } catch (const Error &error) {
        if (error.status != SIM_ERROR_NO_DRIVER &&
            error.status != SIM_ERROR_NO_DEVICE)
          throw;
        note = error.what();
      }
    }
    if (!backend && !cpu)
      fail(SIM_ERROR_BUNDLE, "cannot run strategy '" + name + "' of bundle '" +
                                 bundle->name + "': " + note + ", and " +
                                 missingIsaMessage(*plan_));
    if (!backend)
      backend = createCpuBackend(options.cpu_threads);
    break;
  case SIM_BACKEND_CPU:
    if (!cpu)
      fail(SIM_ERROR_BUNDLE, "cannot run strategy '" + name + "' of bundle '" +
                                 bundle->name +
                                 "' on the CPU: " + missingIsaMessage(*plan_));
    backend = createCpuBackend(options.cpu_threads);
    break;
  default:
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "unknown backend " + std::to_string(int(options.backend)));
  }
  setMemoryLimit(options.max_memory, backend->memoryBytes());
  groupSize_ = options.group_size ? options.group_size : plan_->group_size;
  // The bundle's group size, which the caller did not choose, is named as
  // such, with the way to choose another.
  try {
    backend->checkGroupSize(groupSize_);
  } catch (const Error &error) {
    if (options.group_size || error.status != SIM_ERROR_INVALID_ARGUMENT)
      throw;
    fail(error.status, std::string(error.what()) +
                           " (the bundle's group size, from " +
                           "sim-translate --sim-group-size; choose another "
                           "for the session: sim-run --group-size)");
  }
  backend->load(*bundle, *plan_);
  // Again with the kernels loaded: CUDA knows each kernel's thread limit.
  backend->checkGroupSize(groupSize_);
  // And the shared memory hip-cache's caches ask for at this group size:
  // refused here rather than at the first launch of the run.
  for (const auto &phase : plan_->phases)
    for (const schema::LaunchT *launch : unrollPhase(*phase))
      if (launch->shape != LaunchShape::Single)
        backend->checkSharedMemory(int(launch->kernel),
                                   int64_t(launch->shared_per_thread),
                                   int64_t(launch->shared_fixed), groupSize_);
  // After load: the CPU backend names the instruction-set level it loaded.
  deviceName = backend->device();
  for (const auto &phase : plan_->phases)
    hasPhase[int(phase->kind)] = true;

  evaluations.assign(plan_->components.size(), 0);
  histogram.assign(size_t(scene().max_steps) + 1, 0);
  for (const auto &kernel : plan_->kernels)
    kernelFigures.push_back({kernel->name, 0, -1});
  if (distributed())
    ensureAgreed();
}

Session::~Session() {
  try {
    backend->activate();
  } catch (const Error &) {
    // Freeing below fails quietly too; nothing else to do.
  }
  releaseAll();
}

//===----------------------------------------------------------------------===//
// Values
//===----------------------------------------------------------------------===//

void Session::set(const std::string &name, const std::string &text) {
  bool rangeChanged = settings.set(name, text, [&](int64_t range) {
    checkMemory(range, "range " + std::to_string(range));
  });
  if (rangeChanged) {
    // The state of another size is meaningless: start over.
    backend->activate();
    releaseAll();
  } else {
    forgetKeptLevels();
  }
  // dt and parameters are launch arguments.
  prepared = false;
  agreed = false;
}

void Session::forgetKeptLevels() {
  // The levels a keeps_levels component kept came from num_steps at the
  // old dt and parameters; the state stays, the levels must be
  // computed again. Between runs the session is at the end of a big step,
  // where zeroed levels are what init leaves: levels_C computes every
  // block's code afresh in the next big step and limit_levels_C keeps them
  // again.
  if (!allocated)
    return;
  bool any = false;
  for (size_t c = 0; c < plan_->components.size(); ++c) {
    if (!plan_->components[c]->keeps_levels || !levels[c].pointer)
      continue;
    if (!any)
      backend->activate();
    any = true;
    backend->zero(levels[c].pointer, levels[c].bytes);
    if (c < levelsKept.size())
      levelsKept[c] = false;
    // Its unit request came from the same num_steps (local_parity_C never
    // clears a component's that keeps its levels).
    int64_t none = 0;
    backend->write(subClockSlot(c, schema::SubClockSlot::UnitRequest), &none,
                   sizeof none);
  }
  // A kept largest estimate (keeps_estimate) came from the same num_steps:
  // 0 in its Kept slot has the next big step take it again.
  for (const auto &component : plan_->components) {
    if (!component->keeps_estimate)
      continue;
    if (!any)
      backend->activate();
    any = true;
    uint32_t kept = component->largest_estimate +
                    uint32_t(schema::LargestEstimateSlot::Kept);
    backend->zero(clockMemory.pointer + kept * sizeof(int64_t),
                  sizeof(int64_t));
    estimatesKept.erase(component->largest_estimate);
  }
}

int Session::bufferIndex(const std::string &name) const {
  for (size_t i = 0; i < plan_->buffers.size(); ++i)
    if (sceneBuffer(i).name == name)
      return int(i);
  std::vector<std::string> names;
  for (size_t i = 0; i < plan_->buffers.size(); ++i)
    names.push_back(sceneBuffer(i).name);
  fail(SIM_ERROR_INVALID_ARGUMENT,
       "'" + name + "' is not a buffer of the plan of strategy '" +
           strategyName(plan_->strategy) + "' (buffers: " + listNames(names) +
           ")");
}

size_t Session::deviceStride(int buffer) const {
  return size_t(plan_->buffers[buffer]->stride);
}

int64_t Session::extentAt(int64_t range) const {
  if (!distributed())
    return range;
  Decomposition split(range, groupSize_, comm->size());
  return split.count(comm->rank()) + 2 * halo;
}

int64_t Session::memoryBytes(int64_t globalRange) const {
  // This rank's share: a distributed session's limit is per rank.
  int64_t range = extentAt(globalRange);
  int64_t bytes = saturatingMul(plan_->clock_slots, sizeof(int64_t));
  for (size_t i = 0; i < plan_->buffers.size(); ++i) {
    const schema::PlanBufferT &buffer = *plan_->buffers[i];
    int64_t copies =
        2 + int64_t(buffer.snapshot) + int64_t(sceneBuffer(i).exact);
    // Every rank holds all of a replicated buffer.
    int64_t elements = replicated(i) ? globalRange : range;
    bytes = saturatingAdd(
        bytes, saturatingMul(saturatingMul(elements, buffer.stride), copies));
  }
  for (const auto &component : plan_->components)
    if (component->advance == Advance::LocalSteps)
      bytes = saturatingAdd(
          bytes, saturatingMul(levelCount(range), int64_t(sizeof(int64_t))));
  return saturatingAdd(bytes,
                       saturatingMul(saturatingMul(range, sizeof(double)),
                                     int64_t(plan_->totals.size())));
}

size_t Session::hostBytes(const std::string &name) const {
  return size_t(settings.range) *
         size_t(packedBytes(*sceneBuffer(size_t(bufferIndex(name))).element));
}

//===----------------------------------------------------------------------===//
// Memory and launches
//===----------------------------------------------------------------------===//

void Session::allocate() {
  // Before anything a rank could refuse alone (the range's blocks): ranks
  // with different ranges would otherwise part ways here.
  if (distributed())
    ensureAgreed();
  checkMemory(settings.range, "range " + std::to_string(settings.range));
  layout();
  auto take = [&](size_t bytes) {
    Memory memory{backend->allocate(bytes), bytes};
    return memory;
  };
  clockMemory = take(size_t(plan_->clock_slots) * sizeof(int64_t));
  for (size_t i = 0; i < plan_->buffers.size(); ++i) {
    size_t half = size_t(elementsOf(i)) * deviceStride(int(i));
    buffers.push_back(take(2 * half));
    snapshots.push_back(plan_->buffers[i]->snapshot ? take(half) : Memory{});
    exacts.push_back(sceneBuffer(i).exact ? take(half) : Memory{});
  }
  for (size_t i = 0; i < plan_->totals.size(); ++i)
    totalValues.push_back(take(size_t(extent) * sizeof(double)));
  for (const auto &component : plan_->components)
    levels.push_back(component->advance == Advance::LocalSteps
                         ? take(size_t(levelCount()) * sizeof(int64_t))
                         : Memory{});
  clock.assign(size_t(plan_->clock_slots), 0);
  allocated = true;
}

void Session::releaseAll() {
  backend->dropGraph();
  graphReady = false;
  auto give = [&](Memory &memory) {
    if (memory.pointer)
      backend->release(memory.pointer);
    memory = {};
  };
  give(clockMemory);
  for (std::vector<Memory> *list :
       {&buffers, &snapshots, &exacts, &totalValues, &levels}) {
    for (Memory &memory : *list)
      give(memory);
    list->clear();
  }
  clock.clear();
  ghostCache.clear();
  slotSelections.clear();
  levelListsCache.clear();
  allocated = initialized = prepared = false;
}

void Session::prepare() {
  if (prepared)
    return;
  if (distributed())
    ensureAgreed();
  backend->dropGraph();
  graphReady = false;
  launches.clear();
  // Every launch once; phases refer to them by index, so a repeat costs an
  // index per unrolled launch.
  std::map<const schema::LaunchT *, uint32_t> index;
  for (int phase = 0; phase < kNumPhases; ++phase)
    phases[phase].clear();
  // The launches of each repeat, and the component whose sub-step clock
  // runs it (the one that takes grid-wide or local sub-steps).
  std::map<const schema::LaunchT *, int> roundOf;
  for (const auto &phase : plan_->phases)
    for (const auto &step : phase->body) {
      if (!step->repeat)
        continue;
      int clockOf = -1;
      for (const auto &inner : step->repeat->body)
        if (inner->launch && inner->launch->component >= 0) {
          Advance advance =
              plan_->components[size_t(inner->launch->component)]->advance;
          if (advance == Advance::GridSubSteps ||
              advance == Advance::LocalSteps)
            clockOf = inner->launch->component;
        }
      for (const auto &inner : step->repeat->body)
        if (inner->launch)
          roundOf[inner->launch.get()] = clockOf;
    }
  for (const auto &phase : plan_->phases) {
    std::vector<uint32_t> &order = phases[int(phase->kind)];
    for (const schema::LaunchT *launch : unrollPhase(*phase)) {
      auto [it, inserted] = index.try_emplace(launch, launches.size());
      if (inserted) {
        launches.push_back(prepareLaunch(*launch));
        if (auto found = roundOf.find(launch); found != roundOf.end())
          launches.back().roundOf = found->second;
      }
      order.push_back(it->second);
    }
  }
  // The values are final: point at them (each Prepared owns its vector,
  // and moving a vector keeps its storage).
  for (Prepared &p : launches) {
    p.params.clear();
    for (uint64_t &value : p.values)
      p.params.push_back(&value);
  }
  prepared = true;
}

Session::Prepared Session::prepareLaunch(const schema::LaunchT &launch) {
  Prepared p;
  p.launch = &launch;
  p.kernel = int(launch.kernel);
  bool single = launch.shape == LaunchShape::Single;
  p.groupSize = single ? 1 : groupSize_;
  p.groups = single ? 1 : (count + groupSize_ - 1) / groupSize_;
  p.sharedBytes =
      int64_t(launch.shared_per_thread) * p.groupSize + launch.shared_fixed;
  // A memref travels as its descriptor: allocated pointer, aligned
  // pointer, offset, size, stride.
  auto memref = [&](DevicePtr pointer, int64_t elements) {
    p.values.insert(p.values.end(),
                    {pointer, pointer, 0, uint64_t(elements), 1});
  };
  for (const schema::Arg &arg : launch.args) {
    switch (arg.kind()) {
    case ArgKind::Clock:
      memref(clockMemory.pointer, plan_->clock_slots);
      break;
    case ArgKind::Buffer:
      memref(buffers[arg.index()].pointer, 2 * elementsOf(arg.index()));
      break;
    case ArgKind::Snapshot:
      memref(snapshots[arg.index()].pointer, elementsOf(arg.index()));
      break;
    case ArgKind::Exact:
      memref(exacts[arg.index()].pointer, elementsOf(arg.index()));
      break;
    case ArgKind::Total:
      memref(totalValues[arg.index()].pointer, extent);
      break;
    case ArgKind::Levels:
      memref(levels[arg.index()].pointer, levelCount());
      break;
    case ArgKind::Param:
      p.values.push_back(settings.params[arg.index()].bits());
      break;
    case ArgKind::Range:
      p.values.push_back(uint64_t(settings.range));
      break;
    case ArgKind::Dt:
      p.values.push_back(settings.dt.bits());
      break;
    case ArgKind::Time:
      p.timeValues.push_back(p.values.size());
      p.values.push_back(0);
      break;
    case ArgKind::First:
      p.values.push_back(uint64_t(first));
      break;
    case ArgKind::Extent:
      p.values.push_back(uint64_t(extent));
      break;
    }
  }
  if (distributed()) {
    for (const schema::Exchange &entry : launch.exchange)
      p.exchanges.push_back(refreshOf(entry.buffer(), entry.snapshot()));
    for (uint32_t buffer : launch.exchange_targets) {
      p.exchanges.push_back(refreshOf(buffer, false));
      p.exchanges.back().half = GhostRefresh::Half::Target;
    }
    for (uint32_t buffer : launch.exchange_sub_step) {
      p.exchanges.push_back(refreshOf(buffer, false));
      p.exchanges.back().half = GhostRefresh::Half::SubStep;
    }
    for (uint32_t buffer : launch.exchange_local_step) {
      p.exchanges.push_back(refreshOf(buffer, false));
      // A replicated buffer travels whole (an all-gather of both halves).
      if (!p.exchanges.back().replicated)
        p.exchanges.back().half = GhostRefresh::Half::LocalStep;
    }
    for (uint32_t buffer : launch.exchange_local_flux) {
      p.exchanges.push_back(refreshOf(buffer, false));
      if (!p.exchanges.back().replicated)
        p.exchanges.back().half = GhostRefresh::Half::LocalFlux;
    }
  }
  return p;
}

void Session::launch(Prepared &p) {
  backend->launch(p.kernel, p.params.data(), p.groups, p.groupSize,
                  p.sharedBytes);
  ++metrics.launches;
  ++kernelFigures[size_t(p.kernel)].launches;
}

void Session::runPhase(PhaseKind phase) {
  if (distributed()) {
    for (uint32_t index : phases[int(phase)])
      launchDistributed(launches[index], true);
    endGhosts();
    return;
  }
  for (uint32_t index : phases[int(phase)])
    launch(launches[index]);
}

void Session::runUncounted(PhaseKind phase) {
  if (distributed()) {
    for (uint32_t index : phases[int(phase)])
      launchDistributed(launches[index], false);
    endGhosts();
    return;
  }
  for (uint32_t index : phases[int(phase)]) {
    Prepared &p = launches[index];
    backend->launch(p.kernel, p.params.data(), p.groups, p.groupSize,
                    p.sharedBytes);
  }
}

void Session::runStepPhase() {
  const std::vector<uint32_t> &step = phases[int(PhaseKind::Step)];
  if (distributed()) {
    for (uint32_t index : step) {
      Prepared &p = launches[index];
      launchDistributed(p, true, true);
      if (options.check_finite && p.launch->component >= 0) {
        endGhosts();
        checkFinite(p);
      }
    }
    endGhosts();
    return;
  }
  if (options.check_finite) {
    for (uint32_t index : step) {
      Prepared &p = launches[index];
      // Where in the big step a sub-step or slot kernel starts, for the
      // message: it moves the sub-step clock on.
      std::optional<SubStepTimes> before;
      if (p.launch->component >= 0 && p.roundOf >= 0 &&
          p.launch->shape != LaunchShape::Single)
        before = subStepTimes(p.roundOf);
      launch(p);
      if (p.launch->component >= 0)
        checkFinite(p, before);
    }
    return;
  }
  if (options.cuda_graph && backend->supportsGraphs()) {
    // The step phase is the same every big step (docs/Plan.md): record it
    // once, replay it.
    if (!graphReady) {
      backend->beginCapture();
      for (uint32_t index : step) {
        Prepared &p = launches[index];
        backend->launch(p.kernel, p.params.data(), p.groups, p.groupSize,
                        p.sharedBytes);
      }
      backend->endCapture();
      graphReady = true;
    }
    backend->replay();
    metrics.launches += int64_t(step.size());
    for (uint32_t index : step)
      ++kernelFigures[size_t(launches[index].kernel)].launches;
    ++metrics.graph_launches;
    return;
  }
  // Where the host sees the clock for free, the rounds and slots that
  // would change nothing (those after a component's last sub-step of the
  // big step) are not launched.
  bool skipNoOps = backend->launchesSynchronously();
  for (uint32_t index : step) {
    Prepared &p = launches[index];
    if (!skipNoOps || !noOpLaunch(p))
      launch(p);
  }
}

void Session::readClock(size_t slots) {
  backend->read(clock.data(), clockMemory.pointer, slots * sizeof(int64_t));
}

std::string
Session::subStepNote(int component,
                     const std::optional<SubStepTimes> &before) const {
  if (!before || before->subBegin < before->begin ||
      before->subBegin >= before->begin + before->size)
    return "";
  // A slot kernel: each block that starts at the slot takes its own
  // sub-step from there.
  if (plan_->components[size_t(component)]->advance == Advance::LocalSteps)
    return ", in the slot at base step " + std::to_string(before->subBegin);
  // A grid round: the sub-step [t, t + n] of every item.
  if (before->subSize > 0)
    return ", sub-step from " + std::to_string(before->subBegin) + " to " +
           std::to_string(before->subBegin + before->subSize);
  return "";
}

void Session::checkFinite(const Prepared &p,
                          const std::optional<SubStepTimes> &before) {
  const schema::ComponentT &component =
      *plan_->components[size_t(p.launch->component)];
  // Per buffer written, its first non-finite value in the order half,
  // item, lane, as the key (half * range + item) * lanes + lane (none:
  // INT64_MAX): a distributed session's ranks agree on the smallest, so
  // they all report what one process would.
  std::vector<int64_t> keys;
  std::vector<double> values;
  for (uint32_t index : component.writes) {
    const schema::Element &type = *sceneBuffer(index).element;
    size_t stride = deviceStride(int(index));
    std::vector<uint8_t> data(buffers[index].bytes);
    backend->read(data.data(), buffers[index].pointer, data.size());
    ++metrics.host_syncs;
    int64_t key = std::numeric_limits<int64_t>::max();
    double found = 0;
    // Both halves: the target just written, and the source, which holds
    // the initial state the first time round. Ghost elements (and the
    // other ranks' items of a replicated buffer) are copies: each rank
    // looks at its own items only.
    int64_t elements = elementsOf(index), own = ownElement(index);
    for (int64_t half = 0;
         half < 2 && key == std::numeric_limits<int64_t>::max(); ++half) {
      for (int64_t i = 0; i < count; ++i) {
        const uint8_t *item =
            data.data() + size_t(half * elements + own + i) * stride;
        int32_t lane = 0;
        double value = 0;
        for (; lane < int32_t(type.lanes()); ++lane) {
          if (isF64(type)) {
            std::memcpy(&value, item + lane * 8, 8);
          } else {
            float single;
            std::memcpy(&single, item + lane * 4, 4);
            value = single;
          }
          if (!std::isfinite(value))
            break;
        }
        if (lane == int32_t(type.lanes()))
          continue;
        key =
            (half * settings.range + first + i) * int64_t(type.lanes()) + lane;
        found = value;
        break;
      }
    }
    keys.push_back(key);
    values.push_back(found);
  }
  std::vector<int64_t> mine = keys;
  if (distributed())
    comm->minimum(keys.data(), int32_t(keys.size()));
  size_t w = 0;
  while (w < keys.size() && keys[w] == std::numeric_limits<int64_t>::max())
    ++w;
  if (w == keys.size())
    return;
  double value = values[w];
  if (distributed()) {
    // The rank that holds the item tells the others its value.
    int64_t bits = 0;
    if (mine[w] == keys[w])
      std::memcpy(&bits, &value, sizeof bits);
    comm->sum(&bits, 1);
    std::memcpy(&value, &bits, sizeof bits);
  }
  uint32_t index = component.writes[w];
  const schema::BufferT &buffer = sceneBuffer(index);
  const schema::Element &type = *buffer.element;
  int32_t lane = int32_t(keys[w] % int64_t(type.lanes()));
  int64_t item = keys[w] / int64_t(type.lanes()) % settings.range;
  readClock(2);
  nonFinite.found = true;
  nonFinite.baseStep = clock[kSlotBegin];
  nonFinite.component = component.name;
  nonFinite.buffer = buffer.name;
  nonFinite.kernel = plan_->kernels[p.launch->kernel]->name;
  nonFinite.item = item;
  nonFinite.lane = lane;
  nonFinite.value = value;
  std::string where = "item " + std::to_string(nonFinite.item);
  if (type.lanes() > 1)
    where += ", lane " + std::to_string(lane);
  fail(SIM_ERROR_NONFINITE,
       "non-finite value " +
           std::string(std::isnan(value) ? "nan"
                       : value > 0       ? "inf"
                                         : "-inf") +
           " in buffer '" + buffer.name + "' (" + where + ") after kernel '" +
           nonFinite.kernel + "' for component '" + component.name +
           "' at base step " + std::to_string(nonFinite.baseStep) +
           " (big step of " + std::to_string(clock[kSlotSize]) +
           subStepNote(p.roundOf, before) + ")");
}

//===----------------------------------------------------------------------===//
// Phases
//===----------------------------------------------------------------------===//

void Session::init() {
  // Every rank makes this call: agree on the values first (as run does).
  if (distributed()) {
    agreed = false;
    ensureAgreed();
  }
  backend->activate();
  if (!allocated) {
    allocate();
  } else {
    // Every run from the initial state starts from the same memory. The
    // addresses stay, so a captured step phase stays valid.
    backend->zero(clockMemory.pointer, clockMemory.bytes);
    for (std::vector<Memory> *list :
         {&buffers, &snapshots, &exacts, &totalValues, &levels})
      for (Memory &memory : *list)
        if (memory.pointer)
          backend->zero(memory.pointer, memory.bytes);
  }
  // The levels were zeroed (or just allocated), kept codes included, and
  // the clock with them, kept estimates included.
  levelsKept.assign(plan_->components.size(), false);
  estimatesKept.clear();
  prepare();
  runUncounted(PhaseKind::Init);
  // Whatever the init phase's own exchanges refreshed, every ghost holds
  // its item's initial state before anything reads it.
  if (distributed())
    refreshAllGhosts();
  readClock(clock.size());
  initialized = true;
  onBoundary = true;
}

void Session::ensureInitialized() {
  if (!initialized)
    init();
}

void Session::run(int64_t steps, int64_t pause) {
  runEnd(0, steps); // Checks the steps before touching the device.
  runPause(0, steps, pause);
  // Every rank makes this call: agree here on what each was given since
  // (a --set on one rank alone cleared only its own agreement, and it
  // would then have waited in the agreement's all-reduce while the
  // others waited in another collective call).
  if (distributed()) {
    agreed = false;
    ensureAgreed();
  }
  // A run that failed inside a big step (check_finite's NaN, a kernel
  // that failed) left some buffers at T and others past it, and the clock
  // at T + m: continuing would start the next big step from that mix.
  // (The reference executor commits a big step only once every component
  // has run, so it stays at T.)
  if (initialized && !onBoundary)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "the last run stopped inside the big step from base step " +
             std::to_string(clock[kSlotBegin]) +
             ", so the state is at no single time: init starts over from "
             "the initial state, or restart from a checkpoint");
  backend->activate();
  ensureInitialized();
  prepare();
  // Ranks restarted from checkpoints of different base steps would take
  // different numbers of big steps, and of collective calls (not counted
  // in the run's all-reduces, like the agreement above).
  if (distributed())
    agreeOn("base step the run starts from",
            clock[kSlotBegin] + clock[kSlotSize]);
  metrics = {};
  for (KernelFigures &kernel : kernelFigures)
    kernel.launches = 0, kernel.seconds = -1;
  cutBigSteps = 0;
  nonFinite = {};
  std::vector<int64_t> before = clock;
  int64_t allReducesBefore = distributed() ? comm->allReduces : 0;
  int64_t exchangesBefore = haloExchanges, bytesBefore = exchangedBytes;
  // After init and after finish m is 0, so this is T.
  int64_t begin = clock[kSlotBegin] + clock[kSlotSize];
  int64_t end = runEnd(begin, steps);
  int64_t pauseAt = runPause(begin, steps, pause);
  // The largest big step, as the front end recorded it.
  int64_t cap = plan_->step_cap;

  auto wallStart = std::chrono::steady_clock::now();
  // Until finish commits the last big step and the clock checks out.
  onBoundary = false;
  backend->write(clockMemory.pointer + kSlotEnd * sizeof(int64_t), &end,
                 sizeof end);
  backend->startTimer();
  int64_t now = begin;
  // Base steps per big step as last observed. Starting from the cap, the
  // first batch never launches past the end; later batches follow the
  // kernels' recent step sizes, so a run of small big steps does not need
  // a host round trip per few of them. A step phase launched past the end
  // only costs its (empty) launches.
  double meanStep = double(cap);
  int64_t batchCap = progress ? kFirstProgressBatch : kMaxBatch;
  bool interrupted = false;
  // Ends the run on the big-step boundary reached: finish commits the last
  // big step and decides none, so no big step is cut.
  auto stopHere = [&] {
    end = now;
    backend->write(clockMemory.pointer + kSlotEnd * sizeof(int64_t), &end,
                   sizeof end);
  };
  while (now < end) {
    // Towards the pause, if there is one: batches sized for it stop near
    // it.
    int64_t target = std::min(end, pauseAt);
    int64_t batch =
        options.check_finite
            ? 1
            : std::clamp<int64_t>(
                  int64_t(std::ceil(double(target - now) / meanStep)), 1,
                  batchCap);
    bool stop = interruptPending();
    if (distributed()) {
      // Every rank launches the same step phases: the smallest batch (the
      // progress callback's timing differs between ranks), and all stop
      // when one was interrupted.
      int64_t agree[2] = {batch, stop ? -1 : 0};
      comm->minimum(agree, 2);
      batch = agree[0];
      stop = agree[1] < 0;
    }
    if (stop) {
      interrupted = true;
      stopHere();
      break;
    }
    auto batchStart = std::chrono::steady_clock::now();
    for (int64_t i = 0; i < batch; ++i)
      runStepPhase();
    readClock(2);
    ++metrics.host_syncs;
    if (progress) {
      double perPhase = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - batchStart)
                            .count() /
                        double(batch);
      batchCap =
          perPhase > 0
              ? std::clamp<int64_t>(int64_t(kProgressBatchSeconds / perPhase),
                                    1, kMaxBatch)
              : kMaxBatch;
    }
    int64_t reached = clock[kSlotBegin] + clock[kSlotSize];
    if (reached <= now)
      fail(SIM_ERROR_CLOCK,
           "the step phase made no progress at base step " +
               std::to_string(now) + " of a run to " + std::to_string(end) +
               " (clock: T = " + std::to_string(clock[kSlotBegin]) +
               ", m = " + std::to_string(clock[kSlotSize]) + ")");
    if (reached > end)
      fail(SIM_ERROR_CLOCK, "the clock ran past the end of the run: T + m = " +
                                std::to_string(reached) + " > " +
                                std::to_string(end));
    meanStep =
        std::clamp(double(reached - now) / double(batch), 1.0, double(cap));
    now = reached;
    if (progress)
      progress(progressUser, now - begin, steps);
    if (now >= pauseAt && now < end) {
      stopHere();
      break;
    }
  }
  runPhase(PhaseKind::Finish);
  metrics.kernel_seconds = backend->stopTimer();
  std::vector<double> seconds = backend->kernelSeconds();
  if (seconds.size() == kernelFigures.size())
    for (size_t k = 0; k < seconds.size(); ++k)
      kernelFigures[k].seconds = seconds[k];
  readClock(clock.size());
  ++metrics.host_syncs;
  metrics.wall_seconds = std::chrono::duration<double>(
                             std::chrono::steady_clock::now() - wallStart)
                             .count();

  // The device-side clamp makes a run end exactly at its end.
  if (clock[kSlotBegin] != end || clock[kSlotSize] != 0)
    fail(SIM_ERROR_CLOCK, "a run of " + std::to_string(end - begin) +
                              " base steps from base step " +
                              std::to_string(begin) + " ended at base step " +
                              std::to_string(clock[kSlotBegin]) +
                              " (m = " + std::to_string(clock[kSlotSize]) +
                              "), not at " + std::to_string(end));
  onBoundary = true;
  metrics.steps = end - begin;
  metrics.begin = begin;
  metrics.end = end;
  // The kernels add to the counters without overflow checks, so a counter
  // restored from a checkpoint near the top of int64 wraps: take each
  // difference modulo 2^64 too (a signed one would be undefined there).
  auto counted = [&](size_t slot) {
    return int64_t(uint64_t(clock[slot]) - uint64_t(before[slot]));
  };
  metrics.big_steps = counted(kSlotBigSteps);
  cutBigSteps = counted(kSlotCuts);
  for (size_t i = 0; i < plan_->components.size(); ++i)
    evaluations[i] = counted(size_t(plan_->components[i]->evaluations));
  if (distributed()) {
    // Each rank counts its own items' evaluations.
    if (!evaluations.empty())
      comm->sum(evaluations.data(), int32_t(evaluations.size()));
    metrics.allreduces = comm->allReduces - allReducesBefore;
    metrics.halo_exchanges = haloExchanges - exchangesBefore;
    metrics.exchanged_bytes = exchangedBytes - bytesBefore;
  }
  for (int64_t m = 1; m < int64_t(histogram.size()); ++m)
    histogram[m] = counted(size_t(plan_->histogram + m));
  if (interrupted)
    failInterrupted(begin, end, begin + steps);
}

//===----------------------------------------------------------------------===//
// Distributed plans
//===----------------------------------------------------------------------===//

void Session::layout() {
  ghostCache.clear();
  slotSelections.clear();
  levelListsCache.clear();
  if (!distributed()) {
    first = 0;
    count = extent = settings.range;
    return;
  }
  // Every rank computes every rank's block from the same (agreed) numbers:
  // a range too small fails on all of them alike, before any exchange.
  decomposition =
      std::make_unique<Decomposition>(settings.range, groupSize_, comm->size());
  if (!decomposition->fits())
    fail(SIM_ERROR_DISTRIBUTED, decomposition->tooManyRanks());
  first = decomposition->first(comm->rank());
  count = decomposition->count(comm->rank());
  extent = count + 2 * halo;
}

void Session::agreeOn(const std::string &what, int64_t value) {
  int64_t both[2] = {value, -value};
  comm->minimum(both, 2);
  if (both[0] != -both[1])
    fail(SIM_ERROR_DISTRIBUTED,
         "the ranks disagree on the " + what + " (from " +
             std::to_string(both[0]) + " to " + std::to_string(-both[1]) +
             " over the " + std::to_string(comm->size()) + " ranks)");
}

void Session::ensureAgreed() {
  if (agreed)
    return;
  // Each value's minimum and the minimum of its negation: the ranks agree
  // when both give it back. What identifies the bundle first, as a fixed
  // number of values, so that ranks with different bundles (and numbers
  // of parameters) still make the same calls.
  struct Named {
    std::string what;
    int64_t value;
    /// Written as every message writes a CRC-32 (hex), not in decimal.
    bool crc = false;
  };
  auto text = [](const Named &named, int64_t value) {
    return named.crc ? crcText(uint32_t(value)) : std::to_string(value);
  };
  auto check = [&](const std::vector<Named> &values) {
    std::vector<int64_t> both;
    for (const Named &named : values)
      both.push_back(named.value);
    for (const Named &named : values)
      both.push_back(-named.value);
    comm->minimum(both.data(), int32_t(both.size()));
    size_t n = values.size();
    for (size_t i = 0; i < n; ++i)
      if (both[i] != -both[n + i])
        fail(SIM_ERROR_DISTRIBUTED,
             "the ranks disagree on the " + values[i].what + " (from " +
                 text(values[i], both[i]) + " to " +
                 text(values[i], -both[n + i]) + " over the " +
                 std::to_string(comm->size()) + " ranks)");
  };
  check({{"bundle (its CRC-32)", int64_t(bundle->checksum), true},
         {"number of parameters", int64_t(settings.params.size())},
         {"strategy (its number)", int64_t(plan_->strategy)},
         {"group size", groupSize_}});
  std::vector<Named> values = {{"range", settings.range},
                               {"dt (its bits)", int64_t(settings.dt.bits())}};
  for (size_t p = 0; p < settings.params.size(); ++p)
    values.push_back({"parameter '" + scene().params[p]->name + "' (its bits)",
                      int64_t(settings.params[p].bits())});
  check(values);
  agreed = true;
}

const GhostLists &Session::ghostsOf(size_t buffer) {
  const schema::PlanBufferT &planBuffer = *plan_->buffers[buffer];
  Boundary boundary = sceneBuffer(buffer).boundary;
  auto key = std::make_tuple(planBuffer.halo_below, planBuffer.halo_above,
                             int(boundary));
  auto it = ghostCache.find(key);
  if (it == ghostCache.end())
    it = ghostCache
             .emplace(key, ghostLists(*decomposition, comm->rank(), halo,
                                      planBuffer.halo_below,
                                      planBuffer.halo_above, boundary))
             .first;
  return it->second;
}

Session::GhostRefresh Session::refreshOf(size_t buffer, bool snapshot) {
  bool whole = replicated(buffer);
  return {snapshot ? snapshots[buffer].pointer : buffers[buffer].pointer,
          deviceStride(int(buffer)),
          snapshot ? 1 : 2,
          elementsOf(buffer),
          whole,
          whole ? nullptr : &ghostsOf(buffer),
          buffer};
}

void Session::refreshGhosts(const std::vector<GhostRefresh> &refreshes,
                            bool counted) {
  beginGhosts(refreshes, counted);
  endGhosts();
}

void Session::beginGhosts(const std::vector<GhostRefresh> &refreshes,
                          bool counted, std::optional<size_t> entries) {
  endGhosts();
  // Ghost items move through the backend's reads and writes (runs of
  // consecutive elements each), which wait for the launches before them:
  // host memory on the CPU, staged device memory on CUDA. Every rank has
  // the same entries, so all make the same collective calls (or skip them
  // alike). Replicated buffers are all-gathered at once.
  PendingGhosts &p = pendingGhosts;
  p.counted = counted;
  p.entries = entries.value_or(refreshes.size());
  p.bytes = gatherReplicated(refreshes);
  p.ghosts.clear();
  for (const GhostRefresh &r : refreshes)
    if (!r.replicated)
      p.ghosts.push_back(r);
  p.active = true;
  if (p.ghosts.empty())
    return;
  size_t ranks = size_t(comm->size());
  p.sendBytes.assign(ranks, 0);
  p.recvBytes.assign(ranks, 0);
  for (const GhostRefresh &r : p.ghosts)
    for (size_t peer = 0; peer < ranks; ++peer) {
      p.sendBytes[peer] += r.lists->send[peer].size() * r.stride * r.halves;
      p.recvBytes[peer] += r.lists->recv[peer].size() * r.stride * r.halves;
    }
  // The previous exchange's writes from the receive memory are done
  // before it is written again (finishCopies below), and so are the
  // copies into the send memory before it travels.
  sendStore.resize(ranks);
  recvStore.resize(ranks);
  p.send.assign(ranks, nullptr);
  p.recv.assign(ranks, nullptr);
  for (size_t peer = 0; peer < ranks; ++peer) {
    uint8_t *out = sendStore[peer].ensure(*backend, p.sendBytes[peer]);
    p.send[peer] = out;
    p.recv[peer] = recvStore[peer].ensure(*backend, p.recvBytes[peer]);
    p.bytes += p.sendBytes[peer];
    for (const GhostRefresh &r : p.ghosts)
      for (int half = 0; half < r.halves; ++half)
        forEachRun(r.lists->send[peer], [&](int64_t e, int64_t n) {
          backend->readAsync(out, r.element(half, e), size_t(n) * r.stride);
          out += size_t(n) * r.stride;
        });
  }
  // Ghosts of this rank's own items (a wrap or clamp around a range on
  // one rank): copied on the device.
  for (const GhostRefresh &r : p.ghosts)
    for (int half = 0; half < r.halves; ++half)
      for (auto [from, to] : r.lists->local)
        backend->copy(r.element(half, to), r.element(half, from), r.stride);
  backend->finishCopies();
  comm->exchangeBegin(p.send.data(), p.sendBytes.data(), p.recv.data(),
                      p.recvBytes.data());
}

void Session::endGhosts() {
  PendingGhosts &p = pendingGhosts;
  if (!p.active)
    return;
  p.active = false;
  if (!p.ghosts.empty()) {
    comm->exchangeEnd();
    for (size_t peer = 0; peer < size_t(comm->size()); ++peer) {
      const uint8_t *in = static_cast<const uint8_t *>(p.recv[peer]);
      for (const GhostRefresh &r : p.ghosts)
        for (int half = 0; half < r.halves; ++half)
          forEachRun(r.lists->recv[peer], [&](int64_t e, int64_t n) {
            backend->write(r.element(half, e), in, size_t(n) * r.stride);
            in += size_t(n) * r.stride;
          });
    }
  }
  if (p.counted) {
    haloExchanges += int64_t(p.entries);
    exchangedBytes += int64_t(p.bytes);
  }
}

bool Session::readsPendingGhosts(const Prepared &p) const {
  if (!pendingGhosts.active)
    return false;
  for (const schema::Arg &arg : p.launch->args)
    if (arg.kind() == ArgKind::Buffer || arg.kind() == ArgKind::Snapshot)
      for (const GhostRefresh &r : pendingGhosts.ghosts)
        if (r.buffer == arg.index())
          return true;
  return false;
}

void Session::launchAroundExchange(Prepared &p) {
  // The groups whose items' windows (the halos of the buffers on their
  // way) stay inside the block need no ghost item: [lo, hi).
  int64_t below = 0, above = 0;
  for (const GhostRefresh &r : pendingGhosts.ghosts) {
    below = std::max<int64_t>(below, plan_->buffers[r.buffer]->halo_below);
    above = std::max<int64_t>(above, plan_->buffers[r.buffer]->halo_above);
  }
  int64_t size = p.groupSize;
  int64_t lo = (below + size - 1) / size;
  int64_t hi = count >= above ? std::min(p.groups, (count - above) / size) : 0;
  bool split = p.launch->shape == LaunchShape::Items &&
               backend->launchesGroupRanges() && comm->overlaps() && lo < hi;
  if (!split) {
    endGhosts();
    backend->launch(p.kernel, p.params.data(), p.groups, p.groupSize,
                    p.sharedBytes);
    return;
  }
  backend->launchGroups(p.kernel, p.params.data(), lo, hi - lo, size);
  endGhosts();
  if (lo > 0)
    backend->launchGroups(p.kernel, p.params.data(), 0, lo, size);
  if (hi < p.groups)
    backend->launchGroups(p.kernel, p.params.data(), hi, p.groups - hi, size);
}

size_t Session::gatherReplicated(const std::vector<GhostRefresh> &refreshes) {
  std::vector<const GhostRefresh *> whole;
  for (const GhostRefresh &r : refreshes)
    if (r.replicated)
      whole.push_back(&r);
  if (whole.empty())
    return 0;
  // A rank's block is contiguous in each half (item i at element i): one
  // all-gather of every rank's blocks of all entries and halves, in that
  // order, then each piece into place. The block of a rank is its own
  // items only, so the ranks' pieces never overlap.
  int32_t ranks = comm->size(), me = comm->rank();
  std::vector<size_t> bytes(size_t(ranks), 0);
  for (int32_t r = 0; r < ranks; ++r)
    for (const GhostRefresh *g : whole)
      bytes[size_t(r)] +=
          size_t(decomposition->count(r)) * g->stride * size_t(g->halves);
  auto block = [&](const GhostRefresh *g, int half, int32_t r) {
    return g->base +
           DevicePtr(half * g->elements + decomposition->first(r)) * g->stride;
  };
  // MPI wants the contribution apart from the gathered array.
  std::vector<uint8_t> mine(bytes[size_t(me)]);
  uint8_t *out = mine.data();
  size_t own = size_t(decomposition->count(me));
  for (const GhostRefresh *g : whole)
    for (int half = 0; half < g->halves; ++half) {
      backend->read(out, block(g, half, me), own * g->stride);
      out += own * g->stride;
    }
  size_t all = 0;
  for (size_t b : bytes)
    all += b;
  gatherStore.resize(all);
  comm->allgather(mine.data(), bytes.data(), gatherStore.data());
  const uint8_t *in = gatherStore.data();
  for (int32_t r = 0; r < ranks; ++r) {
    size_t items = size_t(decomposition->count(r));
    for (const GhostRefresh *g : whole)
      for (int half = 0; half < g->halves; ++half) {
        if (r != me)
          backend->write(block(g, half, r), in, items * g->stride);
        in += items * g->stride;
      }
  }
  // What this rank's block costs: it reaches every other rank.
  return mine.size() * size_t(ranks - 1);
}

void Session::refreshAllGhosts() {
  std::vector<GhostRefresh> refreshes;
  for (size_t b = 0; b < plan_->buffers.size(); ++b)
    refreshes.push_back(refreshOf(b, false));
  if (!refreshes.empty())
    refreshGhosts(refreshes, false);
}

void Session::reduceLevels(const std::vector<uint32_t> &components,
                           bool counted) {
  // The codes of this big step's blocks are half `parity` of each levels
  // array; every rank has written those of its own items (0, the identity,
  // elsewhere), so a block's maximum over the ranks that hold items of it
  // is what one process's atomics would have left. A rank's kernels read
  // the levels of the blocks near its own only, and those depend on the
  // codes within the component's level reach (docs/Distributed.md): only
  // those travel, from the ranks that hold them. Blocks further away keep
  // the code 0, which limit_levels_C decodes as the big step; their
  // levels come out no finer than one process's and nothing reads them.
  int64_t clock[kSlotParity + 1];
  backend->read(clock, clockMemory.pointer, sizeof clock);
  int64_t parity = clock[kSlotParity];
  if (parity != 0 && parity != 1)
    fail(SIM_ERROR_CLOCK, "the clock's parity is " + std::to_string(parity) +
                              ", not 0 or 1, before the reduction of the "
                              "levels");
  // With a big step of one base step (or none) every block's sub-step is
  // 1 whatever the codes say, and limit_levels_C decodes a code this rank
  // did not write (0) as the big step: nothing to share. Every rank holds
  // the same big step, so all skip alike.
  if (clock[kSlotSize] <= 1)
    return;
  // A component that keeps its codes (keeps_levels) kept them in the
  // limit_levels_C after its first gathering, complete for every block
  // within its reach; from then on its kernels read the kept codes and
  // levels_C writes none, so nothing is left to gather. Every rank takes
  // the same big steps, so all skip alike.
  std::vector<uint32_t> gathered;
  for (uint32_t c : components)
    if (!levelsKept[c])
      gathered.push_back(c);
  if (gathered.empty())
    return;
  for (uint32_t c : gathered)
    if (plan_->components[c]->keeps_levels)
      levelsKept[c] = true;
  reduceUnitRequests(gathered);
  reduceLevelCodes(gathered, counted, parity);
}

void Session::reduceUnitRequests(const std::vector<uint32_t> &components) {
  // The unit of the levels (docs/Model.md, "Levels") is the smallest
  // num_steps of every item, and each rank's levels_C combined those of its
  // own items into the UnitRequest slot of the sub-step clock: their
  // minimum over the ranks, in one all-reduce, is one process's. A
  // component that keeps its levels keeps its request too (local_parity_C
  // leaves it), so it travels with the codes, once.
  minimumOverRanks(components, schema::SubClockSlot::UnitRequest);
}

DevicePtr Session::subClockSlot(size_t component,
                                schema::SubClockSlot slot) const {
  return clockMemory.pointer +
         DevicePtr(plan_->components[component]->sub_clock + int64_t(slot)) *
             sizeof(int64_t);
}

void Session::minimumOverRanks(const std::vector<uint32_t> &components,
                               schema::SubClockSlot slot) {
  std::vector<int64_t> values(components.size());
  for (size_t i = 0; i < components.size(); ++i)
    backend->read(&values[i], subClockSlot(components[i], slot),
                  sizeof(int64_t));
  comm->minimum(values.data(), int32_t(values.size()));
  for (size_t i = 0; i < components.size(); ++i)
    backend->write(subClockSlot(components[i], slot), &values[i],
                   sizeof(int64_t));
}

void Session::reduceLevelCodes(const std::vector<uint32_t> &components,
                               bool counted, int64_t parity) {
  const int64_t blockItems = int64_t(schema::LocalStepBlock::Items);
  int64_t blocks = (settings.range + blockItems - 1) / blockItems;
  endGhosts();
  int32_t me = comm->rank(), ranks = comm->size();
  DevicePtr offset = DevicePtr(parity * blocks) * sizeof(int64_t);
  // What travels to and from each rank, component after component.
  auto listsOf = [&](uint32_t component) -> const LevelLists & {
    int64_t reach = int64_t(plan_->components[component]->level_reach);
    auto [found, fresh] = levelListsCache.try_emplace(reach);
    if (fresh) {
      found->second.send.resize(size_t(ranks));
      found->second.recv.resize(size_t(ranks));
      for (int32_t peer = 0; peer < ranks; ++peer) {
        if (peer == me)
          continue;
        found->second.send[size_t(peer)] =
            levelBlocksFor(*decomposition, me, peer, reach, blockItems);
        found->second.recv[size_t(peer)] =
            levelBlocksFor(*decomposition, peer, me, reach, blockItems);
      }
    }
    return found->second;
  };
  // This rank's codes of the blocks it sends or merges, per component: its
  // own items' and, for a flux pair, its interfaces' readers' (which may
  // be another rank's), read in runs of consecutive blocks.
  std::vector<std::map<int64_t, int64_t>> mine(components.size());
  for (size_t c = 0; c < components.size(); ++c) {
    const LevelLists &lists = listsOf(components[c]);
    std::map<int64_t, int64_t> &codes = mine[c];
    for (int32_t peer = 0; peer < ranks; ++peer)
      for (const auto *list :
           {&lists.send[size_t(peer)], &lists.recv[size_t(peer)]})
        for (int64_t block : *list)
          codes.emplace(block, 0);
    for (auto it = codes.begin(); it != codes.end();) {
      int64_t start = it->first;
      std::vector<int64_t> run;
      auto from = it;
      while (it != codes.end() && it->first == start + int64_t(run.size())) {
        run.push_back(0);
        ++it;
      }
      backend->read(run.data(),
                    levels[components[c]].pointer + offset +
                        DevicePtr(start) * sizeof(int64_t),
                    run.size() * sizeof(int64_t));
      for (int64_t code : run)
        (from++)->second = code;
    }
  }
  const size_t peers = size_t(ranks);
  std::vector<std::vector<int64_t>> out(peers), in(peers);
  std::vector<const void *> sendPointers(peers);
  std::vector<void *> recvPointers(peers);
  std::vector<size_t> sendBytes(peers), recvBytes(peers);
  size_t sent = 0;
  for (int32_t peer = 0; peer < ranks; ++peer) {
    size_t incoming = 0;
    for (size_t c = 0; c < components.size(); ++c) {
      const LevelLists &lists = listsOf(components[c]);
      for (int64_t block : lists.send[size_t(peer)])
        out[size_t(peer)].push_back(mine[c].at(block));
      incoming += lists.recv[size_t(peer)].size();
    }
    in[size_t(peer)].resize(incoming);
    sendPointers[size_t(peer)] = out[size_t(peer)].data();
    recvPointers[size_t(peer)] = in[size_t(peer)].data();
    sendBytes[size_t(peer)] = out[size_t(peer)].size() * sizeof(int64_t);
    recvBytes[size_t(peer)] = incoming * sizeof(int64_t);
    sent += sendBytes[size_t(peer)];
  }
  comm->exchangeBegin(sendPointers.data(), sendBytes.data(),
                      recvPointers.data(), recvBytes.data());
  comm->exchangeEnd();
  // Each block's maximum, written back in runs of consecutive blocks.
  for (size_t c = 0; c < components.size(); ++c) {
    std::map<int64_t, int64_t> merged;
    for (int32_t peer = 0; peer < ranks; ++peer) {
      const std::vector<int64_t> &from =
          listsOf(components[c]).recv[size_t(peer)];
      size_t at = 0;
      for (size_t p = 0; p < c; ++p)
        at += listsOf(components[p]).recv[size_t(peer)].size();
      for (size_t k = 0; k < from.size(); ++k) {
        int64_t block = from[k];
        auto [it, fresh] = merged.try_emplace(block, mine[c].at(block));
        it->second = std::max(it->second, in[size_t(peer)][at + k]);
      }
    }
    for (auto it = merged.begin(); it != merged.end();) {
      int64_t start = it->first;
      std::vector<int64_t> run;
      while (it != merged.end() && it->first == start + int64_t(run.size()))
        run.push_back((it++)->second);
      backend->write(levels[components[c]].pointer + offset +
                         DevicePtr(start) * sizeof(int64_t),
                     run.data(), run.size() * sizeof(int64_t));
    }
  }
  if (counted) {
    ++metrics.host_syncs;
    exchangedBytes += int64_t(sent);
  }
}

void Session::reduceFinest(const std::vector<uint32_t> &components) {
  // Each rank's limit_levels_C took the finest sub-step over the blocks
  // whose codes it holds, among them its own; every block is some rank's
  // own, so the minimum over the ranks is one process's, and every rank
  // takes the same slots.
  int64_t size = 0;
  backend->read(&size, clockMemory.pointer + kSlotSize * sizeof(int64_t),
                sizeof size);
  if (size <= 1)
    return;
  minimumOverRanks(components, schema::SubClockSlot::Size);
}

Session::SubStepTimes Session::subStepTimes(int component) {
  int64_t fixed[kSlotSize + 1];
  backend->read(fixed, clockMemory.pointer, sizeof fixed);
  int64_t sub[2];
  backend->read(sub,
                clockMemory.pointer +
                    plan_->components[size_t(component)]->sub_clock *
                        sizeof(int64_t),
                sizeof sub);
  return {fixed[kSlotBegin], fixed[kSlotSize],
          sub[int(schema::SubClockSlot::Begin)],
          sub[int(schema::SubClockSlot::Size)]};
}

bool Session::noOpLaunch(const Prepared &p) {
  if (p.roundOf < 0)
    return false;
  SubStepTimes t = subStepTimes(p.roundOf);
  if (plan_->components[size_t(p.roundOf)]->advance == Advance::GridSubSteps)
    // The component has committed its last sub-step (docs/Plan.md): the
    // estimate finds no time left, substep_advance decides none and
    // rewrites the clock as it is, substep_C takes none.
    return t.subSize == 0 && t.subBegin >= t.begin + t.size;
  // A slot kernel does something (and moves the clock on) only while its
  // slot, the sub-step clock's Begin less T, lies inside the big step.
  return !(t.size > 0 && t.subBegin - t.begin < t.size);
}

bool Session::keptEstimateSlot(uint32_t slot) const {
  return std::any_of(plan_->components.begin(), plan_->components.end(),
                     [&](const auto &component) {
                       return component->keeps_estimate &&
                              component->largest_estimate == slot;
                     });
}

bool Session::settledRound(const Prepared &p) {
  if (p.roundOf < 0 || p.launch->shape != LaunchShape::Single ||
      plan_->components[size_t(p.roundOf)]->advance != Advance::GridSubSteps)
    return false;
  SubStepTimes t = subStepTimes(p.roundOf);
  // substep_advance commits the sub-step in progress and decides the
  // next from the estimate only while the big step has more than one base
  // step left after it (with one left the next sub-step is 1, and
  // substep_estimate_C estimated nothing).
  return t.begin + t.size - (t.subBegin + t.subSize) <= 1;
}

void Session::launchDistributed(Prepared &p, bool counted, bool step) {
  // A round or slot that takes no sub-step (a round after the last
  // sub-step, a slot past the big step) changes nothing: no launch, no
  // all-reduce, no exchange (a buffer travels once per sub-step its writer
  // takes). Every rank holds the same sub-step clock, so all skip alike.
  if (noOpLaunch(p))
    return;
  // A slot launch whose blocks' items travel (exchange_local_step,
  // exchange_local_flux): its slot, the sub-step clock's Begin less T,
  // before the launch moves it on.
  int64_t slot = -1;
  int stepping = slotComponent(*p.launch);
  if (stepping >= 0) {
    SubStepTimes t = subStepTimes(stepping);
    slot = t.subBegin - t.begin;
  }
  // A kept largest estimate (keeps_estimate) that the ranks agreed on
  // before holds the same value on every rank until its slot is zeroed: no
  // all-reduce for it. Every rank keeps the same record, so all skip alike.
  std::vector<uint32_t> slots;
  for (uint32_t slot : p.launch->reduce_min)
    if (!estimatesKept.count(slot))
      slots.push_back(slot);
  // A round's estimate decides nothing once its component has at most one
  // base step of the big step left (the next sub-step is then 1 or none):
  // no all-reduce for it. Every rank holds the same sub-step clock, so all
  // skip alike.
  if (!slots.empty() && !settledRound(p)) {
    // The decisions every rank must share (the big step): their minimum
    // over the ranks, in one all-reduce.
    std::vector<int64_t> values(slots.size());
    for (size_t i = 0; i < slots.size(); ++i)
      backend->read(&values[i],
                    clockMemory.pointer + slots[i] * sizeof(int64_t),
                    sizeof(int64_t));
    comm->minimum(values.data(), int32_t(values.size()));
    for (size_t i = 0; i < slots.size(); ++i)
      backend->write(clockMemory.pointer + slots[i] * sizeof(int64_t),
                     &values[i], sizeof(int64_t));
    // A kept estimate that some rank took (not 0) is now every rank's.
    for (size_t i = 0; i < slots.size(); ++i)
      if (values[i] != 0 && keptEstimateSlot(slots[i]))
        estimatesKept.insert(slots[i]);
    if (counted)
      ++metrics.host_syncs;
  }
  if (!p.launch->reduce_max_levels.empty())
    reduceLevels(p.launch->reduce_max_levels, counted);
  if (readsPendingGhosts(p))
    launchAroundExchange(p);
  else
    backend->launch(p.kernel, p.params.data(), p.groups, p.groupSize,
                    p.sharedBytes);
  if (counted) {
    ++metrics.launches;
    ++kernelFigures[size_t(p.kernel)].launches;
  }
  if (!p.launch->reduce_max_levels.empty())
    reduceFinest(p.launch->reduce_max_levels);
  if (p.exchanges.empty())
    return;
  if (step) {
    // A step phase launched past the end of the run (T at the end, no big
    // step decided) changes nothing, so neither do its exchanges: a
    // buffer's ghosts travel once per big step, however far ahead the
    // host launches.
    int64_t fixed[kSlotEnd + 1];
    backend->read(fixed, clockMemory.pointer, sizeof fixed);
    if (fixed[kSlotSize] == 0 && fixed[kSlotBegin] >= fixed[kSlotEnd])
      return;
  }
  // The items travel while the next launches compute what needs none of
  // them (launchAroundExchange); endGhosts puts them in place before
  // anything else looks. Of a buffer the launch wrote in one half only,
  // that half travels: the target half of a whole_step or group_substeps
  // writer and of a parity copy (the other, the big step's source, is
  // unchanged since it travelled as the previous big step's target), the
  // half a grid-wide sub-step wrote (the other holds what the previous
  // sub-step read, which travelled before it).
  bool anyOneHalf = std::any_of(
      p.exchanges.begin(), p.exchanges.end(),
      [](const GhostRefresh &r) { return r.half != GhostRefresh::Half::Both; });
  if (!anyOneHalf)
    return beginGhosts(p.exchanges, counted);
  int64_t parity = 0;
  backend->read(&parity, clockMemory.pointer + kSlotParity * sizeof(int64_t),
                sizeof parity);
  if (parity != 0 && parity != 1)
    fail(SIM_ERROR_CLOCK, "the clock's parity is " + std::to_string(parity) +
                              ", not 0 or 1, after a launch");
  int64_t written = 1 - parity;
  if (std::any_of(p.exchanges.begin(), p.exchanges.end(),
                  [](const GhostRefresh &r) {
                    return r.half == GhostRefresh::Half::SubStep;
                  })) {
    // substep_C reads half parity xor (done mod 2) and writes the other.
    int64_t done = 0;
    backend->read(
        &done,
        subClockSlot(size_t(p.launch->component), schema::SubClockSlot::Done),
        sizeof done);
    written = 1 - (parity ^ (done & 1));
  }
  // The lists of a slot's refreshes are refilled below: the exchange that
  // still uses them ends first.
  endGhosts();
  std::vector<GhostRefresh> refreshes;
  size_t entries = 0;
  for (const GhostRefresh &entry : p.exchanges) {
    if (entry.half == GhostRefresh::Half::LocalStep ||
        entry.half == GhostRefresh::Half::LocalFlux) {
      // Counted where items of the blocks the slot started travel.
      entries += slotRefreshes(entry, slotComponent(*p.launch), slot, parity,
                               refreshes);
      continue;
    }
    ++entries;
    GhostRefresh r = entry;
    if (r.half != GhostRefresh::Half::Both) {
      r.base = r.element(
          int(r.half == GhostRefresh::Half::Target ? 1 - parity : written), 0);
      r.halves = 1;
    }
    refreshes.push_back(r);
  }
  beginGhosts(refreshes, counted, entries);
}

int Session::slotComponent(const schema::LaunchT &launch) const {
  if (!launch.exchange_local_step.empty())
    return int(launch.component);
  // A flux writer's slot: its one Levels argument is the flux pair's
  // reader (BundleVerifier checks), whose clock and levels say which.
  if (!launch.exchange_local_flux.empty())
    for (const schema::Arg &arg : launch.args)
      if (arg.kind() == schema::ArgKind::Levels)
        return int(arg.index());
  return -1;
}

bool Session::slotRefreshes(const GhostRefresh &r, int component, int64_t slot,
                            int64_t parity, std::vector<GhostRefresh> &out) {
  // Every rank holds the sub-step of every block within its level reach
  // (limit_levels_C limits those on each), those of its own and its
  // ghost items among them, so sender and receiver select the same items,
  // in the order the lists have.
  const int64_t blockItems = int64_t(schema::LocalStepBlock::Items);
  auto [found, fresh] = slotSelections.try_emplace({r.lists, r.buffer});
  SlotSelection &selection = found->second;
  size_t ranks = r.lists->send.size();
  if (fresh) {
    // Which block each element's item lies in: its own item, or the
    // source item of a ghost this rank receives.
    Boundary boundary = sceneBuffer(r.buffer).boundary;
    auto ownBlock = [&](int64_t e) { return (first - halo + e) / blockItems; };
    auto sourceBlock = [&](int64_t e) {
      return ghostSource(first - halo + e, settings.range, boundary) /
             blockItems;
    };
    std::map<int64_t, uint32_t> indexOf;
    for (const std::vector<int64_t> &list : r.lists->send)
      for (int64_t e : list)
        indexOf.try_emplace(ownBlock(e));
    for (const std::vector<int64_t> &list : r.lists->recv)
      for (int64_t e : list)
        indexOf.try_emplace(sourceBlock(e));
    for (auto [from, to] : r.lists->local)
      indexOf.try_emplace(ownBlock(from));
    for (auto &[block, index] : indexOf) {
      index = uint32_t(selection.blocks.size());
      selection.blocks.push_back(block);
    }
    selection.sendBlock.resize(ranks);
    selection.recvBlock.resize(ranks);
    for (size_t peer = 0; peer < ranks; ++peer) {
      for (int64_t e : r.lists->send[peer])
        selection.sendBlock[peer].push_back(indexOf.at(ownBlock(e)));
      for (int64_t e : r.lists->recv[peer])
        selection.recvBlock[peer].push_back(indexOf.at(sourceBlock(e)));
    }
    for (auto [from, to] : r.lists->local)
      selection.localBlock.push_back(indexOf.at(ownBlock(from)));
    for (GhostLists &lists : selection.selected) {
      lists.send.resize(ranks);
      lists.recv.resize(ranks);
    }
  }
  // The half each block wrote at the slot, or -1 when it did not start a
  // sub-step there. Sub-steps and slots count in the big step's unit
  // (docs/Model.md, "Levels"), which limit_levels_C left in the sub-step
  // clock; every slot is a multiple of it.
  int64_t unit = 0;
  backend->read(&unit,
                subClockSlot(size_t(component), schema::SubClockSlot::Unit),
                sizeof unit);
  if (unit < 1 || slot % unit != 0)
    fail(SIM_ERROR_CLOCK,
         "component '" + plan_->components[size_t(component)]->name +
             "' has the unit " + std::to_string(unit) + " at slot " +
             std::to_string(slot) + ", which is not a multiple of it");
  slot /= unit;
  const int64_t blocks = (settings.range + blockItems - 1) / blockItems;
  DevicePtr steps =
      levels[size_t(component)].pointer +
      DevicePtr(int64_t(schema::LocalStepLevels::Steps) * blocks) *
          sizeof(int64_t);
  selection.halfOfBlock.assign(selection.blocks.size(), -1);
  for (size_t i = 0; i < selection.blocks.size(); ++i) {
    int64_t step = 0;
    backend->read(&step,
                  steps + DevicePtr(selection.blocks[i]) * sizeof(int64_t),
                  sizeof step);
    if (step < 1 || (step & (step - 1)) != 0)
      fail(SIM_ERROR_CLOCK,
           "block " + std::to_string(selection.blocks[i]) + " of component '" +
               plan_->components[size_t(component)]->name +
               "' has the sub-step " + std::to_string(step) +
               ", not a power of two, at slot " + std::to_string(slot));
    if (slot % step == 0)
      selection.halfOfBlock[i] = r.half == GhostRefresh::Half::LocalFlux
                                     ? int(1 - parity)
                                     : int(1 - (parity ^ ((slot / step) & 1)));
  }
  bool any = false;
  for (int h = 0; h < 2; ++h) {
    GhostLists &lists = selection.selected[h];
    bool some = false;
    auto select = [&](const std::vector<int64_t> &all,
                      const std::vector<uint32_t> &blockOf,
                      std::vector<int64_t> &into) {
      into.clear();
      for (size_t k = 0; k < all.size(); ++k)
        if (selection.halfOfBlock[blockOf[k]] == h)
          into.push_back(all[k]);
      some = some || !into.empty();
    };
    for (size_t peer = 0; peer < ranks; ++peer) {
      select(r.lists->send[peer], selection.sendBlock[peer], lists.send[peer]);
      select(r.lists->recv[peer], selection.recvBlock[peer], lists.recv[peer]);
    }
    lists.local.clear();
    for (size_t k = 0; k < r.lists->local.size(); ++k)
      if (selection.halfOfBlock[selection.localBlock[k]] == h)
        lists.local.push_back(r.lists->local[k]);
    some = some || !lists.local.empty();
    if (!some)
      continue;
    GhostRefresh one = r;
    one.base = r.element(h, 0);
    one.halves = 1;
    one.lists = &lists;
    out.push_back(one);
    any = true;
  }
  return any;
}

void Session::gatherItems(DevicePtr array, int64_t own, size_t stride,
                          size_t packed, void *out) {
  std::vector<uint8_t> device(size_t(count) * stride);
  backend->read(device.data(), array + size_t(own) * stride, device.size());
  std::vector<uint8_t> mine(size_t(count) * packed);
  for (int64_t i = 0; i < count; ++i)
    std::memcpy(mine.data() + size_t(i) * packed,
                device.data() + size_t(i) * stride, packed);
  std::vector<size_t> bytes(size_t(comm->size()));
  for (int32_t r = 0; r < comm->size(); ++r)
    bytes[size_t(r)] = size_t(decomposition->count(r)) * packed;
  comm->allgather(mine.data(), bytes.data(), out);
}

//===----------------------------------------------------------------------===//
// Checkpoints
//===----------------------------------------------------------------------===//

std::vector<std::string> Session::stateBuffers() const {
  std::vector<std::string> names;
  for (size_t i = 0; i < plan_->buffers.size(); ++i)
    names.push_back(sceneBuffer(i).name);
  return names;
}

std::vector<int64_t> Session::checkpointClock() {
  backend->activate();
  ensureInitialized();
  if (!onBoundary)
    fail(SIM_ERROR_CHECKPOINT,
         "the state is inside a big step (the last run failed at base step " +
             std::to_string(clock[kSlotBegin]) +
             "): a checkpoint needs a big-step boundary; init or restart "
             "first");
  // The host's copy is the device's after init, a run's finish or a
  // restart; read it again all the same.
  readClock(clock.size());
  if (!distributed())
    return clock;
  // Every rank counts its own items' evaluations: the checkpoint holds
  // their sums, as one process would have counted (restoreClock gives
  // them to rank 0).
  std::vector<int64_t> counted;
  for (const auto &component : plan_->components)
    counted.push_back(clock[component->evaluations]);
  if (!counted.empty())
    comm->sum(counted.data(), int32_t(counted.size()));
  std::vector<int64_t> saved = clock;
  for (size_t i = 0; i < counted.size(); ++i)
    saved[plan_->components[i]->evaluations] = counted[i];
  return saved;
}

void Session::restoreClock(int64_t, const std::vector<int64_t> &saved) {
  backend->activate();
  // The memory of this range, zeroed, and the init phase: what no
  // checkpoint holds (the other halves, snapshots) is as after init.
  init();
  clock = saved;
  if (distributed() && comm->rank() != 0)
    for (const auto &component : plan_->components)
      clock[component->evaluations] = 0;
  // A pair writer's largest estimate is taken again (a kept one came from
  // the parameters of the run that wrote the checkpoint, which this one may
  // have changed), and a hint from the file could name a group outside the
  // range.
  for (const auto &component : plan_->components) {
    if (component->largest_estimate == 0)
      continue;
    for (uint32_t slot = 0; slot < uint32_t(schema::LargestEstimateSlot::Slots);
         ++slot)
      clock[component->largest_estimate + slot] = 0;
  }
  backend->write(clockMemory.pointer, clock.data(),
                 clock.size() * sizeof(int64_t));
  onBoundary = true;
}

//===----------------------------------------------------------------------===//
// Host arrays
//===----------------------------------------------------------------------===//

namespace {

void checkBytes(size_t given, size_t expected, const std::string &buffer) {
  if (given != expected)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "a host array of buffer '" + buffer + "' takes " +
             std::to_string(expected) + " bytes, not " + std::to_string(given));
}

} // namespace

Session::CurrentHalf Session::currentHalf(const std::string &name,
                                          size_t bytes) {
  int index = bufferIndex(name);
  checkBytes(bytes, hostBytes(name), name);
  backend->activate();
  ensureInitialized();
  size_t stride = deviceStride(index);
  size_t packed = size_t(packedBytes(*sceneBuffer(size_t(index)).element));
  DevicePtr half =
      buffers[index].pointer +
      size_t(clock[kSlotParity]) * size_t(elementsOf(size_t(index))) * stride;
  return {half, stride, packed};
}

void Session::getBuffer(const std::string &name, void *data, size_t bytes) {
  auto [half, stride, packed] = currentHalf(name, bytes);
  if (distributed()) {
    // A replicated buffer is whole on every rank after its exchanges; its
    // owners' blocks all the same, as for any other buffer.
    gatherItems(half, ownElement(size_t(bufferIndex(name))), stride, packed,
                data);
    return;
  }
  if (stride == packed) {
    backend->read(data, half, bytes);
    return;
  }
  std::vector<uint8_t> device(size_t(settings.range) * stride);
  backend->read(device.data(), half, device.size());
  for (int64_t i = 0; i < settings.range; ++i)
    std::memcpy(static_cast<uint8_t *>(data) + size_t(i) * packed,
                device.data() + size_t(i) * stride, packed);
}

void Session::setBuffer(const std::string &name, const void *data,
                        size_t bytes) {
  auto [half, stride, packed] = currentHalf(name, bytes);
  // A replicated buffer takes every item, as on one process (below), and
  // nothing travels.
  if (distributed() && !replicated(size_t(bufferIndex(name)))) {
    // This rank's block of the whole array, then its ghosts from their
    // owners (both halves: the other half's ghosts are refreshed again).
    std::vector<uint8_t> device(size_t(count) * stride, 0);
    for (int64_t i = 0; i < count; ++i)
      std::memcpy(device.data() + size_t(i) * stride,
                  static_cast<const uint8_t *>(data) +
                      size_t(first + i) * packed,
                  packed);
    backend->write(half + size_t(halo) * stride, device.data(), device.size());
    refreshGhosts({refreshOf(size_t(bufferIndex(name)), false)}, false);
    return;
  }
  if (stride == packed) {
    backend->write(half, data, bytes);
    return;
  }
  std::vector<uint8_t> device(size_t(settings.range) * stride, 0);
  for (int64_t i = 0; i < settings.range; ++i)
    std::memcpy(device.data() + size_t(i) * stride,
                static_cast<const uint8_t *>(data) + size_t(i) * packed,
                packed);
  backend->write(half, device.data(), device.size());
  // The CPU backend copies at once, CUDA stages pageable memory before
  // returning: `device` may go.
}

bool Session::hasExact(const std::string &name) const {
  for (size_t i = 0; i < plan_->buffers.size(); ++i)
    if (sceneBuffer(i).name == name)
      return sceneBuffer(i).exact && hasPhase[int(PhaseKind::Exact)];
  return false;
}

void Session::exact(const std::string &name, void *data, size_t bytes) {
  int index = bufferIndex(name);
  if (!sceneBuffer(size_t(index)).exact)
    fail(SIM_ERROR_INVALID_ARGUMENT, "scene '" + scene().name +
                                         "' declares no exact solution of "
                                         "buffer '" +
                                         name + "'");
  if (!hasPhase[int(PhaseKind::Exact)])
    fail(SIM_ERROR_BUNDLE, std::string("the plan of strategy '") +
                               strategyName(plan_->strategy) +
                               "' has no exact phase");
  checkBytes(bytes, hostBytes(name), name);
  backend->activate();
  ensureInitialized();
  prepare();
  double time = double(clock[kSlotBegin]) * settings.dtValue();
  uint64_t bits;
  std::memcpy(&bits, &time, sizeof bits);
  for (uint32_t launch : phases[int(PhaseKind::Exact)])
    for (size_t position : launches[launch].timeValues)
      launches[launch].values[position] = bits;
  // Outside a run: the last run's metrics stay as they were.
  runUncounted(PhaseKind::Exact);
  size_t stride = deviceStride(index);
  size_t packed = size_t(packedBytes(*sceneBuffer(size_t(index)).element));
  if (distributed()) {
    gatherItems(exacts[index].pointer, ownElement(size_t(index)), stride,
                packed, data);
    return;
  }
  std::vector<uint8_t> device(size_t(settings.range) * stride);
  backend->read(device.data(), exacts[index].pointer, device.size());
  for (int64_t i = 0; i < settings.range; ++i)
    std::memcpy(static_cast<uint8_t *>(data) + size_t(i) * packed,
                device.data() + size_t(i) * stride, packed);
}

std::vector<double> Session::totals() {
  std::vector<double> sums(plan_->totals.size(), 0.0);
  if (sums.empty())
    return sums;
  if (!hasPhase[int(PhaseKind::Total)])
    fail(SIM_ERROR_BUNDLE, std::string("the plan of strategy '") +
                               strategyName(plan_->strategy) +
                               "' has no total phase");
  backend->activate();
  ensureInitialized();
  prepare();
  // Outside a run: the last run's metrics stay as they were.
  runUncounted(PhaseKind::Total);
  // The device computes every item's value; the host adds them in item
  // order, so the sum does not depend on the backend's grouping.
  std::vector<double> values(size_t(settings.range));
  for (size_t t = 0; t < sums.size(); ++t) {
    // A distributed session's ranks gather every item's value and add
    // them in the same order: the same sums on every rank.
    if (distributed())
      gatherItems(totalValues[t].pointer, halo, sizeof(double), sizeof(double),
                  values.data());
    else
      backend->read(values.data(), totalValues[t].pointer,
                    values.size() * sizeof(double));
    double sum = 0.0;
    for (double value : values)
      sum += value;
    sums[t] = sum;
  }
  return sums;
}

} // namespace sim::rt
