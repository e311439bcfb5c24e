//===- Reference.h - the reference executor -----------------------*- C++
//-*-===//
//
// The oracle every backend is checked against (docs/Reference.md). It runs
// the per-body functions of the bundle's reference object (section kind 6)
// one item at a time, following the model text (kind 5), and decides
// everything about time itself: big steps, sub-steps, read roles and
// interpolation, in plain C++ written from the semantics of docs/Model.md.
// Nothing of the plan executor (clock, memory plan, kernels) takes part.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_REFERENCE_H
#define SIM_RUNTIME_REFERENCE_H

#include "Bundle.h"
#include "Executor.h"
#include "SharedObject.h"
#include "sim/Runtime/sim_reference.h"

#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace sim::rt {

/// What sim_session_check_init found for one buffer: its init against what
/// its writer's evaluate body gives with n = 0 at t = 0 on the initial
/// state (docs/Runtime.md, "Warnings").
struct InitCheck {
  std::string buffer, component;
  /// Items evaluated: the whole range, or the first and the last of it.
  int64_t items = 0;
  /// The largest |evaluate - init| over the finite values, where it is and
  /// the two values there (item -1: no finite value).
  double maxAbs = 0;
  int64_t item = -1;
  int32_t lane = 0;
  double initial = 0, evaluated = 0;
  /// The largest |value| of the buffer over the items (init and evaluate),
  /// the relative tolerance, and how many values differ by more than
  /// tolerance * scale.
  double scale = 0, tolerance = 0;
  int64_t count = 0;
  /// Values where one side is NaN or infinite and the other is not the
  /// same: evaluate cannot run with n = 0 (it divides by n, say) or the
  /// init is not finite; the first such item.
  int64_t nonFinite = 0, nonFiniteItem = -1;
  /// A component later in the schedule reads the buffer: hip and
  /// hip-cache interpolate it from its init in the first big step.
  bool interpolated = false;

  bool mismatch() const { return count > 0; }
};

/// The items sim_session_check_init evaluates at most by default, and the
/// relative tolerances of f32 and f64 buffers.
constexpr int64_t kInitCheckItems = int64_t(1) << 16;
constexpr double kInitToleranceF32 = 1e-5;
constexpr double kInitToleranceF64 = 1e-12;

/// Whether total `name` of the bundle's reference model reads only buffers
/// with an exact solution, so that its value on the exact solution exists;
/// if not, `why` says why not.
bool hasExactTotal(const Bundle &bundle, const std::string &name,
                   std::string *why = nullptr);

class ReferenceSession final : public Executor {
public:
  ReferenceSession(std::shared_ptr<const Bundle> bundle,
                   const sim_session_options &options);
  ~ReferenceSession() override;

  const schema::SceneT &scene() const override { return bundle->scene(); }
  const std::shared_ptr<const Bundle> &sharedBundle() const override {
    return bundle;
  }
  Strategy strategy() const override { return strategy_; }
  const Settings &currentSettings() const override { return settings; }
  const schema::ReferenceT &model() const { return *model_; }
  sim_backend backendKind() const override { return SIM_BACKEND_REFERENCE; }
  const std::string &device() const override { return deviceName; }
  const std::string &backendNote() const override { return note; }
  int64_t groupSize() const override { return groupSize_; }
  int64_t range() const override { return settings.range; }

  void set(const std::string &name, const std::string &value) override;
  std::string get(const std::string &name) const override {
    return settings.get(name);
  }

  void init() override;
  int64_t time() const override { return now; }

  int64_t memoryBytes(int64_t range) const override;
  size_t hostBytes(const std::string &buffer) const override;
  void getBuffer(const std::string &buffer, void *data, size_t bytes) override;
  void setBuffer(const std::string &buffer, const void *data,
                 size_t bytes) override;
  bool hasExact(const std::string &buffer) const override;
  void exact(const std::string &buffer, void *data, size_t bytes) override;

  using Executor::run;
  void run(int64_t steps, int64_t pause) override;

  size_t numTotals() const override { return model_->totals.size(); }
  const std::string &totalName(size_t index) const override {
    return scene().totals[model_->totals[index]->total]->name;
  }
  std::vector<double> totals() override;

