//===- Progress.h - sim-run's progress line ---------------------*- C++ -*-===//
//
// While a run takes longer than a second, sim-run shows on a terminal one
// line on stderr, rewritten in place: the base steps done of the run's
// total, the percentage, the rate in base steps per second and the time
// left. Where stderr is not a terminal (a log, a pipe) it prints nothing,
// so that logs hold only what matters, unless --progress asks for it: then
// it writes the same line, one per ten seconds. The runtime calls back
// after each host synchronisation, so the line changes at most that often.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_PROGRESS_H
#define SIM_RUN_PROGRESS_H

#include "sim/Runtime/sim_runtime.h"

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <string>

namespace simrun {

/// Seconds before the first line, and between two lines on a terminal and
/// elsewhere.
constexpr double kProgressDelay = 1.0;
constexpr double kProgressTerminalPeriod = 0.25;
constexpr double kProgressLogPeriod = 10.0;

/// The text of one progress line (without "\r" or "\n"): "sim-run: <label>
/// base step 120000 of 1000000 (12%), 45.3k base steps/s, ETA 19 s", for a
/// run that started at base step `started` (a restart's) `seconds` ago.
std::string progressLine(const std::string &label, int64_t done, int64_t total,
                         double seconds, int64_t started = 0);

/// A rate with three significant digits and a k, M, G or T suffix: "812",
/// "45.3k", "1.20M".
std::string formatRate(double perSecond);

/// The time left: "ETA 19 s", "ETA 2 min 05 s", "ETA 3 h 07 min", "ETA -"
/// when it cannot be told yet.
std::string formatEta(double seconds);

/// The progress of sim-run's runs, one at a time.
class Progress {
public:
  /// `terminal`: the output is a terminal (lines rewritten in place);
  /// `forced`: --progress (lines also where it is not).
  explicit Progress(bool terminal, bool forced = false, std::FILE *out = stderr)
      : terminal(terminal), enabled(terminal || forced), out(out) {}

  /// Shows the progress of `session`'s next runs, with `label` ("check: ").
  void begin(sim_session *session, std::string label);
  /// The next session run of one run to `end` made of several session runs
  /// (output times, checkpoints), from base step `from`: one line for the
  /// whole run.
  void resume(sim_session *session, int64_t from, int64_t end);
  /// Between two session runs: clears the line on a terminal (output rows
  /// follow).
  void pause();
  /// Clears the line on a terminal.
  void end();

  /// What the runtime calls after each host synchronisation; `seconds`
  /// since begin().
  void report(int64_t done, int64_t total, double seconds);

private:
  static void callback(void *user, int64_t done, int64_t total);

  bool terminal, enabled;
  std::FILE *out;
  std::chrono::steady_clock::time_point start;
  double last = 0;
  std::string label;
  bool shown = false;
  /// Of a run made of several session runs: where the current one started,
  /// and the whole run's end (0: the session run's own).
  int64_t offset = 0, whole = 0;
  /// Where the first of them started (-1 before it): the rate counts the
  /// base steps of this process only, not those before a restart.
  int64_t started = -1;
};

} // namespace simrun

#endif // SIM_RUN_PROGRESS_H
