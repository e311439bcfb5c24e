//===- CApi.cpp - the C API of sim_runtime.h ------------------------------===//
//
// Thin wrappers over Bundle and the two executors (Session, the plan
// executor, and ReferenceSession) behind the Executor interface. This is the
// only place where exceptions are caught: every entry point turns an Error (or
// any other exception, e.g. std::bad_alloc) into a status code and a
// thread-local message, so nothing but C crosses the API.
//
//===----------------------------------------------------------------------===//

#include "sim/Runtime/sim_runtime.h"

#include "Bundle.h"
#include "Checkpoint.h"
#include "CudaDriver.h"
#include "Error.h"
#include "Reference.h"
#include "Session.h"

#include <cmath>
#include <cstring>
#include <new>

using namespace sim::rt;

struct sim_bundle {
  std::shared_ptr<const Bundle> bundle;
};

struct sim_session {
  std::unique_ptr<Executor> session;
  /// The last sim_session_check_init's results.
  std::vector<InitCheck> initChecks;
  /// A run is in progress: its progress callback may read the session, and
  /// interrupt it, but not change it (a new range, state or clock under the
  /// running loop would leave it stepping freed or stale memory).
  bool running = false;
  /// sim_session_destroy was called during the run: it ends at its next
  /// host synchronisation and then deletes the session.
  bool destroyed = false;
};

