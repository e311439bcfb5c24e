//===- Safety.h - sim-run's warnings about a scene and a run ----*- C++ -*-===//
//
// Two checks that need no option, because what they find is an error a
// user would not see otherwise (docs/Runtime.md, "Warnings"):
//
// - before the runs, the init check (sim_session_check_init): a buffer
//   whose init disagrees with its writer evaluated with n = 0 at t = 0 is
//   invisible under simple and a silent error under hip, which
//   interpolates from the init in its first big step;
// - after the measured run, NaNs and infinities in its final state or
//   totals, which make sim-run exit with status 3.
//
// Plain functions of the values and messages, for the unit tests.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_SAFETY_H
#define SIM_RUN_SAFETY_H

#include "Compare.h"

#include "sim/Runtime/sim_runtime.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace simrun {

/// What the init check found, for the messages and the JSON.
struct InitCheckReport {
  /// Whether it ran, and if not why not (a bundle without reference
  /// functions, a failing body).
  bool ran = false;
  std::string skipped;
  /// Items evaluated, of the range.
  int64_t items = 0, range = 0;
  struct Row {
    std::string buffer, component;
    int32_t lanes = 1;
    double maxAbs = 0, initial = 0, evaluated = 0, scale = 0, tolerance = 0;
    int64_t item = -1;
    int32_t lane = 0;
    int64_t count = 0, nonFinite = 0, nonFiniteItem = -1;
    bool interpolated = false;

    bool consistent() const { return count == 0; }
  };
  std::vector<Row> rows;
};

/// Runs the init check on `session` (its range, dt and parameters).
InitCheckReport checkInit(sim_session *session, const sim_bundle *bundle);

/// The messages the report gives on stderr, each one or more lines without
/// a trailing newline: "sim-run: warning: ..." per buffer whose init
/// disagrees, "sim-run: note: ..." where evaluate gave NaN or infinity with
/// n = 0, where the check evaluated part of the range, and where it could
/// not run for a reason other than a bundle without reference functions.
std::vector<std::string> initCheckMessages(const InitCheckReport &report);

/// NaNs and infinities in a buffer or a total at the end of the run.
struct NonFiniteValues {
  std::string name;
  bool total = false;
  /// How many values, and the first: its item, lane (of `lanes`) and value.
  int64_t count = 0;
  int64_t item = 0;
  int32_t lane = 0, lanes = 1;
  double value = 0;
};

/// The NaNs and infinities of `buffer`, if any.
std::optional<NonFiniteValues> findNonFinite(const Buffer &buffer);
/// The totals that are not finite.
std::vector<NonFiniteValues>
findNonFiniteTotals(const std::vector<std::string> &names,
                    const std::vector<double> &values);

/// "sim-run: warning: buffer 'X' holds 3 NaN or infinite values at the end
/// of the run (the first: nan at item 7)".
std::string nonFiniteWarning(const NonFiniteValues &found);
/// "buffer 'X' holds 3 NaN or infinite values (the first: nan at item
/// 7)": why a state is no checkpoint to restart from.
std::string nonFiniteStateText(const NonFiniteValues &found);
/// "sim-run: warning: the exact solution of buffer 'X' holds 3 NaN or
/// infinite values at the end of the run (...), so its errors are not
/// finite; ...": --reference exact compared with values that mean nothing.
std::string exactNonFiniteWarning(const NonFiniteValues &found);

} // namespace simrun

#endif // SIM_RUN_SAFETY_H
