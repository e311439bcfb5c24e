//===- LaunchSplit.h - when a CPU launch is worth splitting -----*- C++ -*-===//
//
// The CPU backend splits a launch of several groups over its threads, the
// calling thread included. Waking the other threads and waiting for them
// costs microseconds, so a launch with less work than that runs faster on
// the calling thread alone: on the two-core machine of docs/benchmarks.md
// the 64 x 64 plate under simple ran 1.35 times slower on two threads than
// on one. How much work a launch holds depends on the kernel, the scene
// and the slot, not on anything the backend is told, so the backend
// measures it, per kernel: kTrials launches shared, then, unless those
// were long (kLongLaunch: splitting them always pays), kTrials alone; from
// then on the faster way, decided again every kWindow launches, with the
// other way tried again now and then (less often the further behind it
// is), so that a change of the work (a big step that grows, levels that
// move) is noticed. Groups are independent and the clock's counters are
// integer atomics, so the way a launch runs changes no result, only its
// time.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_LAUNCHSPLIT_H
#define SIM_RUNTIME_LAUNCHSPLIT_H

#include <algorithm>
#include <cstdint>
#include <vector>

namespace sim::rt {

class LaunchSplit {
public:
  enum Mode : int { Shared = 0, Alone = 1 };

  /// How kernel `kernel`'s next launch runs.
  Mode choose(size_t kernel) {
    Kernel &k = at(kernel);
    ++k.launches;
    if (k.phase != Phase::Running)
      return k.phase == Phase::TrialShared ? Shared : Alone;
    if (k.burstLeft > 0) {
      --k.burstLeft;
      return other(k.chosen);
    }
    if (k.launches % k.probeEvery == 0) {
      k.burstLeft = kBurst - 1;
      return other(k.chosen);
    }
    return k.chosen;
  }

  /// Records a launch of `kernel` that ran `mode` over `groups` groups
  /// and took `ticks` (of the backend's launch clock). The first launch
  /// after a change of mode is not counted: the first shared one pays for
  /// waking the threads that slept while the caller ran alone, which a run
  /// of shared launches does not.
  void record(size_t kernel, Mode mode, uint64_t ticks, int64_t groups) {
    Kernel &k = at(kernel);
    bool first = mode != k.last || k.launches == 1;
    k.last = mode;
    if (first)
      return;
    Window &window = k.window[mode];
    window.ticks += double(ticks);
    window.groups += double(std::max<int64_t>(groups, 1));
    ++window.launches;
    switch (k.phase) {
    case Phase::TrialShared:
      if (window.launches < kTrials)
        return;
      if (window.ticks / double(window.launches) >= kLongLaunch) {
        // Long launches: splitting pays whatever the balance of the work,
        // so alone is tried only rarely.
        k.phase = Phase::Running;
        k.cost[Shared] = window.ticks / window.groups;
        k.window[Shared] = Window();
        k.probeEvery = kLongestProbeEvery;
        return;
      }
      k.phase = Phase::TrialAlone;
      return;
    case Phase::TrialAlone:
      if (window.launches < kTrials)
        return;
      k.phase = Phase::Running;
      decide(k);
      return;
    case Phase::Running:
      if (++k.recorded % kWindow == 0)
        decide(k);
      return;
    }
  }

  /// The way kernel `kernel` runs now, for tests and reports.
  Mode chosen(size_t kernel) { return at(kernel).chosen; }

  /// The parts a shared launch of `groups` groups is cut into, dealt to
  /// `threads` threads in turn (part p to thread p mod threads): one to
  /// kPartsPerThread per thread, of at least kMinGroupsPerPart groups, so
  /// that uneven work spreads over the threads while a launch stays a few
  /// calls (a call has fixed costs: its lane variables, its atomics on the
  /// clock). A kernel whose groups' work differs widely within a launch
  /// (`uneven`: the bundle's Kernel.uneven_groups, a slot kernel of local
  /// time steps, where only the blocks due at the slot evaluate) gets
  /// parts of kMinGroupsPerUnevenPart groups: with one contiguous range
  /// per thread, the heat rod's 16 groups gave one thread the stiff half
  /// and the other only quick returns.
  static int64_t partsFor(int64_t groups, int64_t threads, bool uneven) {
    int64_t least = uneven ? kMinGroupsPerUnevenPart : kMinGroupsPerPart;
    return threads *
           std::clamp<int64_t>(groups / (threads * least), 1, kPartsPerThread);
  }
  static constexpr int64_t kPartsPerThread = 4, kMinGroupsPerPart = 16,
                           kMinGroupsPerUnevenPart = 4;

  /// Counted launches of each mode at first (after one not counted).
  static constexpr uint64_t kTrials = 4;
  /// Shared launches this long (in ticks: about 50-200 microseconds at the
  /// 1-4 GHz of a time stamp counter, or 200 with steady_clock's
  /// nanoseconds) hold enough work to split.
  static constexpr double kLongLaunch = 200000;
  /// Counted launches of a kernel between two decisions.
  static constexpr uint64_t kWindow = 512;
  /// Every so many launches the mode not chosen runs kBurst times in a
  /// row: an odd number, so that a kernel whose work repeats with a period
  /// (the slots of a big step, a power of two) is not always tried at the
  /// same phase; while it stays kFarBehind, about twice as seldom after
  /// each decision (2 n + 1, odd again), up to kLongestProbeEvery.
  static constexpr uint64_t kProbeEvery = 67, kBurst = 4,
                            kLongestProbeEvery = 64 * kProbeEvery - 1;
  static constexpr double kFarBehind = 1.5;

private:
  enum class Phase { TrialShared, TrialAlone, Running };
  struct Window {
    double ticks = 0, groups = 0;
    uint64_t launches = 0;
  };
  struct Kernel {
    Phase phase = Phase::TrialShared;
    Mode chosen = Shared, last = Shared;
    uint64_t launches = 0, recorded = 0, probeEvery = kProbeEvery,
             burstLeft = 0;
    /// Ticks per group of each mode, 0 until measured.
    double cost[2] = {0, 0};
    Window window[2];
  };

  static Mode other(Mode mode) { return mode == Shared ? Alone : Shared; }

  Kernel &at(size_t kernel) {
    if (kernel >= kernels.size())
      kernels.resize(kernel + 1);
    return kernels[kernel];
  }

  void decide(Kernel &k) {
    for (Mode mode : {Shared, Alone}) {
      Window &window = k.window[mode];
      if (window.groups == 0)
        continue;
      double cost = window.ticks / window.groups;
      // The mode in use has a window's launches at every phase; the other
      // a few probes, averaged with what it measured before.
      k.cost[mode] = mode == k.chosen || k.cost[mode] == 0
                         ? cost
                         : (k.cost[mode] + cost) / 2;
      window = Window();
    }
    if (k.cost[Shared] == 0 || k.cost[Alone] == 0)
      return;
    Mode faster = k.cost[Alone] < k.cost[Shared] ? Alone : Shared;
    double behind = k.cost[other(faster)] / k.cost[faster];
    if (faster != k.chosen || behind < kFarBehind)
      k.probeEvery = kProbeEvery;
    else
      k.probeEvery = std::min(k.probeEvery * 2 + 1, kLongestProbeEvery);
    k.chosen = faster;
  }

  std::vector<Kernel> kernels;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_LAUNCHSPLIT_H