namespace {

thread_local std::string lastError;

/// A reference executor of the session's bundle with its range, dt and
/// parameters, for what only the reference functions can compute.
std::unique_ptr<ReferenceSession> probeOf(const Executor &session) {
  sim_session_options options;
  options = {};
  options.strategy = SIM_STRATEGY_SIMPLE;
  options.backend = SIM_BACKEND_REFERENCE;
  options.group_size = 1;
  auto probe =
      std::make_unique<ReferenceSession>(session.sharedBundle(), options);
  probe->adopt(session.currentSettings());
  return probe;
}

sim_status failWith(sim_status status, const std::string &message) {
  lastError = message;
  return status;
}

/// Runs `body`, mapping exceptions to a status and sim_last_error().
template <typename Body> sim_status guard(Body &&body) {
  try {
    body();
    lastError.clear();
    return SIM_OK;
  } catch (const Error &error) {
    return failWith(error.status, error.what());
  } catch (const std::bad_alloc &) {
    return failWith(SIM_ERROR_BACKEND, "out of host memory");
  } catch (const std::exception &error) {
    return failWith(SIM_ERROR_BACKEND, error.what());
  }
}

sim_status nullArgument(const char *function, const char *what) {
  return failWith(SIM_ERROR_INVALID_ARGUMENT,
                  std::string(function) + ": " + what + " is null");
}

#define SIM_REQUIRE(pointer)                                                   \
  if (!(pointer))                                                              \
  return nullArgument(__func__, #pointer)

/// `function` was called on a session whose run is in progress (from the
/// progress callback, or from another thread).
sim_status sessionRunning(const char *function) {
  lastError = std::string(function) +
              ": the session's run is in progress (a progress callback may "
              "read the session or interrupt the run, not change it)";
  return SIM_ERROR_INVALID_ARGUMENT;
}

#define SIM_REQUIRE_IDLE(session)                                              \
  if ((session)->running)                                                      \
  return sessionRunning(__func__)

/// Runs `session` (sim_session_run and sim_session_run_pausing), marked as
/// running, and deletes it afterwards where sim_session_destroy was called
/// meanwhile.
sim_status runSession(sim_session *session, int64_t steps, int64_t pause) {
  session->running = true;
  sim_status status = guard([&] { session->session->run(steps, pause); });
  session->running = false;
  if (!session->destroyed)
    return status;
  delete session;
  lastError = "the session was destroyed during its run (sim_session_destroy "
              "from the progress callback): the run stopped and the session "
              "is gone";
  return SIM_ERROR_INTERRUPTED;
}

} // namespace

extern "C" {

const char *sim_last_error(void) { return lastError.c_str(); }

const char *sim_status_name(sim_status status) {
  switch (status) {
  case SIM_OK:
    return "ok";
  case SIM_ERROR_INVALID_ARGUMENT:
    return "invalid argument";
  case SIM_ERROR_IO:
    return "i/o error";
  case SIM_ERROR_BUNDLE:
    return "bad bundle";
  case SIM_ERROR_NO_DRIVER:
    return "no CUDA driver";
  case SIM_ERROR_NO_DEVICE:
    return "no CUDA device";
  case SIM_ERROR_BACKEND:
    return "backend error";
  case SIM_ERROR_NONFINITE:
    return "non-finite value";
  case SIM_ERROR_CLOCK:
    return "clock error";
  case SIM_ERROR_INTERRUPTED:
    return "interrupted";
  case SIM_ERROR_MEMORY_LIMIT:
    return "memory limit";
  case SIM_ERROR_CHECKPOINT:
    return "bad checkpoint";
  case SIM_ERROR_DISTRIBUTED:
    return "distributed run failed";
  }
  return "unknown status";
}

const char *sim_strategy_name(sim_strategy strategy) {
  if (uint32_t(strategy) >= uint32_t(kNumStrategies))
    return "unknown";
  return strategyName(Strategy(strategy));
}

sim_status sim_strategy_parse(const char *name, sim_strategy *out) {
  SIM_REQUIRE(name);
  SIM_REQUIRE(out);
  std::optional<Strategy> strategy = parseStrategy(name);
  if (!strategy) {
    // Every name the runtime knows, so that a new strategy is listed too.
    std::string known;
    for (int index = 0; index < kNumStrategies; ++index)
      known += (index ? ", " : "") + std::string(strategyName(Strategy(index)));
    return failWith(SIM_ERROR_INVALID_ARGUMENT, "unknown strategy '" +
                                                    std::string(name) + "' (" +
                                                    known + ")");
  }
  *out = sim_strategy(*strategy);
  lastError.clear();
  return SIM_OK;
}

const char *sim_backend_name(sim_backend backend) {
  switch (backend) {
  case SIM_BACKEND_AUTO:
    return "auto";
  case SIM_BACKEND_CPU:
    return "cpu";
  case SIM_BACKEND_CUDA:
    return "cuda";
  case SIM_BACKEND_REFERENCE:
    return "reference";
  }
  return "unknown";
}

sim_status sim_backend_parse(const char *name, sim_backend *out) {
  SIM_REQUIRE(name);
  SIM_REQUIRE(out);
  for (sim_backend backend : {SIM_BACKEND_AUTO, SIM_BACKEND_CPU,
                              SIM_BACKEND_CUDA, SIM_BACKEND_REFERENCE})
    if (std::strcmp(name, sim_backend_name(backend)) == 0) {
      *out = backend;
      lastError.clear();
      return SIM_OK;
    }
  return failWith(SIM_ERROR_INVALID_ARGUMENT,
                  "unknown backend '" + std::string(name) +
                      "' (auto, cpu, cuda, reference)");
}

sim_status sim_cuda_device_count(int32_t *out) {
  SIM_REQUIRE(out);
  return guard([&] {
    const cuda::Driver &cu = cuda::driver();
    int count = 0;
    cu.check(cu.cuDeviceGetCount(&count), "cuDeviceGetCount");
    *out = count;
  });
}

//===----------------------------------------------------------------------===//
// Bundles
//===----------------------------------------------------------------------===//

sim_status sim_bundle_open(const char *path, sim_bundle **out) {
  SIM_REQUIRE(path);
  SIM_REQUIRE(out);
  *out = nullptr;
  return guard([&] { *out = new sim_bundle{Bundle::read(path)}; });
}

sim_status sim_bundle_open_memory(const void *data, size_t size,
                                  sim_bundle **out) {
  SIM_REQUIRE(out);
  *out = nullptr;
  if (!data && size)
    return nullArgument(__func__, "data");
  return guard([&] {
    *out = new sim_bundle{
        Bundle::parse(static_cast<const uint8_t *>(data), size, "<memory>")};
  });
}

void sim_bundle_close(sim_bundle *bundle) { delete bundle; }

const char *sim_bundle_scene_name(const sim_bundle *bundle) {
  return bundle ? bundle->bundle->scene().name.c_str() : "";
}
int64_t sim_bundle_range(const sim_bundle *bundle) {
  return bundle ? bundle->bundle->scene().range : 0;
}
double sim_bundle_dt(const sim_bundle *bundle) {
  return bundle ? bundle->bundle->scene().dt->float_value() : 0;
}
const char *sim_bundle_dt_type(const sim_bundle *bundle) {
  return bundle ? scalarTypeName(bundle->bundle->scene().dt->type()) : "";
}
int64_t sim_bundle_max_steps(const sim_bundle *bundle) {
  return bundle ? bundle->bundle->scene().max_steps : 0;
}

static const schema::PlanT *planOf(const sim_bundle *bundle,
                                   sim_strategy strategy) {
  if (!bundle || uint32_t(strategy) >= uint32_t(kNumStrategies))
    return nullptr;
  return bundle->bundle->plan(Strategy(strategy));
}

int sim_bundle_has_strategy(const sim_bundle *bundle, sim_strategy strategy) {
  return planOf(bundle, strategy) != nullptr;
}
int sim_bundle_has_ptx(const sim_bundle *bundle, sim_strategy strategy) {
  const schema::PlanT *plan = planOf(bundle, strategy);
  return plan && !plan->ptx.empty();
}
int sim_bundle_has_cpu(const sim_bundle *bundle, sim_strategy strategy) {
  const schema::PlanT *plan = planOf(bundle, strategy);
  return plan && bundle->bundle->cpuCode(*plan) != nullptr;
}
int sim_bundle_flushes_subnormals(const sim_bundle *bundle) {
  return bundle && bundle->bundle->flushesSubnormals();
}
int sim_bundle_has_reference(const sim_bundle *bundle) {
  return bundle && bundle->bundle->reference() != nullptr;
}

int32_t sim_bundle_num_buffers(const sim_bundle *bundle) {
  return bundle ? int32_t(bundle->bundle->scene().buffers.size()) : 0;
}

sim_status sim_bundle_buffer(const sim_bundle *bundle, int32_t index,
                             sim_buffer_info *out) {
  SIM_REQUIRE(bundle);
  SIM_REQUIRE(out);
  const Bundle &contents = *bundle->bundle;
  const auto &buffers = contents.scene().buffers;
  if (index < 0 || size_t(index) >= buffers.size())
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "buffer index " + std::to_string(index) +
                        " is out of range (" + std::to_string(buffers.size()) +
                        " buffers)");
  const schema::BufferT &buffer = *buffers[size_t(index)];
  out->name = buffer.name.c_str();
  out->element_type = contents.elementTexts[size_t(index)].c_str();
  out->scalar_type = isF64(*buffer.element) ? "f64" : "f32";
  out->scalar_bytes = int32_t(scalarBytes(*buffer.element));
  out->lanes = buffer.element->lanes();
  out->interp = contents.interpTexts[size_t(index)].c_str();
  out->boundary = boundaryName(buffer.boundary);
  out->observed = buffer.observed;
  out->exact = buffer.exact;
  out->precision_bytes = precisionBytes(buffer);
  lastError.clear();
  return SIM_OK;
}

int32_t sim_bundle_total_precision_bytes(const sim_bundle *bundle,
                                         const char *name) {
  if (!bundle || !name)
    return 0;
  for (const auto &total : bundle->bundle->scene().totals)
    if (total->name == name)
      return precisionBytes(*total);
  return 0;
}

int32_t sim_bundle_num_params(const sim_bundle *bundle) {
  return bundle ? int32_t(bundle->bundle->scene().params.size()) : 0;
}

sim_status sim_bundle_param(const sim_bundle *bundle, int32_t index,
                            sim_param_info *out) {
  SIM_REQUIRE(bundle);
  SIM_REQUIRE(out);
  const Bundle &contents = *bundle->bundle;
  const auto &params = contents.scene().params;
  if (index < 0 || size_t(index) >= params.size())
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "parameter index " + std::to_string(index) +
                        " is out of range (" + std::to_string(params.size()) +
                        " parameters)");
  const schema::ParamT &param = *params[size_t(index)];
  out->name = param.name.c_str();
  out->type = scalarTypeName(param.value->type());
  out->default_value = contents.defaultTexts[size_t(index)].c_str();
  lastError.clear();
  return SIM_OK;
}

