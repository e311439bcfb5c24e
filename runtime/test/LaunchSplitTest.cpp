//===- LaunchSplitTest.cpp - when the CPU backend splits a launch ---------===//
//
// LaunchSplit.h with made-up launch times: the trials, the choice of the
// faster way, launches long enough that alone is not tried, probes of the
// other way that notice a change of the work, and the first launch after a
// change of mode (which pays for waking threads) not counted.
//
//===----------------------------------------------------------------------===//

#include "LaunchSplit.h"

#include <gtest/gtest.h>

using namespace sim::rt;

namespace {

/// Runs `launches` launches of kernel 0 of 16 groups, each taking
/// `ticksOf(mode)`; returns how many ran alone.
template <typename Ticks>
int runLaunches(LaunchSplit &split, int launches, Ticks ticksOf) {
  int alone = 0;
  for (int i = 0; i < launches; ++i) {
    LaunchSplit::Mode mode = split.choose(0);
    alone += mode == LaunchSplit::Alone;
    split.record(0, mode, ticksOf(mode), 16);
  }
  return alone;
}

TEST(LaunchSplit, TriesBothThenRunsTheFaster) {
  LaunchSplit split;
  // Shared launches cost 3000 ticks, alone 1000: after 5 shared and 5
  // alone trials every launch but the probes runs alone.
  auto ticks = [](LaunchSplit::Mode mode) {
    return mode == LaunchSplit::Shared ? 3000 : 1000;
  };
  int trials = 2 * (LaunchSplit::kTrials + 1);
  for (int i = 0; i < trials; ++i) {
    LaunchSplit::Mode mode = split.choose(0);
    EXPECT_EQ(mode, i <= int(LaunchSplit::kTrials) ? LaunchSplit::Shared
                                                   : LaunchSplit::Alone)
        << "launch " << i;
    split.record(0, mode, ticks(mode), 16);
  }
  EXPECT_EQ(split.chosen(0), LaunchSplit::Alone);
  int alone = runLaunches(split, 10000, ticks);
  // Probes of kBurst shared launches every kProbeEvery at most, fewer as
  // shared stays far behind.
  EXPECT_GE(alone, 10000 - 10000 / int(LaunchSplit::kProbeEvery) *
                               int(LaunchSplit::kBurst));
  EXPECT_EQ(split.chosen(0), LaunchSplit::Alone);
}

TEST(LaunchSplit, SharedWhenFaster) {
  LaunchSplit split;
  int alone = runLaunches(split, 10000, [](LaunchSplit::Mode mode) {
    return mode == LaunchSplit::Shared ? 1000 : 1900;
  });
  EXPECT_EQ(split.chosen(0), LaunchSplit::Shared);
  EXPECT_LT(alone,
            10000 / int(LaunchSplit::kProbeEvery) * int(LaunchSplit::kBurst) +
                int(LaunchSplit::kTrials) + 1);
}

TEST(LaunchSplit, LongLaunchesAreNotTriedAlone) {
  // Shared launches of kLongLaunch ticks: no alone trials, and alone is
  // probed only every kLongestProbeEvery launches.
  LaunchSplit split;
  int alone = runLaunches(split, 4000, [](LaunchSplit::Mode mode) {
    return uint64_t(mode == LaunchSplit::Shared ? LaunchSplit::kLongLaunch
                                                : 2 * LaunchSplit::kLongLaunch);
  });
  EXPECT_EQ(alone, 0);
  EXPECT_EQ(split.chosen(0), LaunchSplit::Shared);
}

TEST(LaunchSplit, ProbesFallAtEveryPhaseOfAPowerOfTwo) {
  // Alone far behind: the probes grow rarer, but at odd intervals, so
  // that a kernel whose work repeats every 8 launches (the slots of a big
  // step) is not always probed at the same slot.
  LaunchSplit split;
  bool phases[8] = {};
  for (int i = 0; i < 200000; ++i) {
    LaunchSplit::Mode mode = split.choose(0);
    if (mode == LaunchSplit::Alone && i > 1000)
      phases[i % 8] = true;
    split.record(0, mode, mode == LaunchSplit::Shared ? 1000 : 4000, 16);
  }
  EXPECT_EQ(split.chosen(0), LaunchSplit::Shared);
  for (int phase = 0; phase < 8; ++phase)
    EXPECT_TRUE(phases[phase]) << "no probe at phase " << phase;
}

TEST(LaunchSplit, NoticesAChangeOfTheWork) {
  // Alone is faster at first; then the work grows and shared is: the
  // probes find it within a few windows.
  LaunchSplit split;
  runLaunches(split, 3000, [](LaunchSplit::Mode mode) {
    return mode == LaunchSplit::Shared ? 2000 : 1000;
  });
  EXPECT_EQ(split.chosen(0), LaunchSplit::Alone);
  runLaunches(split, 20 * int(LaunchSplit::kWindow),
              [](LaunchSplit::Mode mode) {
                return mode == LaunchSplit::Shared ? 5000 : 9000;
              });
  EXPECT_EQ(split.chosen(0), LaunchSplit::Shared);
}

TEST(LaunchSplit, TheFirstLaunchAfterAChangeIsNotCounted) {
  // Every shared launch that follows an alone one costs 100 times more
  // (threads woken from sleep); shared launches in a row cost half of an
  // alone one. Counting the first would make alone look faster.
  LaunchSplit split;
  LaunchSplit::Mode last = LaunchSplit::Shared;
  for (int i = 0; i < 5000; ++i) {
    LaunchSplit::Mode mode = split.choose(0);
    uint64_t ticks = mode == LaunchSplit::Alone   ? 1000
                     : last == LaunchSplit::Alone ? 100000
                                                  : 500;
    split.record(0, mode, ticks, 16);
    last = mode;
  }
  EXPECT_EQ(split.chosen(0), LaunchSplit::Shared);
}

TEST(LaunchSplit, KernelsAreTheirOwn) {
  LaunchSplit split;
  for (int i = 0; i < 2000; ++i)
    for (size_t kernel : {0, 1}) {
      LaunchSplit::Mode mode = split.choose(kernel);
      bool sharedFaster = kernel == 1;
      uint64_t ticks =
          (mode == LaunchSplit::Shared) == sharedFaster ? 1000 : 3000;
      split.record(kernel, mode, ticks, 16);
    }
  EXPECT_EQ(split.chosen(0), LaunchSplit::Alone);
  EXPECT_EQ(split.chosen(1), LaunchSplit::Shared);
}

} // namespace