  std::vector<std::string> stateBuffers() const override;
  size_t clockSlots() const override { return 0; }
  std::vector<int64_t> checkpointClock() override;
  void restoreClock(int64_t time, const std::vector<int64_t> &clock) override;

  size_t numComponents() const override { return model_->components.size(); }
  const std::string &componentName(size_t index) const override {
    return model_->components[index]->name;
  }

  /// Takes range, dt and the parameters of another session of the bundle.
  void adopt(const Settings &values) { settings = values; }

  /// Evaluates every component's evaluate body at t = 0 with n = 0 on the
  /// initial state, for every item (for at most `maxItems`, 0:
  /// kInitCheckItems; above, the first and the last half of that many),
  /// and compares what it yields with the initial state of each buffer it
  /// writes. A relative `tolerance` of 0 takes kInitToleranceF32 or F64 by
  /// the buffer's type. Leaves the session's state as it was. Throws
  /// SIM_ERROR_INTERRUPTED when this session or `owner` (the session whose
  /// init it checks) is interrupted meanwhile.
  std::vector<InitCheck> checkInit(double tolerance, int64_t maxItems,
                                   const Executor *owner = nullptr);

  /// The value of total `name` on the exact solution at base step `time`:
  /// its body's reads see the exact solutions of the buffers it reads.
  double exactTotal(const std::string &name, int64_t time);

private:
  using InitFn = sim_ref_init_fn;
  using ExactFn = sim_ref_exact_fn;
  using TotalFn = sim_ref_total_fn;
  using NumStepsFn = sim_ref_num_steps_fn;
  using EvaluateFn = sim_ref_evaluate_fn;

  /// A buffer's values, `range` items of packed lanes each: at the start
  /// T of the big step, at its end T + m (once the writer ran), and as the
  /// writer advances through the step.
  struct State {
    std::vector<uint8_t> begin, end, current;
  };

  /// Initial states, computed on demand item by item: after init() every
  /// item of every buffer; in a probe (checkInit, exactTotal), which needs
  /// no state, only the items the bodies read, in `range` elements per
  /// buffer allocated on first use, or above kDenseProbeItems in a map per
  /// buffer.
  struct InitialStates {
    struct Item {
      uint8_t status = 0;
      std::vector<uint8_t> element;
    };
    bool sparse = false;
    /// Dense: per buffer the elements and a status byte per item (0 not
    /// computed, 1 being computed, 2 done).
    std::vector<std::vector<uint8_t>> elements, status;
    std::vector<std::unordered_map<int64_t, Item>> items;

    void reset(size_t buffers, bool sparseItems);
  };
  static constexpr int64_t kDenseProbeItems = int64_t(1) << 20;

  /// The body running now: what its reads mean.
  enum class Body {
    None,
    Init,
    Exact,
    NumSteps,
    Evaluate,
    Total,
    /// checkInit's evaluate with n = 0: every read sees the initial state.
    InitCheck,
    /// exactTotal's total body: every read sees the exact solution.
    ExactTotal,
  };
  struct Running {
    Body body = Body::None;
    /// The component (the total for ExactTotal).
    int32_t component = -1;
    /// The local time reads of earlier components' buffers are at.
    int64_t readTime = 0;
    /// The local time the body advances from (the start of its sub-step):
    /// what reads of its own buffers see under local time steps.
    int64_t localTime = 0;
  };

  /// The time levels of a component that takes local time steps, during
  /// its big step (docs/Model.md, "Local time stepping"): every block's
  /// sub-step and the times of its two levels; every item's previous level
  /// of each buffer it writes (the latest is the state's `current`).
  struct LocalLevels {
    int32_t component = -1;
    /// The flux writer of a flux pair with `component`, which reads its
    /// state from these levels (-1: none).
    int32_t fluxWriter = -1;
    std::vector<int64_t> level, latest, previous;
    std::vector<std::vector<uint8_t>> previousState;
  };

  static void readCallback(void *executor, int32_t buffer, int64_t item,
                           void *out);
  static void paramCallback(void *executor, int32_t param, void *out);
  void read(int32_t buffer, int64_t item, void *out);
  void param(int32_t param, void *out);
  /// Throws what a callback could not (no exception crosses the C frames
  /// of a body): call after every body.
  void rethrowCallbackError();

