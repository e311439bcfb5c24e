//===- sim-run.cpp - run a scene bundle and report ------------------------===//
//
// The driver users run: loads a bundle (or translates a .mlir scene into
// one with sim-translate), runs a number of base steps with a strategy on
// CUDA or the CPU, and reports wall and kernel time, launches, host
// synchronisations, evaluations per component, the big steps taken and,
// with --reference, the error against the simple strategy or the exact
// solution. With --check it runs the reference executor too and compares
// values, evaluations and big steps. It uses only the C API of
// sim_runtime.h, like any other client.
//
//===----------------------------------------------------------------------===//

#include "sim/Runtime/sim_runtime.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace {

const char *kUsage =
    R"(OVERVIEW: run a sim scene bundle and report time, work and error

USAGE: sim-run <scene.simb | scene.mlir> [options]

A .mlir scene is first translated with `sim-translate --sim-to-bundle`
(looked up next to sim-run, then on PATH).

OPTIONS:
  --backend B                 auto, cpu, cuda or reference (default auto: CUDA
                              when a driver, a device and the strategy's PTX
                              are there; reference: the reference executor)
  --strategy S                simple, traditional, hip or hip-cache (default hip)
  --steps N                   base steps to run (default 100)
  --repeat K                  run K times from the initial state and report the
                              median; with K > 1 one more warm-up run comes
                              first and is not counted (default 1)
  --report-every N            run once more (a session of its own) from the
                              initial state in chunks of N base steps and print
                              the scene's totals at every output time (0, N,
                              2N, ..., the end)
  --set NAME=VALUE            set range, dt or a scene parameter (repeatable)
  --group-size G              threads per group (default: the plan's; a
                              multiple of 32 on CUDA)
  --reference simple|exact    also run the simple strategy on the same backend,
                              or evaluate the scene's exact solution at the
                              final time, and report per observed buffer the
                              max-abs and the RMS-relative error
  --check                     also run the reference executor with the same
                              strategy, group size, --set values and steps,
                              and compare per observed buffer, total,
                              evaluations and big steps; exit status 1 if they
                              disagree
  --check-tolerance X         a buffer passes --check when max-abs <= X *
                              max(1, max|reference|) (default 1e-4 for f32
                              buffers, 1e-10 for f64; 1e-8 for totals)
  --dump DIR                  write the observed buffers as DIR/<buffer>.npy
                              (and the reference as <buffer>.reference.npy,
                              --check's as <buffer>.check.npy)
  --json FILE                 write every metric as JSON
  --check-finite              run launch by launch and stop at the first NaN
                              or infinity, naming base step, component and item
  --threads N                 CPU backend threads (default: all)
  --device N                  CUDA device ordinal (default 0)
  --cuda-graph                replay the step phase as a CUDA graph
  -h, --help                  print this help

ENVIRONMENT:
  SIM_CUDA_DRIVER             the driver library to load instead of libcuda.so.1

EXIT STATUS: 0 on success, 1 when the run fails or --check finds a
difference, 2 on a usage error.
)";

struct Options {
  std::string input;
  sim_backend backend = SIM_BACKEND_AUTO;
  sim_strategy strategy = SIM_STRATEGY_HIP;
  int64_t steps = 100;
  int64_t repeat = 1;
  /// --report-every; 0: no report per output time.
  int64_t reportEvery = 0;
  std::vector<std::pair<std::string, std::string>> sets;
  int64_t groupSize = 0;
  std::string reference;
  bool check = false;
  /// --check-tolerance; 0: by scalar type.
  double checkTolerance = 0;
  std::string dump;
  std::string json;
  bool checkFinite = false;
  int32_t threads = 0;
  int32_t device = 0;
  bool cudaGraph = false;
};

/// A failure that ends the program with a message and an exit status.
struct Exit {
  int status;
  std::string message;
};

[[noreturn]] void usageError(const std::string &message) {
  throw Exit{2, message + " (see sim-run --help)"};
}

[[noreturn]] void runError(const std::string &message) {
  throw Exit{1, message};
}

void check(sim_status status) {
  if (status != SIM_OK)
    runError(sim_last_error());
}

int64_t parseCount(const std::string &option, const std::string &text,
                   int64_t min) {
  char *end = nullptr;
  errno = 0;
  long long value = std::strtoll(text.c_str(), &end, 10);
  if (text.empty() || *end || errno == ERANGE || value < min)
    usageError(option + " expects an integer >= " + std::to_string(min) +
               ", not '" + text + "'");
  return value;
}

