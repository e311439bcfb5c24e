//===- Executor.h - what the C API runs: a session of a bundle ----*- C++
//-*-===//
//
// Two kinds of session sit behind a sim_session: the plan executor
// (Session.h), which runs a strategy's plan on CUDA or the CPU, and the
// reference executor (Reference.h), which runs the per-body reference
// functions with plain C++ semantics. The C API sees only this interface,
// and both share the handling of range, dt and the scene parameters
// (Settings).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_EXECUTOR_H
#define SIM_RUNTIME_EXECUTOR_H

#include "Bundle.h"
#include "sim/Runtime/sim_runtime.h"

#include <atomic>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace sim::rt {

class Communicator;

/// `range`, `dt` and the scene's parameters, set and read as text.
class Settings {
public:
  explicit Settings(const Bundle &bundle);

  /// Sets `name` from `text`. `checkRange` is called with a new range
  /// before it is taken and throws if the state would not fit. Returns
  /// whether the range changed (the caller discards its state then). A
  /// range is a positive item count of at most kMaxRange, dt a positive,
  /// finite, normal number of its type.
  bool set(const std::string &name, const std::string &text,
           const std::function<void(int64_t)> &checkRange);
  std::string get(const std::string &name) const;

  /// dt as the bodies compute with it: an f32 dt rounded to float first.
  double dtValue() const {
    return dt.type == ScalarType::F32 ? double(float(dt.f)) : dt.f;
  }

  const Bundle *bundle;
  int64_t range;
  Value dt;
  std::vector<Value> params;
};

/// The largest range a session takes: far above any memory, and small
/// enough that item indices, element offsets and byte counts of a buffer
/// fit in 64 bits.
constexpr int64_t kMaxRange = int64_t(1) << 40;

/// `a * b` and `a + b` of byte counts, saturating at INT64_MAX (which no
/// memory limit allows).
int64_t saturatingMul(int64_t a, int64_t b);
int64_t saturatingAdd(int64_t a, int64_t b);

/// Bytes of physical memory of this machine (0 if unknown).
int64_t physicalMemoryBytes();

/// "1.50 GiB", "512 KiB", "37 bytes".
std::string formatBytes(int64_t bytes);

/// Comma-separated names, "none" for none.
std::string listNames(const std::vector<std::string> &names);

/// The end `begin + steps` of a run, after checking that `steps` is not
/// negative and the end fits in the clock.
int64_t runEnd(int64_t begin, int64_t steps);

/// Where a run of `steps` from `begin` may pause: `begin + pause`, or its
/// end when `pause >= steps`; a pause below 1 is an invalid argument.
int64_t runPause(int64_t begin, int64_t steps, int64_t pause);

class Executor {
public:
  virtual ~Executor() = default;

  virtual const schema::SceneT &scene() const = 0;
  /// The bundle the session runs, and its current range, dt and
  /// parameters: what a reference executor needs to probe the same scene
  /// (sim_session_check_init, sim_session_exact_total).
  virtual const std::shared_ptr<const Bundle> &sharedBundle() const = 0;
  /// The bundle and strategy the session runs (a checkpoint must match
  /// them).
  const Bundle &sourceBundle() const { return *sharedBundle(); }
  virtual Strategy strategy() const = 0;
  virtual const Settings &currentSettings() const = 0;
  virtual sim_backend backendKind() const = 0;
  virtual const std::string &device() const = 0;
  /// Why `auto` did not choose CUDA (empty otherwise).
  virtual const std::string &backendNote() const = 0;
  virtual int64_t groupSize() const = 0;
  virtual int64_t range() const = 0;

  virtual void set(const std::string &name, const std::string &value) = 0;
  virtual std::string get(const std::string &name) const = 0;

  /// Discards the state and computes the initial one (base step 0).
  virtual void init() = 0;
  /// The current base step T.
  virtual int64_t time() const = 0;

  /// Host arrays hold `range` items of `lanes` packed scalars.
  virtual size_t hostBytes(const std::string &buffer) const = 0;
  virtual void getBuffer(const std::string &buffer, void *data,
                         size_t bytes) = 0;
  virtual void setBuffer(const std::string &buffer, const void *data,
                         size_t bytes) = 0;
  virtual bool hasExact(const std::string &buffer) const = 0;
  /// The exact solution at time T * dt.
  virtual void exact(const std::string &buffer, void *data, size_t bytes) = 0;