//===----------------------------------------------------------------------===//
// Sessions
//===----------------------------------------------------------------------===//

void sim_session_options_init(sim_session_options *options) {
  if (!options)
    return;
  *options = {};
  options->strategy = SIM_STRATEGY_HIP;
  options->backend = SIM_BACKEND_AUTO;
}

sim_status sim_session_create(const sim_bundle *bundle,
                              const sim_session_options *options,
                              sim_session **out) {
  SIM_REQUIRE(bundle);
  SIM_REQUIRE(out);
  *out = nullptr;
  sim_session_options defaults;
  sim_session_options_init(&defaults);
  const sim_session_options &chosen = options ? *options : defaults;
  return guard([&] {
    std::unique_ptr<Executor> session;
    if (chosen.backend == SIM_BACKEND_REFERENCE)
      session = std::make_unique<ReferenceSession>(bundle->bundle, chosen);
    else
      session = std::make_unique<Session>(bundle->bundle, chosen);
    *out = new sim_session{std::move(session), {}};
  });
}

void sim_session_destroy(sim_session *session) {
  if (session && session->running) {
    // From the progress callback: the run stops at its next host
    // synchronisation and runSession deletes the session then.
    session->destroyed = true;
    session->session->interrupt();
    return;
  }
  delete session;
}