Options parseOptions(int argc, char **argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "-h" || arg == "--help" || arg == "-help") {
      std::fputs(kUsage, stdout);
      throw Exit{0, ""};
    }
    if (arg.size() < 2 || arg[0] != '-') {
      if (!options.input.empty())
        usageError("more than one input: '" + options.input + "' and '" + arg +
                   "'");
      options.input = arg;
      continue;
    }
    // --name value or --name=value.
    std::string name = arg, value;
    bool inlineValue = false;
    size_t equals = arg.find('=');
    if (arg.rfind("--", 0) == 0 && equals != std::string::npos) {
      name = arg.substr(0, equals);
      value = arg.substr(equals + 1);
      inlineValue = true;
    }
    auto takeValue = [&]() -> std::string {
      if (inlineValue)
        return value;
      if (i + 1 >= argc)
        usageError(name + " expects a value");
      return argv[++i];
    };
    auto flag = [&]() {
      if (inlineValue)
        usageError(name + " takes no value");
    };
    if (name == "--backend") {
      if (sim_backend_parse(takeValue().c_str(), &options.backend) != SIM_OK)
        usageError(sim_last_error());
    } else if (name == "--strategy") {
      if (sim_strategy_parse(takeValue().c_str(), &options.strategy) != SIM_OK)
        usageError(sim_last_error());
    } else if (name == "--steps") {
      options.steps = parseCount(name, takeValue(), 0);
    } else if (name == "--repeat") {
      options.repeat = parseCount(name, takeValue(), 1);
    } else if (name == "--report-every") {
      options.reportEvery = parseCount(name, takeValue(), 1);
    } else if (name == "--set") {
      std::string assignment = takeValue();
      size_t at = assignment.find('=');
      if (at == 0 || at == std::string::npos)
        usageError("--set expects NAME=VALUE, not '" + assignment + "'");
      options.sets.emplace_back(assignment.substr(0, at),
                                assignment.substr(at + 1));
    } else if (name == "--group-size") {
      options.groupSize = parseCount(name, takeValue(), 1);
    } else if (name == "--reference") {
      options.reference = takeValue();
      if (options.reference != "simple" && options.reference != "exact")
        usageError("--reference expects simple or exact, not '" +
                   options.reference + "'");
    } else if (name == "--check") {
      flag();
      options.check = true;
    } else if (name == "--check-tolerance") {
      std::string text = takeValue();
      char *end = nullptr;
      options.checkTolerance = std::strtod(text.c_str(), &end);
      if (text.empty() || *end || !(options.checkTolerance > 0) ||
          !std::isfinite(options.checkTolerance))
        usageError("--check-tolerance expects a positive number, not '" + text +
                   "'");
    } else if (name == "--dump") {
      options.dump = takeValue();
    } else if (name == "--json") {
      options.json = takeValue();
    } else if (name == "--check-finite") {
      flag();
      options.checkFinite = true;
    } else if (name == "--threads") {
      options.threads = int32_t(parseCount(name, takeValue(), 1));
    } else if (name == "--device") {
      options.device = int32_t(parseCount(name, takeValue(), 0));
    } else if (name == "--cuda-graph") {
      flag();
      options.cudaGraph = true;
    } else {
      usageError("unknown option '" + arg + "'");
    }
  }
  if (options.input.empty())
    usageError("no input scene");
  if (options.checkTolerance > 0 && !options.check)
    usageError("--check-tolerance needs --check");
  return options;
}

//===----------------------------------------------------------------------===//
// .mlir input
//===----------------------------------------------------------------------===//

bool isExecutable(const std::string &path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         access(path.c_str(), X_OK) == 0;
}

/// sim-translate next to this binary, else on PATH.
std::optional<std::string> findTranslate(std::string &searched) {
  char self[4096];
  ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length > 0) {
    std::string dir(self, size_t(length));
    dir = dir.substr(0, dir.rfind('/'));
    searched = dir;
    if (isExecutable(dir + "/sim-translate"))
      return dir + "/sim-translate";
  }
  const char *path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  std::string dir;
  while (std::getline(dirs, dir, ':'))
    if (!dir.empty() && isExecutable(dir + "/sim-translate"))
      return dir + "/sim-translate";
  return std::nullopt;
}

/// A file removed when the program ends.
struct TemporaryFile {
  std::string path;
  ~TemporaryFile() {
    if (!path.empty())
      unlink(path.c_str());
  }
};

/// Translates a .mlir scene into a temporary bundle.
void translate(const std::string &scene, TemporaryFile &bundle) {
  std::string searched;
  std::optional<std::string> tool = findTranslate(searched);
  if (!tool)
    runError("cannot translate '" + scene +
             "': sim-translate not found (looked in " +
             (searched.empty() ? std::string("the directory of sim-run")
                               : searched) +
             " and on PATH); build it, or pass a .simb bundle");
  const char *tmp = std::getenv("TMPDIR");
  std::string path =
      std::string(tmp && *tmp ? tmp : "/tmp") + "/sim-run-XXXXXX.simb";
  int fd = mkstemps(path.data(), 5);
  if (fd < 0)
    runError("cannot create a temporary bundle: " +
             std::string(std::strerror(errno)));
  close(fd);
  bundle.path = path;
  std::vector<std::string> args = {*tool, scene, "--sim-to-bundle", "-o", path};
  std::vector<char *> argv;
  for (std::string &arg : args)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  pid_t pid;
  if (int error = posix_spawn(&pid, tool->c_str(), nullptr, nullptr,
                              argv.data(), environ))
    runError("cannot run " + *tool + ": " + std::strerror(error));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    runError("sim-translate failed on '" + scene + "'" +
             (WIFEXITED(status)
                  ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")"
                  : std::string(" (killed by a signal)")));
}

bool isBundle(const std::string &path) {
  char magic[8] = {};
  std::ifstream file(path, std::ios::binary);
  file.read(magic, sizeof magic);
  return file.gcount() == 8 && std::memcmp(magic, "SIMBNDL", 8) == 0;
}

