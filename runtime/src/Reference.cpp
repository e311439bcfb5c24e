//===- Reference.cpp - the reference executor -----------------------------===//
//
// docs/Reference.md, "What the executor does", literally. Deliberately
// simple: one thread, one item at a time, every value copied, every rule
// spelled out where it applies. Speed does not matter here; being obviously
// right does.
//
//===----------------------------------------------------------------------===//

#include "Reference.h"
#include "Backend.h"
#include "Error.h"
#include "FloatMode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

namespace sim::rt {

namespace {

enum : uint8_t { kNotComputed = 0, kComputing = 1, kComputed = 2 };

template <typename S> S lane(const uint8_t *element, int32_t index) {
  S value;
  std::memcpy(&value, element + size_t(index) * sizeof(S), sizeof(S));
  return value;
}

/// The interpolation table of docs/Reference.md, lane by lane in the
/// element's scalar type S. `va`, `vb` are only used by hermite.
template <typename S>
void interpolateLanes(Interp interp, int32_t lanes, S f, S h, const uint8_t *a,
                      const uint8_t *b, const uint8_t *va, const uint8_t *vb,
                      uint8_t *out) {
  for (int32_t l = 0; l < lanes; ++l) {
    S av = lane<S>(a, l), bv = lane<S>(b, l);
    S value;
    switch (interp) {
    case Interp::Linear:
      value = (1 - f) * av + f * bv;
      break;
    case Interp::Cubic: {
      S s = f * f * (3 - 2 * f);
      value = (1 - s) * av + s * bv;
      break;
    }
    case Interp::Hermite: {
      S dva = lane<S>(va, l), dvb = lane<S>(vb, l);
      // Grouped as docs/Reference.md writes it: (1 - f)^2 and f^2 are
      // products of their own, and the weights of the derivatives are
      // scaled by h before they meet them. A product of three roundings
      // in another order differs in the last bit for most f.
      S oneMinusFSq = (1 - f) * (1 - f);
      S fSq = f * f;
      S h00 = (1 + 2 * f) * oneMinusFSq;
      S h10 = f * oneMinusFSq;
      S h01 = fSq * (3 - 2 * f);
      S h11 = fSq * (f - 1);
      value = h00 * av + (h10 * h) * dva + h01 * bv + (h11 * h) * dvb;
      break;
    }
    case Interp::None:
      // The caller reports the read; there is no value to give.
      value = 0;
      break;
    case Interp::Flux:
      // The flux over the writer's whole step.
      value = f > 0 ? bv : av;
      break;
    }
    std::memcpy(out + size_t(l) * sizeof(S), &value, sizeof(S));
  }
}

} // namespace

ReferenceSession::ReferenceSession(std::shared_ptr<const Bundle> bundleIn,
                                   const sim_session_options &options)
    : bundle(std::move(bundleIn)), settings(*bundle) {
  // It follows every item in one process, in plain C++: nothing to split.
  if (options.communicator)
    fail(SIM_ERROR_DISTRIBUTED,
         "the reference executor runs on one process and takes no "
         "communicator; distributed runs use the plan executor");
  model_ = bundle->reference();
  if (!model_)
    fail(SIM_ERROR_BUNDLE,
         "bundle '" + bundle->name + "' has no reference model and functions");
  if (uint32_t(options.strategy) >= kNumStrategies)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "unknown strategy " + std::to_string(int(options.strategy)));
  strategy_ = Strategy(options.strategy);
  // It runs on one thread and ignores the value, but a negative or huge
  // one is a caller's mistake all the same.
  checkCpuThreads(options.cpu_threads);
  checkFinite_ = options.check_finite;
  setMemoryLimit(options.max_memory, physicalMemoryBytes());

  // The group size decides the sub-steps of hip: by default the one the
  // strategy's plan was made for, so a check compares like with like.
  groupSize_ = options.group_size;
  if (groupSize_ < 0)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "group size " + std::to_string(groupSize_) + " is not positive");
  if (groupSize_ == 0) {
    const schema::PlanT *plan = bundle->plan(strategy_);
    if (!plan)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "bundle '" + bundle->name + "' has no plan for strategy '" +
               strategyName(strategy_) +
               "' to take the group size from; give a group size");
    groupSize_ = plan->group_size;
  }

  // The model against the scene (indices the verifier checked).
  std::vector<int32_t> modelIndex(scene().buffers.size(), -1);
  for (size_t b = 0; b < model_->buffers.size(); ++b) {
    buffers_.push_back({scene().buffers[model_->buffers[b]].get()});
    modelIndex[model_->buffers[b]] = int32_t(b);
  }
  for (ModelBuffer &buffer : buffers_)
    if (buffer.info->interp == Interp::Hermite)
      buffer.derivative = modelIndex[size_t(buffer.info->derivative)];
  for (size_t c = 0; c < model_->components.size(); ++c) {
    for (uint32_t write : model_->components[c]->writes)
      buffers_[write].writer = int32_t(c);
    stepping.push_back(model_->components[c]->stepping[size_t(strategy_)]);
  }
  stepCap = model_->step_caps[size_t(strategy_)];

  object =
      std::make_unique<SharedObject>(model_->object, "the reference functions");
  auto lookUp = [&](const std::string &symbol, const std::string &body) {
    void *address = object->find(symbol);
    if (!address)
      fail(SIM_ERROR_BACKEND, "the reference functions do not export " +
                                  symbol + " (" + body + ")");
    return address;
  };
  for (size_t b = 0; b < buffers_.size(); ++b) {
    const schema::BufferT &buffer = *buffers_[b].info;
    std::string index = std::to_string(b);
    initFns.push_back(reinterpret_cast<InitFn>(
        lookUp("sim_ref_init_" + index,
               "the init body of buffer '" + buffer.name + "'")));
    exactFns.push_back(
        buffer.exact ? reinterpret_cast<ExactFn>(lookUp(
                           "sim_ref_exact_" + index,
                           "the exact body of buffer '" + buffer.name + "'"))
                     : nullptr);
  }
  for (size_t c = 0; c < model_->components.size(); ++c) {
    const schema::RefComponentT &component = *model_->components[c];
    std::string index = std::to_string(c);
    numStepsFns.push_back(
        component.num_steps
            ? reinterpret_cast<NumStepsFn>(lookUp(
                  "sim_ref_num_steps_" + index,
                  "the num_steps body of component '" + component.name + "'"))
            : nullptr);
    evaluateFns.push_back(reinterpret_cast<EvaluateFn>(
        lookUp("sim_ref_evaluate_" + index,
               "the evaluate body of component '" + component.name + "'")));
  }
  for (size_t t = 0; t < model_->totals.size(); ++t)
    totalFns.push_back(reinterpret_cast<TotalFn>(
        lookUp("sim_ref_total_" + std::to_string(t),
               "the body of total '" + totalName(t) + "'")));
  context = {this, &ReferenceSession::readCallback,
             &ReferenceSession::paramCallback};
  evaluations.assign(model_->components.size(), 0);
  histogram.assign(size_t(scene().max_steps) + 1, 0);
}