  int bufferIndex(const std::string &name) const;
  size_t packed(int32_t buffer) const {
    return size_t(packedBytes(*buffers_[size_t(buffer)].info->element));
  }
  void ensureInitialized();
  /// The initial element of `buffer` at `item`, computed on demand.
  const uint8_t *initialItem(int32_t buffer, int64_t item);
  /// Where that element and its status live in the current store.
  uint8_t *initialSlot(int32_t buffer, int64_t item, uint8_t *&status);
  /// Runs `body` on initial states of its own, then restores the session's.
  template <typename Body> void probe(Body &&body);
  /// Fails unless the running component's model lists `buffer` in its
  /// `reads`.
  void requireListedRead(int32_t buffer, int64_t item) const;
  /// The exact solution of `buffer` at `item` at exactTime, for a read of
  /// the running exactTotal.
  void exactItem(int32_t buffer, int64_t item, uint8_t *out);
  /// The sum over the items of total `index`'s body, in item order in
  /// double, with `running` set by the caller.
  double sumTotal(size_t index);
  /// What the running num_steps or evaluate body sees of `buffer` at
  /// `item` (inside the range).
  void readInStep(int32_t buffer, int64_t item, uint8_t *out);
  void interpolate(int32_t buffer, int64_t item, uint8_t *out);
  std::string describeRead(int32_t buffer, int64_t item) const;

  void bigStep(int64_t end);
  int64_t numSteps(int32_t component, int64_t item, int64_t t);
  void evaluate(int32_t component, int64_t first, int64_t last, int64_t t,
                int64_t n);
  /// Evaluates items [first, last) from t over n base steps into
  /// `results` (one array per written buffer), without committing them.
  void evaluateInto(int32_t component, int64_t first, int64_t last, int64_t t,
                    int64_t n, std::vector<std::vector<uint8_t>> &results);
  /// Takes `component`'s big step of m in local time steps.
  void localSteps(int32_t component, int64_t m);
  /// A read of `buffer`, written by the component taking local time
  /// steps, from the time levels of `item`'s group.
  void readLevels(int32_t buffer, int64_t item, uint8_t *out);
  void checkFinite(int32_t component, int64_t first, int64_t last, int64_t t,
                   int64_t n);

  std::shared_ptr<const Bundle> bundle;
  const schema::ReferenceT *model_;
  /// The model's buffers resolved against the scene: what a buffer is, its
  /// Hermite derivative and its writer as model indices (-1: none).
  struct ModelBuffer {
    const schema::BufferT *info;
    int32_t derivative = -1;
    int32_t writer = -1;
  };
  std::vector<ModelBuffer> buffers_;
  /// How each component takes a big step under the session's strategy,
  /// and the largest big step: the front end's records.
  std::vector<schema::Stepping> stepping;
  int64_t stepCap = 1;
  Strategy strategy_;
  int64_t groupSize_ = 0;
  bool checkFinite_ = false;
  std::string deviceName = "reference executor (CPU, 1 thread)", note;
  Settings settings;

  std::unique_ptr<SharedObject> object;
  std::vector<InitFn> initFns;
  std::vector<ExactFn> exactFns;
  std::vector<NumStepsFn> numStepsFns;
  std::vector<EvaluateFn> evaluateFns;
  std::vector<TotalFn> totalFns;
  sim_ref_context context;

  std::vector<State> states;
  /// The initial states of init(), those of a probe, and the store
  /// initialItem uses now.
  InitialStates initialStates, probeStates;
  InitialStates *initial = &initialStates;
  /// The time exactTotal evaluates exact solutions at (time units).
  double exactTime = 0;
  /// The init bodies running, outermost first (for cycle messages).
  std::vector<std::pair<int32_t, int64_t>> initChain;
  bool initialized = false;
  /// T, and the big step [T, T + m] being taken (m = 0 while it is being
  /// decided).
  int64_t now = 0, stepSize = 0;
  /// Which components have run in this big step: their buffers' end exists.
  std::vector<bool> ran;
  Running running;
  LocalLevels levels;
  /// The first error a callback met, thrown when the body returns.
  bool callbackFailed = false;
  sim_status callbackStatus = SIM_OK;
  std::string callbackMessage;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_REFERENCE_H