TEST(LaunchSplit, DealsUnevenKernelsInFinerParts) {
  // One range per thread for a small launch, up to four per thread of at
  // least 16 groups for a large one; a kernel marked uneven_groups (a slot
  // of local time steps) gets ranges of 4 groups, so that the heat rod's
  // 16 groups (a stiff half) go to two threads as four ranges dealt in
  // turn, each thread a quarter of each half, not one half each.
  EXPECT_EQ(LaunchSplit::partsFor(16, 2, false), 2);
  EXPECT_EQ(LaunchSplit::partsFor(16, 2, true), 4);
  EXPECT_EQ(LaunchSplit::partsFor(256, 2, false), 8);
  EXPECT_EQ(LaunchSplit::partsFor(256, 2, true), 8);
  EXPECT_EQ(LaunchSplit::partsFor(64, 2, false), 4);
  EXPECT_EQ(LaunchSplit::partsFor(64, 2, true), 8);
  // Never fewer parts than threads, never more than four per thread.
  for (int64_t threads : {1, 2, 3, 16})
    for (int64_t groups :
         {int64_t(1), int64_t(5), int64_t(17), int64_t(1000), int64_t(1) << 30})
      for (bool uneven : {false, true}) {
        int64_t parts = LaunchSplit::partsFor(groups, threads, uneven);
        EXPECT_GE(parts, threads);
        EXPECT_LE(parts, 4 * threads);
        EXPECT_EQ(parts % threads, 0);
      }
}