ReferenceSession::~ReferenceSession() = default;

//===----------------------------------------------------------------------===//
// Values and host arrays
//===----------------------------------------------------------------------===//

void ReferenceSession::set(const std::string &name, const std::string &text) {
  bool rangeChanged = settings.set(name, text, [&](int64_t range) {
    checkMemory(range, "range " + std::to_string(range));
  });
  // The state of another size is meaningless: start over.
  if (rangeChanged)
    initialized = false;
}

int ReferenceSession::bufferIndex(const std::string &name) const {
  for (size_t b = 0; b < buffers_.size(); ++b)
    if (buffers_[b].info->name == name)
      return int(b);
  std::vector<std::string> names;
  for (const ModelBuffer &buffer : buffers_)
    names.push_back(buffer.info->name);
  fail(SIM_ERROR_INVALID_ARGUMENT,
       "'" + name + "' is not a buffer of the reference model (buffers: " +
           listNames(names) + ")");
}

int64_t ReferenceSession::memoryBytes(int64_t range) const {
  // Per buffer: the initial state, begin, end and current copies, the
  // temporaries of a sub-step, and a status byte per item.
  int64_t bytes = 0;
  for (const ModelBuffer &buffer : buffers_)
    bytes = saturatingAdd(
        bytes,
        saturatingAdd(
            saturatingMul(
                saturatingMul(range, packedBytes(*buffer.info->element)), 5),
            range));
  return bytes;
}

size_t ReferenceSession::hostBytes(const std::string &name) const {
  return size_t(settings.range) * packed(bufferIndex(name));
}

namespace {

void checkBytes(size_t given, size_t expected, const std::string &buffer) {
  if (given != expected)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "a host array of buffer '" + buffer + "' takes " +
             std::to_string(expected) + " bytes, not " + std::to_string(given));
}

} // namespace

void ReferenceSession::getBuffer(const std::string &name, void *data,
                                 size_t bytes) {
  int index = bufferIndex(name);
  checkBytes(bytes, hostBytes(name), name);
  ensureInitialized();
  std::memcpy(data, states[index].begin.data(), bytes);
}

void ReferenceSession::setBuffer(const std::string &name, const void *data,
                                 size_t bytes) {
  int index = bufferIndex(name);
  checkBytes(bytes, hostBytes(name), name);
  ensureInitialized();
  std::memcpy(states[index].begin.data(), data, bytes);
}

bool ReferenceSession::hasExact(const std::string &name) const {
  for (const ModelBuffer &buffer : buffers_)
    if (buffer.info->name == name)
      return buffer.info->exact;
  return false;
}

void ReferenceSession::exact(const std::string &name, void *data,
                             size_t bytes) {
  SubnormalScope mode(bundle->flushesSubnormals());
  int index = bufferIndex(name);
  if (!buffers_[size_t(index)].info->exact)
    fail(SIM_ERROR_INVALID_ARGUMENT, "scene '" + scene().name +
                                         "' declares no exact solution of "
                                         "buffer '" +
                                         name + "'");
  checkBytes(bytes, hostBytes(name), name);
  ensureInitialized();
  double time = double(now) * settings.dtValue();
  running = {Body::Exact, -1, now};
  for (int64_t i = 0; i < settings.range; ++i) {
    exactFns[index](&context, i, time,
                    static_cast<uint8_t *>(data) + size_t(i) * packed(index));
    rethrowCallbackError();
  }
  running = {};
}

std::vector<double> ReferenceSession::totals() {
  SubnormalScope mode(bundle->flushesSubnormals());
  std::vector<double> sums(model_->totals.size(), 0.0);
  if (sums.empty())
    return sums;
  ensureInitialized();
  for (size_t t = 0; t < sums.size(); ++t) {
    running = {Body::Total, -1, now};
    sums[t] = sumTotal(t);
  }
  running = {};
  return sums;
}

double ReferenceSession::sumTotal(size_t index) {
  bool isF32 =
      scene().totals[model_->totals[index]->total]->type == ScalarType::F32;
  double sum = 0.0;
  for (int64_t i = 0; i < settings.range; ++i) {
    // Room for either type; an f32 widens to double as the kernels do.
    alignas(8) uint8_t out[8] = {};
    totalFns[index](&context, i, out);
    rethrowCallbackError();
    if (isF32) {
      float value;
      std::memcpy(&value, out, sizeof value);
      sum += double(value);
    } else {
      double value;
      std::memcpy(&value, out, sizeof value);
      sum += value;
    }
  }
  return sum;
}

//===----------------------------------------------------------------------===//
// Callbacks
//===----------------------------------------------------------------------===//

void ReferenceSession::readCallback(void *executor, int32_t buffer,
                                    int64_t item, void *out) {
  static_cast<ReferenceSession *>(executor)->read(buffer, item, out);
}

void ReferenceSession::paramCallback(void *executor, int32_t param, void *out) {
  static_cast<ReferenceSession *>(executor)->param(param, out);
}

void ReferenceSession::rethrowCallbackError() {
  if (!callbackFailed)
    return;
  callbackFailed = false;
  running = {};
  fail(callbackStatus, callbackMessage);
}

