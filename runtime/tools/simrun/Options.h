//===- Options.h - sim-run's command line -----------------------*- C++ -*-===//
//
// What the user asked sim-run for, parsed by CLI11: every value is checked
// against its domain here, so that a bad one is a usage error (exit status
// 2) before anything is compiled, allocated or run. The value parsers are
// exposed for the unit tests.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_OPTIONS_H
#define SIM_RUN_OPTIONS_H

#include "sim/Runtime/sim_runtime.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace simrun {

/// sim-run's exit statuses (docs/Runtime.md, "Exit status").
enum ExitStatus : int {
  kExitSuccess = 0,
  /// The run failed, or --check found a difference.
  kExitFailure = 1,
  /// A value outside its domain, an unknown option, an output path that
  /// cannot be written or would overwrite an input.
  kExitUsage = 2,
  /// The run completed (and --check, if asked for, passed), but its final
  /// state or totals hold NaN or infinity.
  kExitNonFinite = 3,
  /// 128 + the signal: SIGINT gives 130, SIGTERM 143.
  kExitSignalBase = 128,
};

/// A failure that ends sim-run with a message and an exit status; main()
/// prints the message. An exception, so that every destructor (sessions,
/// the temporary bundle) runs on the way out.
struct Exit {
  int status;
  std::string message;
};

/// A usage error (status 2); the message gets " (see sim-run --help)".
[[noreturn]] void usageError(const std::string &message);
/// A failure of the run (status 1).
[[noreturn]] void runError(const std::string &message);

/// The domains of the numeric options.
constexpr int64_t kMaxSteps = 1'000'000'000'000; // 10^12 base steps
constexpr int64_t kMaxRepeat = 1'000'000;
/// The CPU backend's largest group (CUDA takes multiples of 32 up to 1024,
/// which session creation checks).
constexpr int64_t kMaxGroupSize = 4096;
/// The CPU backend's most worker threads.
constexpr int64_t kMaxThreads = 1024;
/// The largest max_steps a scene may have (the compiler's and the bundle
/// verifier's limit).
constexpr int64_t kMaxMaxSteps = int64_t(1) << 20;

/// Whether `--set NAME=...` is a compile-time setting (max_steps): for a
/// .mlir input sim-run compiles the scene with it; a bundle has it fixed.
bool isCompileTimeSetting(const std::string &name);

struct Options {
  std::string input;
  sim_backend backend = SIM_BACKEND_AUTO;
  sim_strategy strategy = SIM_STRATEGY_HIP;
  /// Whether --strategy was given (else a bundle without hip runs the
  /// first plan it has, defaultStrategy in sim-run.cpp).
  bool strategyGiven = false;
  int64_t steps = 100;
  int64_t repeat = 1;
  /// --output-every (or its old name --report-every): the run stops at
  /// every multiple of it; 0: no output times.
  int64_t outputEvery = 0;
  /// --output FILE: the .npz of the output times; empty: none.
  std::string output;
  /// --checkpoint FILE (empty: none), written at the end, on a signal and
  /// with --checkpoint-every (0: not periodically); --restart FILE.
  std::string checkpoint;
  int64_t checkpointEvery = 0;
  std::string restart;
  /// --set NAME=VALUE, in the order given.
  std::vector<std::pair<std::string, std::string>> sets;
  /// 0: the plan's.
  int64_t groupSize = 0;
  /// "", "simple" or "exact".
  std::string reference;
  bool check = false;
  /// --check-tolerance; negative (not given): by scalar type, 0: equal.
  double checkTolerance = -1;
  /// Output paths; empty: not asked for.
  std::string dump;
  std::string json;
  bool checkFinite = false;
  /// --distributed: one block of the range per rank of mpirun.
  bool distributed = false;
  /// --progress: the progress line also where stderr is not a terminal.
  bool progress = false;
  /// --no-init-check: skip the check of inits against their writers.
  bool noInitCheck = false;
  /// --profile: the table of the plan's kernels after the report.
  bool profile = false;
  /// 0: one per hardware thread.
  int32_t threads = 0;
  int32_t device = 0;
  bool cudaGraph = false;
  /// --max-memory in bytes; 0: the runtime's default.
  int64_t maxMemory = 0;
};

/// Parses the command line. Prints the help and throws Exit{0} for --help;
/// throws Exit{2} with a message naming the option and the value for
/// anything else that is wrong.
Options parseOptions(int argc, const char *const *argv);

/// `sim-run --help` (docs/Runtime.md keeps a copy).
std::string helpText();

/// A decimal integer in [min, max] (an optional '-', digits, nothing else:
/// no spaces, no "0x", no octal), or nullopt.
std::optional<int64_t> parseInteger(std::string_view text, int64_t min,
                                    int64_t max);

/// A byte count: decimal digits and an optional suffix K, M, G or T (either
/// case; powers of 1024), at most INT64_MAX; nullopt otherwise.
std::optional<int64_t> parseSize(std::string_view text);

/// A finite number >= 0 read by the rules of a floating-point --set value
/// (the whole text as strtod reads it, no leading blank, not hexadecimal,
/// not overflowing or underflowing to 0; -0 as 0), or nullopt with why not
/// in `why` ("is hexadecimal; give a number in decimal"), when given.
std::optional<double> parseNonNegative(std::string_view text,
                                       std::string *why = nullptr);

} // namespace simrun

#endif // SIM_RUN_OPTIONS_H
