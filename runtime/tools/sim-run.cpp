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
// Everything the user can get wrong is checked before anything runs:
// option values (Options.cpp), output paths (Output.cpp), then, with the
// bundle open, every session sim-run will need and every --set. The runs
// follow, each session's results copied out and the session destroyed as
// soon as its part is done; a signal (Signals.cpp) stops the run in
// progress and skips the rest. The report (Report.cpp) and the output
// files come last.
//
// With --distributed every rank of mpirun runs this program: the same
// calls on every rank (the sessions are collective), rank 0 alone prints,
// shows progress and writes files. A rank that fails prints its error and
// aborts every rank (MPI_Abort), so that none waits for it.
//
//===----------------------------------------------------------------------===//

#include "simrun/Compare.h"
#include "simrun/Npz.h"
#include "simrun/Options.h"
#include "simrun/Output.h"
#include "simrun/Progress.h"
#include "simrun/Report.h"
#include "simrun/Safety.h"
#include "simrun/Series.h"
#include "simrun/Signals.h"
#include "simrun/Timeline.h"

#include "sim/Runtime/sim_runtime.h"

#include "MpiCommunicator.h"

#include <dlfcn.h>
#include <fcntl.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <poll.h>
#include <spawn.h>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char **environ;

using namespace simrun;

namespace {

/// --distributed: MPI_COMM_WORLD's communicator and this process's rank
/// (null and 0 otherwise).
const sim_communicator *world = nullptr;
int worldRank = 0, worldSize = 0;

/// Whether this process prints and writes files: rank 0.
bool printing() { return worldRank == 0; }

void check(sim_status status) {
  if (status != SIM_OK)
    runError(sim_last_error());
}

//===----------------------------------------------------------------------===//
// Input: a bundle, or a .mlir scene translated into a temporary one
//===----------------------------------------------------------------------===//

/// A file removed when sim-run ends, on every path: normally and through an
/// exception by the destructor, by the signal handler when a second signal
/// kills the process.
class TemporaryFile {
public:
  TemporaryFile() = default;
  TemporaryFile(const TemporaryFile &) = delete;
  TemporaryFile &operator=(const TemporaryFile &) = delete;
  ~TemporaryFile() {
    if (!path_.empty())
      unlink(path_.c_str());
    unregisterTemporary(slot);
  }