void ReferenceSession::read(int32_t buffer, int64_t item, void *out) {
  if (buffer < 0 || size_t(buffer) >= buffers_.size()) {
    // Without a valid buffer the size of `out` is unknown: write nothing.
    if (!callbackFailed) {
      callbackFailed = true;
      callbackStatus = SIM_ERROR_BACKEND;
      callbackMessage = "a reference body read buffer " +
                        std::to_string(buffer) + ", but the model has " +
                        std::to_string(buffers_.size()) + " buffers";
    }
    return;
  }
  uint8_t *bytes = static_cast<uint8_t *>(out);
  std::memset(bytes, 0, packed(buffer));
  // After a failure the body runs to its end on zeros; the executor throws
  // when it returns.
  if (callbackFailed)
    return;
  try {
    const schema::BufferT &info = *buffers_[size_t(buffer)].info;
    int64_t range = settings.range;
    int64_t index = item;
    if (item < 0 || item >= range) {
      switch (info.boundary) {
      case Boundary::Clamp:
        index = std::clamp<int64_t>(item, 0, range - 1);
        break;
      case Boundary::Wrap:
        index = (item % range + range) % range;
        break;
      case Boundary::Zero:
        return;
      }
    }
    switch (running.body) {
    case Body::Init:
    case Body::Exact:
      std::memcpy(bytes, initialItem(buffer, index), packed(buffer));
      return;
    case Body::NumSteps:
    case Body::Evaluate:
      readInStep(buffer, index, bytes);
      return;
    case Body::Total:
      // A total sees the state at T.
      std::memcpy(bytes,
                  states[buffer].begin.data() + size_t(index) * packed(buffer),
                  packed(buffer));
      return;
    case Body::InitCheck:
      // At t = 0 with n = 0 every role (own, back edge, interpolated at
      // the start of the big step, no writer) is the initial state.
      requireListedRead(buffer, index);
      std::memcpy(bytes, initialItem(buffer, index), packed(buffer));
      return;
    case Body::ExactTotal:
      exactItem(buffer, index, bytes);
      return;
    case Body::None:
      fail(SIM_ERROR_BACKEND, "a read of buffer '" + info.name +
                                  "' while no reference body is running");
    }
  } catch (const Error &error) {
    callbackFailed = true;
    callbackStatus = error.status;
    callbackMessage = error.what();
    std::memset(bytes, 0, packed(buffer));
  }
}

void ReferenceSession::param(int32_t index, void *out) {
  auto store = [&](const Value &value) {
    switch (value.type) {
    case ScalarType::I32: {
      int32_t v = int32_t(value.i);
      std::memcpy(out, &v, sizeof v);
      break;
    }
    case ScalarType::I64:
    case ScalarType::Index:
      std::memcpy(out, &value.i, sizeof value.i);
      break;
    case ScalarType::F32: {
      float v = float(value.f);
      std::memcpy(out, &v, sizeof v);
      break;
    }
    case ScalarType::F64:
      std::memcpy(out, &value.f, sizeof value.f);
      break;
    }
  };
  if (index >= 0 && size_t(index) < model_->params.size()) {
    store(settings.params[model_->params[size_t(index)]]);
  } else if (index == -1) {
    store(Value{ScalarType::I64, settings.range, 0});
  } else if (index == -2) {
    store(settings.dt);
  } else if (index == -3) {
    store(Value{ScalarType::I32, scene().max_steps, 0});
  } else if (!callbackFailed) {
    callbackFailed = true;
    callbackStatus = SIM_ERROR_BACKEND;
    callbackMessage = "a reference body asked for parameter " +
                      std::to_string(index) + ", but the model has " +
                      std::to_string(model_->params.size()) +
                      " (and -1 range, -2 dt, -3 max_steps)";
  }
}

//===----------------------------------------------------------------------===//
// Checkpoints
//===----------------------------------------------------------------------===//

std::vector<std::string> ReferenceSession::stateBuffers() const {
  std::vector<std::string> names;
  for (const ModelBuffer &buffer : buffers_)
    names.push_back(buffer.info->name);
  return names;
}

std::vector<int64_t> ReferenceSession::checkpointClock() {
  // Between runs the executor is always on a big-step boundary: a big step
  // changes the state at T only once every component has run.
  ensureInitialized();
  return {};
}

void ReferenceSession::restoreClock(int64_t time,
                                    const std::vector<int64_t> &) {
  // The initial state too: exact bodies read it.
  init();
  now = time;
  stepSize = 0;
}

//===----------------------------------------------------------------------===//
// Initial states
//===----------------------------------------------------------------------===//

void ReferenceSession::init() {
  SubnormalScope mode(bundle->flushesSubnormals());
  initialized = false;
  int64_t range = settings.range;
  checkMemory(range, "range " + std::to_string(range));
  states.assign(buffers_.size(), State{});
  initialStates.reset(buffers_.size(), false);
  initChain.clear();
  callbackFailed = false;
  for (size_t b = 0; b < states.size(); ++b)
    for (int64_t i = 0; i < range; ++i)
      initialItem(int32_t(b), i);
  for (size_t b = 0; b < states.size(); ++b)
    states[b].begin = states[b].end = states[b].current =
        initialStates.elements[b];
  now = stepSize = 0;
  initialized = true;
}

void ReferenceSession::ensureInitialized() {
  if (!initialized)
    init();
}

void ReferenceSession::InitialStates::reset(size_t buffers, bool sparseItems) {
  sparse = sparseItems;
  elements.assign(buffers, {});
  status.assign(buffers, {});
  items.assign(sparse ? buffers : 0, {});
}

uint8_t *ReferenceSession::initialSlot(int32_t buffer, int64_t item,
                                       uint8_t *&status) {
  InitialStates &store = *initial;
  size_t bytes = packed(buffer);
  if (store.sparse) {
    // Elements of an unordered_map stay where they are when it grows.
    InitialStates::Item &entry = store.items[size_t(buffer)][item];
    if (entry.element.empty())
      entry.element.assign(bytes, 0);
    status = &entry.status;
    return entry.element.data();
  }
  std::vector<uint8_t> &elements = store.elements[size_t(buffer)];
  if (elements.empty()) {
    elements.assign(size_t(settings.range) * bytes, 0);
    store.status[size_t(buffer)].assign(size_t(settings.range), kNotComputed);
  }
  status = &store.status[size_t(buffer)][size_t(item)];
  return elements.data() + size_t(item) * bytes;
}

