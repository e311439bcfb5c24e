//===- Series.h - the output times of one run -------------------*- C++ -*-===//
//
// With --output-every N, sim-run's measured run stops at base steps T0, the
// multiples of N after it, and the end (docs/Runtime.md, "Output times").
// At each it takes the totals, the error of every observed buffer against
// --reference, and with --output the buffers themselves (and the exact
// solution): a Series. The table prints each row as the run reaches it, as
// ARKODE's examples print their output times, and --output writes the
// whole series as one .npz file in the layout below, which python/ writes
// too:
//
//   t                        int64 [K]        base steps
//   time                     float64 [K]      t * dt
//   buffer/<name>            [K, range(, lanes)] in the buffer's dtype
//   exact/<name>             the same, with --reference exact
//   total/<name>             float64 [K]
//   error/<name>/max_abs     float64 [K]      with --reference
//   error/<name>/rms_rel     float64 [K]
//   meta/scene, meta/strategy, meta/backend   0-d unicode arrays
//
// <name> is sanitiseName's (Output.h), unique within its prefix.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_SERIES_H
#define SIM_RUN_SERIES_H

#include "Compare.h"
#include "Npz.h"

#include <optional>
#include <string>
#include <vector>

namespace simrun {

struct Series {
  /// What is recorded: every total always; per observed buffer its values
  /// with `keepValues` (--output), its exact solution with `keepExact`
  /// where the scene has one, and its error where `reference` is set.
  struct Column {
    std::string name;
    int32_t scalarBytes = 8, lanes = 1;
    bool hasReference = false, hasExact = false;
  };
  int64_t every = 0;
  double dt = 0;
  int64_t range = 0;
  std::string referenceKind;
  bool keepValues = false;
  /// Whether every row stays until the end, for what reads them after the
  /// run: --output, --json, --check's totals at every output time. Else
  /// only the last row stays, for the table that prints it, so that a run
  /// of any length with --output-every 1 holds a fixed amount of memory.
  bool keepRows = true;
  std::vector<std::string> totalNames;
  std::vector<Column> buffers;

  /// Per output time (only the last without keepRows).
  std::vector<int64_t> times;
  std::vector<std::vector<double>> totals;
  /// [time][buffer]; a buffer without reference has zeros.
  std::vector<std::vector<ErrorNorms>> errors;
  /// Per buffer: its rows one after the other (keepValues), and the exact
  /// solution's (keepValues and hasExact).
  std::vector<std::string> values, exact;

  /// The rows held: all of them (keepRows), or the last one.
  size_t size() const { return times.size(); }
  /// The output times recorded since clear(), held or not.
  int64_t recorded = 0;
  /// Appends the row at `time`: `values` of every observed buffer (needed
  /// for errors and keepValues), `references` per buffer (--reference's
  /// values, absent where there are none).
  void add(int64_t time, const std::vector<double> &rowTotals,
           const std::vector<Buffer> &rowValues,
           const std::vector<std::optional<Buffer>> &references);
  /// Forgets every row (a new measured run).
  void clear();
};

/// The bytes one row keeps (its buffers and exact solutions).
int64_t rowBytes(const Series &series);

/// What one output time holds until the end besides its buffers, where
/// every row is kept: its time, `totals` totals and the errors of
/// `buffers` buffers in the series; with `json`, its part of the JSON
/// (the tree, then the text); with `check`, the reference executor's
/// totals at it and their comparison. A generous estimate: what matters is
/// that it grows with the output times.
int64_t rowOverheadBytes(size_t totals, size_t buffers, bool json, bool check);

/// The message of the usage error for `times` output times of `row` bytes
/// each that take more than half of `memory` bytes (this machine's); empty
/// when they fit. `what` names the options that keep them ("--output").
std::string seriesMemoryError(const std::string &what, int64_t times,
                              int64_t row, double memory);

/// The table as the run goes: a header, then one line per output time:
/// t, time, every total, per buffer with a reference its max-abs and
/// rms-rel.
void printSeriesHeader(const Series &series);
void printSeriesRow(const Series &series, size_t row);

/// The arrays of --output, in the layout above; they point into `series`
/// and `storage`, which must outlive them.
std::vector<NpzArray> seriesArrays(const Series &series,
                                   const std::string &scene,
                                   const std::string &strategy,
                                   const std::string &backend,
                                   std::vector<std::string> &storage);

} // namespace simrun

#endif // SIM_RUN_SERIES_H
