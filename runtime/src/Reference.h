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
#include <vector>

namespace sim::rt {

class ReferenceSession final : public Executor {
public:
  ReferenceSession(std::shared_ptr<const Bundle> bundle,
                   const sim_session_options &options);
  ~ReferenceSession() override;

  const schema::SceneT &scene() const override { return bundle->scene(); }
  const Bundle &sourceBundle() const override { return *bundle; }
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

private:
  using InitFn = sim_ref_init_fn;
  using ExactFn = sim_ref_exact_fn;
  using TotalFn = sim_ref_total_fn;
  using NumStepsFn = sim_ref_num_steps_fn;
  using EvaluateFn = sim_ref_evaluate_fn;

  /// A buffer's values, `range` items of packed lanes each: the initial
  /// state, at the start T of the big step, at its end T + m (once the
  /// writer ran), and as the writer advances through the step.
  struct State {
    std::vector<uint8_t> initial, begin, end, current;
  };

  /// The body running now: what its reads mean.
  enum class Body { None, Init, Exact, NumSteps, Evaluate, Total };
  struct Running {
    Body body = Body::None;
    int32_t component = -1;
    /// The local time reads of earlier components' buffers are at.
    int64_t readTime = 0;
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
  /// What the running num_steps or evaluate body sees of `buffer` at
  /// `item` (inside the range).
  void readInStep(int32_t buffer, int64_t item, uint8_t *out);
  void interpolate(int32_t buffer, int64_t item, uint8_t *out);
  std::string describeRead(int32_t buffer, int64_t item) const;

  void bigStep(int64_t end);
  int64_t numSteps(int32_t component, int64_t item, int64_t t);
  void evaluate(int32_t component, int64_t first, int64_t last, int64_t t,
                int64_t n);
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
  /// Per buffer and item: 0 not computed, 1 being computed, 2 done.
  std::vector<std::vector<uint8_t>> initStatus;
  /// The init bodies running, outermost first (for cycle messages).
  std::vector<std::pair<int32_t, int64_t>> initChain;
  bool initialized = false;
  /// T, and the big step [T, T + m] being taken (m = 0 while it is being
  /// decided).
  int64_t now = 0, stepSize = 0;
  /// Which components have run in this big step: their buffers' end exists.
  std::vector<bool> ran;
  Running running;
  /// The first error a callback met, thrown when the body returns.
  bool callbackFailed = false;
  sim_status callbackStatus = SIM_OK;
  std::string callbackMessage;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_REFERENCE_H