  /// Creates an empty file from `pattern` (mkstemps with `suffix` bytes
  /// after the XXXXXX).
  void create(std::string pattern, int suffix) {
    int fd, error;
    {
      BlockSignals blocked;
      fd = mkstemps(pattern.data(), suffix);
      error = errno;
      if (fd >= 0) {
        path_ = pattern;
        slot = registerTemporary(path_.c_str());
      }
    }
    if (fd < 0)
      runError("cannot create a temporary bundle '" + pattern +
               "': " + std::strerror(error));
    close(fd);
  }
  const std::string &path() const { return path_; }

private:
  std::string path_;
  int slot = -1;
};

bool isExecutable(const std::string &path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0 && S_ISREG(info.st_mode) &&
         access(path.c_str(), X_OK) == 0;
}

/// sim-translate next to this binary, else on PATH; `searched` is the
/// directory of this binary.
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

/// Throws the exit status of a signal received so far, if any.
void stopIfInterrupted(const std::string &what) {
  if (int signal = receivedSignal())
    throw Exit{kExitSignalBase + signal, std::string("interrupted by ") +
                                             signalName(signal) + " " + what +
                                             "; nothing was run"};
}

/// The scene sim-run translated for this run and the temporary bundle it
/// runs, for messages that would name the bundle.
std::string translatedScene, translatedBundle;

/// Translates a .mlir scene into the temporary bundle `bundle`, with the
/// compile-time settings `compiled` (NAME=VALUE) applied by
/// --sim-set-params, for the strategies `strategies` (sim-translate's
/// --sim-strategies; empty: its default, every strategy).
void translate(const std::string &scene, TemporaryFile &bundle,
               const std::vector<std::string> &compiled,
               const std::vector<sim_strategy> &strategies, bool announce) {
  std::string searched;
  std::optional<std::string> tool = findTranslate(searched);
  if (!tool)
    runError("cannot translate '" + scene +
             "': sim-translate not found (looked in " +
             (searched.empty() ? std::string("the directory of sim-run")
                               : searched) +
             " and on PATH); build it, or pass a .simb bundle");
  const char *tmp = std::getenv("TMPDIR");
  bundle.create(
      std::string(tmp && *tmp ? tmp : "/tmp") + "/sim-run-XXXXXX.simb", 5);
  std::vector<std::string> args = {*tool, scene, "--sim-to-bundle", "-o",
                                   bundle.path()};
  // The bundle runs here and is then thrown away: CPU kernels for the level
  // this machine runs only (a third of the compile time of every level).
  args.push_back("--sim-cpu-isas=host");
  if (world)
    args.push_back("--sim-distributed");
  if (!strategies.empty()) {
    std::string names;
    for (sim_strategy strategy : strategies)
      names +=
          (names.empty() ? "" : ",") + std::string(sim_strategy_name(strategy));
    args.push_back("--sim-strategies=" + names);
  }
  if (!compiled.empty()) {
    std::string values;
    for (const std::string &value : compiled)
      values += (values.empty() ? "" : ",") + value;
    args.push_back("--sim-set-params=" + values);
  }
  std::vector<char *> argv;
  for (std::string &arg : args)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  // Compiling a large scene takes seconds: say what the wait is for, where
  // progress is shown.
  if (announce)
    std::fprintf(stderr, "sim-run: compiling '%s' (sim-translate, %s)...\n",
                 scene.c_str(),
                 strategies.empty()
                     ? "every strategy"
                     : (std::to_string(strategies.size()) +
                        (strategies.size() == 1 ? " strategy" : " strategies"))
                           .c_str());
  // sim-run ignores SIGPIPE (main); sim-translate gets the default back.
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  pid_t pid;
  int spawnError = posix_spawn(&pid, tool->c_str(), nullptr, &attributes,
                               argv.data(), environ);
  posix_spawnattr_destroy(&attributes);
  if (spawnError)
    runError("cannot run " + *tool + ": " + std::strerror(spawnError));
  // A signal meanwhile goes to sim-translate too.
  setChild(pid);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  setChild(0);
  stopIfInterrupted("while translating '" + scene + "'");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    runError("sim-translate failed on '" + scene + "'" +
             (WIFEXITED(status)
                  ? " (exit status " + std::to_string(WEXITSTATUS(status)) + ")"
                  : std::string(" (killed by a signal)")));
  translatedScene = scene;
  translatedBundle = bundle.path();
}

/// Starts the measured session at the --restart checkpoint. A checkpoint
/// of another bundle, where the input is a scene sim-run compiled, names
/// the scene rather than the temporary bundle, and says what decides the
/// bundle: the strategies --strategy and --reference name.
void restartMeasured(sim_session *session, const std::string &restart) {
  if (translatedScene.empty())
    return startAt(session, restart);
  if (sim_session_restart(session, restart.c_str()) == SIM_OK)
    return;
  std::string message = sim_last_error();
  std::string temporary = "'" + translatedBundle + "'";
  for (size_t at = message.find(temporary); at != std::string::npos;
       at = message.find(temporary))
    message.replace(at, temporary.size(),
                    "the compile of '" + translatedScene + "'");
  if (message.find("belongs to another bundle") != std::string::npos)
    message += "; sim-run compiles a .mlir input for the strategies that "
               "--strategy and --reference name: restart with the same "
               "ones as the run that wrote the checkpoint, or compile the "
               "scene once with sim-translate --sim-to-bundle and run "
               "that bundle";
  runError("--restart: " + message);
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

/// Whether the input is a scene to translate rather than a bundle.
bool isScene(const std::string &path) {
  return endsWith(path, ".mlir") && !isBundle(path);
}

/// The bundle that runs: the input itself, or its translation with the
/// compile-time settings `compiled` for the strategies `strategies` (empty:
/// every strategy).
class Input {
public:
  Input(const std::string &path, const std::vector<std::string> &compiled,
        const std::vector<sim_strategy> &strategies, bool announce) {
    if (isScene(path)) {
      translate(path, translated, compiled, strategies, announce);
      check(sim_bundle_open(translated.path().c_str(), &handle));
    } else {
      check(sim_bundle_open(path.c_str(), &handle));
    }
  }
  ~Input() { sim_bundle_close(handle); }
  Input(const Input &) = delete;
  Input &operator=(const Input &) = delete;

  const sim_bundle *bundle() const { return handle; }

private:
  TemporaryFile translated;
  sim_bundle *handle = nullptr;
};

/// An input (`what`: "the input", "the --restart checkpoint") must be there
/// to read; a missing one is a usage error.
void checkInput(const std::string &path, const std::string &what) {
  struct stat info;
  if (stat(path.c_str(), &info) != 0)
    usageError("cannot read " + what + " '" + path +
               "': " + std::strerror(errno));
  if (S_ISDIR(info.st_mode))
    usageError(what + " '" + path + "' is a directory");
}

//===----------------------------------------------------------------------===//
// Sessions
//===----------------------------------------------------------------------===//

/// A session with the --set values applied, registered for the signal
/// handler. Values the session refuses (a group size CUDA cannot take, an
/// unknown parameter, a dt of 0) are usage errors.
class Session {
public:
  Session(const sim_bundle *bundle, const sim_session_options &options,
          const Options &cli) {
    sim_status created;
    {
      // The session's threads inherit this: signals go to the main thread.
      BlockSignals blocked;
      created = sim_session_create(bundle, &options, &handle);
    }
    require(created, "");
    try {
      registerSession(handle);
      for (const auto &[name, value] : cli.sets)
        require(sim_session_set(handle, name.c_str(), value.c_str()),
                "--set " + name + "=" + value + ": ");
    } catch (const Exit &) {
      release();
      throw;
    }
  }
  ~Session() { release(); }
  Session(const Session &) = delete;
  Session &operator=(const Session &) = delete;

  sim_session *get() const { return handle; }

private:
  /// An invalid argument is the user's (exit 2), anything else the run's
  /// (a memory limit, a missing driver: exit 1).
  static void require(sim_status status, const std::string &prefix) {
    if (status == SIM_ERROR_INVALID_ARGUMENT)
      usageError(prefix + sim_last_error());
    if (status != SIM_OK)
      runError(prefix + sim_last_error());
  }
  void release() {
    if (!handle)
      return;
    unregisterSession(handle);
    sim_session_destroy(handle);
    handle = nullptr;
  }

  sim_session *handle = nullptr;
};

/// Every session sim-run needs, created (and every --set checked) before
/// anything runs; each is reset when its part is done, freeing its state.
struct Sessions {
  std::unique_ptr<Session> main, simple, check;
  /// The measured session already stands at its start (--restart, read
  /// and checked before anything runs).
  bool mainStarted = false;
};

sim_session_options mainOptions(const Options &options) {
  sim_session_options session;
  sim_session_options_init(&session);
  session.strategy = options.strategy;
  session.backend = options.backend;
  session.group_size = options.groupSize;
  session.cpu_threads = options.threads;
  session.cuda_device = options.device;
  session.cuda_graph = options.cudaGraph;
  session.check_finite = options.checkFinite;
  session.max_memory = options.maxMemory;
  session.communicator = world;
  return session;
}

Sessions createSessions(const sim_bundle *bundle, const Options &options) {
  Sessions sessions;
  sim_session_options main = mainOptions(options);
  sessions.main = std::make_unique<Session>(bundle, main, options);
  sim_session *measured = sessions.main->get();
  if (options.reference == "simple") {
    // The simple strategy where the measured run ran, with its group size.
    sim_session_options simple = main;
    simple.strategy = SIM_STRATEGY_SIMPLE;
    simple.backend = sim_session_backend(measured);
    simple.group_size = sim_session_group_size(measured);
    simple.cuda_graph = 0;
    sessions.simple = std::make_unique<Session>(bundle, simple, options);
  }
  if (options.check) {
    sim_session_options reference = main;
    reference.backend = SIM_BACKEND_REFERENCE;
    reference.group_size = sim_session_group_size(measured);
    reference.cuda_graph = 0;
    // The reference executor runs on one process: under --distributed every
    // rank runs the whole scene on its own, and the comparison is with the
    // distributed run's buffers, which every rank gathers.
    reference.communicator = nullptr;
    sessions.check = std::make_unique<Session>(bundle, reference, options);
  }
  // A checkpoint that does not belong to the sessions (another bundle,
  // strategy, group size or --set values, or a damaged file) is refused
  // here, before anything runs. --check's reference executor restarts from
  // the same checkpoint.
  if (!options.restart.empty()) {
    restartMeasured(measured, options.restart);
    sessions.mainStarted = true;
    int64_t at = sim_session_time(measured);
    if (at > options.steps)
      usageError("--restart: checkpoint '" + options.restart +
                 "' is at base step " + std::to_string(at) + ", past --steps " +
                 std::to_string(options.steps) +
                 " (the end of the run, counted from base step 0)");
    if (sessions.check)
      startAt(sessions.check->get(), options.restart);
  }
  return sessions;
}

//===----------------------------------------------------------------------===//
// Buffers and counters of a session
//===----------------------------------------------------------------------===//

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

/// A buffer's current state, or with `exact` its exact solution now.
Buffer readBuffer(sim_session *session, const sim_buffer_info &info,
                  bool exact) {
  Buffer buffer;
  buffer.name = info.name;
  buffer.scalarBytes = info.scalar_bytes;
  buffer.precisionBytes = info.precision_bytes;
  buffer.lanes = info.lanes;
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

std::vector<Buffer> readBuffers(sim_session *session,
                                const std::vector<sim_buffer_info> &observed) {
  std::vector<Buffer> buffers;
  for (const sim_buffer_info &info : observed)
    buffers.push_back(readBuffer(session, info, false));
  return buffers;
}

std::vector<std::string> totalNamesOf(sim_session *session) {
  std::vector<std::string> names;
  for (int32_t t = 0; t < sim_session_num_totals(session); ++t)
    names.push_back(sim_session_total_name(session, t));
  return names;
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

//===----------------------------------------------------------------------===//
// Runs
//===----------------------------------------------------------------------===//

/// Runs `steps` base steps from the initial state. Done, or Cut by a signal
/// (at the base step reached); a signal received before it began leaves
/// the session as it was and says Cut at its time.
PartState runFromStart(sim_session *session, int64_t steps, Progress &progress,
                       const std::string &label) {
  if (interrupted())
    return {Stage::Cut, sim_session_time(session), steps};
  check(sim_session_init(session));
  progress.begin(session, label);
  sim_status status = sim_session_run(session, steps);
  progress.end();
  if (status == SIM_ERROR_INTERRUPTED)
    return {Stage::Cut, sim_session_time(session), steps};
  // A non-finite value (--check-finite) ends here with a message that
  // names the base step, component, buffer and item.
  check(status);
  sim_metrics metrics;
  check(sim_session_metrics(session, &metrics));
  if (metrics.end != steps || sim_session_time(session) != steps)
    runError("the run ended at base step " +
             std::to_string(sim_session_time(session)) + ", not at " +
             std::to_string(steps));
  return {Stage::Done, steps, steps};
}

Stops stopsOf(const Options &options) {
  return {options.steps, options.outputEvery, options.checkpointEvery};
}

/// Progress of a run through its stops: one line for the whole run.
TimelineHooks progressHooks(Progress &progress, const std::string &label,
                            int64_t end) {
  TimelineHooks hooks;
  bool first = true;
  hooks.beforeRun = [&progress, label, end, first](sim_session *session,
                                                   int64_t from) mutable {
    if (first)
      progress.begin(session, label);
    first = false;
    progress.resume(session, from, end);
  };
  hooks.afterRun = [&progress] { progress.pause(); };
  return hooks;
}

/// Whether the checkpoint write that every rank took part in succeeded on
/// all: rank 0 writes the file, and what it alone meets (creating the
/// folder or the temporary file, renaming it) every rank must know, so that
/// all go on alike. `wrote` without --distributed.
bool everyRankWrote(bool wrote) {
  if (!world)
    return wrote;
  int64_t value = wrote ? 1 : 0;
  if (world->allreduce_min_i64(world->user, &value, 1) != 0)
    runError("rank " + std::to_string(worldRank) +
             ": the all-reduce after a checkpoint failed");
  return value == 1;
}

/// The runtime's message about a checkpoint written to descriptor `fd`,
/// for a message that names the path already: without the descriptor.
std::string checkpointWhy(std::string message, int fd,
                          const std::string &path) {
  std::string byDescriptor = "'file descriptor " + std::to_string(fd) + "'";
  std::string prefix = "cannot write checkpoint " + byDescriptor + ": ";
  if (message.compare(0, prefix.size(), prefix) == 0)
    return message.substr(prefix.size());
  if (size_t at = message.find(byDescriptor); at != std::string::npos)
    message.replace(at, byDescriptor.size(), "'" + path + "'");
  return message;
}

/// The first buffer of the session's state that holds NaN or infinity, if
/// any. Under --distributed every rank reads every buffer whole (the reads
/// all-gather the ranks' items), so all find the same.
std::optional<NonFiniteValues> nonFiniteBufferOf(sim_session *session,
                                                 const sim_bundle *bundle) {
  std::optional<NonFiniteValues> found;
  for (int32_t b = 0; b < sim_bundle_num_buffers(bundle) && !found; ++b) {
    sim_buffer_info info;
    check(sim_bundle_buffer(bundle, b, &info));
    size_t bytes = 0;
    // A buffer the strategy's plan pruned is not in the session.
    if (sim_session_buffer_bytes(session, info.name, &bytes) == SIM_OK)
      found = findNonFinite(readBuffer(session, info, false));
  }
  return found;
}

/// Writes --checkpoint's file with the session's state (atomically, like
/// every output; the checkpoint may replace the --restart file). A write
/// that fails does not lose the run: it is reported at once and recorded,
/// the run goes on (without more periodic checkpoints when `periodic`, a
/// write of --checkpoint-every), and sim-run ends with status 1 once every
/// other output is written (docs/Runtime.md, "Checkpoints"). A state that
/// holds NaN or infinity is not written either: a checkpoint is what a run
/// restarts from, and the file keeps the last good one (the --restart
/// checkpoint, when it is the same file).
void writeCheckpoint(sim_session *session, const sim_bundle *bundle,
                     MainRun &main, bool periodic) {
  int64_t time = sim_session_time(session);
  std::string why;
  // Every rank finds the same, so all skip the write alike.
  std::optional<NonFiniteValues> nonFinite = nonFiniteBufferOf(session, bundle);
  if (nonFinite) {
    why = nonFiniteStateText(*nonFinite) +
          ", and a checkpoint is what a run restarts from (--dump writes such "
          "a state)";
  } else if (!printing()) {
    // The state is gathered collectively; rank 0 writes it.
    if (sim_session_checkpoint_fd(session, -1) != SIM_OK)
      why = sim_last_error();
  } else {
    bool gathered = false;
    try {
      writeFileAtomically(main.checkpointFile, [&](int fd) {
        gathered = true;
        if (sim_session_checkpoint_fd(session, fd) != SIM_OK)
          runError(checkpointWhy(sim_last_error(), fd, main.checkpointFile));
      });
    } catch (const Exit &exit) {
      why = exit.message;
      // The other ranks wait for rank 0 in the gather of the state: a rank
      // 0 that failed before it got there takes part all the same, with no
      // file to write (the runtime fails the write on every rank).
      if (!gathered && world)
        sim_session_checkpoint_fd(session, -1);
    }
  }
  if (everyRankWrote(why.empty())) {
    ++main.checkpointsWritten;
    main.checkpointTime = time;
    return;
  }
  // Where rank 0 alone failed, the other ranks only know that.
  if (why.empty())
    why = "rank 0 could not write it";
  main.checkpointFailures.push_back({time, why});
  if (!printing())
    return;
  std::fprintf(
      stderr,
      "sim-run: error: %s: checkpoint '%s' of base step %lld was not "
      "written: %s%s\n",
      periodic ? "--checkpoint-every" : "--checkpoint",
      main.checkpointFile.c_str(), static_cast<long long>(time), why.c_str(),
      periodic ? "; the run goes on without periodic checkpoints" : "");
  std::fflush(stderr);
}

/// What the measured run records at an output time: the totals, the error
/// of every observed buffer against --reference (the simple strategy's
/// session advanced to the same base step, or the exact solution), and
/// with --output the buffers. Prints the row. False when a signal stopped
/// the simple strategy's run (the row is incomplete and dropped).
bool recordOutput(Results &results, sim_session *session, Session *simple,
                  const std::vector<sim_buffer_info> &observed, int64_t time) {
  auto start = std::chrono::steady_clock::now();
  Series &series = results.series;
  std::vector<std::optional<Buffer>> references(observed.size());
  if (simple) {
    // The simple strategy takes every base step: nothing is cut.
    sim_session *reference = simple->get();
    int64_t at = sim_session_time(reference);
    if (at < time) {
      Progress lockstep(false);
      lockstep.begin(reference, "reference: ");
      lockstep.resume(reference, at, time);
      sim_status status = sim_session_run(reference, time - at);
      lockstep.end();
      if (status == SIM_ERROR_INTERRUPTED) {
        results.reference = {Stage::Cut, sim_session_time(reference),
                             results.main.steps};
        return false;
      }
      check(status);
    }
    for (size_t i = 0; i < observed.size(); ++i)
      references[i] = readBuffer(reference, observed[i], false);
  } else if (results.referenceKind == "exact") {
    for (size_t i = 0; i < observed.size(); ++i)
      if (series.buffers[i].hasReference)
        references[i] = readBuffer(session, observed[i], true);
  }
  std::vector<Buffer> values;
  if (series.keepValues || !results.referenceKind.empty())
    values = readBuffers(session, observed);
  series.add(time, totalsOf(session), values, references);
  if (simple && time == results.main.steps)
    for (size_t i = 0; i < observed.size(); ++i)
      results.referenceValues[i] = references[i];
  results.main.outputSeconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
          .count();
  if (series.recorded == 1)
    printSeriesHeader(series);
  printSeriesRow(series, series.size() - 1);
  return true;
}

/// Whether anything reads the output times after the run: --output's
/// .npz, --json's "output" and "totals_per_output_time", --check's
/// comparison of the totals at every output time. Else the table prints
/// each row as it comes and only the last one is kept.
bool keepsEveryOutputTime(const Options &options, size_t totals) {
  return !options.output.empty() || !options.json.empty() ||
         (options.check && totals > 0);
}

/// What the output times record: every total, per observed buffer its
/// error where --reference has a value of it, and with --output its values
/// (and the exact solution).
void setUpSeries(Results &results, const Options &options, sim_session *session,
                 const std::vector<sim_buffer_info> &observed) {
  Series &series = results.series;
  series.every = options.outputEvery;
  series.dt = results.main.dt;
  series.range = results.main.range;
  series.referenceKind = options.reference;
  series.keepValues = !options.output.empty();
  series.totalNames = totalNamesOf(session);
  series.keepRows = keepsEveryOutputTime(options, series.totalNames.size());
  for (const sim_buffer_info &info : observed) {
    Series::Column column;
    column.name = info.name;
    column.scalarBytes = info.scalar_bytes;
    column.lanes = info.lanes;
    bool exact = options.reference == "exact" &&
                 sim_session_has_exact(session, info.name);
    column.hasReference = options.reference == "simple" || exact;
    column.hasExact = exact;
    series.buffers.push_back(column);
  }
}

/// The measured runs: a warm-up first when several are measured, each from
/// the initial state (or the --restart checkpoint) through the same stops;
/// the last records the output times (with --reference simple the simple
/// strategy in step with it) and writes the checkpoints. Then the state,
/// counters, totals and observed buffers at the end.
void runMain(Results &results, Sessions &sessions, const sim_bundle *bundle,
             const Options &options,
             const std::vector<sim_buffer_info> &observed, Progress &progress) {
  MainRun &main = results.main;
  sim_session *session = sessions.main->get();
  main.scene = sim_bundle_scene_name(bundle);
  main.strategy = sim_strategy_name(options.strategy);
  main.backend = sim_backend_name(sim_session_backend(session));
  main.device = sim_session_device(session);
  main.backendNote = sim_session_backend_note(session);
  main.showNote = options.backend == SIM_BACKEND_AUTO;
  main.range = sim_session_range(session);
  char dt[64];
  check(sim_session_get(session, "dt", dt, sizeof dt));
  main.dtText = dt;
  main.dt = std::strtod(dt, nullptr);
  for (int32_t p = 0; p < sim_bundle_num_params(bundle); ++p) {
    sim_param_info param;
    char value[64];
    if (sim_bundle_param(bundle, p, &param) == SIM_OK &&
        sim_session_get(session, param.name, value, sizeof value) == SIM_OK)
      main.params.emplace_back(param.name, value);
  }
  main.groupSize = sim_session_group_size(session);
  main.steps = options.steps;
  main.repeat = options.repeat;
  main.maxSteps = sim_bundle_max_steps(bundle);
  main.flushSubnormals = sim_bundle_flushes_subnormals(bundle) != 0;
  main.maxMemory = options.maxMemory;
  main.memoryBytes = sim_session_memory_bytes(session);
  main.memoryLimit = sim_session_memory_limit(session);
  main.ranks = worldSize;
  main.restartFile = options.restart;
  main.checkpointFile = options.checkpoint;
  main.checkpointEvery = options.checkpointEvery;
  if (sessions.mainStarted)
    main.restartTime = sim_session_time(session);

  setUpSeries(results, options, session, observed);
  Stops stops = stopsOf(options);
  int64_t runs = options.repeat > 1 ? options.repeat + 1 : 1;
  main.state = {Stage::Done, options.steps, options.steps};
  for (int64_t r = 0; r < runs && main.state.stage == Stage::Done; ++r) {
    bool warmUp = runs > 1 && r == 0, last = r == runs - 1;
    std::string label;
    if (warmUp)
      label = "warm-up: ";
    else if (runs > 1)
      label = "run " + std::to_string(r) + " of " +
              std::to_string(options.repeat) + ": ";
    main.cutRun = runs > 1 ? r : 1;
    if (interrupted()) {
      main.state = {Stage::Cut, sim_session_time(session), options.steps};
      break;
    }
    if (!sessions.mainStarted)
      startAt(session, options.restart);
    sessions.mainStarted = false;

    TimelineHooks hooks = progressHooks(progress, label, options.steps);
    if (last) {
      results.series.clear();
      if (options.outputEvery > 0) {
        if (sessions.simple)
          check(sim_session_init(sessions.simple->get()));
        hooks.output = [&](int64_t time) {
          return recordOutput(results, session, sessions.simple.get(), observed,
                              time);
        };
      }
      // After a failed write no more periodic ones: each would take the
      // time of a write that fails again. The one at the end is tried.
      if (options.checkpointEvery > 0)
        hooks.checkpoint = [&](int64_t) {
          if (main.checkpointFailures.empty())
            writeCheckpoint(session, bundle, main, true);
        };
    }
    RunTotals totals;
    main.state = runThrough(session, stops, main.maxSteps, totals, hooks);
    progress.end();
    main.metrics = totals.metrics;
    main.counts = totals.counts;
    main.cuts = totals.cuts;
    main.cutsAtOutputs = totals.cutsAtOutputs;
    if (!warmUp && main.state.stage == Stage::Done) {
      main.walls.push_back(main.metrics.wall_seconds);
      main.kernels.push_back(main.metrics.kernel_seconds);
    }
  }
  if (main.state.stage == Stage::Done) {
    main.wall = median(main.walls);
    main.kernel = median(main.kernels);
  } else {
    main.wall = main.metrics.wall_seconds;
    main.kernel = main.metrics.kernel_seconds;
  }
  // The checkpoint of where the run stands: its end, or where a signal
  // stopped it (a big-step boundary, so it restarts bit for bit).
  if (!main.checkpointFile.empty())
    writeCheckpoint(session, bundle, main, false);
  main.totalNames = totalNamesOf(session);
  for (const std::string &name : main.totalNames)
    main.totalPrecisionBytes.push_back(
        sim_bundle_total_precision_bytes(bundle, name.c_str()));
  main.totals = totalsOf(session);
  main.values = readBuffers(session, observed);
}

/// NaNs and infinities at the end of the measured run: in the observed
/// buffers, the session's other buffers (read one at a time) and the
/// totals.
std::vector<NonFiniteValues> findNonFiniteState(sim_session *session,
                                                const sim_bundle *bundle,
                                                const MainRun &main) {
  std::vector<NonFiniteValues> found;
  for (int32_t b = 0; b < sim_bundle_num_buffers(bundle); ++b) {
    sim_buffer_info info;
    check(sim_bundle_buffer(bundle, b, &info));
    size_t bytes = 0;
    // The observed buffers are read already; a buffer the strategy's
    // plan pruned is not in the session.
    std::optional<NonFiniteValues> values;
    if (info.observed) {
      for (const Buffer &buffer : main.values)
        if (buffer.name == info.name)
          values = findNonFinite(buffer);
    } else if (sim_session_buffer_bytes(session, info.name, &bytes) == SIM_OK) {
      values = findNonFinite(readBuffer(session, info, false));
    }
    if (values)
      found.push_back(*values);
  }
  for (NonFiniteValues &total :
       findNonFiniteTotals(main.totalNames, main.totals))
    found.push_back(total);
  return found;
}

/// --reference's error of every total: against the simple strategy's
/// totals, or their values on the exact solution at the time the measured
/// run reached.
void compareTotalsWithReference(Results &results, sim_session *measured,
                                sim_session *simple) {
  const MainRun &main = results.main;
  std::vector<double> theirs;
  if (simple)
    theirs = totalsOf(simple);
  for (size_t t = 0; t < main.totalNames.size(); ++t) {
    const std::string &name = main.totalNames[t];
    if (simple) {
      results.totalErrors.push_back(
          compareTotal(name, main.totals[t], theirs[t]));
      continue;
    }
    double exact = 0;
    sim_status status = sim_session_exact_total(measured, name.c_str(), &exact);
    if (status == SIM_ERROR_INVALID_ARGUMENT || status == SIM_ERROR_BUNDLE) {
      TotalError unavailable;
      unavailable.total = name;
      unavailable.why = sim_last_error();
      results.totalErrors.push_back(unavailable);
      continue;
    }
    check(status);
    results.totalErrors.push_back(compareTotal(name, main.totals[t], exact));
  }
}

/// --reference: the simple strategy's run, or the exact solution at the
/// time the measured run reached; then the error of every observed buffer
/// and total. With --output-every the simple strategy ran in step with the
/// measured run and its values at the end are there already.
void runReference(Results &results, sim_session *measured, Session *simple,
                  const std::vector<sim_buffer_info> &observed,
                  const Options &options, Progress &progress) {
  if (options.reference.empty())
    return;
  if (options.reference == "exact") {
    // Also after a signal: the solution at the base step reached.
    for (size_t i = 0; i < observed.size(); ++i)
      if (sim_session_has_exact(measured, observed[i].name))
        results.referenceValues[i] = readBuffer(measured, observed[i], true);
    results.reference = {Stage::Done, 0, 0};
  } else if (options.outputEvery > 0) {
    if (results.reference.stage == Stage::NotAsked)
      results.reference = results.main.state.stage == Stage::Done
                              ? PartState{Stage::Done, 0, 0}
                              : PartState{Stage::Skipped, 0, 0};
  } else if (interrupted()) {
    results.reference = {Stage::Skipped, 0, 0};
  } else {
    results.reference =
        runFromStart(simple->get(), options.steps, progress, "reference: ");
    if (results.reference.stage == Stage::Done)
      for (size_t i = 0; i < observed.size(); ++i)
        results.referenceValues[i] =
            readBuffer(simple->get(), observed[i], false);
  }
  if (results.reference.stage != Stage::Done)
    return;
  compareTotalsWithReference(results, measured,
                             options.reference == "simple" ? simple->get()
                                                           : nullptr);
  for (size_t i = 0; i < observed.size(); ++i) {
    const std::optional<Buffer> &reference = results.referenceValues[i];
    results.errors.push_back({observed[i].name, reference.has_value(),
                              reference
                                  ? compare(results.main.values[i], *reference)
                                  : ErrorNorms{}});
  }
}

/// --check: the same run on the reference executor, from the same start
/// and through the same output times (so it cuts the same big steps),
/// compared with the measured one: values, totals (at every output time
/// too) and counters.
void runCheck(Results &results, Session &session,
              const std::vector<sim_buffer_info> &observed,
              const Options &options, Progress &progress) {
  if (interrupted()) {
    results.checkState = {Stage::Skipped, 0, 0};
    return;
  }
  const MainRun &main = results.main;
  sim_session *reference = session.get();
  // No --checkpoint-every pauses: they change nothing.
  Stops stops = stopsOf(options);
  stops.checkpointEvery = 0;
  TimelineHooks hooks = progressHooks(progress, "check: ", options.steps);
  std::vector<TotalsAt> theirs;
  if (options.outputEvery > 0 && !main.totalNames.empty())
    hooks.output = [&](int64_t time) {
      theirs.push_back({time, totalsOf(reference)});
      return true;
    };
  // The restart checkpoint was applied when the sessions were made.
  if (options.restart.empty())
    check(sim_session_init(reference));
  RunTotals totals;
  PartState state = runThrough(reference, stops, main.maxSteps, totals, hooks);
  progress.end();
  if (state.stage != Stage::Done) {
    results.checkState = state;
    return;
  }
  results.checkValues = readBuffers(reference, observed);
  Check check =
      compareWithReference(main.values, results.checkValues, main.counts,
                           totals.counts, options.checkTolerance);
  std::vector<double> totalTolerance;
  for (int32_t bytes : main.totalPrecisionBytes)
    totalTolerance.push_back(options.checkTolerance >= 0
                                 ? options.checkTolerance
                                 : defaultTotalTolerance(bytes));
  compareTotals(main.totalNames, options.steps, main.totals,
                totalsOf(reference), totalTolerance, check.totals,
                check.failures);
  const Series &ours = results.series;
  for (size_t k = 0; k < ours.size() && k < theirs.size(); ++k)
    compareTotals(main.totalNames, ours.times[k], ours.totals[k],
                  theirs[k].values, totalTolerance, check.totalsPerOutputTime,
                  check.failures);
  results.checkState = {Stage::Done, options.steps, options.steps};
  results.check = std::move(check);
}

//===----------------------------------------------------------------------===//
// Output files
//===----------------------------------------------------------------------===//

/// A .npy file (format 1.0): shape (range,) or (range, lanes).
std::string npy(const Buffer &buffer, int64_t range) {
  std::vector<int64_t> shape = {range};
  if (buffer.lanes > 1)
    shape.push_back(buffer.lanes);
  return npyFile(
      floatDescr(buffer.scalarBytes), shape,
      std::string_view(reinterpret_cast<const char *>(buffer.bytes.data()),
                       buffer.bytes.size()));
}

/// Plans and checks the dump files of the observed buffers (before the
/// run); returns their stems. Every file a buffer can have is planned, also
/// the .reference.npy and .check.npy this run will not write: writeDumps
/// removes those if an earlier run left them, so they must not be an input
/// or another output.
std::vector<std::string>
planDumps(OutputPlan &plan, const Options &options,
          const std::vector<sim_buffer_info> &observed) {
  if (options.dump.empty())
    return {};
  std::vector<std::string> names;
  for (const sim_buffer_info &info : observed)
    names.push_back(info.name);
  std::vector<std::string> stems = dumpStems(names);
  for (size_t i = 0; i < stems.size(); ++i) {
    std::string option = "--dump (buffer '" + displayName(names[i]) + "')";
    std::string base = options.dump + "/" + stems[i];
    for (const char *suffix : kDumpSuffixes)
      plan.addFile(option, base + suffix);
  }
  return stems;
}

/// Writes the dump files: the state, and the reference's and the check's
/// values where they exist. Where this run has no such values (no
/// --reference or --check, a buffer without an exact solution, a part a
/// signal cut or skipped), a file an earlier run left is removed: beside
/// the new state it would pass for this run's.
void writeDumps(Results &results, const Options &options,
                const std::vector<std::string> &stems) {
  if (options.dump.empty())
    return;
  results.dumpDir = options.dump;
  makeDirectories(options.dump);
  int64_t range = results.main.range;
  for (size_t i = 0; i < stems.size(); ++i) {
    DumpFiles files{results.main.values[i].name, stems[i] + ".npy", "", ""};
    std::string base = options.dump + "/" + stems[i];
    writeFileAtomically(base + ".npy", npy(results.main.values[i], range));
    if (!options.reference.empty() && results.reference.stage == Stage::Done &&
        results.referenceValues[i]) {
      files.reference = stems[i] + ".reference.npy";
      writeFileAtomically(base + ".reference.npy",
                          npy(*results.referenceValues[i], range));
    } else {
      removeStale(base + ".reference.npy");
    }
    if (results.check) {
      files.check = stems[i] + ".check.npy";
      writeFileAtomically(base + ".check.npy",
                          npy(results.checkValues[i], range));
    } else {
      removeStale(base + ".check.npy");
    }
    results.dumpFiles.push_back(files);
  }
}

//===----------------------------------------------------------------------===//
// The run
//===----------------------------------------------------------------------===//

/// The input and the output paths, checked before the bundle is read.
OutputPlan planOutputs(const Options &options) {
  checkInput(options.input, "the input");
  OutputPlan outputs;
  outputs.addInput(options.input);
  // The checkpoint may replace the one the run restarts from (read whole
  // before anything runs): the latest state is what it is for.
  if (!options.restart.empty()) {
    checkInput(options.restart, "the --restart checkpoint");
    if (options.checkpoint.empty() ||
        !sameFile(options.restart, options.checkpoint))
      outputs.addInput(options.restart);
  }
  if (!options.dump.empty())
    outputs.addDirectory("--dump", options.dump);
  if (!options.json.empty())
    outputs.addFile("--json", options.json);
  if (!options.output.empty())
    outputs.addFile("--output", options.output);
  if (!options.checkpoint.empty())
    outputs.addFile("--checkpoint", options.checkpoint);
  return outputs;
}

/// --output keeps every output time's buffers until the end, and --output,
/// --json and --check every output time's time, totals and errors (the
/// JSON holds them once more): refuse, before anything runs, a series that
/// would take more than half of the memory. Without them only the last
/// output time is kept, whatever the run's length.
void checkSeriesMemory(const Options &options, sim_session *session,
                       const std::vector<sim_buffer_info> &observed) {
  size_t totals = size_t(std::max(0, sim_session_num_totals(session)));
  if (options.outputEvery <= 0 || !keepsEveryOutputTime(options, totals))
    return;
  int64_t row = 0;
  if (!options.output.empty())
    for (const sim_buffer_info &info : observed) {
      size_t bytes = 0;
      check(sim_session_buffer_bytes(session, info.name, &bytes));
      bool exact = options.reference == "exact" &&
                   sim_session_has_exact(session, info.name);
      row += int64_t(bytes) * (exact ? 2 : 1);
    }
  bool checksTotals = options.check && totals > 0;
  row += rowOverheadBytes(totals, observed.size(), !options.json.empty(),
                          checksTotals);
  std::vector<std::string> keeping;
  if (!options.output.empty())
    keeping.push_back("--output");
  if (!options.json.empty())
    keeping.push_back("--json");
  if (checksTotals)
    keeping.push_back("--check");
  std::string what;
  for (size_t i = 0; i < keeping.size(); ++i)
    what += (i == 0                    ? ""
             : i + 1 == keeping.size() ? " and "
                                       : ", ") +
            keeping[i];
  Stops stops = stopsOf(options);
  int64_t times = stops.outputTimes(sim_session_time(session));
  long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  if (pages <= 0 || pageSize <= 0)
    return;
  std::string error =
      seriesMemoryError(what, times, row, double(pages) * double(pageSize));
  if (!error.empty())
    usageError(error);
}

/// --output: the series as one .npz file.
void writeSeries(const Results &results, const Options &options) {
  if (options.output.empty())
    return;
  std::vector<std::string> storage;
  std::vector<NpzArray> arrays =
      seriesArrays(results.series, results.main.scene, results.main.strategy,
                   results.main.backend, storage);
  writeFileAtomically(options.output,
                      [&](int fd) { writeNpz(fd, arrays, options.output); });
}

/// --reference exact needs an exact solution of an observed buffer.
void requireExactSolution(const sim_bundle *bundle, sim_session *session,
                          const std::vector<sim_buffer_info> &observed) {
  for (const sim_buffer_info &info : observed)
    if (sim_session_has_exact(session, info.name))
      return;
  usageError(std::string("--reference exact: scene '") +
             displayName(sim_bundle_scene_name(bundle)) +
             "' declares no exact solution of an observed buffer");
}

/// Every run in order, each session freed when its part is done, into
/// `results` (which keeps what was recorded when a run fails).
void runAll(Results &results, Sessions &sessions, const sim_bundle *bundle,
            const Options &options,
            const std::vector<sim_buffer_info> &observed) {
  Progress progress(printing() && isatty(STDERR_FILENO),
                    printing() && options.progress);
  // The init check first: what it finds matters before a long run. It
  // runs the reference functions in this process: rank 0's is enough.
  if (options.noInitCheck)
    results.initCheck.skipped = "--no-init-check";
  else if (!printing())
    results.initCheck.skipped = "not rank 0";
  else
    results.initCheck = checkInit(sessions.main->get(), bundle);
  // The init check of a large scene takes a while: a signal meanwhile
  // stops sim-run before anything ran.
  stopIfInterrupted("during the init check");
  if (printing())
    for (const std::string &message : initCheckMessages(results.initCheck))
      std::fprintf(stderr, "%s\n", message.c_str());
  std::fflush(stderr);
  results.referenceKind = options.reference;
  results.referenceValues.assign(observed.size(), std::nullopt);
  results.outputEvery = options.outputEvery;
  results.profile = options.profile;
  results.outputFile = options.output;
  runMain(results, sessions, bundle, options, observed, progress);
  results.nonFinite =
      findNonFiniteState(sessions.main->get(), bundle, results.main);
  runReference(results, sessions.main->get(), sessions.simple.get(), observed,
               options, progress);
  sessions.simple.reset();
  sessions.main.reset();
  if (sessions.check) {
    runCheck(results, *sessions.check, observed, options, progress);
    sessions.check.reset();
  }
  results.signal = receivedSignal();
}

/// Where a run wrote no checkpoint at its end (it failed, or the write
/// failed, or its state held NaN), notes what --checkpoint's path still
/// holds to restart from: the last checkpoint the run wrote, or the
/// --restart checkpoint when that is the same file and the run wrote none.
void noteCheckpointThatStays(const MainRun &main) {
  struct stat info;
  if (main.checkpointFile.empty() ||
      stat(main.checkpointFile.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
    return;
  if (main.checkpointsWritten > 0)
    std::fprintf(stderr,
                 "sim-run: note: the checkpoint '%s' of base step %lld "
                 "stays, to restart from\n",
                 main.checkpointFile.c_str(),
                 static_cast<long long>(main.checkpointTime));
  else if (!main.restartFile.empty() && main.restartTime >= 0 &&
           sameFile(main.restartFile, main.checkpointFile))
    std::fprintf(stderr,
                 "sim-run: note: the checkpoint '%s' this run restarted from "
                 "(base step %lld) stays, to restart from\n",
                 main.checkpointFile.c_str(),
                 static_cast<long long>(main.restartTime));
}

/// A run that failed (--check-finite found a NaN, a kernel failed) still
/// writes the output times it reached into --output's .npz; the last
/// checkpoint of --checkpoint-every stays. No JSON and no dumps: the state
/// stopped inside a big step, and the JSON's presence says the run ended.
void keepWhatTheFailedRunReached(const Results &results,
                                 const Options &options) {
  if (!printing())
    return;
  if (!options.output.empty() && results.series.size() > 0) {
    writeSeries(results, options);
    std::fprintf(stderr,
                 "sim-run: note: the run failed after %zu output time%s "
                 "(the last at base step %lld); '%s' holds them\n",
                 results.series.size(), results.series.size() == 1 ? "" : "s",
                 static_cast<long long>(results.series.times.back()),
                 options.output.c_str());
  }
  noteCheckpointThatStays(results.main);
}

/// For a .mlir input, moves the compile-time settings (max_steps) out of
/// `options.sets`: they go to the translation. A bundle has them compiled
/// in, and the sessions refuse them.
std::vector<std::string> takeCompileTimeSettings(Options &options) {
  std::vector<std::string> compiled;
  if (!isScene(options.input))
    return compiled;
  std::vector<std::pair<std::string, std::string>> runTime;
  for (auto &[name, value] : options.sets) {
    if (isCompileTimeSetting(name))
      compiled.push_back(name + "=" + value);
    else
      runTime.emplace_back(name, value);
  }
  options.sets = std::move(runTime);
  return compiled;
}

/// Without --strategy: hip, or where a bundle was compiled without it (for
/// example --sim-strategies=simple) the first plan it has, so that such a
/// bundle runs as it is.
sim_strategy defaultStrategy(const sim_bundle *bundle, sim_strategy preferred) {
  for (sim_strategy strategy :
       {preferred, SIM_STRATEGY_HIP_CACHE, SIM_STRATEGY_LTS,
        SIM_STRATEGY_TRADITIONAL, SIM_STRATEGY_SIMPLE})
    if (sim_bundle_has_strategy(bundle, strategy))
      return strategy;
  return preferred; // No plan at all: the session says so.
}

/// --distributed: every rank must run the same steps and the same stops,
/// checks and outputs, since each of them makes collective calls (a
/// gather for --dump, an all-reduce per big step); a rank that ran fewer
/// would leave the others waiting. Before anything else, so that it is the
/// first collective call on every rank whatever the options. The session
/// checks the bundle, strategy, group size, range, dt and parameters.
void agreeOnRunOptions(const Options &options) {
  if (!world)
    return;
  struct Named {
    const char *what;
    int64_t value;
  };
  auto given = [](const std::string &text) { return int64_t(!text.empty()); };
  int64_t reference = options.reference.empty()       ? 0
                      : options.reference == "simple" ? 1
                                                      : 2;
  const Named values[] = {
      {"--steps", options.steps},
      {"--repeat", options.repeat},
      {"--output-every", options.outputEvery},
      {"--output (given or not)", given(options.output)},
      {"--checkpoint (given or not)", given(options.checkpoint)},
      {"--checkpoint-every", options.checkpointEvery},
      {"--restart (given or not)", given(options.restart)},
      {"--reference (none, simple or exact)", reference},
      {"--check", int64_t(options.check)},
      {"--dump (given or not)", given(options.dump)},
      {"--json (given or not)", given(options.json)},
      {"--check-finite", int64_t(options.checkFinite)},
      {"--progress", int64_t(options.progress)},
      {"--no-init-check", int64_t(options.noInitCheck)},
      {"--backend", int64_t(options.backend)},
      {"--cuda-graph", int64_t(options.cudaGraph)},
  };
  // Each value's minimum and the minimum of its negation: the ranks agree
  // when both give it back.
  constexpr size_t n = std::size(values);
  int64_t both[2 * n];
  for (size_t i = 0; i < n; ++i) {
    both[i] = values[i].value;
    both[n + i] = -values[i].value;
  }
  if (world->allreduce_min_i64(world->user, both, int32_t(2 * n)) != 0)
    runError("rank " + std::to_string(worldRank) +
             ": the all-reduce that compares the ranks' options failed");
  for (size_t i = 0; i < n; ++i)
    if (both[i] != -both[n + i])
      usageError("the ranks were given different " +
                 std::string(values[i].what) + " (from " +
                 std::to_string(both[i]) + " to " +
                 std::to_string(-both[n + i]) + " over the " +
                 std::to_string(worldSize) +
                 " ranks): give every rank the same options");
}

/// The strategies a .mlir scene is translated for: the one that runs
/// (--strategy, default hip, which a bundle of every strategy runs too),
/// and simple for --reference simple. Compiling one strategy instead of
/// five is faster and leaves out the other strategies' remarks.
std::vector<sim_strategy> translatedStrategies(const Options &options) {
  std::vector<sim_strategy> strategies;
  if (options.reference == "simple" && options.strategy != SIM_STRATEGY_SIMPLE)
    strategies.push_back(SIM_STRATEGY_SIMPLE);
  strategies.push_back(options.strategy);
  return strategies;
}

int run(Options options) {
  agreeOnRunOptions(options);
  // Before anything runs: the paths, the bundle, every session and every
  // --set, the dump files.
  OutputPlan outputs = planOutputs(options);
  std::vector<std::string> compiled = takeCompileTimeSettings(options);
  Input input(options.input, compiled, translatedStrategies(options),
              printing() && (options.progress || isatty(STDERR_FILENO)));
  const sim_bundle *bundle = input.bundle();
  if (!options.strategyGiven)
    options.strategy = defaultStrategy(bundle, options.strategy);
  Sessions sessions = createSessions(bundle, options);
  std::vector<sim_buffer_info> observed = observedBuffers(bundle);
  std::vector<std::string> stems = planDumps(outputs, options, observed);
  if (options.reference == "exact")
    requireExactSolution(bundle, sessions.main->get(), observed);
  checkSeriesMemory(options, sessions.main->get(), observed);
  // A signal that came before the first run leaves nothing to report.
  stopIfInterrupted("before the run");

  Results results;
  try {
    runAll(results, sessions, bundle, options, observed);
  } catch (const Exit &exit) {
    // A distributed run's ranks report their errors their own way
    // (runDistributed).
    if (options.distributed) {
      keepWhatTheFailedRunReached(results, options);
      throw;
    }
    // The error first, then what it left.
    if (!exit.message.empty() && exit.status < kExitSignalBase)
      std::fprintf(stderr, "sim-run: error: %s\n", exit.message.c_str());
    keepWhatTheFailedRunReached(results, options);
    throw Exit{exit.status, exit.status < kExitSignalBase ? "" : exit.message};
  }
  bool checkpointFailed = !results.main.checkpointFailures.empty();
  if (!printing()) {
    // Rank 0 reports; the exit status is every rank's.
    if (int signal = receivedSignal())
      return kExitSignalBase + signal;
    if (checkpointFailed)
      return kExitFailure;
    return results.nonFinite.empty() ? kExitSuccess : kExitNonFinite;
  }

  // The report and the files: the JSON last, so that its presence says
  // the dumps are complete.
  printTable(results);
  writeDumps(results, options, stems);
  writeSeries(results, options);
  if (!options.json.empty())
    writeFileAtomically(options.json, toJson(results));

  for (const NonFiniteValues &found : results.nonFinite)
    std::fprintf(stderr, "%s\n", nonFiniteWarning(found).c_str());
  if (results.referenceKind == "exact")
    for (const std::optional<Buffer> &exact : results.referenceValues)
      if (exact)
        if (std::optional<NonFiniteValues> found = findNonFinite(*exact))
          std::fprintf(stderr, "%s\n", exactNonFiniteWarning(*found).c_str());
  // A checkpoint write that failed was reported at once, and the table and
  // the JSON record it. What is left to restart from, after the last one (a
  // failed write leaves the file as it was, if nothing else removed it):
  const MainRun &main = results.main;
  if (checkpointFailed &&
      (main.checkpointsWritten == 0 ||
       main.checkpointTime < main.checkpointFailures.back().time))
    noteCheckpointThatStays(main);
  if (int signal = receivedSignal()) {
    std::fprintf(stderr, "sim-run: interrupted by %s%s\n", signalName(signal),
                 results.interrupted() ? "; wrote what was complete" : "");
    return kExitSignalBase + signal;
  }
  // With --check-finite on, no base step made them (the state held them
  // before the first, or the run took none): no hint to turn it on.
  auto nonFiniteError = [&] {
    std::fprintf(
        stderr, "sim-run: error: the run ended with NaN or infinite values%s\n",
        options.checkFinite ? ""
                            : " (--check-finite stops at the first "
                              "and says where it appeared)");
  };
  // A checkpoint not written is status 1, also where the state's NaN was
  // why (which is said all the same).
  if (checkpointFailed) {
    if (!results.nonFinite.empty())
      nonFiniteError();
    return kExitFailure;
  }
  if (results.check && !results.check->pass())
    return kExitFailure;
  if (!results.nonFinite.empty()) {
    nonFiniteError();
    return kExitNonFinite;
  }
  return kExitSuccess;
}

/// The directory of this binary ("" if unknown).
std::string selfDirectory() {
  char self[4096];
  ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  if (length <= 0)
    return "";
  std::string path(self, size_t(length));
  return path.substr(0, path.rfind('/'));
}

/// How long a failing rank other than 0 waits before it reports and ends
/// every rank (runDistributed).
constexpr std::chrono::seconds kRankErrorDelay{2};

/// --distributed: run on every rank of MPI_COMM_WORLD, through the MPI
/// plugin next to the runtime's libraries (opened only here, so that
/// sim-run runs without MPI's libraries otherwise).
int runDistributed(Options options, int &argc, char **&argv) {
  std::string path = selfDirectory() + "/" + SIM_MPI_PLUGIN;
  void *plugin = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!plugin)
    usageError("--distributed needs the MPI plugin " + path + " (" + dlerror() +
               "); it is built when CMake finds MPI: install libopenmpi-dev "
               "and configure the build again");
  auto open = reinterpret_cast<sim_mpi_open_fn>(dlsym(plugin, "sim_mpi_open"));
  auto close =
      reinterpret_cast<sim_mpi_close_fn>(dlsym(plugin, "sim_mpi_close"));
  auto abort =
      reinterpret_cast<sim_mpi_abort_fn>(dlsym(plugin, "sim_mpi_abort"));
  if (!open || !close || !abort)
    usageError("--distributed: " + path +
               " is not sim's MPI plugin (it lacks sim_mpi_open, "
               "sim_mpi_close or sim_mpi_abort)");
  sim_mpi_world_info info{};
  void *mpi = open(&argc, &argv, &info);
  world = info.communicator;
  worldRank = info.rank;
  worldSize = info.size;
  // The ranks of a machine take its GPUs in turn from --device on; where
  // there are more ranks than GPUs, they share them round-robin (a --device
  // past the last is left for the backend to refuse).
  int32_t devices = 0;
  if (options.backend != SIM_BACKEND_CPU &&
      options.backend != SIM_BACKEND_REFERENCE &&
      sim_cuda_device_count(&devices) == SIM_OK && options.device < devices)
    options.device += info.local_rank % (devices - options.device);
  try {
    // Rank 0 prints the report and the output rows.
    if (!printing() && !std::freopen("/dev/null", "w", stdout))
      runError("cannot silence the standard output of rank " +
               std::to_string(worldRank));
    int status = run(std::move(options));
    world = nullptr;
    close(mpi);
    return status;
  } catch (const Exit &exit) {
    // Most errors stop every rank alike (a bad option or bundle, too many
    // ranks, ranks that disagree): the others give rank 0 time to print
    // the message once and end them all. A rank that fails alone still
    // says so after the wait.
    // mpirun answers rank 0's abort with SIGTERM, which the handler only
    // records (Signals.h): a rank that gets it while it waits ends without
    // repeating the message, whatever the scheduler does to the wait.
    if (worldRank != 0) {
      auto until = std::chrono::steady_clock::now() + kRankErrorDelay;
      while (!interrupted() && std::chrono::steady_clock::now() < until)
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      if (interrupted())
        std::_Exit(kExitSignalBase + receivedSignal());
    }
    if (!exit.message.empty())
      std::fprintf(stderr, "sim-run: rank %d: %s\n", worldRank,
                   exit.message.c_str());
    std::fflush(stderr);
    // The other ranks may wait in a collective call for this one.
    abort(exit.status);
    std::exit(exit.status ? exit.status : 1);
  }
}

} // namespace

/// Every process mpirun starts without --distributed would run the whole
/// scene alone and write the same output files; and a rank that was given
/// --distributed would wait for it forever. The world's size comes from
/// the launcher's environment (Open MPI and MPICH set one of these).
static void checkNotUnderMpirun() {
  for (const char *name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char *value = std::getenv(name);
    if (!value)
      continue;
    char *end = nullptr;
    long size = std::strtol(value, &end, 10);
    if (*end == '\0' && size > 1)
      usageError("this process is one of " + std::to_string(size) +
                 " that mpirun started (" + name +
                 "), but has no "
                 "--distributed: each would run the whole scene alone and "
                 "write the same files; give every rank --distributed, or "
                 "run sim-run without mpirun");
  }
}

/// Whether descriptor 1 was closed when sim-run started.
static bool stdoutWasClosed = false;

/// Gives a closed descriptor 0, 1 or 2 /dev/null, so that no file sim-run
/// or the runtime opens becomes it: with `>&-` the report would otherwise
/// be written into whatever file took descriptor 1 (the CPU backend's
/// kernel object). A closed standard output is still an error at the end.
static void reserveStandardDescriptors() {
  for (int fd = 0; fd <= 2; ++fd) {
    if (fcntl(fd, F_GETFD) != -1 || errno != EBADF)
      continue;
    // The lowest free descriptor: `fd` itself, as the lower ones are open.
    int opened = open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (opened >= 0 && opened != fd)
      close(opened);
    if (fd == 1)
      stdoutWasClosed = true;
  }
}

/// The exit status once the report is out: a report that could not be
/// written (standard output closed, a full disk, a reader that stopped
/// reading) makes a successful run fail, after every file was written.
static int finishStandardOutput(int status) {
  errno = 0;
  bool flushFailed = std::fflush(stdout) != 0;
  int error = errno;
  if (!stdoutWasClosed && !flushFailed && !std::ferror(stdout))
    return status;
  // The error of a write before the last flush is gone; a pipe whose
  // reader left still says so.
  std::string why = stdoutWasClosed ? "it is closed"
                    : error         ? std::strerror(error)
                                    : "a write failed";
  pollfd reader{STDOUT_FILENO, 0, 0};
  if (!stdoutWasClosed && !error && poll(&reader, 1, 0) == 1 &&
      (reader.revents & POLLERR))
    why = "its reader stopped reading";
  std::fprintf(stderr, "sim-run: error: cannot write to standard output: %s\n",
               why.c_str());
  return status == kExitSuccess ? kExitFailure : status;
}

int main(int argc, char **argv) {
  captureUmask();
  reserveStandardDescriptors();
  // A reader of the report that stops early (`| head`) must not kill the
  // run before its files are written: writes to it fail instead, and
  // finishStandardOutput reports it.
  std::signal(SIGPIPE, SIG_IGN);
  installSignalHandlers();
  int status;
  try {
    Options options = parseOptions(argc, argv);
    if (options.distributed)
      status = runDistributed(std::move(options), argc, argv);
    else {
      checkNotUnderMpirun();
      status = run(std::move(options));
    }
  } catch (const Exit &exit) {
    if (!exit.message.empty())
      std::fprintf(stderr, "sim-run: %s%s\n",
                   exit.status >= kExitSignalBase ? "" : "error: ",
                   exit.message.c_str());
    status = exit.status;
  }
  return finishStandardOutput(status);
}
