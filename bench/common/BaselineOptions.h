//===- BaselineOptions.h - The baselines' command line ----------*- C++ -*-===//
//
// sim-baseline-cpu, sim-baseline-host and sim-baseline-cuda take the same
// scene options, declared here once with CLI11 and checked as sim-run checks
// its own (runtime/tools/CommandLine.h): a value outside its domain, an
// unknown option or a stray argument is a usage error (exit status 2) that
// names the option and quotes the value. Each baseline adds its own options
// (threads, flush-to-zero, the clock on the host) to the same CLI::App.
// Header-only, so that nvcc compiles it into sim-baseline-cuda too.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_COMMON_BASELINEOPTIONS_H
#define SIM_BENCH_COMMON_BASELINEOPTIONS_H

#include "CommandLine.h"
#include "Scenes.h"

#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <sys/stat.h>
#include <unistd.h>

namespace sim::bench {

enum class Strategy { Simple, Traditional, Hip, HipCache, Lts };

/// Indexed by Strategy: the names sim-run takes.
inline const std::vector<std::string> &strategyNames() {
  static const std::vector<std::string> names = {"simple", "traditional", "hip",
                                                 "hip-cache", "lts"};
  return names;
}

inline const char *strategyName(Strategy s) {
  return strategyNames()[(int)s].c_str();
}

/// What every baseline takes: the scene, the run and the outputs.
struct SceneOptions {
  std::string scene = "gravity_like";
  Strategy strategy = Strategy::Hip;
  long long steps = 100;
  int repeat = 1;
  int groupSize = 256;
  std::string interp = "linear";
  std::string dumpDir, jsonPath;
  Params params{65536, 1.0e-3f, 8, 0, 32, kMaxSteps, 0};
};

/// The group sizes a baseline can run: [min, max] in multiples of `multiple`.
struct GroupSizes {
  int min, max, multiple;
  const char *help;
};

/// A baseline's command line: the scene options, then whatever the baseline
/// adds to `app` before parse().
class BaselineCommandLine {
public:
  BaselineCommandLine(std::string program, std::string overview,
                      std::string intro, std::string footer,
                      SceneOptions &options, GroupSizes groupSizes)
      : app(std::move(overview), program), program_(std::move(program)),
        options_(options), groupSizes_(groupSizes) {
    app.formatter(std::make_shared<simcli::HelpFormatter>(
        program_ + " [options]", std::move(intro)));
    app.footer(std::move(footer));
    app.set_help_flag("-h,--help", "print this help");
    app.option_defaults()->multi_option_policy(
        CLI::MultiOptionPolicy::TakeLast);
    // Unknown options and stray arguments are reported by parse().
    app.allow_extras();

    app.add_option("--scene", options.scene,
                   "gravity_like or pbd_like (default gravity_like)")
        ->option_text("S")
        ->check(simcli::oneOf({"gravity_like", "pbd_like"},
                              "gravity_like or pbd_like"));
    app.add_option("--strategy", strategy_,
                   "simple, traditional, hip, hip-cache or lts (as\n"
                   "hip: no scene here takes local time steps;\n"
                   "default hip)")
        ->option_text("S")
        ->check(simcli::oneOf(strategyNames(),
                              "simple, traditional, hip, hip-cache or lts"));
    app.add_option("--steps", options.steps,
                   "base steps per run, 0 to 10^12 (default 100)")
        ->option_text("N")
        ->transform(simcli::integerIn(0, 1'000'000'000'000,
                                      "an integer from 0 to 10^12"));
    app.add_option("--repeat", options.repeat,
                   "measured runs from the initial state, median\n"
                   "reported; with K > 1 one more warm-up run comes\n"
                   "first (1 to 100000, default 1)")
        ->option_text("K")
        ->transform(
            simcli::integerIn(1, 100000, "an integer from 1 to 100000"));
    app.add_option("--set", sets_,
                   "range (1 to 2^31), dt (> 0), L (>= 0), dist or\n"
                   "group, as for sim-run --set (defaults 65536,\n"
                   "1e-3, 8, 0, 32)")
        ->option_text("NAME=VALUE")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
        ->check(simcli::assignment());
    app.add_option("--group-size", options.groupSize, groupSizes.help)
        ->option_text("G")
        ->transform(simcli::integerIn(
            groupSizes.min, groupSizes.max,
            "an integer from " + std::to_string(groupSizes.min) + " to " +
                std::to_string(groupSizes.max)));
    app.add_option("--interp", options.interp,
                   "linear: the scene as checked in (pbd_like keeps\n"
                   "B3 and B4 cubic); cubic: every buffer cubic, as\n"
                   "bench/run substitutes it (default linear)")
        ->option_text("I")
        ->check(simcli::oneOf({"linear", "cubic"}, "linear or cubic"));
    app.add_option("--dump", options.dumpDir,
                   "write the observed buffer as DIR/<buffer>.npy (DIR is "
                   "created if missing, as sim-run does)")
        ->option_text("DIR")
        ->check(simcli::path());
    app.add_option("--json", options.jsonPath,
                   "write the metrics as JSON (sim-run's keys)")
        ->option_text("FILE")
        ->check(simcli::path());
  }

