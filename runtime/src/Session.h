//===- Session.h - the plan executor ------------------------------*- C++
//-*-===//
//
// A Session runs one strategy's plan (docs/Plan.md) of a bundle on one
// backend: it owns the clock and the buffers, turns plan arguments into
// kernel parameters, and runs the phases. Runs launch the step phase many
// big steps ahead and look at the clock once per batch; the kernels decide
// every step size on the device.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_SESSION_H
#define SIM_RUNTIME_SESSION_H

#include "Backend.h"
#include "Bundle.h"
#include "Distribution.h"
#include "Executor.h"
#include "sim/Runtime/sim_runtime.h"

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace sim::rt {

class Session final : public Executor {
public:
  Session(std::shared_ptr<const Bundle> bundle,
          const sim_session_options &options);
  ~Session() override;
  Session(const Session &) = delete;
  Session &operator=(const Session &) = delete;

  const schema::SceneT &scene() const override { return bundle->scene(); }
  const std::shared_ptr<const Bundle> &sharedBundle() const override {
    return bundle;
  }
  Strategy strategy() const override { return plan_->strategy; }
  const Settings &currentSettings() const override { return settings; }
  const schema::PlanT &plan() const { return *plan_; }
  sim_backend backendKind() const override { return backend->kind(); }
  const std::string &device() const override { return deviceName; }
  const std::string &backendNote() const override { return note; }
  int64_t groupSize() const override { return groupSize_; }
  int64_t range() const override { return settings.range; }

  void set(const std::string &name, const std::string &value) override;
  std::string get(const std::string &name) const override {
    return settings.get(name);
  }

  /// Allocates what is missing, zeroes everything and runs phase init.
  void init() override;
  /// The clock's T (0 before init).
  int64_t time() const override {
    return clock.empty() ? 0 : clock[kSlotBegin];
  }

  int64_t memoryBytes(int64_t range) const override;
  size_t hostBytes(const std::string &buffer) const override;
  void getBuffer(const std::string &buffer, void *data, size_t bytes) override;
  void setBuffer(const std::string &buffer, const void *data,
                 size_t bytes) override;
  bool hasExact(const std::string &buffer) const override;
  void exact(const std::string &buffer, void *data, size_t bytes) override;

  using Executor::run;
  void run(int64_t steps, int64_t pause) override;

  size_t numTotals() const override { return plan_->totals.size(); }
  const std::string &totalName(size_t index) const override {
    return scene().totals[plan_->totals[index]]->name;
  }
  std::vector<double> totals() override;

  std::vector<std::string> stateBuffers() const override;
  size_t clockSlots() const override { return plan_->clock_slots; }
  std::vector<int64_t> checkpointClock() override;
  void restoreClock(int64_t time, const std::vector<int64_t> &clock) override;

  size_t numComponents() const override { return plan_->components.size(); }
  const std::string &componentName(size_t index) const override {
    return plan_->components[index]->name;
  }

  Communicator *communicator() override { return comm.get(); }

private:
  /// Where a buffer's current state lives on the device (the half the
  /// clock's parity selects) and its element stride there and on the host,
  /// after checking a host array of `bytes` for it and initialising.
  struct CurrentHalf {
    DevicePtr half;
    size_t stride, packed;
  };
  CurrentHalf currentHalf(const std::string &buffer, size_t bytes);
  /// One device allocation, released with the session.
  struct Memory {
    DevicePtr pointer = 0;
    size_t bytes = 0;
  };
  /// Distributed plans: one `exchange` entry of a launch, resolved against
  /// the current allocation. `halves` copies of `elements` elements of
  /// `stride` bytes from `base` (2 for a buffer, 1 for a snapshot). A
  /// replicated buffer's entry all-gathers every rank's block (`lists` is
  /// null); any other refreshes the ghosts in `lists`.
  struct GhostRefresh {
    DevicePtr base;
    size_t stride;
    int halves;
    int64_t elements;
    bool replicated;
    const GhostLists *lists;
    /// The plan buffer.
    size_t buffer;
    /// Which half travels: both, only the target half (1 - parity,
    /// `exchange_targets`), only the half the launch's grid-wide sub-step
    /// wrote (`exchange_sub_step`), or only the items of the blocks a local
    /// time step's slot started, in the halves they wrote
    /// (`exchange_local_step`), or only the target half's items of the
    /// blocks where a flux pair's reader starts a sub-step at the slot
    /// (`exchange_local_flux`); launchDistributed points a copy's `base`
    /// at one half and gives it `halves` 1 (and, for a slot, `lists` of
    /// the items of that half).
    enum class Half {
      Both,
      Target,
      SubStep,
      LocalStep,
      LocalFlux
    } half = Half::Both;
    /// Where element `e` of half `half` lies.
    DevicePtr element(int half, int64_t e) const {
      return base + DevicePtr(half * elements + e) * stride;
    }
  };
  /// A launch with its parameter values laid out for the backend.
  struct Prepared {
    const schema::LaunchT *launch;
    int kernel;
    int64_t groups, groupSize, sharedBytes;
    std::vector<uint64_t> values;
    std::vector<void *> params;
    /// Positions of `time` arguments in `values`.
    std::vector<size_t> timeValues;
    /// Distributed plans: the ghosts to refresh after the launch.
    std::vector<GhostRefresh> exchanges;
    /// A launch inside a repeat (a grid-wide sub-step round or a local
    /// time step's slot): the plan component whose sub-step clock says,
    /// the same on every rank, whether the round or slot takes a sub-step
    /// at all; -1 outside repeats.
    int roundOf = -1;
  };

  int bufferIndex(const std::string &name) const;
  /// The plan buffer `index` as the scene declares it.
  const schema::BufferT &sceneBuffer(size_t index) const {
    return *scene().buffers[plan_->buffers[index]->buffer];
  }
  void allocate();
  void releaseAll();
  void prepare();
  Prepared prepareLaunch(const schema::LaunchT &launch);
  void ensureInitialized();
  void runPhase(PhaseKind phase);
  void runUncounted(PhaseKind phase);
  void runStepPhase();
  void launch(Prepared &prepared);
  void readClock(size_t slots);
  /// The bytes of one item on the device and in a host array.
  size_t deviceStride(int buffer) const;

  // Distributed plans (Distribution.h); without `distributed` in the plan,
  // `comm` is null, first is 0 and count and extent are the range.
  bool distributed() const { return comm != nullptr; }
  /// The elements of one half of a buffer at `range` items on this rank.
  int64_t extentAt(int64_t range) const;
  /// Whether every rank holds all of plan buffer `buffer` (PlanBuffer.
  /// replicated): one half, its snapshot and its exact array are `range`
  /// elements, item i at element i; otherwise `extent` elements.
  bool replicated(size_t buffer) const {
    return distributed() && plan_->buffers[buffer]->replicated;
  }
  int64_t elementsOf(size_t buffer) const {
    return replicated(buffer) ? settings.range : extent;
  }
  /// The entries of a component's levels at `range` items: sections of
  /// one per block of LocalStepBlock::Items items.
  static int64_t levelCount(int64_t range) {
    const int64_t block = int64_t(schema::LocalStepBlock::Items);
    return int64_t(schema::LocalStepLevels::Sections) *
           ((range + block - 1) / block);
  }
  int64_t levelCount() const { return levelCount(settings.range); }
  /// The element of this rank's first item in one half of `buffer`.
  int64_t ownElement(size_t buffer) const {
    return replicated(buffer) ? first : halo;
  }
  /// Splits the current range over the ranks: first, count, extent.
  void layout();
  /// Checks once per change of the settings that every rank runs the same
  /// bundle, strategy, group size, range, dt and parameters.
  void ensureAgreed();
  /// Fails on every rank unless every rank holds the same `value` (a
  /// collective call).
  void agreeOn(const std::string &what, int64_t value);
  const GhostLists &ghostsOf(size_t buffer);
  GhostRefresh refreshOf(size_t buffer, bool snapshot);
  /// Fills the ghost elements of `refreshes` from their owners (one
  /// exchange for the ghosts, one all-gather for the replicated buffers);
  /// `counted` adds them to the run's metrics.
  void refreshGhosts(const std::vector<GhostRefresh> &refreshes, bool counted);
  /// refreshGhosts in two halves: beginGhosts sends the ghost items (after
  /// ending the exchange under way, if any), endGhosts waits for them and
  /// puts them in place; the launches between compute what needs none.
  /// `entries` is what the exchange counts (default: one per refresh).
  void beginGhosts(const std::vector<GhostRefresh> &refreshes, bool counted,
                   std::optional<size_t> entries = std::nullopt);
  void endGhosts();
  /// Of a `local_steps` component's buffer `r` (Half::LocalStep), after
  /// the launch of slot `slot`: the refreshes of the items of the blocks
  /// of `component` that started a sub-step at the slot, one per half they
  /// wrote (appended to `out`, their lists in `slotSelections`); of a flux
  /// writer's buffer (Half::LocalFlux, `component` the flux pair's reader),
  /// the target half's items of those blocks. Returns whether any item
  /// travels to, from or within this rank.
  bool slotRefreshes(const GhostRefresh &r, int component, int64_t slot,
                     int64_t parity, std::vector<GhostRefresh> &out);
  /// The component whose slot a launch's selective exchange follows: its
  /// own (`exchange_local_step`), the flux pair's reader
  /// (`exchange_local_flux`), or -1.
  int slotComponent(const schema::LaunchT &launch) const;
  /// Launches `p` while the exchange under way travels: its groups whose
  /// items' windows stay inside the block first, then (the ghost items in
  /// place) the others; or, where that cannot be, after the exchange.
  void launchAroundExchange(Prepared &p);
  /// Whether `p` takes a buffer (or snapshot) whose ghost items are under
  /// way.
  bool readsPendingGhosts(const Prepared &p) const;
  /// The all-gather of the replicated entries of `refreshes`: every rank's
  /// block into place in every half. Returns the bytes this rank sent.
  size_t gatherReplicated(const std::vector<GhostRefresh> &refreshes);
  /// Every buffer's ghosts, both halves (after init and setBuffer).
  void refreshAllGhosts();
  /// Whether `p`, a launch of a round or slot of the component
  /// `p.roundOf`, would change nothing because that component has taken
  /// its last sub-step of the big step (docs/Plan.md), from the clock as
  /// every rank holds it.
  bool noOpLaunch(const Prepared &p);
  /// The big step (T, m) and the sub-step clock's Begin and Size of
  /// `component`, as the clock holds them now.
  struct SubStepTimes {
    int64_t begin, size, subBegin, subSize;
  };
  SubStepTimes subStepTimes(int component);
  /// Scans the buffers the component of `prepared` writes after its
  /// launch; `before` is where its sub-step clock stood before a sub-step
  /// or slot launch, which the message names.
  void checkFinite(const Prepared &prepared,
                   const std::optional<SubStepTimes> &before = std::nullopt);
  /// ", sub-step from t to t + n" (a grid round) or ", in the slot at base
  /// step t" (local steps) for `component`'s clock `before` a launch.
  std::string subStepNote(int component,
                          const std::optional<SubStepTimes> &before) const;
  /// Whether `p` decides the next sub-step of a grid round whose component
  /// has at most one base step of the big step left (so its all-reduce of
  /// the estimate would decide nothing).
  bool settledRound(const Prepared &p);
  /// Whether clock `slot` is a kept largest estimate (keeps_estimate).
  bool keptEstimateSlot(uint32_t slot) const;
  /// The maximum over the ranks that hold items of them of the codes of
  /// this big step's blocks within each component's level reach of this
  /// rank's block, in the levels of `components` (a launch's
  /// `reduce_max_levels`): one exchange with those ranks.
  void reduceLevels(const std::vector<uint32_t> &components, bool counted);
  /// The exchange of reduceLevels for `components`, whose codes are in
  /// half `parity` of their levels.
  void reduceLevelCodes(const std::vector<uint32_t> &components, bool counted,
                        int64_t parity);
  /// After that launch (limit_levels_C): the finest sub-step of each of
  /// `components` (its sub-step clock's Size) by its minimum over all
  /// ranks, one all-reduce.
  void reduceFinest(const std::vector<uint32_t> &components);
  /// The minimum over the ranks of the unit requests of `components`
  /// (local time steps, before limit_levels_C).
  void reduceUnitRequests(const std::vector<uint32_t> &components);
  /// Where slot `slot` of `component`'s sub-step clock lies.
  DevicePtr subClockSlot(size_t component, schema::SubClockSlot slot) const;
  /// Replaces slot `slot` of the sub-step clocks of `components` by its
  /// minimum over the ranks, in one all-reduce.
  void minimumOverRanks(const std::vector<uint32_t> &components,
                        schema::SubClockSlot slot);
  /// A launch of a distributed plan: its all-reduces, the kernel, its
  /// exchanges (in the step phase, `step`, none past the run's end).
  void launchDistributed(Prepared &prepared, bool counted, bool step = false);
  /// Every rank's owned items of the array at `array`, whose element
  /// `own` holds this rank's first item (`stride` bytes per element),
  /// `packed` bytes of each, in item order into the host array `out`.
  void gatherItems(DevicePtr array, int64_t own, size_t stride, size_t packed,
                   void *out);

  std::shared_ptr<const Bundle> bundle;
  const schema::PlanT *plan_ = nullptr;
  sim_session_options options;
  std::unique_ptr<Backend> backend;
  std::string deviceName, note;

  int64_t groupSize_ = 0;
  Settings settings;

  Memory clockMemory;
  std::vector<Memory> buffers, snapshots, exacts;
  /// Per total: its per-item values (`range` doubles).
  std::vector<Memory> totalValues;
  /// Per plan component: the sub-steps of its groups when it takes local
  /// time steps (ArgKind::Levels), else nothing.
  std::vector<Memory> levels;
  /// The host's copy of the clock as last read (valid after init).
  std::vector<int64_t> clock;
  bool allocated = false, initialized = false, prepared = false;
  /// The state is on a big-step boundary (after init, a run that ended or
  /// was interrupted, a restart), not inside a big step a failed run left.
  bool onBoundary = false;
  bool graphReady = false;
  /// Every launch of the plan once, and per phase the order they run in
  /// (repeats unrolled into indices).
  std::vector<Prepared> launches;
  std::vector<uint32_t> phases[kNumPhases];
  bool hasPhase[kNumPhases] = {};

  std::unique_ptr<Communicator> comm;
  /// plan.distributed.halo; this rank's block [first, first + count) and
  /// the elements of one half, count + 2 * halo.
  int64_t halo = 0, first = 0, count = 0, extent = 0;
  std::unique_ptr<Decomposition> decomposition;
  /// Per (below, above, boundary): the ghost lists of the decomposition.
  std::map<std::tuple<uint32_t, uint32_t, int>, GhostLists> ghostCache;
  /// Per (ghost lists, plan buffer) of a slot's exchange: the level
  /// blocks its elements' items lie in (each once, and per element its
  /// index among them), and the lists of the items a slot selects in each
  /// half, refilled per slot (slotRefreshes) and kept until the exchange
  /// ends.
  struct SlotSelection {
    std::vector<int64_t> blocks;
    std::vector<std::vector<uint32_t>> sendBlock, recvBlock;
    std::vector<uint32_t> localBlock;
    std::vector<int> halfOfBlock;
    GhostLists selected[2];
  };
  std::map<std::pair<const GhostLists *, size_t>, SlotSelection> slotSelections;
  /// Per level reach: the level blocks whose codes this rank sends to and
  /// receives from each rank (reduceLevels).
  struct LevelLists {
    std::vector<std::vector<int64_t>> send, recv;
  };
  std::map<int64_t, LevelLists> levelListsCache;
  /// Per component: its kernels keep its codes (keeps_levels) and have kept
  /// them since reduceLevels gathered them last, so later big steps need
  /// no gathering. Cleared at every run from the initial state (init), as
  /// the kept codes are.
  std::vector<bool> levelsKept;
  /// The clock slots of kept largest estimates (keeps_estimate) that the
  /// ranks have all-reduced since the slot was last zeroed: later big steps
  /// read the kept value, so they need no all-reduce. Cleared with
  /// levelsKept.
  std::set<uint32_t> estimatesKept;
  /// Zeroes the levels of every keeps_levels component, kept codes
  /// included, and every kept largest estimate (keeps_estimate), after dt or
  /// a parameter changed (set).
  void forgetKeptLevels();
  /// Host memory of the backend's allocateHost (page-locked on CUDA),
  /// grown as needed: per peer, what this rank sends and receives.
  class Staging {
  public:
    Staging() = default;
    Staging(Staging &&other) noexcept
        : backend(other.backend), memory(other.memory),
          capacity(other.capacity) {
      other.memory = nullptr;
      other.capacity = 0;
    }
    Staging(const Staging &) = delete;
    Staging &operator=(const Staging &) = delete;
    Staging &operator=(Staging &&) = delete;
    ~Staging() { release(); }
    /// At least `bytes` of it (its contents are lost when it grows).
    uint8_t *ensure(Backend &owner, size_t bytes) {
      if (!memory || bytes > capacity) {
        release();
        backend = &owner;
        memory = owner.allocateHost(bytes);
        capacity = bytes;
      }
      return static_cast<uint8_t *>(memory);
    }
    void release() {
      if (memory)
        backend->releaseHost(memory);
      memory = nullptr;
      capacity = 0;
    }

  private:
    Backend *backend = nullptr;
    void *memory = nullptr;
    size_t capacity = 0;
  };
  std::vector<Staging> sendStore, recvStore;
  /// The exchange under way (beginGhosts to endGhosts): its ghost entries,
  /// the arrays the communicator holds, and what it counts once done.
  struct PendingGhosts {
    bool active = false, counted = false;
    std::vector<GhostRefresh> ghosts;
    std::vector<const void *> send;
    std::vector<void *> recv;
    std::vector<size_t> sendBytes, recvBytes;
    size_t entries = 0, bytes = 0;
  } pendingGhosts;
  std::vector<uint8_t> gatherStore;
  bool agreed = false;
  /// Since the session began (a run's metrics take the difference).
  int64_t haloExchanges = 0, exchangedBytes = 0;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_SESSION_H