const uint8_t *ReferenceSession::initialItem(int32_t buffer, int64_t item) {
  uint8_t *statusSlot;
  uint8_t *element = initialSlot(buffer, item, statusSlot);
  uint8_t &status = *statusSlot;
  if (status == kComputed)
    return element;
  if (status == kComputing) {
    std::string cycle;
    bool inCycle = false;
    for (auto [b, i] : initChain) {
      inCycle |= b == buffer && i == item;
      if (inCycle)
        cycle +=
            buffers_[size_t(b)].info->name + "[" + std::to_string(i) + "] -> ";
    }
    cycle +=
        buffers_[size_t(buffer)].info->name + "[" + std::to_string(item) + "]";
    fail(SIM_ERROR_BUNDLE,
         "the init bodies read each other in a cycle: " + cycle);
  }
  status = kComputing;
  initChain.emplace_back(buffer, item);
  Running saved = running;
  running = {Body::Init, -1, 0};
  initFns[buffer](&context, item, element);
  running = saved;
  initChain.pop_back();
  status = kComputed;
  // Only the outermost init rethrows: an inner one returns into a body.
  if (initChain.empty())
    rethrowCallbackError();
  return element;
}

//===----------------------------------------------------------------------===//
// Reads in a big step
//===----------------------------------------------------------------------===//

std::string ReferenceSession::describeRead(int32_t buffer, int64_t item) const {
  const schema::RefComponentT &component =
      *model_->components[size_t(running.component)];
  return std::string(running.body == Body::NumSteps ? "num_steps"
                                                    : "evaluate") +
         " of component '" + component.name + "' reads buffer '" +
         buffers_[size_t(buffer)].info->name + "' (item " +
         std::to_string(item) + ") at base step " +
         std::to_string(running.readTime);
}

void ReferenceSession::requireListedRead(int32_t buffer, int64_t item) const {
  const schema::RefComponentT &component =
      *model_->components[size_t(running.component)];
  if (std::find(component.reads.begin(), component.reads.end(), buffer) ==
      component.reads.end())
    fail(SIM_ERROR_BACKEND,
         describeRead(buffer, item) +
             ", which the model's 'reads' of the component does not list");
}

void ReferenceSession::readInStep(int32_t buffer, int64_t item, uint8_t *out) {
  requireListedRead(buffer, item);
  const State &state = states[buffer];
  size_t at = size_t(item) * packed(buffer);
  int32_t writer = buffers_[size_t(buffer)].writer;
  const uint8_t *from;
  if (writer < 0) {
    // No writer: the initial state (or what the user set).
    from = state.begin.data();
  } else if (writer == running.component) {
    if (writer == levels.component && running.body == Body::Evaluate) {
      readLevels(buffer, item, out);
      return;
    }
    from = state.current.data();
  } else if (writer == levels.component &&
             running.component == levels.fluxWriter &&
             running.body == Body::Evaluate) {
    // A flux pair's writer reads its reader's state at its local time.
    readLevels(buffer, item, out);
    return;
  } else if (writer == levels.fluxWriter &&
             running.component == levels.component &&
             running.body == Body::Evaluate) {
    // The reader of a pair reads its writer's latest value: computed when
    // its block started the sub-step, for an item pair; held over the
    // interface's step, for a flux pair (docs/Model.md, "Item pairs").
    from = state.end.data();
  } else if (writer > running.component) {
    // A back edge: the writer has not advanced yet.
    from = state.begin.data();
  } else {
    interpolate(buffer, item, out);
    return;
  }
  std::memcpy(out, from + at, packed(buffer));
}

void ReferenceSession::interpolate(int32_t buffer, int64_t item, uint8_t *out) {
  const schema::BufferT &info = *buffers_[size_t(buffer)].info;
  const schema::Element &element = *info.element;
  const State &state = states[buffer];
  size_t bytes = packed(buffer), at = size_t(item) * bytes;
  int64_t time = running.readTime;
  if (time == now) {
    std::memcpy(out, state.begin.data() + at, bytes);
    return;
  }
  if (time == now + stepSize) {
    std::memcpy(out, state.end.data() + at, bytes);
    return;
  }
  std::string inside = " inside the big step [" + std::to_string(now) + ", " +
                       std::to_string(now + stepSize) + "]";
  if (info.interp == Interp::None)
    fail(SIM_ERROR_BACKEND,
         describeRead(buffer, item) + inside +
             ", but it has interp(none): its value means nothing there");
  const uint8_t *va = nullptr, *vb = nullptr;
  if (info.interp == Interp::Hermite) {
    int32_t derivative = buffers_[size_t(buffer)].derivative;
    int32_t writer = buffers_[size_t(derivative)].writer;
    const State &dstate = states[size_t(derivative)];
    va = dstate.begin.data() + at;
    if (writer < 0)
      vb = va;
    else if (ran[writer])
      vb = dstate.end.data() + at;
    else
      fail(SIM_ERROR_BACKEND,
           describeRead(buffer, item) + inside +
               ", but its hermite derivative '" +
               buffers_[size_t(derivative)].info->name +
               "' has no value at the end of the big step yet (its writer '" +
               model_->components[size_t(writer)]->name + "' runs later)");
  }
  const uint8_t *a = state.begin.data() + at, *b = state.end.data() + at;
  int64_t offset = time - now;
  if (isF64(element)) {
    double f = double(offset) / double(stepSize);
    double h = double(stepSize) * settings.dtValue();
    interpolateLanes<double>(info.interp, element.lanes(), f, h, a, b, va, vb,
                             out);
  } else {
    float f = float(offset) / float(stepSize);
    float h = float(stepSize) * float(settings.dtValue());
    interpolateLanes<float>(info.interp, element.lanes(), f, h, a, b, va, vb,
                            out);
  }
}

//===----------------------------------------------------------------------===//
// Big steps
//===----------------------------------------------------------------------===//

int64_t ReferenceSession::numSteps(int32_t component, int64_t item, int64_t t) {
  running = {Body::NumSteps, component, t};
  int32_t n = numStepsFns[component](&context, item, t);
  rethrowCallbackError();
  running = {};
  return std::clamp<int64_t>(n, 1, scene().max_steps);
}