sim_backend sim_session_backend(const sim_session *session) {
  return session ? session->session->backendKind() : SIM_BACKEND_AUTO;
}
const char *sim_session_device(const sim_session *session) {
  return session ? session->session->device().c_str() : "";
}
const char *sim_session_backend_note(const sim_session *session) {
  return session ? session->session->backendNote().c_str() : "";
}
int64_t sim_session_group_size(const sim_session *session) {
  return session ? session->session->groupSize() : 0;
}

sim_status sim_session_set(sim_session *session, const char *name,
                           const char *value) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  SIM_REQUIRE(name);
  SIM_REQUIRE(value);
  return guard([&] { session->session->set(name, value); });
}

sim_status sim_session_get(const sim_session *session, const char *name,
                           char *value, size_t capacity) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(name);
  SIM_REQUIRE(value);
  return guard([&] {
    std::string text = session->session->get(name);
    if (text.size() + 1 > capacity)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "the value of '" + std::string(name) + "' takes " +
               std::to_string(text.size() + 1) + " bytes, more than " +
               std::to_string(capacity));
    std::memcpy(value, text.c_str(), text.size() + 1);
  });
}

int64_t sim_session_memory_bytes(const sim_session *session) {
  return session ? session->session->memoryBytes(session->session->range()) : 0;
}

int64_t sim_session_memory_limit(const sim_session *session) {
  return session ? session->session->memoryLimit() : 0;
}

int64_t sim_session_range(const sim_session *session) {
  return session ? session->session->range() : 0;
}

sim_status sim_session_init(sim_session *session) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  return guard([&] { session->session->init(); });
}

int64_t sim_session_time(const sim_session *session) {
  return session ? session->session->time() : 0;
}

sim_status sim_session_buffer_bytes(const sim_session *session,
                                    const char *buffer, size_t *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(buffer);
  SIM_REQUIRE(out);
  return guard([&] { *out = session->session->hostBytes(buffer); });
}

