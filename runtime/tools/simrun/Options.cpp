//===- Options.cpp - sim-run's command line -------------------------------===//
//
// The options are declared once, with CLI11: name, value name, help text
// and a transform that checks the value's domain and writes it back in
// canonical decimal (so that CLI11's own conversion, which reads "010" as
// octal, never sees anything but plain digits). The generic validators and
// the help layout of LLVM's tools (which docs/Runtime.md shows) are
// CommandLine.h's, which the hand-written baselines share.
//
//===----------------------------------------------------------------------===//

#include "Options.h"

#include "CommandLine.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace simrun {

void usageError(const std::string &message) {
  throw Exit{kExitUsage, message + " (see sim-run --help)"};
}

void runError(const std::string &message) { throw Exit{kExitFailure, message}; }

bool isCompileTimeSetting(const std::string &name) {
  return name == "max_steps";
}

//===----------------------------------------------------------------------===//
// Value parsers
//===----------------------------------------------------------------------===//

std::optional<int64_t> parseInteger(std::string_view text, int64_t min,
                                    int64_t max) {
  return simcli::parseInteger(text, min, max);
}

std::optional<int64_t> parseSize(std::string_view text) {
  int shift = 0;
  if (!text.empty()) {
    switch (text.back()) {
    case 'K':
    case 'k':
      shift = 10;
      break;
    case 'M':
    case 'm':
      shift = 20;
      break;
    case 'G':
    case 'g':
      shift = 30;
      break;
    case 'T':
    case 't':
      shift = 40;
      break;
    }
  }
  if (shift)
    text.remove_suffix(1);
  if (!text.empty() && text.front() == '-')
    return std::nullopt;
  std::optional<int64_t> count =
      parseInteger(text, 0, std::numeric_limits<int64_t>::max());
  if (!count || *count > (std::numeric_limits<int64_t>::max() >> shift))
    return std::nullopt;
  return *count << shift;
}

std::optional<double> parseNonNegative(std::string_view text,
                                       std::string *why) {
  // The rules of a floating-point --set value (parseValue in the runtime's
  // Bundle.cpp, which sim-run reaches only through the C API), so that the
  // options agree on what a number is; then the domain.
  std::string copy(text);
  auto refuse = [&](const char *reason) -> std::optional<double> {
    if (why)
      *why = reason;
    return std::nullopt;
  };
  const char *notInDomain = "is not a finite number >= 0";
  // strtod skips leading blanks and accepts an empty string; a value is one
  // token.
  if (copy.empty() || std::isspace(static_cast<unsigned char>(copy[0])))
    return refuse(notInDomain);
  char *end = nullptr;
  errno = 0;
  double value = std::strtod(copy.c_str(), &end);
  if (*end)
    return refuse(notInDomain);
  if (errno == ERANGE && std::isinf(value))
    return refuse("is out of range for f64");
  if (errno == ERANGE && value == 0)
    return refuse("underflows to 0 in f64");
  // strtod reads 0x10 as 16, where an MLIR float literal 0x... is the
  // value's bits: --set refuses both readings, and so does every option.
  std::string_view digits = text;
  if (!digits.empty() && (digits.front() == '-' || digits.front() == '+'))
    digits.remove_prefix(1);
  if (digits.size() > 1 && digits[0] == '0' &&
      (digits[1] == 'x' || digits[1] == 'X'))
    return refuse("is hexadecimal; give a number in decimal");
  if (!std::isfinite(value) || !(value >= 0))
    return refuse(notInDomain);
  return value == 0 ? 0.0 : value; // -0 is 0
}

namespace {

using simcli::assignment;
using simcli::describe;
using simcli::inQuotes;
using simcli::integerIn;
using simcli::oneOf;
using simcli::path;

//===----------------------------------------------------------------------===//
// Validators: check a value's domain, rewrite it in canonical form
//===----------------------------------------------------------------------===//

CLI::Validator size() {
  return CLI::Validator(
      [](std::string &text) -> std::string {
        std::optional<int64_t> bytes = parseSize(text);
        if (!bytes)
          return inQuotes(text) +
                 " is not a size in bytes (digits with an optional K, M, G "
                 "or T, below 8 EiB)";
        text = std::to_string(*bytes);
        return "";
      },
      "", "size");
}

CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string &text) -> std::string {
        std::string why;
        if (!parseNonNegative(text, &why))
          return inQuotes(text) + " " + why;
        return "";
      },
      "", "non-negative");
}

/// A name that `parse` (sim_strategy_parse, sim_backend_parse) knows.
template <typename T>
CLI::Validator knownName(sim_status (*parse)(const char *, T *)) {
  return CLI::Validator(
      [=](std::string &text) -> std::string {
        T value;
        if (parse(text.c_str(), &value) != SIM_OK)
          return sim_last_error();
        return "";
      },
      "", "name");
}