void ReferenceSession::evaluateInto(
    int32_t component, int64_t first, int64_t last, int64_t t, int64_t n,
    std::vector<std::vector<uint8_t>> &results) {
  const schema::RefComponentT &info = *model_->components[size_t(component)];
  results.clear();
  for (int32_t buffer : info.writes)
    results.emplace_back(size_t(last - first) * packed(buffer));
  std::vector<void *> outs(info.writes.size());
  double dt = settings.dtValue();
  running = {Body::Evaluate, component, t + n, t};
  for (int64_t i = first; i < last; ++i) {
    for (size_t k = 0; k < info.writes.size(); ++k)
      outs[k] = results[k].data() + size_t(i - first) * packed(info.writes[k]);
    evaluateFns[component](&context, i, t, int32_t(n), dt, outs.data());
    rethrowCallbackError();
  }
  running = {};
  evaluations[component] += last - first;
}

void ReferenceSession::evaluate(int32_t component, int64_t first, int64_t last,
                                int64_t t, int64_t n) {
  const schema::RefComponentT &info = *model_->components[size_t(component)];
  // Every item of the group reads the state before the sub-step: evaluate
  // into temporaries, then commit.
  std::vector<std::vector<uint8_t>> temporaries;
  evaluateInto(component, first, last, t, n, temporaries);
  for (size_t k = 0; k < info.writes.size(); ++k) {
    int32_t buffer = info.writes[k];
    std::memcpy(states[buffer].current.data() + size_t(first) * packed(buffer),
                temporaries[k].data(), temporaries[k].size());
  }
  if (checkFinite_)
    checkFinite(component, first, last, t, n);
}

void ReferenceSession::checkFinite(int32_t component, int64_t first,
                                   int64_t last, int64_t t, int64_t n) {
  const schema::RefComponentT &info = *model_->components[size_t(component)];
  for (uint32_t buffer : info.writes) {
    const schema::BufferT &type = *buffers_[buffer].info;
    const schema::Element &elementType = *type.element;
    const uint8_t *data = states[buffer].current.data();
    for (int64_t i = first; i < last; ++i) {
      const uint8_t *element = data + size_t(i) * packed(int32_t(buffer));
      for (int32_t l = 0; l < int32_t(elementType.lanes()); ++l) {
        double value = isF64(elementType) ? lane<double>(element, l)
                                          : double(lane<float>(element, l));
        if (std::isfinite(value))
          continue;
        nonFinite.found = true;
        nonFinite.baseStep = now;
        nonFinite.component = info.name;
        nonFinite.buffer = type.name;
        nonFinite.kernel = "sim_ref_evaluate_" + std::to_string(component);
        nonFinite.item = i;
        nonFinite.lane = l;
        nonFinite.value = value;
        std::string where = "item " + std::to_string(i);
        if (elementType.lanes() > 1)
          where += ", lane " + std::to_string(l);
        fail(SIM_ERROR_NONFINITE,
             "non-finite value " +
                 std::string(std::isnan(value) ? "nan"
                             : value > 0       ? "inf"
                                               : "-inf") +
                 " in buffer '" + type.name + "' (" + where +
                 ") after the reference evaluate of component '" + info.name +
                 "' at base step " + std::to_string(now) + " (big step of " +
                 std::to_string(stepSize) + ", sub-step from " +
                 std::to_string(t) + " to " + std::to_string(t + n) + ")");
      }
    }
  }
}

/// The largest power of two not above `value` (positive).
static int64_t floorPowerOfTwo(int64_t value) {
  int64_t power = 1;
  while (power <= value / 2)
    power *= 2;
  return power;
}

void ReferenceSession::bigStep(int64_t end) {
  const int64_t range = settings.range;
  const int32_t components = int32_t(model_->components.size());
  for (State &state : states)
    state.current = state.begin;
  ran.assign(model_->components.size(), false);
  stepSize = 0;

  // The size m of the big step: the minimum num_steps at T of the
  // components that estimate it, within the strategy's cap; a pair writer
  // under lts bounds it by its largest num_steps instead (docs/Model.md,
  // "The big step").
  int64_t m = stepCap;
  for (int32_t c = 0; c < components; ++c) {
    if (!stepping[size_t(c)].estimates())
      continue;
    if (stepping[size_t(c)].advance() == Advance::LocalFlux) {
      int64_t largest = 0;
      for (int64_t i = 0; i < range; ++i)
        largest = std::max(largest, numSteps(c, i, now));
      if (range > 0)
        m = std::min(m, largest);
      continue;
    }
    for (int64_t i = 0; i < range; ++i)
      m = std::min(m, numSteps(c, i, now));
  }
  // The end of the run cuts the big step short (the device clock's Cuts).
  if (end - now < m) {
    m = end - now;
    ++cutBigSteps;
  }
  // Local time steps take the same m: their sub-steps are cut at its end
  // (localSteps).
  stepSize = m;
  ++histogram[size_t(m)];
  ++metrics.big_steps;

  // The components in schedule order, each as the front end recorded it
  // takes the big step: whole, or in sub-steps of the minimum num_steps of
  // a group or of the whole range.
  for (int32_t c = 0; c < components; ++c) {
    const schema::RefComponentT &component = *model_->components[size_t(c)];
    Advance advance = stepping[size_t(c)].advance();
    if (advance == Advance::WholeStep) {
      evaluate(c, 0, range, now, m);
    } else if (advance == Advance::LocalFlux) {
      // Runs inside the slots of the component that reads its fluxes.
    } else if (advance == Advance::LocalSteps) {
      localSteps(c, m);
    } else {
      int64_t group = advance == Advance::GridSubSteps ? range : groupSize_;
      for (int64_t first = 0; first < range; first += group) {
        int64_t last = std::min(first + group, range);
        for (int64_t t = now; t < now + m;) {
          int64_t n = now + m - t;
          for (int64_t i = first; i < last; ++i)
            n = std::min(n, numSteps(c, i, t));
          evaluate(c, first, last, t, n);
          t += n;
        }
      }
    }
    for (uint32_t buffer : component.writes)
      states[buffer].end = states[buffer].current;
    ran[c] = true;
  }
  for (size_t b = 0; b < states.size(); ++b)
    if (buffers_[b].writer >= 0)
      states[b].begin = states[b].end;
  now += m;
  stepSize = 0;
}

