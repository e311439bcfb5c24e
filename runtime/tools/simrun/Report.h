//===- Report.h - sim-run's table and JSON ----------------------*- C++ -*-===//
//
// The results of a sim-run, gathered from the sessions as plain values (so
// that a session can be destroyed, and its state freed, as soon as its
// part is done), and the two ways they are reported: the table on stdout
// and the JSON of --json, written with nlohmann-json.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_REPORT_H
#define SIM_RUN_REPORT_H

#include "Compare.h"
#include "Safety.h"
#include "Series.h"

#include <optional>
#include <string>
#include <vector>

namespace simrun {

/// A part of a sim-run after a signal: done, cut short by it, or not
/// started.
enum class Stage { NotAsked, Done, Cut, Skipped };

struct PartState {
  Stage stage = Stage::NotAsked;
  /// For Cut: the base step its run reached, of how many.
  int64_t reached = 0, of = 0;
};

/// A checkpoint that could not be written: the base step it was of, and
/// why ("File too large").
struct CheckpointFailure {
  int64_t time = 0;
  std::string why;
};

/// The totals at one output time.
struct TotalsAt {
  int64_t time = 0;
  std::vector<double> values;
};

/// The measured session and its runs.
struct MainRun {
  std::string scene, strategy, backend, device;
  /// Why `auto` did not choose CUDA (shown with --backend auto).
  std::string backendNote;
  bool showNote = false;
  int64_t range = 0;
  std::string dtText;
  double dt = 0;
  /// Every parameter of the scene and the value the run used (a --set or
  /// the default), as the runtime writes it.
  std::vector<std::pair<std::string, std::string>> params;
  int64_t groupSize = 0;
  int64_t steps = 0, repeat = 1, maxSteps = 1;
  /// The bundle's floating-point mode (sim-translate --sim-ftz).
  bool flushSubnormals = false;
  /// --max-memory, and the state's bytes and limit.
  int64_t maxMemory = 0, memoryBytes = 0, memoryLimit = 0;
  /// --distributed: the ranks (0: not distributed).
  int32_t ranks = 0;

  /// The last run's metrics and counters (the interrupted one if cut),
  /// added up over its session runs.
  sim_metrics metrics{};
  RunCounts counts;
  /// Big steps the run cut short: all of them, and those at output times
  /// before the end.
  int64_t cuts = 0, cutsAtOutputs = 0;
  /// Seconds spent at the output times (totals, buffers, errors).
  double outputSeconds = 0;
  /// --restart: the file and the base step it started at (-1: none).
  std::string restartFile;
  int64_t restartTime = -1;
  /// --checkpoint: the file, --checkpoint-every, how many were written and
  /// the base step of the last (-1: none).
  std::string checkpointFile;
  int64_t checkpointEvery = 0, checkpointsWritten = 0, checkpointTime = -1;
  /// The checkpoint writes that failed, in order: the run went on, and
  /// sim-run ends with status 1 once its other outputs are written.
  std::vector<CheckpointFailure> checkpointFailures;
  /// Wall and kernel time of every measured run that completed, and their
  /// medians; those of the interrupted run when a signal cut one.
  std::vector<double> walls, kernels;
  double wall = 0, kernel = 0;
  /// Done, or Cut: reached/of base steps. `cutRun` is 0 for the warm-up,
  /// else the measured run (1-based) the signal stopped.
  PartState state;
  int64_t cutRun = 0;

  std::vector<std::string> totalNames;
  /// Bytes of the narrowest float each total's values derive from (4 or
  /// 8): --check's default tolerance for it.
  std::vector<int32_t> totalPrecisionBytes;
  /// At the end of the run (the base step reached when cut).
  std::vector<double> totals;
  /// The observed buffers at the end of the run.
  std::vector<Buffer> values;
};

/// One observed buffer against --reference.
struct ReferenceError {
  std::string buffer;
  /// False: the scene has no exact solution of the buffer.
  bool available = false;
  ErrorNorms norms;
};

/// One total against --reference: the simple strategy's value, or its
/// value on the exact solution (sim_session_exact_total).
struct TotalError {
  std::string total;
  /// False: no reference value (`why` says why not).
  bool available = false;
  std::string why;
  double value = 0, reference = 0;
  /// |value - reference|, and that over |reference| (0 when both are 0,
  /// inf when only the reference is).
  double absolute = 0, relative = 0;
};

/// `value` against `reference`.
TotalError compareTotal(const std::string &name, double value,
                        double reference);

/// A dump file's name per kind, empty for one not written.
struct DumpFiles {
  std::string buffer, state, reference, check;
};

struct Results {
  MainRun main;

  /// --reference: "", "simple" or "exact".
  std::string referenceKind;
  PartState reference;
  std::vector<ReferenceError> errors;
  std::vector<TotalError> totalErrors;
  /// Per observed buffer: the reference's values, if any.
  std::vector<std::optional<Buffer>> referenceValues;

  /// --check.
  PartState checkState;
  std::optional<Check> check;
  std::vector<Buffer> checkValues;

  /// --output-every: the output times of the last measured run, and the
  /// file of --output ("" without).
  int64_t outputEvery = 0;
  std::string outputFile;
  Series series;

  /// --profile.
  bool profile = false;

  /// --dump: the folder and its files.
  std::string dumpDir;
  std::vector<DumpFiles> dumpFiles;

  /// The init check before the runs (not run: no reference functions, or
  /// it failed).
  InitCheckReport initCheck;
  /// NaNs and infinities in the measured run's final state and totals.
  std::vector<NonFiniteValues> nonFinite;

  /// The signal that stopped sim-run (0: none).
  int signal = 0;

  /// Whether a signal cut or skipped anything.
  bool interrupted() const;
};

/// The table on stdout.
void printTable(const Results &results);

/// --output-every's estimate of the evaluations its cuts cost, per
/// component: one evaluation per item for every cut at an output time
/// (a cut splits one big step in two; each big step evaluates every item of
/// a component at least once, a whole-step component exactly once). Under
/// lts an output time can cut several big steps, one per power of two in
/// the base steps before it: each is a big step more, and counts.
std::vector<std::pair<std::string, int64_t>>
extraEvaluations(const MainRun &main);

/// The JSON of --json: the keys of docs/Runtime.md, NaN and infinities as
/// null, invalid UTF-8 in names replaced by U+FFFD.
std::string toJson(const Results &results);

/// "4.282 ms", "12.5 us", "3.100 s".
std::string formatTime(double seconds);
/// "37 bytes", "1.50 KiB", "11.25 GiB".
std::string formatBytes(int64_t bytes);
double median(std::vector<double> values);

} // namespace simrun

#endif // SIM_RUN_REPORT_H