//===----------------------------------------------------------------------===//
// Help
//===----------------------------------------------------------------------===//

constexpr const char *kOverview =
    "run a sim scene bundle and report time, work and error";

constexpr const char *kIntro =
    R"(A .mlir scene is first translated with `sim-translate --sim-to-bundle`
(looked up next to sim-run, then on PATH) into a temporary bundle, for
the strategy that runs (--strategy, default hip) and simple for
--reference simple, with CPU kernels for this machine's instruction-set
level only (--sim-cpu-isas=host).
)";

constexpr const char *kFooter =
    R"(Every output is written to a temporary file in its folder and renamed
into place, never onto an input (but --checkpoint may replace the --restart
file). The first SIGINT or SIGTERM stops the run at its next host
synchronisation, on a big-step boundary: sim-run reports and writes what is
complete (the output times reached, a checkpoint where it stopped) and
skips the rest; a second one kills it (one within a second of the first
is the same request sent twice, and is ignored).

ENVIRONMENT:
  SIM_CUDA_DRIVER             the driver library to load instead of libcuda.so.1
  SIM_CPU_ISA                 the highest CPU instruction-set level to run
                              (x86-64, x86-64-v2, x86-64-v3, x86-64-v4; default:
                              the highest the CPU has and the bundle carries)
  SIM_MPI_MAX_MESSAGE         --distributed: the most bytes one MPI message
                              carries (default and cap 2147483647); longer
                              transfers go as several messages

WARNINGS: before the runs, a buffer whose init disagrees with its writer
evaluated with n = 0 at t = 0 (hip interpolates from the init); after the
run, NaN or infinity in the final state or the totals (exit status 3).

EXIT STATUS: 0 on success, 1 when the run fails or --check finds a
difference, 2 on a usage error (before anything runs), 3 when the run
ended with NaN or infinite values, 130 or 143 when SIGINT or SIGTERM
stopped it.
)";

//===----------------------------------------------------------------------===//
// The options
//===----------------------------------------------------------------------===//