void ReferenceSession::localSteps(int32_t component, int64_t m) {
  const schema::RefComponentT &info = *model_->components[size_t(component)];
  const int64_t range = settings.range;
  const int64_t group = int64_t(schema::LocalStepBlock::Items);
  const int64_t groups = (range + group - 1) / group;
  auto firstOf = [&](int64_t g) { return g * group; };
  auto lastOf = [&](int64_t g) { return std::min(range, (g + 1) * group); };

  // A flux pair: the writer whose fluxes this component reads.
  int32_t fluxWriter = -1;
  for (int32_t c = 0; c < int32_t(model_->components.size()); ++c) {
    if (stepping[size_t(c)].advance() != Advance::LocalFlux)
      continue;
    for (uint32_t buffer : model_->components[size_t(c)]->writes)
      if (std::find(info.reads.begin(), info.reads.end(), buffer) !=
          info.reads.end())
        fluxWriter = c;
  }
  // The items that read interface j of its fluxes: j - o for the offsets o
  // of its flux_window, under the fluxes' boundary rule (docs/Model.md,
  // "Conservation").
  auto readersOf = [&](int64_t j) {
    std::vector<int64_t> readers;
    const schema::RefComponentT &writer =
        *model_->components[size_t(fluxWriter)];
    schema::Boundary boundary = buffers_[writer.writes[0]].info->boundary;
    for (int64_t o = writer.flux_window[0]; o <= writer.flux_window[1]; ++o) {
      int64_t r = j - o;
      if (boundary == schema::Boundary::Wrap)
        r = ((r % range) + range) % range;
      else if (boundary == schema::Boundary::Clamp)
        r = std::clamp<int64_t>(r, 0, range - 1);
      else if (r < 0 || r >= range)
        continue;
      readers.push_back(r);
    }
    return readers;
  };

  // Each block's sub-step (blocks of LocalStepBlock::Items items, whatever
  // the group size), from the minimum of its items' num_steps at T and
  // those of the interfaces its items read, in units of u, the smallest
  // num_steps of any item or interface (at most m): the whole big step when
  // the minimum is m or more (counted as the smallest power of two of
  // units not below m, so that every sub-step is u times a power of two),
  // else u times the largest power of two within minimum / u. Every
  // sub-step ends at the end of the big step at the latest.
  levels = {};
  levels.level.assign(size_t(groups), 0);
  std::vector<int64_t> smallest(size_t(groups), m);
  int64_t unit = m;
  // (A pair's reader without num_steps: its writer's alone.)
  if (info.num_steps)
    for (int64_t g = 0; g < groups; ++g)
      for (int64_t i = firstOf(g); i < lastOf(g); ++i) {
        int64_t steps = numSteps(component, i, now);
        smallest[size_t(g)] = std::min(smallest[size_t(g)], steps);
        unit = std::min(unit, steps);
      }
  if (fluxWriter >= 0 && model_->components[size_t(fluxWriter)]->num_steps)
    for (int64_t j = 0; j < range; ++j) {
      int64_t steps = numSteps(fluxWriter, j, now);
      unit = std::min(unit, steps);
      for (int64_t r : readersOf(j))
        smallest[size_t(r / group)] =
            std::min(smallest[size_t(r / group)], steps);
    }
  int64_t whole = unit;
  while (whole < m)
    whole *= 2;
  for (int64_t g = 0; g < groups; ++g)
    levels.level[size_t(g)] =
        smallest[size_t(g)] >= m
            ? whole
            : unit * floorPowerOfTwo(smallest[size_t(g)] / unit);
  // No block more than twice as coarse as a block within reach of its
  // window (ceil(reach / block) blocks, around the range under wrap).
  int64_t reach = std::max(-info.local_window[0], info.local_window[1]);
  // A distance of `groups` or more reaches no other block than a shorter
  // one does: a window wider than the range costs the range.
  int64_t radius = std::min((reach + group - 1) / group, groups - 1);
  bool cyclic = false;
  for (uint32_t buffer : info.writes)
    cyclic |= buffers_[buffer].info->boundary == schema::Boundary::Wrap;
  for (bool changed = true; changed;) {
    changed = false;
    for (int64_t g = 0; g < groups; ++g)
      for (int64_t d = 1; d <= radius; ++d)
        for (int64_t h : {g - d, g + d}) {
          if (cyclic)
            h = ((h % groups) + groups) % groups;
          else if (h < 0 || h >= groups)
            continue;
          int64_t &own = levels.level[size_t(g)];
          if (own > 2 * levels.level[size_t(h)]) {
            own = 2 * levels.level[size_t(h)];
            changed = true;
          }
        }
  }

  // Slots in time order; the blocks whose sub-step starts at a slot read
  // the levels as they are before it, then all commit.
  levels.component = component;
  levels.fluxWriter = fluxWriter;
  levels.latest.assign(size_t(groups), now);
  levels.previous.assign(size_t(groups), now);
  levels.previousState.clear();
  for (uint32_t buffer : info.writes)
    levels.previousState.push_back(states[buffer].current);
  std::vector<std::vector<std::vector<uint8_t>>> results(
      static_cast<size_t>(groups));
  std::vector<std::vector<uint8_t>> flux;
  for (int64_t q = 0; q < m; ++q) {
    // The interfaces whose coarsest reader starts a sub-step here, from the
    // levels before the slot; their fluxes hold until its next one.
    if (fluxWriter >= 0) {
      const auto &writes = model_->components[size_t(fluxWriter)]->writes;
      std::vector<std::pair<int64_t, int64_t>> due;
      for (int64_t j = 0; j < range; ++j) {
        int64_t level = 0;
        for (int64_t r : readersOf(j))
          level = std::max(level, levels.level[size_t(r / group)]);
        if (level == 0)
          level = whole;
        if (q % level == 0)
          due.emplace_back(j, std::min(level, m - q));
      }
      std::vector<std::vector<uint8_t>> values;
      for (auto [j, length] : due) {
        evaluateInto(fluxWriter, j, j + 1, now + q, length, flux);
        for (size_t k = 0; k < writes.size(); ++k)
          values.push_back(flux[k]);
      }
      size_t next = 0;
      for (auto [j, length] : due) {
        for (uint32_t buffer : writes) {
          size_t bytes = packed(int32_t(buffer)), at = size_t(j) * bytes;
          std::memcpy(states[buffer].current.data() + at, values[next].data(),
                      bytes);
          std::memcpy(states[buffer].end.data() + at, values[next].data(),
                      bytes);
          ++next;
        }
        if (checkFinite_)
          checkFinite(fluxWriter, j, j + 1, now + q, length);
      }
    }
    std::vector<int64_t> starting;
    for (int64_t g = 0; g < groups; ++g)
      if (q % levels.level[size_t(g)] == 0)
        starting.push_back(g);
    auto lengthOf = [&](int64_t g) {
      return std::min(levels.level[size_t(g)], m - q);
    };
    for (int64_t g : starting)
      evaluateInto(component, firstOf(g), lastOf(g), now + q, lengthOf(g),
                   results[size_t(g)]);
    for (int64_t g : starting) {
      for (size_t k = 0; k < info.writes.size(); ++k) {
        uint32_t buffer = info.writes[k];
        size_t at = size_t(firstOf(g)) * packed(int32_t(buffer));
        std::vector<uint8_t> &current = states[buffer].current;
        std::memcpy(levels.previousState[k].data() + at, current.data() + at,
                    results[size_t(g)][k].size());
        std::memcpy(current.data() + at, results[size_t(g)][k].data(),
                    results[size_t(g)][k].size());
      }
      levels.previous[size_t(g)] = levels.latest[size_t(g)];
      levels.latest[size_t(g)] += lengthOf(g);
      if (checkFinite_)
        checkFinite(component, firstOf(g), lastOf(g), now + q, lengthOf(g));
    }
  }
  levels = {};
}