sim_status sim_session_get_buffer(sim_session *session, const char *buffer,
                                  void *data, size_t bytes) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(buffer);
  SIM_REQUIRE(data);
  return guard([&] { session->session->getBuffer(buffer, data, bytes); });
}

sim_status sim_session_set_buffer(sim_session *session, const char *buffer,
                                  const void *data, size_t bytes) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  SIM_REQUIRE(buffer);
  SIM_REQUIRE(data);
  return guard([&] { session->session->setBuffer(buffer, data, bytes); });
}

int sim_session_has_exact(const sim_session *session, const char *buffer) {
  return session && buffer && session->session->hasExact(buffer);
}

sim_status sim_session_exact(sim_session *session, const char *buffer,
                             void *data, size_t bytes) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(buffer);
  SIM_REQUIRE(data);
  return guard([&] { session->session->exact(buffer, data, bytes); });
}

int32_t sim_session_num_totals(const sim_session *session) {
  return session ? int32_t(session->session->numTotals()) : 0;
}

const char *sim_session_total_name(const sim_session *session, int32_t index) {
  if (!session || index < 0 || size_t(index) >= session->session->numTotals())
    return nullptr;
  return session->session->totalName(size_t(index)).c_str();
}

sim_status sim_session_total(sim_session *session, const char *name,
                             double *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(name);
  SIM_REQUIRE(out);
  return guard([&] {
    Executor &executor = *session->session;
    for (size_t i = 0; i < executor.numTotals(); ++i)
      if (executor.totalName(i) == name) {
        *out = executor.totals()[i];
        return;
      }
    std::vector<std::string> names;
    for (size_t i = 0; i < executor.numTotals(); ++i)
      names.push_back(executor.totalName(i));
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "'" + std::string(name) + "' is not a total of scene '" +
             executor.scene().name + "' (totals: " + listNames(names) + ")");
  });
}

int sim_session_has_exact_total(const sim_session *session, const char *name) {
  return session && name &&
         hasExactTotal(*session->session->sharedBundle(), name);
}

sim_status sim_session_exact_total(sim_session *session, const char *name,
                                   double *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(name);
  SIM_REQUIRE(out);
  return guard([&] {
    std::string why;
    if (!hasExactTotal(*session->session->sharedBundle(), name, &why))
      fail(SIM_ERROR_INVALID_ARGUMENT, why);
    *out =
        probeOf(*session->session)->exactTotal(name, session->session->time());
  });
}

sim_status sim_session_check_init(sim_session *session, double tolerance,
                                  int64_t max_items, int32_t *count) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(count);
  *count = 0;
  if (!(tolerance >= 0) || !std::isfinite(tolerance))
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "the init check's tolerance must be 0 (the default) or "
                    "positive and finite, not " +
                        std::to_string(tolerance));
  if (max_items < 0)
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "the init check's max_items must be 0 (the default) or "
                    "positive, not " +
                        std::to_string(max_items));
  session->initChecks.clear();
  return guard([&] {
    session->initChecks =
        probeOf(*session->session)
            ->checkInit(tolerance, max_items, session->session.get());
    *count = int32_t(session->initChecks.size());
  });
}

sim_status sim_session_init_check(const sim_session *session, int32_t index,
                                  sim_init_check *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(out);
  if (index < 0 || size_t(index) >= session->initChecks.size())
    return failWith(
        SIM_ERROR_INVALID_ARGUMENT,
        "init check result " + std::to_string(index) + " is out of range (" +
            std::to_string(session->initChecks.size()) + " results)");
  const InitCheck &row = session->initChecks[size_t(index)];
  out->buffer = row.buffer.c_str();
  out->component = row.component.c_str();
  out->items = row.items;
  out->max_abs = row.maxAbs;
  out->item = row.item;
  out->lane = row.lane;
  out->initial = row.initial;
  out->evaluated = row.evaluated;
  out->scale = row.scale;
  out->tolerance = row.tolerance;
  out->count = row.count;
  out->non_finite = row.nonFinite;
  out->non_finite_item = row.nonFiniteItem;
  out->interpolated = row.interpolated;
  lastError.clear();
  return SIM_OK;
}