/// sim-run's options on `app`, stored into `options`; --backend and
/// --strategy, --set and --reference go through the strings given.
void declareOptions(CLI::App &app, Options &options, std::string &backend,
                    std::string &strategy, std::vector<std::string> &sets,
                    int64_t &reportEvery) {
  app.formatter(std::make_shared<simcli::HelpFormatter>(
      "sim-run <scene.simb | scene.mlir> [options]", kIntro));
  app.footer(kFooter);
  app.set_help_flag("-h,--help", "print this help");
  // A repeated option takes its last value, as in most tools; --set
  // collects every one.
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  // Unknown options and extra inputs are reported by parseOptions.
  app.allow_extras();

  app.add_option("scene", options.input);
  app.add_option("--backend", backend,
                 "auto, cpu, cuda or reference (default auto: CUDA\n"
                 "when a driver, a device and the strategy's PTX\n"
                 "are there; reference: the reference executor)")
      ->option_text("B")
      ->check(knownName(&sim_backend_parse));
  app.add_option("--strategy", strategy,
                 "simple, traditional, hip, hip-cache or lts (default\n"
                 "hip, or where the bundle has no hip plan the first\n"
                 "of hip-cache, lts, traditional, simple it has; lts:\n"
                 "local time steps, docs/Model.md)")
      ->option_text("S")
      ->check(knownName(&sim_strategy_parse));
  app.add_option("--steps", options.steps,
                 "base steps to run, 0 to 10^12 (default 100)")
      ->option_text("N")
      ->transform(
          integerIn(0, kMaxSteps, "an integer from 0 to 1000000000000"));
  app.add_option("--repeat", options.repeat,
                 "run K times from the initial state and report the\n"
                 "median; with K > 1 one more warm-up run comes\n"
                 "first and is not counted (1 to 10^6, default 1)")
      ->option_text("K")
      ->transform(integerIn(1, kMaxRepeat, "an integer from 1 to 1000000"));
  app.add_option("--output-every", options.outputEvery,
                 "stop the run exactly at every multiple of N >= 1\n"
                 "base steps and at the end (the big step there is\n"
                 "cut), and print t, time, the totals and\n"
                 "--reference's errors at each as the run goes")
      ->option_text("N")
      ->transform(
          integerIn(1, kMaxSteps, "an integer from 1 to 1000000000000"));
  app.add_option("--report-every", reportEvery,
                 "the old name of --output-every")
      ->option_text("N")
      ->transform(
          integerIn(1, kMaxSteps, "an integer from 1 to 1000000000000"));
  app.add_option("--output", options.output,
                 "with --output-every: write the observed buffers,\n"
                 "totals and errors at every output time into one\n"
                 ".npz file (numpy.load; layout in docs/Runtime.md)")
      ->option_text("FILE")
      ->check(path());
  CLI::Option *checkpoint =
      app.add_option("--checkpoint", options.checkpoint,
                     "keep a checkpoint of the run (clock and state) in\n"
                     "FILE: at the end, where a signal stops it, and\n"
                     "with --checkpoint-every; each replaces the last\n"
                     "(a state with NaN or infinity is not written: the\n"
                     "file keeps the last good one)")
          ->option_text("FILE")
          ->check(path());
  app.add_option("--checkpoint-every", options.checkpointEvery,
                 "also write it on the first big-step boundary at\n"
                 "or after every multiple of N >= 1 base steps (no\n"
                 "big step is cut for it)")
      ->option_text("N")
      ->transform(integerIn(1, kMaxSteps, "an integer from 1 to 1000000000000"))
      ->needs(checkpoint);
  app.add_option("--restart", options.restart,
                 "continue from a checkpoint of the same bundle,\n"
                 "strategy, group size and --set values; --steps\n"
                 "stays the end, counted from base step 0")
      ->option_text("FILE")
      ->check(path());
  app.add_option("--set", sets,
                 "set range, dt or a scene parameter (repeatable);\n"
                 "for a .mlir scene also max_steps, which is\n"
                 "compiled in (sim-translate --sim-set-params)")
      ->option_text("NAME=VALUE")
      ->allow_extra_args(false)
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->check(assignment());
  app.add_option("--group-size", options.groupSize,
                 "threads per group, 1 to 4096 (default: the plan's;\n"
                 "on CUDA a multiple of 32 up to 1024)")
      ->option_text("G")
      ->transform(integerIn(1, kMaxGroupSize, "an integer from 1 to 4096"));
  app.add_option("--reference", options.reference,
                 "also run the simple strategy on the same backend,\n"
                 "or evaluate the scene's exact solution at the\n"
                 "final time, and report per observed buffer the\n"
                 "max-abs and the RMS-relative error")
      ->option_text("simple|exact")
      ->check(oneOf({"simple", "exact"}, "simple or exact"));
  CLI::Option *check =
      app.add_flag("--check", options.check,
                   "also run the reference executor with the same\n"
                   "strategy, group size, --set values and steps,\n"
                   "and compare per observed buffer, total,\n"
                   "evaluations and big steps; exit status 1 if they\n"
                   "disagree or a compared value is NaN or infinite");
  check->disable_flag_override();
  // The value as parseNonNegative reads it, not as CLI11 would convert the
  // text again.
  app.add_option_function<std::string>(
         "--check-tolerance",
         [&options](const std::string &text) {
           options.checkTolerance = *parseNonNegative(text);
         },
         "a buffer passes --check when max-abs <= X *\n"
         "max(1, max|reference|) (default by the floats\n"
         "its values derive from: 1e-4 for f32, 1e-10 for\n"
         "f64; totals 1e-4 and 1e-8); 0: the values must\n"
         "be equal")
      ->option_text("X")
      ->check(nonNegativeNumber())
      ->needs(check);
  app.add_option("--dump", options.dump,
                 "write the observed buffers as DIR/<buffer>.npy\n"
                 "(and the reference as <buffer>.reference.npy,\n"
                 "--check's as <buffer>.check.npy; a name's bytes\n"
                 "other than A-Z a-z 0-9 _ . -, and a leading '.',\n"
                 "as %XX)")
      ->option_text("DIR")
      ->check(path());
  app.add_option("--json", options.json, "write every metric as JSON")
      ->option_text("FILE")
      ->check(path());
  app.add_flag("--check-finite", options.checkFinite,
               "run launch by launch and stop at the first NaN\n"
               "or infinity, naming base step, component and item")
      ->disable_flag_override();
  app.add_flag("--distributed", options.distributed,
               "run on every rank of mpirun (MPI_COMM_WORLD), each\n"
               "a block of the range; the bundle must be compiled\n"
               "with sim-translate --sim-distributed (rank 0 prints\n"
               "and writes files; on CUDA the ranks of a machine\n"
               "take devices --device, --device + 1, ...)")
      ->disable_flag_override();
  app.add_flag("--no-init-check", options.noInitCheck,
               "skip the check that every buffer's init is what\n"
               "its writer computes with n = 0 at t = 0 (for scenes\n"
               "whose inits are inconsistent on purpose)")
      ->disable_flag_override();
  app.add_flag("--profile", options.profile,
               "also print the plan's kernels in the last measured\n"
               "run: launches, kernel time, share and time per\n"
               "launch (timed launch by launch on the CPU; CUDA\n"
               "counts launches only: time its kernels with\n"
               "Nsight Systems); --json always has them")
      ->disable_flag_override();
  app.add_flag("--progress", options.progress,
               "show the progress line also when stderr is not a\n"
               "terminal (one line per 10 s; on a terminal it is\n"
               "always shown, rewritten in place)")
      ->disable_flag_override();
  app.add_option("--threads", options.threads,
                 "CPU backend threads, 1 to 1024 (default: all)")
      ->option_text("N")
      ->transform(integerIn(1, kMaxThreads, "an integer from 1 to 1024"));
  app.add_option("--device", options.device, "CUDA device ordinal (default 0)")
      ->option_text("N")
      ->transform(integerIn(0, std::numeric_limits<int32_t>::max(),
                            "a device ordinal (0 or more)"));
  app.add_flag("--cuda-graph", options.cudaGraph,
               "replay the step phase as a CUDA graph")
      ->disable_flag_override();
  app.add_option("--max-memory", options.maxMemory,
                 "the most bytes the state may take on the device,\n"
                 "with an optional K, M, G or T (powers of 1024)\n"
                 "(default 0: three quarters of its memory)")
      ->option_text("SIZE")
      ->transform(size());
}

} // namespace