void ReferenceSession::readLevels(int32_t buffer, int64_t item, uint8_t *out) {
  const schema::BufferT &info = *buffers_[size_t(buffer)].info;
  const schema::Element &element = *info.element;
  size_t bytes = packed(buffer), at = size_t(item) * bytes;
  size_t g = size_t(item / int64_t(schema::LocalStepBlock::Items));
  int64_t t = running.localTime;
  int64_t a = levels.previous[g], b = levels.latest[g];
  const uint8_t *latest = states[buffer].current.data() + at;
  if (t == b) {
    std::memcpy(out, latest, bytes);
    return;
  }
  const auto &writes = model_->components[size_t(levels.component)]->writes;
  // The levels a buffer the component writes kept at the start of the
  // group's sub-step (none for a buffer it does not write).
  auto previousOf = [&](int32_t kept) -> const uint8_t * {
    auto found = std::find(writes.begin(), writes.end(), uint32_t(kept));
    if (found == writes.end())
      return nullptr;
    return levels.previousState[size_t(found - writes.begin())].data() + at;
  };
  if (!(a < t && t < b))
    fail(SIM_ERROR_BACKEND,
         describeRead(buffer, item) + " at local time " + std::to_string(t) +
             ", outside its group's time levels [" + std::to_string(a) + ", " +
             std::to_string(b) + "]");
  const uint8_t *previous = previousOf(buffer);
  // A Hermite derivative at the same item and the same two levels, which
  // only a buffer of the same component has (docs/Model.md, "What a read
  // returns").
  const uint8_t *va = nullptr, *vb = nullptr;
  if (info.interp == Interp::Hermite) {
    int32_t derivative = buffers_[size_t(buffer)].derivative;
    va = previousOf(derivative);
    if (!va)
      fail(SIM_ERROR_BACKEND,
           describeRead(buffer, item) + " at local time " + std::to_string(t) +
               " between its group's time levels, but its hermite "
               "derivative '" +
               buffers_[size_t(derivative)].info->name +
               "' is not written by the same component, so it has no "
               "value at those levels");
    vb = states[size_t(derivative)].current.data() + at;
  }
  if (isF64(element)) {
    double f = double(t - a) / double(b - a);
    double h = double(b - a) * settings.dtValue();
    interpolateLanes<double>(info.interp, element.lanes(), f, h, previous,
                             latest, va, vb, out);
  } else {
    float f = float(t - a) / float(b - a);
    float h = float(b - a) * float(settings.dtValue());
    interpolateLanes<float>(info.interp, element.lanes(), f, h, previous,
                            latest, va, vb, out);
  }
}

void ReferenceSession::run(int64_t steps, int64_t pause) {
  SubnormalScope mode(bundle->flushesSubnormals());
  runEnd(now, steps); // Checks the steps before initialising.
  runPause(now, steps, pause);
  ensureInitialized();
  metrics = {};
  cutBigSteps = 0;
  nonFinite = {};
  std::fill(evaluations.begin(), evaluations.end(), 0);
  std::fill(histogram.begin(), histogram.end(), 0);
  int64_t begin = now;
  int64_t end = runEnd(begin, steps);
  // Every big step ends on a boundary the host sees: pause at the first.
  int64_t pauseAt = runPause(begin, steps, pause);
  auto start = std::chrono::steady_clock::now();
  bool interrupted = false;
  while (now < end && now < pauseAt) {
    if (interruptPending()) {
      interrupted = true;
      break;
    }
    bigStep(end);
    if (progress)
      progress(progressUser, now - begin, steps);
  }
  metrics.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  // Every moment of a run is spent in or around the bodies.
  metrics.kernel_seconds = metrics.wall_seconds;
  metrics.steps = now - begin;
  metrics.begin = begin;
  metrics.end = now;
  if (interrupted)
    failInterrupted(begin, now, end);
}

//===----------------------------------------------------------------------===//
// Probes: the init check and totals of the exact solution
//===----------------------------------------------------------------------===//

template <typename Body> void ReferenceSession::probe(Body &&body) {
  auto restore = [&] {
    initial = &initialStates;
    probeStates = {};
    initChain.clear();
    running = {};
  };
  probeStates.reset(buffers_.size(), settings.range > kDenseProbeItems);
  initial = &probeStates;
  initChain.clear();
  callbackFailed = false;
  try {
    body();
  } catch (...) {
    restore();
    throw;
  }
  restore();
}