  /// Parses `argv`: prints the help and exits 0 for --help, prints the
  /// error and exits 2 for anything wrong.
  void parse(int argc, char **argv) {
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp &) {
      std::fputs(app.help().c_str(), stdout);
      std::exit(0);
    } catch (const CLI::ParseError &error) {
      usageError(simcli::describe(error));
    }
    if (std::string unexpected = simcli::unexpectedArgument(app);
        !unexpected.empty())
      usageError(unexpected);
    if (options_.groupSize % groupSizes_.multiple)
      usageError("--group-size: '" + std::to_string(options_.groupSize) +
                 "' is not a multiple of " +
                 std::to_string(groupSizes_.multiple));
    if (!strategy_.empty())
      for (size_t index = 0; index < strategyNames().size(); ++index)
        if (strategyNames()[index] == strategy_)
          options_.strategy = Strategy(index);
    for (const std::string &set : sets_)
      applySetting(set);
    checkOutputs();
  }

  /// A usage error: the message on stderr, exit status 2.
  [[noreturn]] void usageError(const std::string &message) const {
    std::fprintf(stderr, "%s: error: %s (see %s --help)\n", program_.c_str(),
                 message.c_str(), program_.c_str());
    std::exit(2);
  }

  CLI::App app;

private:
  /// The outputs are written after the run, which can take minutes: refuse
  /// before it what cannot be written then (--dump names an existing
  /// folder, --json a file in one).
  void checkOutputs() const {
    auto writableFolder = [](const std::string &folder) {
      struct stat info;
      return stat(folder.c_str(), &info) == 0 && S_ISDIR(info.st_mode) &&
             access(folder.c_str(), W_OK | X_OK) == 0;
    };
    if (!options_.dumpDir.empty()) {
      std::error_code error;
      std::filesystem::create_directories(options_.dumpDir, error);
      if (error || !writableFolder(options_.dumpDir))
        usageError("--dump: '" + options_.dumpDir +
                   "' is not a folder this process can write into" +
                   (error ? " (" + error.message() + ")" : ""));
    }
    if (!options_.jsonPath.empty()) {
      const std::string &path = options_.jsonPath;
      struct stat info;
      if (path.back() == '/' ||
          (stat(path.c_str(), &info) == 0 && S_ISDIR(info.st_mode)))
        usageError("--json: '" + path + "' is a directory, not a file");
      size_t slash = path.rfind('/');
      std::string folder = slash == std::string::npos ? "."
                           : slash == 0               ? "/"
                                                      : path.substr(0, slash);
      if (!writableFolder(folder))
        usageError("--json: '" + folder +
                   "' is not a folder this process can write into");
    }
  }

  /// One --set NAME=VALUE (assignment() has checked its shape).
  void applySetting(const std::string &set) {
    size_t equals = set.find('=');
    std::string name = set.substr(0, equals), text = set.substr(equals + 1);
    auto integer = [&](long long min, long long max) {
      std::optional<int64_t> value = simcli::parseInteger(text, min, max);
      if (!value)
        usageError("--set " + name + ": " + simcli::inQuotes(text) +
                   " is not an integer from " + std::to_string(min) + " to " +
                   std::to_string(max));
      return *value;
    };
    Params &params = options_.params;
    if (name == "range") {
      params.range = integer(1, 1ll << 31);
    } else if (name == "L") {
      params.rounds = (int)integer(0, INT_MAX);
    } else if (name == "dist") {
      params.dist = (int)integer(INT_MIN, INT_MAX);
    } else if (name == "group") {
      params.group = (int)integer(INT_MIN, INT_MAX);
    } else if (name == "dt") {
      char *end = nullptr;
      float dt = std::strtof(text.c_str(), &end);
      if (text.empty() || *end || !std::isfinite(dt) || !(dt > 0))
        usageError("--set dt: " + simcli::inQuotes(text) +
                   " is not a finite number > 0");
      params.dt = dt;
    } else {
      usageError("--set: unknown parameter " + simcli::inQuotes(name) +
                 " (range, dt, L, dist or group)");
    }
  }

  std::string program_;
  SceneOptions &options_;
  GroupSizes groupSizes_;
  std::string strategy_;
  std::vector<std::string> sets_;
};

} // namespace sim::bench

#endif // SIM_BENCH_COMMON_BASELINEOPTIONS_H