void sim_session_set_progress(sim_session *session, sim_progress_fn progress,
                              void *user) {
  if (session)
    session->session->setProgress(progress, user);
}

sim_status sim_session_run(sim_session *session, int64_t steps) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  return runSession(session, steps, steps);
}

sim_status sim_session_run_pausing(sim_session *session, int64_t steps,
                                   int64_t pause) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  return runSession(session, steps, pause);
}

void sim_session_interrupt(sim_session *session) {
  if (session)
    session->session->interrupt();
}

void sim_session_resume(sim_session *session) {
  if (session)
    session->session->resume();
}

sim_status sim_session_metrics(const sim_session *session, sim_metrics *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(out);
  *out = session->session->metrics;
  lastError.clear();
  return SIM_OK;
}

int32_t sim_session_num_kernels(const sim_session *session) {
  return session ? int32_t(session->session->kernelFigures.size()) : 0;
}

sim_status sim_session_kernel_profile(const sim_session *session, int32_t index,
                                      sim_kernel_profile *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(out);
  const auto &kernels = session->session->kernelFigures;
  if (index < 0 || size_t(index) >= kernels.size())
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "sim_session_kernel_profile: kernel " +
                        std::to_string(index) +
                        " does not exist: the session's plan has " +
                        std::to_string(kernels.size()) + " kernels");
  const auto &kernel = kernels[size_t(index)];
  *out = {kernel.name.c_str(), kernel.launches, kernel.seconds};
  lastError.clear();
  return SIM_OK;
}

int32_t sim_session_num_components(const sim_session *session) {
  return session ? int32_t(session->session->numComponents()) : 0;
}

const char *sim_session_component(const sim_session *session, int32_t index) {
  if (!session || index < 0 ||
      size_t(index) >= session->session->numComponents())
    return nullptr;
  return session->session->componentName(size_t(index)).c_str();
}

int64_t sim_session_evaluations(const sim_session *session, int32_t component) {
  if (!session || component < 0 ||
      size_t(component) >= session->session->evaluations.size())
    return 0;
  return session->session->evaluations[component];
}

int64_t sim_session_histogram(const sim_session *session, int64_t size) {
  if (!session || size < 1 ||
      size >= int64_t(session->session->histogram.size()))
    return 0;
  return session->session->histogram[size];
}

int64_t sim_session_cut_big_steps(const sim_session *session) {
  return session ? session->session->cutBigSteps : 0;
}

sim_status sim_session_checkpoint(sim_session *session, const char *path) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  SIM_REQUIRE(path);
  return guard([&] { writeCheckpointFile(*session->session, path); });
}

sim_status sim_session_checkpoint_fd(sim_session *session, int fd) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  return guard([&] {
    writeCheckpoint(*session->session, fd,
                    "file descriptor " + std::to_string(fd));
  });
}

sim_status sim_session_restart(sim_session *session, const char *path) {
  SIM_REQUIRE(session);
  SIM_REQUIRE_IDLE(session);
  SIM_REQUIRE(path);
  return guard([&] { restartFromCheckpointFile(*session->session, path); });
}

sim_status sim_session_nonfinite(const sim_session *session,
                                 sim_nonfinite *out) {
  SIM_REQUIRE(session);
  SIM_REQUIRE(out);
  const Executor::NonFinite &found = session->session->nonFinite;
  if (!found.found)
    return failWith(SIM_ERROR_INVALID_ARGUMENT,
                    "the last run found no non-finite value");
  out->base_step = found.baseStep;
  out->component = found.component.c_str();
  out->buffer = found.buffer.c_str();
  out->kernel = found.kernel.c_str();
  out->item = found.item;
  out->lane = found.lane;
  out->value = found.value;
  lastError.clear();
  return SIM_OK;
}

} // extern "C"