namespace {

/// The largest difference of one buffer so far, over the values of the
/// items evaluated.
struct Differences {
  InitCheck row;
  std::vector<double> values;
  bool f64 = false;
};

void compareElement(Differences &found, int64_t item, int32_t lanes,
                    const uint8_t *initial, const uint8_t *evaluated) {
  InitCheck &row = found.row;
  for (int32_t l = 0; l < lanes; ++l) {
    double a =
        found.f64 ? lane<double>(initial, l) : double(lane<float>(initial, l));
    double b = found.f64 ? lane<double>(evaluated, l)
                         : double(lane<float>(evaluated, l));
    if (!std::isfinite(a) || !std::isfinite(b)) {
      // Equal infinities agree; a NaN agrees with nothing.
      if (!(a == b)) {
        if (row.nonFinite++ == 0)
          row.nonFiniteItem = item;
      }
      continue;
    }
    row.scale = std::max({row.scale, std::fabs(a), std::fabs(b)});
    double difference = std::fabs(b - a);
    found.values.push_back(difference);
    if (row.item < 0 || difference > row.maxAbs) {
      row.maxAbs = difference;
      row.item = item;
      row.lane = l;
      row.initial = a;
      row.evaluated = b;
    }
  }
}

} // namespace

std::vector<InitCheck> ReferenceSession::checkInit(double tolerance,
                                                   int64_t maxItems,
                                                   const Executor *owner) {
  SubnormalScope mode(bundle->flushesSubnormals());
  if (maxItems <= 0)
    maxItems = kInitCheckItems;
  const int64_t range = settings.range;
  // The items evaluated: all of them, or the first and the last of the
  // range, where boundary rules and off-by-one inits show.
  std::vector<std::pair<int64_t, int64_t>> spans;
  if (range <= maxItems) {
    spans = {{0, range}};
  } else {
    int64_t tail = maxItems / 2;
    spans = {{0, maxItems - tail}, {range - tail, range}};
  }
  std::vector<InitCheck> rows;
  probe([&] {
    double dt = settings.dtValue();
    for (size_t c = 0; c < model_->components.size(); ++c) {
      const schema::RefComponentT &component = *model_->components[c];
      std::vector<Differences> found(component.writes.size());
      std::vector<std::vector<uint8_t>> outs;
      std::vector<void *> pointers;
      for (size_t k = 0; k < component.writes.size(); ++k) {
        uint32_t buffer = component.writes[k];
        InitCheck &row = found[k].row;
        row.buffer = buffers_[buffer].info->name;
        row.component = component.name;
        row.items = std::min(range, maxItems);
        const schema::BufferT &info = *buffers_[buffer].info;
        found[k].f64 = isF64(*info.element);
        // The tolerance of the floats its values derive from: an f64
        // buffer computed from f32 data is as exact as f32.
        row.tolerance = tolerance > 0               ? tolerance
                        : precisionBytes(info) == 8 ? kInitToleranceF64
                                                    : kInitToleranceF32;
        // A later component reads it: interpolated under hip.
        for (size_t r = c + 1; r < model_->components.size(); ++r) {
          const auto &reads = model_->components[r]->reads;
          row.interpolated |=
              std::find(reads.begin(), reads.end(), buffer) != reads.end();
        }
        outs.emplace_back(packed(int32_t(buffer)));
      }
      for (std::vector<uint8_t> &out : outs)
        pointers.push_back(out.data());
      for (auto [first, last] : spans)
        for (int64_t i = first; i < last; ++i) {
          // Evaluating every item of a large scene takes a while: a
          // request to stop (to this probe or to the session it checks)
          // ends the check.
          if (interruptPending() || (owner && owner->interruptPending()))
            fail(SIM_ERROR_INTERRUPTED, "interrupted during the init check");
          running = {Body::InitCheck, int32_t(c), 0};
          evaluateFns[c](&context, i, 0, 0, dt, pointers.data());
          rethrowCallbackError();
          running = {};
          for (size_t k = 0; k < component.writes.size(); ++k) {
            int32_t buffer = int32_t(component.writes[k]);
            compareElement(found[k], i,
                           buffers_[size_t(buffer)].info->element->lanes(),
                           initialItem(buffer, i), outs[k].data());
          }
        }
      for (size_t k = 0; k < found.size(); ++k) {
        // A flux is read only over its writer's steps, never as the init
        // (docs/Model.md, "Conservation"): nothing to check.
        if (buffers_[component.writes[k]].info->interp == Interp::Flux)
          continue;
        Differences &buffer = found[k];
        InitCheck &row = buffer.row;
        double limit = row.tolerance * row.scale;
        row.count = std::count_if(buffer.values.begin(), buffer.values.end(),
                                  [&](double d) { return d > limit; });
        rows.push_back(std::move(row));
      }
    }
  });
  return rows;
}

void ReferenceSession::exactItem(int32_t buffer, int64_t item, uint8_t *out) {
  const schema::BufferT &info = *buffers_[size_t(buffer)].info;
  if (!info.exact)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "total '" + totalName(size_t(running.component)) + "' reads buffer '" +
             info.name + "', which has no exact solution");
  Running saved = running;
  running = {Body::Exact, -1, saved.readTime};
  exactFns[size_t(buffer)](&context, item, exactTime, out);
  running = saved;
}

double ReferenceSession::exactTotal(const std::string &name, int64_t time) {
  SubnormalScope mode(bundle->flushesSubnormals());
  std::string why;
  if (!hasExactTotal(*bundle, name, &why))
    fail(SIM_ERROR_INVALID_ARGUMENT, why);
  size_t index = 0;
  while (totalName(index) != name)
    ++index;
  double sum = 0;
  probe([&] {
    exactTime = double(time) * settings.dtValue();
    running = {Body::ExactTotal, int32_t(index), time};
    sum = sumTotal(index);
  });
  return sum;
}

bool hasExactTotal(const Bundle &bundle, const std::string &name,
                   std::string *why) {
  auto no = [&](const std::string &reason) {
    if (why)
      *why = reason;
    return false;
  };
  const schema::SceneT &scene = bundle.scene();
  const schema::ReferenceT *model = bundle.reference();
  if (!model)
    return no("bundle '" + bundle.name +
              "' has no reference model to tell which buffers total '" + name +
              "' reads");
  for (const auto &total : model->totals) {
    if (scene.totals[total->total]->name != name)
      continue;
    for (uint32_t read : total->reads) {
      const schema::BufferT &buffer = *scene.buffers[model->buffers[read]];
      if (!buffer.exact)
        return no("total '" + name + "' reads buffer '" + buffer.name +
                  "', which has no exact solution");
    }
    return true;
  }
  return no("'" + name + "' is not a total of scene '" + scene.name + "'");
}

} // namespace sim::rt
