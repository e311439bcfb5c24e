//===- Compare.h - sim-run's error norms and --check ------------*- C++ -*-===//
//
// Host arrays of buffers, the error of a run against --reference, and the
// comparison of a run with the reference executor's (--check): per buffer
// with a tolerance, per total, evaluations and big steps. Plain functions
// of values, so that the unit tests can give them NaNs.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_COMPARE_H
#define SIM_RUN_COMPARE_H

#include "sim/Runtime/sim_runtime.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace simrun {

/// A buffer's host array (item-major, lanes packed).
struct Buffer {
  std::string name;
  /// 4 (f32) or 8 (f64), and scalars per item.
  int32_t scalarBytes = 8;
  /// Bytes of the narrowest float its values derive from (the bundle's
  /// precision_bytes): an f64 buffer computed from f32 data is 4; 0: as
  /// scalarBytes.
  int32_t precisionBytes = 0;
  int32_t lanes = 1;
  std::vector<uint8_t> bytes;

  size_t values() const { return bytes.size() / size_t(scalarBytes); }
  double at(size_t i) const;
  /// NaNs and infinities.
  size_t nonFinite() const;
};

struct ErrorNorms {
  /// The largest |a - b|; NaN when a difference is NaN.
  double maxAbs = 0;
  /// ||a - b||_2 / ||b||_2; 0 when both are zero, inf when only b is.
  double rmsRel = 0;
};

/// `value` against `reference` (same size), over all items and lanes.
ErrorNorms compare(const Buffer &value, const Buffer &reference);

/// What one session counted in its last run.
struct RunCounts {
  std::vector<std::pair<std::string, int64_t>> evaluations;
  /// The plan's kernels (none on the reference executor): launches, and
  /// their kernel time where the backend times each launch (else -1).
  struct Kernel {
    std::string name;
    int64_t launches = 0;
    double seconds = 0;
  };
  std::vector<Kernel> kernels;
  int64_t bigSteps = 0;
  /// Index m in 0 .. max_steps: big steps of m base steps.
  std::vector<int64_t> histogram;
};

/// A run against the reference executor's.
struct Check {
  struct BufferRow {
    std::string buffer;
    ErrorNorms norms;
    double maxReference = 0, tolerance = 0, limit = 0;
    /// NaNs and infinities on either side: any fails the buffer.
    size_t nonFiniteBackend = 0, nonFiniteReference = 0;
    bool pass = false;
  };
  struct CountRow {
    std::string component;
    /// -1: the side has no such component.
    int64_t backend = -1, reference = -1;
  };
  struct TotalRow {
    std::string total;
    int64_t time = 0;
    double backend = 0, reference = 0, limit = 0;
    bool pass = false;
  };
  std::vector<BufferRow> buffers;
  /// The totals at the end of the run, and at every output time of
  /// --report-every (empty without it).
  std::vector<TotalRow> totals, totalsPerOutputTime;
  std::vector<CountRow> evaluations;
  RunCounts backend, reference;
  /// What differs, in words; empty when the check passes.
  std::vector<std::string> failures;

  bool pass() const { return failures.empty(); }
  bool evaluationsEqual() const;
};

/// The default tolerance of a buffer whose values derive from floats of
/// `precisionBytes`: 1e-4 for f32, 1e-10 for f64.
double defaultTolerance(int32_t precisionBytes);
/// The default tolerance of a total (summed in double, so looser than a
/// buffer's for f64): 1e-4 for f32, 1e-8 for f64.
double defaultTotalTolerance(int32_t precisionBytes);

/// Compares buffers and counters. A buffer passes when it has no NaN or
/// infinity on either side (a scene that blows up fails, even when both
/// blow up alike) and max-abs <= tolerance * max(1, max|reference|)
/// (a negative tolerance: defaultTolerance; 0: equal values).
Check compareWithReference(const std::vector<Buffer> &backend,
                           const std::vector<Buffer> &reference,
                           const RunCounts &backendCounts,
                           const RunCounts &referenceCounts, double tolerance);

/// Compares the totals `names` at base step `time`; a total passes when
/// both are finite and |a - b| <= tolerances[t] * max(1, |b|). Appends rows to
/// `rows` and failures to `failures`.
void compareTotals(const std::vector<std::string> &names, int64_t time,
                   const std::vector<double> &backend,
                   const std::vector<double> &reference,
                   const std::vector<double> &tolerances,
                   std::vector<Check::TotalRow> &rows,
                   std::vector<std::string> &failures);

/// A name as the report prints it: control characters and DEL as \xNN.
std::string displayName(const std::string &name);

/// "%.*e" of `value`.
std::string scientific(double value, int digits = 3);

} // namespace simrun

#endif // SIM_RUN_COMPARE_H