std::string helpText() {
  Options options;
  std::string backend, strategy;
  std::vector<std::string> sets;
  int64_t reportEvery = 0;
  CLI::App app(kOverview, "sim-run");
  declareOptions(app, options, backend, strategy, sets, reportEvery);
  return app.help();
}

Options parseOptions(int argc, const char *const *argv) {
  Options options;
  std::string backend, strategy;
  std::vector<std::string> sets;
  int64_t reportEvery = 0;
  CLI::App app(kOverview, "sim-run");
  declareOptions(app, options, backend, strategy, sets, reportEvery);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp &) {
    std::fputs(app.help().c_str(), stdout);
    throw Exit{kExitSuccess, ""};
  } catch (const CLI::ParseError &error) {
    usageError(describe(error));
  }

  // What CLI11 did not take: unknown options, or more than one input.
  bool afterSeparator = false;
  for (const std::string &arg : app.remaining()) {
    if (arg == "--" && !afterSeparator) {
      afterSeparator = true;
      continue;
    }
    if (!afterSeparator && arg.size() > 1 && arg[0] == '-')
      usageError("unknown option '" + arg + "'");
    if (options.input.empty()) {
      options.input = arg;
      continue;
    }
    usageError("more than one input: '" + options.input + "' and '" + arg +
               "'");
  }
  if (options.input.empty())
    usageError("no input scene");
  if (reportEvery > 0) {
    if (options.outputEvery > 0 && options.outputEvery != reportEvery)
      usageError("--report-every " + std::to_string(reportEvery) +
                 " and --output-every " + std::to_string(options.outputEvery) +
                 " disagree (--report-every is the old name of "
                 "--output-every)");
    options.outputEvery = reportEvery;
  }
  if (!options.output.empty() && options.outputEvery == 0)
    usageError("--output needs --output-every (the output times)");

  if (!backend.empty())
    sim_backend_parse(backend.c_str(), &options.backend);
  if (!strategy.empty()) {
    sim_strategy_parse(strategy.c_str(), &options.strategy);
    options.strategyGiven = true;
  }
  // The reference executor runs on one thread: a thread count for it is a
  // mistake, not a setting to ignore.
  if (options.backend == SIM_BACKEND_REFERENCE && options.threads != 0)
    usageError("--threads sets the CPU backend's threads; the reference "
               "executor runs on one");
  // Likewise the CUDA options on a backend named that has no GPU (with
  // --backend auto they choose what a GPU run does, if there is one).
  bool hostBackend = options.backend == SIM_BACKEND_CPU ||
                     options.backend == SIM_BACKEND_REFERENCE;
  if (hostBackend && (options.cudaGraph || app.count("--device") > 0))
    usageError(std::string(options.cudaGraph ? "--cuda-graph" : "--device") +
               " applies to the CUDA backend; --backend " + backend +
               " runs on this machine's CPU");
  if (options.profile && options.backend == SIM_BACKEND_REFERENCE)
    usageError("--profile lists the kernels of a plan; the reference "
               "executor runs none (--backend cpu or cuda)");
  if (options.distributed) {
    if (options.backend == SIM_BACKEND_REFERENCE)
      usageError("--distributed runs the plan executor, not the reference "
                 "executor (--check compares with it)");
  }
  for (const std::string &set : sets) {
    size_t equals = set.find('=');
    std::string name = set.substr(0, equals), value = set.substr(equals + 1);
    // A compile-time value is checked here: for a .mlir scene it goes to
    // the translation, which should never be what finds it wrong.
    if (name == "max_steps" && !parseInteger(value, 1, kMaxMaxSteps))
      usageError("--set: max_steps " + inQuotes(value) +
                 " is not an integer from 1 to " +
                 std::to_string(kMaxMaxSteps));
    options.sets.emplace_back(name, value);
  }
  return options;
}

} // namespace simrun