bool endsWith(const std::string &text, const std::string &suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

//===----------------------------------------------------------------------===//
// Buffers, errors, files
//===----------------------------------------------------------------------===//

struct Buffer {
  sim_buffer_info info;
  std::vector<uint8_t> bytes;

  size_t values() const { return bytes.size() / size_t(info.scalar_bytes); }
  double at(size_t i) const {
    if (info.scalar_bytes == 8) {
      double value;
      std::memcpy(&value, bytes.data() + i * 8, 8);
      return value;
    }
    float value;
    std::memcpy(&value, bytes.data() + i * 4, 4);
    return value;
  }
};

std::vector<sim_buffer_info> observedBuffers(const sim_bundle *bundle) {
  std::vector<sim_buffer_info> observed;
  for (int32_t i = 0; i < sim_bundle_num_buffers(bundle); ++i) {
    sim_buffer_info info;
    check(sim_bundle_buffer(bundle, i, &info));
    if (info.observed)
      observed.push_back(info);
  }
  return observed;
}

Buffer readBuffer(sim_session *session, const sim_buffer_info &info,
                  bool exact) {
  Buffer buffer{info, {}};
  size_t bytes = 0;
  check(sim_session_buffer_bytes(session, info.name, &bytes));
  buffer.bytes.resize(bytes);
  if (exact)
    check(sim_session_exact(session, info.name, buffer.bytes.data(), bytes));
  else
    check(
        sim_session_get_buffer(session, info.name, buffer.bytes.data(), bytes));
  return buffer;
}

struct ErrorNorms {
  double maxAbs = 0;
  /// ||a - b||_2 / ||b||_2; 0 when both are zero, inf when only b is.
  double rmsRel = 0;
  /// Values that are NaN on both sides, or the same infinity, when they are
  /// taken as equal (the check: a scene that blows up must blow up alike).
  size_t sameNonFinite = 0;
};

ErrorNorms compare(const Buffer &value, const Buffer &reference,
                   bool sameNonFiniteIsEqual = false) {
  ErrorNorms norms;
  double diff2 = 0, ref2 = 0;
  for (size_t i = 0; i < value.values(); ++i) {
    double a = value.at(i), b = reference.at(i);
    if (sameNonFiniteIsEqual && !std::isfinite(b) &&
        ((std::isnan(a) && std::isnan(b)) || a == b)) {
      ++norms.sameNonFinite;
      continue;
    }
    double d = a - b;
    norms.maxAbs = std::max(norms.maxAbs, std::fabs(d));
    if (std::isnan(d))
      norms.maxAbs = d;
    diff2 += d * d;
    ref2 += b * b;
  }
  norms.rmsRel = ref2 > 0 ? std::sqrt(diff2 / ref2) : diff2 > 0 ? INFINITY : 0;
  return norms;
}

/// Writes `contents` to `path` through a temporary file and a rename, so a
/// reader never sees half a file.
void writeAtomically(const std::string &path, const std::string &contents) {
  std::string temporary = path + ".tmp." + std::to_string(getpid());
  {
    std::ofstream file(temporary, std::ios::binary | std::ios::trunc);
    file.write(contents.data(), std::streamsize(contents.size()));
    file.close();
    if (!file) {
      unlink(temporary.c_str());
      runError("cannot write '" + temporary + "'");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    int error = errno;
    unlink(temporary.c_str());
    runError("cannot rename '" + temporary + "' to '" + path +
             "': " + std::strerror(error));
  }
}

/// A .npy file (format 1.0): shape (range,) or (range, lanes).
std::string npy(const Buffer &buffer, int64_t range) {
  std::string shape =
      std::to_string(range) +
      (buffer.info.lanes > 1 ? ", " + std::to_string(buffer.info.lanes) + ")"
                             : ",)");
  std::string header = std::string("{'descr': '<f") +
                       std::to_string(buffer.info.scalar_bytes) +
                       "', 'fortran_order': False, 'shape': (" + shape + ", }";
  // Magic, version, length and header end on a multiple of 64 bytes.
  size_t total = 10 + header.size() + 1;
  header.append((64 - total % 64) % 64, ' ');
  header += '\n';
  std::string file("\x93NUMPY\x01\x00", 8);
  file += char(header.size() & 0xff);
  file += char(header.size() >> 8);
  file += header;
  file.append(reinterpret_cast<const char *>(buffer.bytes.data()),
              buffer.bytes.size());
  return file;
}

void makeDirectory(const std::string &dir) {
  if (mkdir(dir.c_str(), 0777) != 0 && errno != EEXIST)
    runError("cannot create directory '" + dir + "': " + std::strerror(errno));
  struct stat info;
  if (stat(dir.c_str(), &info) != 0 || !S_ISDIR(info.st_mode))
    runError("'" + dir + "' is not a directory");
}

std::string jsonString(const std::string &text) {
  std::string out = "\"";
  for (char c : text) {
    switch (c) {
    case '"':
      out += "\\\"";
      break;
    case '\\':
      out += "\\\\";
      break;
    case '\n':
      out += "\\n";
      break;
    default:
      if ((unsigned char)c < 0x20) {
        char escaped[8];
        std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
        out += escaped;
      } else {
        out += c;
      }
    }
  }
  return out + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value))
    return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

/// A value that must read back exactly (totals, whose drift is measured
/// from them): 17 significant digits.
std::string jsonExactNumber(double value) {
  if (!std::isfinite(value))
    return "null";
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

std::string formatTime(double seconds) {
  char text[32];
  if (seconds < 1e-3)
    std::snprintf(text, sizeof text, "%.1f us", seconds * 1e6);
  else if (seconds < 1)
    std::snprintf(text, sizeof text, "%.3f ms", seconds * 1e3);
  else
    std::snprintf(text, sizeof text, "%.3f s", seconds);
  return text;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

//===----------------------------------------------------------------------===//
// --check
//===----------------------------------------------------------------------===//

/// What one session counted in its last run.
struct Work {
  std::vector<std::pair<std::string, int64_t>> evaluations;
  int64_t bigSteps = 0;
  std::vector<int64_t> histogram; // index m in 0 .. max_steps
};

Work workOf(sim_session *session, int64_t maxSteps) {
  Work work;
  for (int32_t c = 0; c < sim_session_num_components(session); ++c)
    work.evaluations.emplace_back(sim_session_component(session, c),
                                  sim_session_evaluations(session, c));
  sim_metrics metrics;
  check(sim_session_metrics(session, &metrics));
  work.bigSteps = metrics.big_steps;
  work.histogram.assign(size_t(maxSteps) + 1, 0);
  for (int64_t m = 1; m <= maxSteps; ++m)
    work.histogram[size_t(m)] = sim_session_histogram(session, m);
  return work;
}

/// The run against the reference executor's.
struct Check {
  struct BufferRow {
    std::string buffer;
    ErrorNorms norms;
    double maxReference = 0, tolerance = 0, limit = 0;
    bool pass = false;
  };
  std::vector<BufferRow> buffers;
  struct CountRow {
    std::string component;
    /// -1: the side has no such component.
    int64_t backend = -1, reference = -1;
  };
  std::vector<CountRow> evaluations;
  Work backend, reference;
  /// What differs, in words; empty when the check passes.
  std::vector<std::string> failures;
};

std::string scientific(double value, int digits = 3) {
  char text[32];
  std::snprintf(text, sizeof text, "%.*e", digits, value);
  return text;
}

Check compareWithReference(const std::vector<Buffer> &results,
                           const std::vector<Buffer> &references,
                           const Work &backend, const Work &reference,
                           double tolerance) {
  Check check;
  check.backend = backend;
  check.reference = reference;
  for (size_t i = 0; i < results.size(); ++i) {
    Check::BufferRow row;
    row.buffer = results[i].info.name;
    row.norms = compare(results[i], references[i],
                        /*sameNonFiniteIsEqual=*/true);
    for (size_t v = 0; v < references[i].values(); ++v)
      if (std::isfinite(references[i].at(v)))
        row.maxReference =
            std::max(row.maxReference, std::fabs(references[i].at(v)));
    row.tolerance = tolerance > 0                       ? tolerance
                    : results[i].info.scalar_bytes == 8 ? 1e-10
                                                        : 1e-4;
    row.limit = row.tolerance * std::max(1.0, row.maxReference);
    // A NaN difference compares false: it fails.
    row.pass = row.norms.maxAbs <= row.limit;
    if (!row.pass)
      check.failures.push_back(
          "buffer " + row.buffer + " exceeds the tolerance (max-abs " +
          scientific(row.norms.maxAbs) + " > " + scientific(row.limit) + ")");
    check.buffers.push_back(row);
  }
  for (const auto &[name, count] : backend.evaluations)
    check.evaluations.push_back({name, count, -1});
  for (const auto &entry : reference.evaluations) {
    auto row = std::find_if(check.evaluations.begin(), check.evaluations.end(),
                            [&](const Check::CountRow &row) {
                              return row.component == entry.first;
                            });
    if (row == check.evaluations.end())
      check.evaluations.push_back({entry.first, -1, entry.second});
    else
      row->reference = entry.second;
  }
  auto count = [](int64_t value) {
    return value < 0 ? std::string("-") : std::to_string(value);
  };
  for (const Check::CountRow &row : check.evaluations)
    if (row.backend != row.reference)
      check.failures.push_back("evaluations of " + row.component + " differ (" +
                               count(row.backend) + " vs " +
                               count(row.reference) + ")");
  if (backend.bigSteps != reference.bigSteps)
    check.failures.push_back("big steps differ (" +
                             std::to_string(backend.bigSteps) + " vs " +
                             std::to_string(reference.bigSteps) + ")");
  for (size_t m = 1; m < backend.histogram.size(); ++m)
    if (backend.histogram[m] != reference.histogram[m])
      check.failures.push_back("big steps of size " + std::to_string(m) +
                               " differ (" +
                               std::to_string(backend.histogram[m]) + " vs " +
                               std::to_string(reference.histogram[m]) + ")");
  return check;
}

//===----------------------------------------------------------------------===//
// Progress
//===----------------------------------------------------------------------===//

/// A progress line on stderr once a run has taken a few seconds.
struct Progress {
  std::chrono::steady_clock::time_point start, last;
  std::string label;
  bool tty = isatty(STDERR_FILENO);
  bool shown = false;

  void begin(std::string runLabel) {
    label = std::move(runLabel);
    start = last = std::chrono::steady_clock::now();
  }
  static void report(void *user, int64_t done, int64_t total) {
    auto *self = static_cast<Progress *>(user);
    auto now = std::chrono::steady_clock::now();
    double elapsed = std::chrono::duration<double>(now - self->start).count();
    double since = std::chrono::duration<double>(now - self->last).count();
    // Past 3 s; on a terminal every half second, in a log every 10 s.
    if (elapsed < 3 || since < (self->tty ? 0.5 : 10))
      return;
    self->last = now;
    self->shown = true;
    std::fprintf(
        stderr, "%ssim-run: %sbase step %lld of %lld (%.0f%%, %.0f s)%s",
        self->tty ? "\r" : "", self->label.c_str(), (long long)done,
        (long long)total, total ? 100.0 * double(done) / double(total) : 100.0,
        elapsed, self->tty ? "\033[K" : "\n");
    std::fflush(stderr);
  }
  void end() {
    if (shown && tty)
      std::fputs("\r\033[K", stderr);
    shown = false;
  }
};

//===----------------------------------------------------------------------===//
// The run
//===----------------------------------------------------------------------===//

struct Session {
  sim_session *handle = nullptr;
  ~Session() { sim_session_destroy(handle); }
};

struct Bundle {
  sim_bundle *handle = nullptr;
  ~Bundle() { sim_bundle_close(handle); }
};

void applySets(sim_session *session, const Options &options) {
  for (const auto &[name, value] : options.sets)
    if (sim_session_set(session, name.c_str(), value.c_str()) != SIM_OK)
      runError(std::string("--set ") + name + "=" + value + ": " +
               sim_last_error());
}

/// Runs `steps` from the initial state and checks it ended exactly there.
void runFromStart(sim_session *session, const Options &options,
                  Progress &progress, const std::string &label) {
  check(sim_session_init(session));
  progress.begin(label);
  sim_session_set_progress(session, &Progress::report, &progress);
  sim_status status = sim_session_run(session, options.steps);
  progress.end();
  check(status);
  sim_metrics metrics;
  check(sim_session_metrics(session, &metrics));
  if (metrics.end != options.steps ||
      sim_session_time(session) != options.steps)
    runError("the run ended at base step " +
             std::to_string(sim_session_time(session)) + ", not at " +
             std::to_string(options.steps));
}

/// The totals of a session at its current time, in declaration order.
std::vector<double> totalsOf(sim_session *session) {
  std::vector<double> values;
  for (int32_t t = 0; t < sim_session_num_totals(session); ++t) {
    double value = 0;
    check(
        sim_session_total(session, sim_session_total_name(session, t), &value));
    values.push_back(value);
  }
  return values;
}

/// The totals at one output time.
struct TotalsAt {
  int64_t time;
  std::vector<double> values;
};

/// --report-every: runs `steps` from the initial state in chunks of
/// `every` base steps and takes the totals at the start and after each.
std::vector<TotalsAt> totalsPerOutputTime(sim_session *session,
                                          const Options &options,
                                          Progress &progress,
                                          const std::string &label) {
  check(sim_session_init(session));
  std::vector<TotalsAt> series = {{0, totalsOf(session)}};
  while (sim_session_time(session) < options.steps) {
    int64_t chunk = std::min(options.reportEvery,
                             options.steps - sim_session_time(session));
    progress.begin(label);
    sim_session_set_progress(session, &Progress::report, &progress);
    sim_status status = sim_session_run(session, chunk);
    progress.end();
    check(status);
    series.push_back({sim_session_time(session), totalsOf(session)});
  }
  return series;
}

/// One total of the backend against the reference executor's.
struct TotalRow {
  std::string total;
  int64_t time;
  double backend, reference, limit;
  bool pass;
};

/// Compares totals with `tolerance` (relative to max(1, |reference|)).
void compareTotals(const std::vector<std::string> &names, int64_t time,
                   const std::vector<double> &backend,
                   const std::vector<double> &reference, double tolerance,
                   std::vector<TotalRow> &rows,
                   std::vector<std::string> &failures) {
  for (size_t t = 0; t < names.size(); ++t) {
    TotalRow row{names[t], time, backend[t], reference[t], 0, false};
    row.limit = tolerance * std::max(1.0, std::fabs(row.reference));
    // A NaN difference compares false: it fails.
    row.pass = std::fabs(row.backend - row.reference) <= row.limit;
    if (!row.pass)
      failures.push_back("total " + row.total + " at base step " +
                         std::to_string(time) + " differs (" +
                         scientific(row.backend, 9) + " vs " +
                         scientific(row.reference, 9) + ")");
    rows.push_back(row);
  }
}

int run(const Options &options) {
  TemporaryFile translated;
  std::string path = options.input;
  if (endsWith(path, ".mlir") && !isBundle(path)) {
    translate(path, translated);
    path = translated.path;
  }
  Bundle bundle;
  check(sim_bundle_open(path.c_str(), &bundle.handle));

  sim_session_options sessionOptions;
  sim_session_options_init(&sessionOptions);
  sessionOptions.strategy = options.strategy;
  sessionOptions.backend = options.backend;
  sessionOptions.group_size = options.groupSize;
  sessionOptions.cpu_threads = options.threads;
  sessionOptions.cuda_device = options.device;
  sessionOptions.cuda_graph = options.cudaGraph;
  sessionOptions.check_finite = options.checkFinite;
  Session session;
  check(sim_session_create(bundle.handle, &sessionOptions, &session.handle));
  applySets(session.handle, options);

  // Runs: a warm-up first when several are measured.
  Progress progress;
  int64_t total = options.repeat > 1 ? options.repeat + 1 : 1;
  std::vector<double> walls, kernels;
  sim_metrics metrics{};
  for (int64_t r = 0; r < total; ++r) {
    bool warmUp = total > 1 && r == 0;
    std::string label;
    if (warmUp)
      label = "warm-up: ";
    else if (total > 1)
      label = "run " + std::to_string(r) + " of " +
              std::to_string(options.repeat) + ": ";
    // A non-finite value (--check-finite) ends here with a message that
    // names the base step, component, buffer and item.
    runFromStart(session.handle, options, progress, label);
    check(sim_session_metrics(session.handle, &metrics));
    if (!warmUp) {
      walls.push_back(metrics.wall_seconds);
      kernels.push_back(metrics.kernel_seconds);
    }
  }
  double wall = median(walls), kernel = median(kernels);

  // Totals at the end of the run (and per output time, below).
  std::vector<std::string> totalNames;
  for (int32_t t = 0; t < sim_session_num_totals(session.handle); ++t)
    totalNames.push_back(sim_session_total_name(session.handle, t));
  std::vector<double> totals = totalsOf(session.handle);

  char range[64], dt[64];
  check(sim_session_get(session.handle, "range", range, sizeof range));
  check(sim_session_get(session.handle, "dt", dt, sizeof dt));
  std::vector<sim_buffer_info> observed = observedBuffers(bundle.handle);
  std::vector<Buffer> results;
  for (const sim_buffer_info &info : observed)
    results.push_back(readBuffer(session.handle, info, false));

  // The reference.
  struct Comparison {
    std::string buffer;
    bool available;
    ErrorNorms norms;
  };
  std::vector<Comparison> comparisons;
  std::vector<std::optional<Buffer>> references(observed.size());
  if (options.reference == "simple") {
    sim_session_options simple = sessionOptions;
    simple.strategy = SIM_STRATEGY_SIMPLE;
    simple.backend = sim_session_backend(session.handle);
    simple.group_size = sim_session_group_size(session.handle);
    simple.cuda_graph = 0;
    Session reference;
    check(sim_session_create(bundle.handle, &simple, &reference.handle));
    applySets(reference.handle, options);
    runFromStart(reference.handle, options, progress, "reference: ");
    for (size_t i = 0; i < observed.size(); ++i)
      references[i] = readBuffer(reference.handle, observed[i], false);
  } else if (options.reference == "exact") {
    bool any = false;
    for (size_t i = 0; i < observed.size(); ++i)
      if (sim_session_has_exact(session.handle, observed[i].name)) {
        references[i] = readBuffer(session.handle, observed[i], true);
        any = true;
      }
    if (!any)
      runError(std::string("--reference exact: scene '") +
               sim_bundle_scene_name(bundle.handle) +
               "' declares no exact solution of an observed buffer");
  }
  if (!options.reference.empty())
    for (size_t i = 0; i < observed.size(); ++i)
      comparisons.push_back(
          {observed[i].name, references[i].has_value(),
           references[i] ? compare(results[i], *references[i]) : ErrorNorms{}});

  // --check: the same run on the reference executor.
  std::optional<Check> checked;
  std::vector<Buffer> checkValues;
  std::vector<TotalsAt> series;
  std::vector<TotalRow> totalRows, seriesRows;
  // --report-every runs on a session of its own, so that the measured run's
  // counters stay what the table and --check report.
  auto seriesOfNewSession = [&] {
    Session chunked;
    check(sim_session_create(bundle.handle, &sessionOptions, &chunked.handle));
    applySets(chunked.handle, options);
    return totalsPerOutputTime(chunked.handle, options, progress, "totals: ");
  };
  if (options.check) {
    sim_session_options referenceOptions = sessionOptions;
    referenceOptions.backend = SIM_BACKEND_REFERENCE;
    referenceOptions.group_size = sim_session_group_size(session.handle);
    referenceOptions.cuda_graph = 0;
    Session reference;
    check(sim_session_create(bundle.handle, &referenceOptions,
                             &reference.handle));
    applySets(reference.handle, options);
    runFromStart(reference.handle, options, progress, "check: ");
    for (const sim_buffer_info &info : observed)
      checkValues.push_back(readBuffer(reference.handle, info, false));
    int64_t maxSteps = sim_bundle_max_steps(bundle.handle);
    checked = compareWithReference(
        results, checkValues, workOf(session.handle, maxSteps),
        workOf(reference.handle, maxSteps), options.checkTolerance);
    double totalTolerance =
        options.checkTolerance > 0 ? options.checkTolerance : 1e-8;
    compareTotals(totalNames, options.steps, totals, totalsOf(reference.handle),
                  totalTolerance, totalRows, checked->failures);
    if (options.reportEvery > 0 && !totalNames.empty()) {
      std::vector<TotalsAt> theirs = totalsPerOutputTime(
          reference.handle, options, progress, "check totals: ");
      series = seriesOfNewSession();
      for (size_t k = 0; k < series.size() && k < theirs.size(); ++k)
        compareTotals(totalNames, series[k].time, series[k].values,
                      theirs[k].values, totalTolerance, seriesRows,
                      checked->failures);
    }
  }
  if (options.reportEvery > 0 && series.empty())
    series = seriesOfNewSession();

  if (!options.dump.empty()) {
    makeDirectory(options.dump);
    for (size_t i = 0; i < observed.size(); ++i) {
      std::string base = options.dump + "/" + observed[i].name;
      writeAtomically(base + ".npy",
                      npy(results[i], sim_session_range(session.handle)));
      if (references[i])
        writeAtomically(base + ".reference.npy",
                        npy(*references[i], sim_session_range(session.handle)));
      if (checked)
        writeAtomically(base + ".check.npy",
                        npy(checkValues[i], sim_session_range(session.handle)));
    }
  }

  // The table.
  std::string backend = sim_backend_name(sim_session_backend(session.handle));
  std::string note = sim_session_backend_note(session.handle);
  std::printf("scene %s, strategy %s, backend %s: %s\n",
              sim_bundle_scene_name(bundle.handle),
              sim_strategy_name(options.strategy), backend.c_str(),
              sim_session_device(session.handle));
  if (options.backend == SIM_BACKEND_AUTO && !note.empty())
    std::printf("  (not CUDA: %s)\n", note.c_str());
  std::printf("range %s, dt %s, group size %lld, %lld base steps", range, dt,
              (long long)sim_session_group_size(session.handle),
              (long long)options.steps);
  if (options.repeat > 1)
    std::printf(", median of %lld runs after a warm-up",
                (long long)options.repeat);
  std::printf("\n\n");
  auto row = [](const char *name, const std::string &value) {
    std::printf("  %-16s %s\n", name, value.c_str());
  };
  row("wall time", formatTime(wall));
  row("kernel time", formatTime(kernel));
  row("launches", std::to_string(metrics.launches) +
                      (metrics.graph_launches
                           ? " (" + std::to_string(metrics.graph_launches) +
                                 " graph replays)"
                           : ""));
  row("host syncs", std::to_string(metrics.host_syncs));
  row("big steps", std::to_string(metrics.big_steps));
  std::string sizes;
  for (int64_t m = 1; m <= sim_bundle_max_steps(bundle.handle); ++m)
    if (int64_t count = sim_session_histogram(session.handle, m))
      sizes += (sizes.empty() ? "" : "  ") + std::to_string(m) + ": " +
               std::to_string(count);
  row("big-step sizes", sizes.empty() ? "-" : sizes);
  std::string evaluations;
  for (int32_t c = 0; c < sim_session_num_components(session.handle); ++c)
    evaluations += (c ? "  " : "") +
                   std::string(sim_session_component(session.handle, c)) + " " +
                   std::to_string(sim_session_evaluations(session.handle, c));
  row("evaluations", evaluations.empty() ? "-" : evaluations);
  for (const Comparison &comparison : comparisons) {
    std::string label = "error vs " + options.reference;
    char text[160];
    if (comparison.available)
      std::snprintf(text, sizeof text, "%s  max-abs %.3e  rms-rel %.3e",
                    comparison.buffer.c_str(), comparison.norms.maxAbs,
                    comparison.norms.rmsRel);
    else
      std::snprintf(text, sizeof text, "%s  (no exact solution)",
                    comparison.buffer.c_str());
    row(label.c_str(), text);
  }
  auto formatTotals = [&](const std::vector<double> &values) {
    std::string text;
    for (size_t t = 0; t < values.size(); ++t)
      text += (t ? "  " : "") + totalNames[t] + " " + scientific(values[t], 9);
    return text;
  };
  if (!series.empty()) {
    std::printf("\ntotals every %lld base steps:\n",
                (long long)options.reportEvery);
    double dtValue = std::strtod(dt, nullptr);
    for (const TotalsAt &at : series)
      std::printf("  T %lld  time %s  %s\n", (long long)at.time,
                  scientific(double(at.time) * dtValue, 9).c_str(),
                  formatTotals(at.values).c_str());
  }
  if (!totalNames.empty())
    std::printf("\ntotals  %s\n", formatTotals(totals).c_str());

  if (checked) {
    std::printf("\ncheck against the reference executor (strategy %s, group "
                "size %lld, %lld base steps):\n",
                sim_strategy_name(options.strategy),
                (long long)sim_session_group_size(session.handle),
                (long long)options.steps);
    for (const Check::BufferRow &buffer : checked->buffers)
      std::printf("  buffer %s  max-abs %.3e  max-ref %.3e  rms-rel %.3e  "
                  "tolerance %.1e  %s%s\n",
                  buffer.buffer.c_str(), buffer.norms.maxAbs,
                  buffer.maxReference, buffer.norms.rmsRel, buffer.tolerance,
                  buffer.pass ? "pass" : "FAIL",
                  buffer.norms.sameNonFinite
                      ? ("  (" + std::to_string(buffer.norms.sameNonFinite) +
                         " values non-finite on both sides)")
                            .c_str()
                      : "");
    for (const TotalRow &total : totalRows)
      std::printf("  total %s  backend %.9e  reference %.9e  limit %.1e  %s\n",
                  total.total.c_str(), total.backend, total.reference,
                  total.limit, total.pass ? "pass" : "FAIL");
    if (!seriesRows.empty()) {
      bool all = std::all_of(seriesRows.begin(), seriesRows.end(),
                             [](const TotalRow &row) { return row.pass; });
      std::printf("  totals at %zu output times  %s\n",
                  seriesRows.size() / totalNames.size(), all ? "pass" : "FAIL");
    }
    auto text = [](int64_t count) {
      return count < 0 ? std::string("-") : std::to_string(count);
    };
    auto same = [](bool equal) { return equal ? "equal" : "DIFFER"; };
    for (const Check::CountRow &row : checked->evaluations)
      std::printf("  evaluations %s  backend %s  reference %s  %s\n",
                  row.component.c_str(), text(row.backend).c_str(),
                  text(row.reference).c_str(),
                  same(row.backend == row.reference));
    std::printf("  big steps  backend %lld  reference %lld  %s\n",
                (long long)checked->backend.bigSteps,
                (long long)checked->reference.bigSteps,
                same(checked->backend.bigSteps == checked->reference.bigSteps));
    for (size_t m = 1; m < checked->backend.histogram.size(); ++m) {
      int64_t mine = checked->backend.histogram[m];
      int64_t theirs = checked->reference.histogram[m];
      if (mine || theirs)
        std::printf("  big-step size %zu  backend %lld  reference %lld  %s\n",
                    m, (long long)mine, (long long)theirs,
                    same(mine == theirs));
    }
    std::string verdict = "pass";
    if (!checked->failures.empty()) {
      verdict = "FAIL: ";
      for (size_t i = 0; i < checked->failures.size(); ++i)
        verdict += (i ? "; " : "") + checked->failures[i];
    }
    std::printf("check: %s\n", verdict.c_str());
  }

  if (!options.json.empty()) {
    std::ostringstream json;
    json << "{\n";
    json << "  \"scene\": " << jsonString(sim_bundle_scene_name(bundle.handle))
         << ",\n";
    json << "  \"strategy\": "
         << jsonString(sim_strategy_name(options.strategy)) << ",\n";
    json << "  \"backend\": " << jsonString(backend) << ",\n";
    json << "  \"device\": " << jsonString(sim_session_device(session.handle))
         << ",\n";
    json << "  \"range\": " << range << ",\n";
    json << "  \"dt\": " << jsonNumber(std::strtod(dt, nullptr)) << ",\n";
    json << "  \"group_size\": " << sim_session_group_size(session.handle)
         << ",\n";
    json << "  \"steps\": " << options.steps << ",\n";
    json << "  \"repeat\": " << options.repeat << ",\n";
    json << "  \"wall_seconds\": " << jsonNumber(wall) << ",\n";
    json << "  \"kernel_seconds\": " << jsonNumber(kernel) << ",\n";
    json << "  \"wall_seconds_runs\": [";
    for (size_t i = 0; i < walls.size(); ++i)
      json << (i ? ", " : "") << jsonNumber(walls[i]);
    json << "],\n  \"kernel_seconds_runs\": [";
    for (size_t i = 0; i < kernels.size(); ++i)
      json << (i ? ", " : "") << jsonNumber(kernels[i]);
    json << "],\n";
    json << "  \"launches\": " << metrics.launches << ",\n";
    json << "  \"graph_launches\": " << metrics.graph_launches << ",\n";
    json << "  \"host_syncs\": " << metrics.host_syncs << ",\n";
    json << "  \"big_steps\": " << metrics.big_steps << ",\n";
    json << "  \"big_step_histogram\": {";
    for (int64_t m = 1; m <= sim_bundle_max_steps(bundle.handle); ++m)
      json << (m > 1 ? ", " : "") << "\"" << m
           << "\": " << sim_session_histogram(session.handle, m);
    json << "},\n  \"evaluations\": {";
    for (int32_t c = 0; c < sim_session_num_components(session.handle); ++c)
      json << (c ? ", " : "")
           << jsonString(sim_session_component(session.handle, c)) << ": "
           << sim_session_evaluations(session.handle, c);
    json << "},\n  \"totals\": {";
    for (size_t t = 0; t < totalNames.size(); ++t)
      json << (t ? ", " : "") << jsonString(totalNames[t]) << ": "
           << jsonExactNumber(totals[t]);
    json << "},\n  \"totals_per_output_time\": ";
    if (series.empty()) {
      json << "null";
    } else {
      json << "[";
      for (size_t k = 0; k < series.size(); ++k) {
        json << (k ? ", " : "") << "{\"T\": " << series[k].time;
        for (size_t t = 0; t < totalNames.size(); ++t)
          json << ", " << jsonString(totalNames[t]) << ": "
               << jsonExactNumber(series[k].values[t]);
        json << "}";
      }
      json << "]";
    }
    json << ",\n  \"reference\": "
         << (options.reference.empty() ? "null" : jsonString(options.reference))
         << ",\n  \"error\": {";
    bool first = true;
    for (const Comparison &comparison : comparisons) {
      if (!comparison.available)
        continue;
      json << (first ? "" : ", ") << jsonString(comparison.buffer)
           << ": {\"max_abs\": " << jsonNumber(comparison.norms.maxAbs)
           << ", \"rms_rel\": " << jsonNumber(comparison.norms.rmsRel) << "}";
      first = false;
    }
    json << "},\n  \"check\": ";
    if (!checked) {
      json << "null";
    } else {
      auto counts = [&](const Work &work) {
        std::ostringstream out;
        out << "{";
        for (size_t c = 0; c < work.evaluations.size(); ++c)
          out << (c ? ", " : "") << jsonString(work.evaluations[c].first)
              << ": " << work.evaluations[c].second;
        out << "}";
        return out.str();
      };
      auto sizes = [&](const Work &work) {
        std::ostringstream out;
        out << "{";
        for (size_t m = 1; m < work.histogram.size(); ++m)
          out << (m > 1 ? ", " : "") << "\"" << m
              << "\": " << work.histogram[m];
        out << "}";
        return out.str();
      };
      bool evaluationsEqual = true;
      for (const Check::CountRow &row : checked->evaluations)
        evaluationsEqual &= row.backend == row.reference;
      auto boolean = [](bool value) { return value ? "true" : "false"; };
      json << "{\n    \"strategy\": "
           << jsonString(sim_strategy_name(options.strategy))
           << ",\n    \"group_size\": "
           << sim_session_group_size(session.handle)
           << ",\n    \"steps\": " << options.steps
           << ",\n    \"pass\": " << boolean(checked->failures.empty())
           << ",\n    \"totals\": {";
      for (size_t i = 0; i < totalRows.size(); ++i)
        json << (i ? ", " : "") << jsonString(totalRows[i].total)
             << ": {\"backend\": " << jsonExactNumber(totalRows[i].backend)
             << ", \"reference\": " << jsonExactNumber(totalRows[i].reference)
             << ", \"limit\": " << jsonNumber(totalRows[i].limit)
             << ", \"pass\": " << boolean(totalRows[i].pass) << "}";
      json << "},\n    \"buffers\": {";
      for (size_t i = 0; i < checked->buffers.size(); ++i) {
        const Check::BufferRow &row = checked->buffers[i];
        json << (i ? ", " : "") << jsonString(row.buffer)
             << ": {\"max_abs\": " << jsonNumber(row.norms.maxAbs)
             << ", \"max_reference\": " << jsonNumber(row.maxReference)
             << ", \"rms_rel\": " << jsonNumber(row.norms.rmsRel)
             << ", \"tolerance\": " << jsonNumber(row.tolerance)
             << ", \"limit\": " << jsonNumber(row.limit)
             << ", \"same_non_finite\": " << row.norms.sameNonFinite
             << ", \"pass\": " << boolean(row.pass) << "}";
      }
      json << "},\n    \"evaluations\": {\"backend\": "
           << counts(checked->backend)
           << ", \"reference\": " << counts(checked->reference)
           << ", \"equal\": " << boolean(evaluationsEqual)
           << "},\n    \"big_steps\": {\"backend\": "
           << checked->backend.bigSteps
           << ", \"reference\": " << checked->reference.bigSteps
           << ", \"equal\": "
           << boolean(checked->backend.bigSteps == checked->reference.bigSteps)
           << "},\n    \"big_step_histogram\": {\"backend\": "
           << sizes(checked->backend)
           << ", \"reference\": " << sizes(checked->reference)
           << ", \"equal\": "
           << boolean(checked->backend.histogram ==
                      checked->reference.histogram)
           << "},\n    \"failures\": [";
      for (size_t i = 0; i < checked->failures.size(); ++i)
        json << (i ? ", " : "") << jsonString(checked->failures[i]);
      json << "]\n  }";
    }
    json << "\n}\n";
    writeAtomically(options.json, json.str());
  }
  return checked && !checked->failures.empty() ? 1 : 0;
}

} // namespace

int main(int argc, char **argv) {
  try {
    return run(parseOptions(argc, argv));
  } catch (const Exit &exit) {
    if (!exit.message.empty())
      std::fprintf(stderr, "sim-run: error: %s\n", exit.message.c_str());
    return exit.status;
  }
}