  /// Runs `steps` base steps; the run ends exactly at T + steps or throws.
  void run(int64_t steps) { run(steps, steps); }
  /// Runs towards T + steps, but stops at the first big-step boundary at or
  /// after T + pause that the host sees (no big step is cut there, so a
  /// later run towards the same end takes the big steps one run would
  /// have); `pause >= steps` is run(steps).
  virtual void run(int64_t steps, int64_t pause) = 0;

  /// The totals the scene declares (sums over items it observes).
  virtual size_t numTotals() const = 0;
  virtual const std::string &totalName(size_t index) const = 0;
  /// Every total at the current T, in declaration order: the per-item
  /// values summed in item order in double precision.
  virtual std::vector<double> totals() = 0;

  /// Checkpoints (Checkpoint.cpp): the buffers whose state a checkpoint
  /// holds, in order (the plan's; the reference model's).
  virtual std::vector<std::string> stateBuffers() const = 0;
  /// The slots of the device clock (0 for the reference executor).
  virtual size_t clockSlots() const = 0;
  /// The clock a checkpoint holds, after initialising a session without a
  /// state: every slot of the device clock, on a big-step boundary (a
  /// session whose last run failed inside a big step is refused); empty for
  /// the reference executor, whose clock is T alone.
  virtual std::vector<int64_t> checkpointClock() = 0;
  /// Starts over from a checkpoint's clock: the state at base step `time`
  /// with `clock` in the device clock (the plan executor; the reference
  /// executor takes `time` alone). The buffers follow with setBuffer.
  virtual void restoreClock(int64_t time,
                            const std::vector<int64_t> &clock) = 0;

  /// A distributed session's ranks (Distribution.h); null otherwise.
  virtual Communicator *communicator() { return nullptr; }

  /// The components the evaluation counters are for.
  virtual size_t numComponents() const = 0;
  virtual const std::string &componentName(size_t index) const = 0;

  void setProgress(sim_progress_fn fn, void *user) {
    progress = fn;
    progressUser = user;
  }

  /// The bytes the state takes at `range` items (saturating).
  virtual int64_t memoryBytes(int64_t range) const = 0;
  /// The most the state may take.
  int64_t memoryLimit() const { return memoryLimit_; }

  /// Requests that runs stop at their next host synchronisation; safe from
  /// a signal handler.
  void interrupt() {
    interruptRequested.store(true, std::memory_order_relaxed);
  }
  void resume() { interruptRequested.store(false, std::memory_order_relaxed); }
  bool interruptPending() const {
    return interruptRequested.load(std::memory_order_relaxed);
  }

  /// The last run's measurements.
  sim_metrics metrics{};
  /// Big steps of the last run that its end cut short (clock slot Cuts):
  /// at most one per run, its last.
  int64_t cutBigSteps = 0;
  std::vector<int64_t> evaluations; // per component
  std::vector<int64_t> histogram;   // index m in 0 .. max_steps

  /// The last run's launches of each kernel of the plan, and their time
  /// where the backend times every launch (the CPU), else -1. Empty for
  /// the reference executor, which launches no kernels.
  struct KernelFigures {
    std::string name;
    int64_t launches = 0;
    double seconds = -1;
  };
  std::vector<KernelFigures> kernelFigures;

  /// Where the last run found a non-finite value.
  struct NonFinite {
    bool found = false;
    int64_t baseStep = 0;
    std::string component, buffer, kernel;
    int64_t item = 0;
    int32_t lane = 0;
    double value = 0;
  } nonFinite;

protected:
  /// Sets the limit from the options (0: three quarters of `deviceBytes`,
  /// the device's memory; no limit when that is unknown).
  void setMemoryLimit(int64_t requested, int64_t deviceBytes);
  /// Throws SIM_ERROR_MEMORY_LIMIT when the state at `range` items would
  /// not fit the limit; `what` names the request ("range 100000000").
  void checkMemory(int64_t range, const std::string &what) const;
  /// Throws SIM_ERROR_INTERRUPTED for a run from `begin` to `end` that
  /// stopped at `reached`.
  [[noreturn]] void failInterrupted(int64_t begin, int64_t reached,
                                    int64_t end) const;

  sim_progress_fn progress = nullptr;
  void *progressUser = nullptr;

private:
  static_assert(std::atomic<bool>::is_always_lock_free,
                "sim_session_interrupt must be async-signal-safe");
  std::atomic<bool> interruptRequested{false};
  int64_t memoryLimit_ = 0;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_EXECUTOR_H
