//===- Timeline.h - where sim-run's runs stop on their way ------*- C++ -*-===//
//
// A measured run of sim-run goes from its start (0, or a --restart
// checkpoint's base step) to --steps in several session runs:
//
// - at every output time (the multiples of --output-every, and the end) it
//   stops exactly there: a run ends exactly at its end, so the big step
//   that crosses an output time is cut (docs/Plan.md, clock slot 6);
// - for --checkpoint-every it pauses on the first big-step boundary at or
//   after each multiple, which cuts nothing (sim_session_run_pausing).
//
// Output times are multiples from base step 0, not from the start, so a
// restarted run stops where the run it continues stopped. The counters of
// the session runs add up to those of the whole run.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_TIMELINE_H
#define SIM_RUN_TIMELINE_H

#include "Compare.h"
#include "Report.h"

#include "sim/Runtime/sim_runtime.h"

#include <cstdint>
#include <functional>

namespace simrun {

struct Stops {
  /// --steps; --output-every and --checkpoint-every (0: none).
  int64_t end = 0, outputEvery = 0, checkpointEvery = 0;

  /// The first output time after `time`: a multiple of outputEvery, or the
  /// end.
  int64_t nextOutput(int64_t time) const;
  /// The first multiple of checkpointEvery after `time` (INT64_MAX: none).
  int64_t nextCheckpoint(int64_t time) const;
  /// How many output times a run from `begin` has (its start included).
  int64_t outputTimes(int64_t begin) const;
};

/// The counters of the session runs of one run, added up.
struct RunTotals {
  sim_metrics metrics{};
  RunCounts counts;
  /// Big steps cut short: all of them, and those at output times before
  /// the end (the cost of the output times; the end cuts one in any run,
  /// or under lts one per power of two in the base steps it left).
  int64_t cuts = 0, cutsAtOutputs = 0;
  bool started = false;

  /// Adds the session's last run; `atOutput`: it ended at an output time
  /// before the end.
  void add(sim_session *session, int64_t maxSteps, bool atOutput);
};

/// What a run does around its session runs.
struct TimelineHooks {
  /// Before and after each session run (the progress display).
  std::function<void(sim_session *session, int64_t begin)> beforeRun;
  std::function<void()> afterRun;
  /// At the start and at every output time reached; returns false when a
  /// signal stopped it (then the run stops too).
  std::function<bool(int64_t time)> output;
  /// On the boundary a --checkpoint-every pause stopped at.
  std::function<void(int64_t time)> checkpoint;
};

/// Runs `session` from its current base step to stops.end through the
/// stops. Done, or Cut at the base step reached when a signal stopped it
/// (also between two session runs). A failure of the run is Exit{1}.
PartState runThrough(sim_session *session, const Stops &stops, int64_t maxSteps,
                     RunTotals &totals, const TimelineHooks &hooks);

/// The --restart file to start from, or "" for the initial state: starts
/// `session` there. A checkpoint the session refuses is Exit{1}.
void startAt(sim_session *session, const std::string &restart);

} // namespace simrun

#endif // SIM_RUN_TIMELINE_H
