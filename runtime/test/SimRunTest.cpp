//===- SimRunTest.cpp - the sim-run tool ----------------------------------===//
//
// Runs the sim-run binary as a user would: help, usage errors (every value
// outside its domain, before anything runs and without an output file), a
// run with its table, the reference, .npy dumps, JSON, the NaN check, .mlir
// input through sim-translate, outputs that never land on an input or
// follow a symlink, hostile buffer names, SIGINT and SIGTERM, and the
// libraries it links.
//
//===----------------------------------------------------------------------===//

#include "TestBundle.h"
#include "TestUtil.h"

#include <gtest/gtest.h>
#include <minizip/unzip.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <map>
#include <spawn.h>
#include <sys/ioctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

using namespace sim::test;
using Json = nlohmann::json;

extern char **environ;

namespace {

struct Result {
  int status;
  std::string output;
};

/// Runs a shell command, stdout and stderr together.
Result shell(const std::string &command) {
  FILE *pipe = popen((command + " 2>&1").c_str(), "r");
  if (!pipe)
    return {-1, "popen failed"};
  std::string output;
  char chunk[4096];
  size_t n;
  while ((n = fread(chunk, 1, sizeof chunk, pipe)) > 0)
    output.append(chunk, n);
  int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

Result simRun(const std::string &args) {
  return shell(std::string(SIM_RUN_PATH) + " " + args);
}

bool exists(const std::string &path) {
  struct stat info;
  return lstat(path.c_str(), &info) == 0;
}

/// The names in a directory, sorted, without "." and "..".
std::vector<std::string> listDirectory(const std::string &path) {
  std::vector<std::string> names;
  if (DIR *listing = opendir(path.c_str())) {
    while (dirent *entry = readdir(listing))
      if (std::strcmp(entry->d_name, ".") && std::strcmp(entry->d_name, ".."))
        names.push_back(entry->d_name);
    closedir(listing);
  }
  std::sort(names.begin(), names.end());
  return names;
}

Json readJson(const std::string &path) {
  // nlohmann's parser rejects invalid JSON and invalid UTF-8.
  return Json::parse(readFile(path));
}

/// Values of a .npy file written by sim-run (after its header).
std::string npyData(const std::string &file) {
  size_t header = uint8_t(file[8]) | uint8_t(file[9]) << 8;
  return file.substr(10 + header);
}

double f64At(const std::string &data, size_t i) {
  double value;
  std::memcpy(&value, data.data() + i * 8, 8);
  return value;
}

float f32At(const std::string &data, size_t i) {
  float value;
  std::memcpy(&value, data.data() + i * 4, 4);
  return value;
}

/// The entries of an .npz file (zip) by name, each a whole .npy file; read
/// with minizip's unzip (the Python tests read them with NumPy).
std::map<std::string, std::string> readNpz(const std::string &path) {
  std::map<std::string, std::string> entries;
  unzFile zip = unzOpen64(path.c_str());
  if (!zip)
    return entries;
  for (int at = unzGoToFirstFile(zip); at == UNZ_OK;
       at = unzGoToNextFile(zip)) {
    char name[512];
    unz_file_info64 info;
    if (unzGetCurrentFileInfo64(zip, &info, name, sizeof name, nullptr, 0,
                                nullptr, 0) != UNZ_OK ||
        unzOpenCurrentFile(zip) != UNZ_OK)
      break;
    std::string data(size_t(info.uncompressed_size), '\0');
    int read = unzReadCurrentFile(zip, data.data(), unsigned(data.size()));
    unzCloseCurrentFile(zip);
    if (read != int(data.size()))
      break;
    entries[name] = data;
  }
  unzClose(zip);
  return entries;
}

/// The shape in a .npy header: "(3, 100)" for {3, 100}.
std::string npyShape(const std::string &file) {
  size_t at = file.find("'shape': ");
  return at == std::string::npos
             ? ""
             : file.substr(at + 9, file.find(')', at) - at - 8);
}

/// sim-run started in the background with stdout and stderr in files and
/// SIGINT and SIGTERM at their defaults (whatever the test runner does).
pid_t spawnSimRun(const std::string &program,
                  const std::vector<std::string> &args, const std::string &out,
                  const std::string &err,
                  const std::vector<std::string> &env = {}) {
  std::vector<std::string> all = {program};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char *> argv;
  for (std::string &arg : all)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  std::vector<std::string> envStrings = env;
  for (char **e = environ; *e; ++e)
    envStrings.push_back(*e);
  std::vector<char *> envp;
  for (std::string &entry : envStrings)
    envp.push_back(entry.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults, none;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGINT);
  sigaddset(&defaults, SIGTERM);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes,
                           POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = -1;
  if (posix_spawn(&pid, program.c_str(), &actions, &attributes, argv.data(),
                  envp.data()) != 0)
    pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return pid;
}

/// The wait status of `pid`, killing it after `seconds`.
int waitFor(pid_t pid, double seconds = 60) {
  auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  while (waitpid(pid, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid, SIGKILL);
      waitpid(pid, &status, 0);
      ADD_FAILURE() << "sim-run did not end within " << seconds << " s";
      return status;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  return status;
}

/// Waits until `path` exists and contains `text`.
bool waitForText(const std::string &path, const std::string &text,
                 double seconds = 60) {
  auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < deadline) {
    if (exists(path) && contains(readFile(path), text))
      return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

/// The decay bundle (with its reference model) with buffers X and V
/// renamed: names are FlatBuffer strings, so any bytes go.
std::string decayBundleNamed(const std::string &x, const std::string &v) {
  schema::BundleT contents = decayContents();
  contents.scene->buffers[0]->name = x;
  contents.scene->buffers[1]->name = v;
  return serialize(contents);
}

class SimRun : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir = makeTempDir();
    bundle = dir + "/decay.simb";
    writeFile(bundle, decayBundle());
  }
  static void TearDownTestSuite() { shell("rm -rf '" + dir + "'"); }

  /// A copy of sim-run in folder `name` of `dir`, next to a stand-in
  /// sim-translate that records its arguments in `args` and copies
  /// `bundle` to the output, and a `scene` it does not read.
  struct StandIn {
    std::string simRun, scene, args;
  };
  static StandIn standInTranslate(const std::string &name) {
    std::string tools = dir + "/" + name;
    EXPECT_EQ(mkdir(tools.c_str(), 0755), 0) << tools;
    StandIn standIn{tools + "/sim-run", tools + "/decay.mlir", tools + "/args"};
    EXPECT_EQ(
        shell("cp " + std::string(SIM_RUN_PATH) + " " + standIn.simRun).status,
        0);
    writeFile(standIn.scene, "// not read by the stand-in sim-translate\n");
    std::string translate = tools + "/sim-translate";
    writeFile(translate, "#!/bin/sh\necho \"$@\" > '" + standIn.args +
                             "'\n/bin/cp '" + bundle + "' \"$4\"\n");
    chmod(translate.c_str(), 0755);
    return standIn;
  }

  static std::string dir, bundle;
};

std::string SimRun::dir, SimRun::bundle;

} // namespace

TEST_F(SimRun, PrintsHelp) {
  Result result = simRun("--help");
  EXPECT_EQ(result.status, 0);
  EXPECT_TRUE(
      contains(result.output, "USAGE: sim-run <scene.simb | scene.mlir>"));
  for (const char *option :
       {"--backend B", "auto, cpu, cuda or reference", "--check",
        "--check-tolerance X", "--strategy S", "--steps N", "--repeat K",
        "--set NAME=VALUE", "--group-size G", "--reference simple|exact",
        "--dump DIR", "--json FILE", "--check-finite", "--max-memory SIZE",
        "EXIT STATUS"})
    EXPECT_TRUE(contains(result.output, option)) << option;
}

TEST_F(SimRun, RejectsBadUsageBeforeAnythingRuns) {
  // Every case also asks for --json and --dump: neither may appear.
  std::string json = dir + "/usage.json", dump = dir + "/usage-dump";
  struct Case {
    std::string args, message;
  } cases[] = {
      {"", "sim-run: error: no input scene (see sim-run --help)"},
      {bundle + " --fast", "unknown option '--fast'"},
      {bundle + " other.simb", "more than one input"},
      {bundle + " --steps x",
       "--steps: 'x' is not an integer from 0 to 1000000000000"},
      {bundle + " --steps -1", "--steps: '-1' is not an integer"},
      {bundle + " --steps 1000000000001",
       "--steps: '1000000000001' is not an integer"},
      {bundle + " --steps 99999999999999999999",
       "--steps: '99999999999999999999' is not"},
      {bundle + " --steps", "--steps expects a value"},
      {bundle + " --repeat 0",
       "--repeat: '0' is not an integer from 1 to 1000000"},
      {bundle + " --repeat 9223372036854775807",
       "--repeat: '9223372036854775807' is not an integer from 1 to 1000000"},
      {bundle + " --repeat 1000001", "--repeat: '1000001' is not"},
      {bundle + " --group-size 0",
       "--group-size: '0' is not an integer from 1 to 4096"},
      {bundle + " --group-size 4097", "--group-size: '4097' is not"},
      {bundle + " --threads 0",
       "--threads: '0' is not an integer from 1 to 1024"},
      {bundle + " --threads 1025", "--threads: '1025' is not"},
      {bundle + " --device -1", "--device: '-1' is not a device ordinal"},
      {bundle + " --report-every 0",
       "--report-every: '0' is not an integer from 1 to"},
      {bundle + " --check --check-tolerance -1",
       "--check-tolerance: '-1' is not a finite number >= 0"},
      {bundle + " --check --check-tolerance nan",
       "--check-tolerance: 'nan' is not"},
      {bundle + " --check --check-tolerance inf",
       "--check-tolerance: 'inf' is not"},
      {bundle + " --check-tolerance 1e-3",
       "--check-tolerance requires --check"},
      {bundle + " --max-memory -1",
       "--max-memory: '-1' is not a size in bytes"},
      {bundle + " --max-memory 12X", "--max-memory: '12X' is not a size"},
      {bundle + " --max-memory 99999999T",
       "--max-memory: '99999999T' is not a size"},
      {bundle + " --strategy best", "--strategy: unknown strategy 'best'"},
      {bundle + " --backend tpu", "--backend: unknown backend 'tpu'"},
      {bundle + " --reference cubic",
       "--reference: 'cubic' is not simple or exact"},
      {bundle + " --set k", "--set: 'k' is not NAME=VALUE"},
      {bundle + " --set =2", "--set: '=2' is not NAME=VALUE"},
      {bundle + " --check-finite=yes", "--check-finite takes no value"},
      {dir + "/missing.simb", "cannot read the input '" + dir +
                                  "/missing.simb': No such file or directory"},
      {dir, "the input '" + dir + "' is a directory"},
  };
  for (const Case &c : cases) {
    // (First: an option that expects a value takes the next argument.)
    Result result = simRun("--json " + json + " --dump " + dump + " " + c.args);
    EXPECT_EQ(result.status, 2) << c.args << ": " << result.output;
    EXPECT_TRUE(contains(result.output, c.message))
        << c.args << ": " << result.output;
    EXPECT_FALSE(exists(json)) << c.args;
    EXPECT_FALSE(exists(dump)) << c.args;
  }
}

TEST_F(SimRun, RejectsSettingsTheSceneRefusesBeforeRunning) {
  std::string json = dir + "/set.json", dump = dir + "/set-dump";
  struct Case {
    std::string args, message;
  } cases[] = {
      {"--set speed=3", "--set speed=3: 'speed' is not range, dt or a "
                        "parameter of scene 'decay'"},
      {"--set k=fast", "--set k=fast: parameter 'k'"},
      {"--set dt=nan", "--set dt=nan: "},
      {"--set dt=inf", "--set dt=inf: "},
      {"--set dt=0", "--set dt=0: dt: 0 is not a positive finite time step"},
      {"--set dt=-1", "--set dt=-1: dt: -1 is not a positive finite"},
      {"--set range=0", "--set range=0: range: 0 is not a number of items"},
      // The sessions of --reference, --check and --report-every are made
      // before anything runs, so their settings are checked too.
      {"--check --reference simple --report-every 5 --set dt=0",
       "--set dt=0: "},
  };
  for (const Case &c : cases) {
    Result result = simRun(bundle + " --backend cpu --steps 5 " + c.args +
                           " --json " + json + " --dump " + dump);
    EXPECT_EQ(result.status, 2) << c.args << ": " << result.output;
    EXPECT_TRUE(contains(result.output, c.message))
        << c.args << ": " << result.output;
    EXPECT_FALSE(contains(result.output, "wall time")) << result.output;
    EXPECT_FALSE(exists(json)) << c.args;
    EXPECT_FALSE(exists(dump)) << c.args;
  }

  // A scene without an exact solution cannot be compared with one (the
  // probe scene runs on the reference executor only).
  std::string probe = dir + "/probe.simb";
  writeFile(probe, probeBundle());
  Result result = simRun(probe + " --backend reference --reference exact");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "--reference exact: scene 'probe' declares no exact "
                       "solution of an observed buffer"))
      << result.output;

  // A state larger than --max-memory is a failure of the run (status 1),
  // found before it starts.
  result = simRun(bundle +
                  " --backend cpu --max-memory 1K --set range=1000 "
                  "--json " +
                  json);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "more than the limit of 1.00 KiB"))
      << result.output;
  EXPECT_FALSE(exists(json));
}

TEST_F(SimRun, RunsAndPrintsTheTable) {
  Result result = simRun(bundle + " --backend cpu --steps 25 --threads 2 "
                                  "--set k=1 --max-memory 1M");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string &out = result.output;
  EXPECT_TRUE(
      contains(out, "scene decay, strategy hip, backend cpu: CPU (2 threads, "
                    "x86-64"))
      << out;
  EXPECT_TRUE(contains(out, "range 100, dt 0.01, group size 32, 25 base steps"))
      << out;
  for (const char *row : {"wall time", "kernel time", "launches", "host syncs",
                          "big steps", "big-step sizes", "evaluations"})
    EXPECT_TRUE(contains(out, row)) << row << "\n" << out;
  // The hip plan's big steps from 0 to 25 (decayBigSteps): 1 x5, 2 x3,
  // 3 x2, 4 x1, 1 x4.
  EXPECT_TRUE(contains(out, "big steps        15")) << out;
  EXPECT_TRUE(contains(out, "1: 9  2: 3  3: 2  4: 1")) << out;
  EXPECT_TRUE(contains(out, "Decay 1500  Grow 1500")) << out;
  // Clock (16 slots), X (f64: two halves and the exact output) and V (16
  // bytes: two halves) at 100 items, against --max-memory.
  EXPECT_TRUE(contains(out, "memory           5.59 KiB (limit 1.00 MiB)"))
      << out;
}

TEST_F(SimRun, AutoFallsBackToTheCpuAndSaysWhy) {
  Result result = simRun(bundle + " --steps 3");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "backend cpu")) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "(not CUDA: the bundle has no PTX for strategy 'hip')"))
      << result.output;
}

TEST_F(SimRun, ReportsTheErrorAgainstAReference) {
  Result simple =
      simRun(bundle + " --backend cpu --steps 40 --reference simple");
  ASSERT_EQ(simple.status, 0) << simple.output;
  // X is exact per base step, so hip and simple agree to rounding; V's
  // lane 2 counts evaluations: 40 under simple, 21 (big steps) under hip.
  EXPECT_TRUE(contains(simple.output, "error vs simple  X  max-abs"))
      << simple.output;
  EXPECT_TRUE(contains(simple.output, "error vs simple  V  max-abs 1.900e+01"))
      << simple.output;

  Result exact = simRun(bundle + " --backend cpu --steps 40 --reference exact");
  ASSERT_EQ(exact.status, 0) << exact.output;
  EXPECT_TRUE(contains(exact.output, "error vs exact   X  max-abs"))
      << exact.output;
  EXPECT_TRUE(contains(exact.output, "error vs exact   V  (no exact solution)"))
      << exact.output;
}

TEST_F(SimRun, DumpsNpyFilesAndJson) {
  std::string out = dir + "/dump";
  std::string json = dir + "/metrics.json";
  Result result = simRun(bundle +
                         " --backend cpu --strategy simple --steps 7 "
                         "--repeat 3 --reference exact --dump " +
                         out + " --json " + json);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "median of 3 runs after a warm-up"));

  std::string x = readFile(out + "/X.npy");
  ASSERT_GE(x.size(), 10u);
  EXPECT_EQ(x.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  size_t headerLength = uint8_t(x[8]) | uint8_t(x[9]) << 8;
  EXPECT_EQ((10 + headerLength) % 64, 0u);
  std::string header = x.substr(10, headerLength);
  EXPECT_EQ(header.rfind("{'descr': '<f8', 'fortran_order': False, "
                         "'shape': (100,), }",
                         0),
            0u)
      << header;
  EXPECT_EQ(header.back(), '\n');
  ASSERT_EQ(x.size(), 10 + headerLength + 100 * 8);
  EXPECT_NEAR(f64At(npyData(x), 5), 1.05 * std::pow(0.98, 7), 1e-12);

  std::string v = readFile(out + "/V.npy");
  size_t vHeader = uint8_t(v[8]) | uint8_t(v[9]) << 8;
  EXPECT_TRUE(contains(v.substr(10, vHeader),
                       "{'descr': '<f4', 'fortran_order': False, 'shape': "
                       "(100, 3), }"));
  EXPECT_EQ(v.size(), 10 + vHeader + 100 * 3 * 4);
  EXPECT_TRUE(contains(readFile(out + "/X.reference.npy"), "'shape': (100,)"));

  // Only the finished files: no temporaries left behind.
  EXPECT_EQ(listDirectory(out),
            (std::vector<std::string>{"V.npy", "X.npy", "X.reference.npy"}));

  Json metrics = readJson(json);
  EXPECT_EQ(metrics["scene"], "decay");
  EXPECT_EQ(metrics["strategy"], "simple");
  EXPECT_EQ(metrics["backend"], "cpu");
  EXPECT_EQ(metrics["range"], 100);
  EXPECT_EQ(metrics["dt"], 0.01);
  // Every parameter with the value the run used (here its default).
  EXPECT_EQ(metrics["params"], Json({{"k", "2"}, {"poison", "-1"}}));
  EXPECT_EQ(metrics["steps"], 7);
  EXPECT_EQ(metrics["steps_done"], 7);
  EXPECT_EQ(metrics["repeat"], 3);
  EXPECT_EQ(metrics["interrupted"], false);
  EXPECT_TRUE(metrics["interruption"].is_null());
  EXPECT_EQ(metrics["big_steps"], 7);
  EXPECT_EQ(metrics["big_step_histogram"],
            Json::parse(R"({"1": 7, "2": 0, "3": 0, "4": 0})"));
  EXPECT_EQ(metrics["evaluations"],
            Json::parse(R"({"Decay": 700, "Grow": 700})"));
  EXPECT_EQ(metrics["reference"], "exact");
  EXPECT_TRUE(metrics["error"]["X"]["max_abs"].is_number());
  EXPECT_TRUE(metrics["error"]["X"]["rms_rel"].is_number());
  EXPECT_FALSE(metrics["error"].contains("V"));
  EXPECT_EQ(metrics["wall_seconds_runs"].size(), 3u);
  EXPECT_EQ(metrics["kernel_seconds_runs"].size(), 3u);
  EXPECT_EQ(metrics["host_syncs"], 2);
  EXPECT_EQ(metrics["max_memory"], 0);
  EXPECT_EQ(metrics["memory_bytes"], 5728);
  EXPECT_GT(metrics["memory_limit"].get<int64_t>(), 0);
  EXPECT_TRUE(metrics["totals"].empty());
  EXPECT_TRUE(metrics["totals_per_output_time"].is_null());
  EXPECT_TRUE(metrics["check"].is_null());
  EXPECT_EQ(metrics["dump"]["directory"], out);
  EXPECT_EQ(metrics["dump"]["files"][0],
            Json::parse(R"({"buffer": "X", "state": "X.npy",
                            "reference": "X.reference.npy", "check": null})"));
}

TEST_F(SimRun, LeavesNoReferenceOrCheckFileThatTheRunDidNotWrite) {
  std::string out = dir + "/restale", json = dir + "/restale.json";
  Result result = simRun(bundle +
                         " --backend cpu --steps 5 --reference simple "
                         "--check --dump " +
                         out);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(
      listDirectory(out),
      (std::vector<std::string>{"V.check.npy", "V.npy", "V.reference.npy",
                                "X.check.npy", "X.npy", "X.reference.npy"}));
  // V has no exact solution: the simple strategy's V of the run before
  // must not pass for this run's reference; and nothing was checked.
  result = simRun(bundle + " --backend cpu --steps 9 --reference exact " +
                  "--dump " + out + " --json " + json);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(listDirectory(out),
            (std::vector<std::string>{"V.npy", "X.npy", "X.reference.npy"}));
  EXPECT_EQ(readJson(json)["dump"]["files"][1]["reference"], nullptr);
  result = simRun(bundle + " --backend cpu --steps 2 --dump " + out);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(listDirectory(out), (std::vector<std::string>{"V.npy", "X.npy"}));
  // So those names are the dump's, whatever the options: no other output
  // may take one, as it would be removed.
  writeFile(out + "/X.check.npy", "kept");
  result = simRun(bundle + " --backend cpu --steps 2 --dump " + out +
                  " --json " + out + "/X.check.npy");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "--dump (buffer 'X'): '" + out +
                                          "/X.check.npy' is also the file of "
                                          "--json"))
      << result.output;
  EXPECT_EQ(readFile(out + "/X.check.npy"), "kept");
}

TEST_F(SimRun, StopsAtTheFirstNonFiniteValue) {
  Result result = simRun(bundle + " --backend cpu --strategy simple --steps 20 "
                                  "--set poison=4 --check-finite");
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output,
                       "sim-run: error: non-finite value nan in buffer 'X' "
                       "(item 7) after kernel 'evaluate_Decay' for component "
                       "'Decay' at base step 4"))
      << result.output;
}

TEST_F(SimRun, KeepsTheOutputTimesAndCheckpointOfARunThatFails) {
  // The NaN in the base step from 4 ends the run; the output times 0, 2
  // and 4 are in the .npz and the checkpoint of base step 4 stays. No JSON (its
  // presence says the run ended) and no dumps (the state stopped inside a
  // big step).
  std::string npz = dir + "/failed.npz", json = dir + "/failed.json",
              dump = dir + "/failed-dump", checkpoint = dir + "/failed.simc";
  Result result =
      simRun(bundle +
             " --backend cpu --strategy simple --steps 20 "
             "--set poison=4 --check-finite "
             "--output-every 2 --output " +
             npz + " --json " + json + " --dump " + dump + " --checkpoint " +
             checkpoint + " --checkpoint-every 2");
  EXPECT_EQ(result.status, 1) << result.output;
  size_t error = result.output.find("sim-run: error: non-finite value nan");
  size_t kept = result.output.find(
      "sim-run: note: the run failed after 3 output times (the last at base "
      "step 4); '" +
      npz + "' holds them");
  EXPECT_NE(error, std::string::npos) << result.output;
  EXPECT_NE(kept, std::string::npos) << result.output;
  EXPECT_LT(error, kept) << result.output;
  EXPECT_TRUE(contains(result.output, "sim-run: note: the checkpoint '" +
                                          checkpoint +
                                          "' of base step 4 stays"))
      << result.output;
  EXPECT_TRUE(exists(npz));
  EXPECT_TRUE(exists(checkpoint));
  EXPECT_FALSE(exists(json));
  EXPECT_FALSE(exists(dump));
}

TEST_F(SimRun, ReportsBadBundles) {
  std::string bad = dir + "/bad.simb";
  writeFile(bad, "not a bundle at all, but long enough");
  Result result = simRun(bad);
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "sim-run: error: bundle '" + bad +
                                          "': not a sim bundle (wrong magic"))
      << result.output;
  result = simRun(bundle + " --backend cuda");
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "has no PTX for strategy 'hip'; the CUDA "
                                      "backend needs it"))
      << result.output;
}

TEST_F(SimRun, TranslatesMlirScenesWithSimTranslate) {
  // A copy of sim-run in a directory of its own, to control what lies
  // next to it.
  std::string tools = dir + "/tools";
  ASSERT_EQ(mkdir(tools.c_str(), 0755), 0);
  std::string simRun = tools + "/sim-run";
  ASSERT_EQ(shell("cp " + std::string(SIM_RUN_PATH) + " " + simRun).status, 0);
  std::string scene = dir + "/decay.mlir";
  writeFile(scene, "// not read by the stand-in sim-translate\n");
  std::string tmp = dir + "/translate-tmp";
  ASSERT_EQ(mkdir(tmp.c_str(), 0755), 0);

  Result missing = shell("PATH=/nonexistent " + simRun + " " + scene);
  EXPECT_EQ(missing.status, 1);
  EXPECT_TRUE(contains(missing.output, "cannot translate '" + scene +
                                           "': sim-translate not found (looked "
                                           "in " +
                                           tools + " and on PATH)"))
      << missing.output;

  // A stand-in sim-translate: `sim-translate <scene> --sim-to-bundle -o <out>`.
  std::string translate = tools + "/sim-translate";
  writeFile(translate, "#!/bin/sh\n[ \"$2\" = --sim-to-bundle ] && [ \"$3\" = "
                       "-o ] || exit 3\n/bin/cp '" +
                           bundle + "' \"$4\"\n");
  chmod(translate.c_str(), 0755);
  Result translated = shell("TMPDIR=" + tmp + " PATH=/nonexistent " + simRun +
                            " " + scene + " --backend cpu --steps 4");
  EXPECT_EQ(translated.status, 0) << translated.output;
  EXPECT_TRUE(contains(translated.output, "scene decay, strategy hip"))
      << translated.output;
  // The temporary bundle is gone.
  EXPECT_EQ(listDirectory(tmp), std::vector<std::string>{});

  // Not even a .mlir input is written onto, before it is translated.
  Result onto = shell("TMPDIR=" + tmp + " PATH=/nonexistent " + simRun + " " +
                      scene + " --json " + scene);
  EXPECT_EQ(onto.status, 2) << onto.output;
  EXPECT_EQ(readFile(scene), "// not read by the stand-in sim-translate\n");

  writeFile(translate, "#!/bin/sh\necho 'error: no such op' >&2\nexit 1\n");
  Result failed =
      shell("TMPDIR=" + tmp + " PATH=/nonexistent " + simRun + " " + scene);
  EXPECT_EQ(failed.status, 1);
  EXPECT_TRUE(contains(failed.output, "error: no such op")) << failed.output;
  EXPECT_TRUE(
      contains(failed.output, "sim-run: error: sim-translate failed on '" +
                                  scene + "' (exit status 1)"))
      << failed.output;
  EXPECT_EQ(listDirectory(tmp), std::vector<std::string>{});
}

TEST_F(SimRun, RunsTheReferenceExecutor) {
  Result result = simRun(bundle + " --backend reference --steps 25 --set k=1 "
                                  "--reference exact");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string &out = result.output;
  EXPECT_TRUE(contains(out, "scene decay, strategy hip, backend reference: "
                            "reference executor (CPU, 1 thread)"))
      << out;
  EXPECT_TRUE(contains(out, "launches         0")) << out;
  EXPECT_TRUE(contains(out, "big steps        15")) << out;
  EXPECT_TRUE(contains(out, "1: 9  2: 3  3: 2  4: 1")) << out;
  EXPECT_TRUE(contains(out, "Decay 1500  Grow 1500")) << out;
  EXPECT_TRUE(contains(out, "error vs exact   X  max-abs")) << out;

  result =
      simRun(bundle + " --backend reference --steps 40 --reference simple");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "error vs simple  V  max-abs 1.900e+01"))
      << result.output;

  std::string old = dir + "/old.simb";
  writeFile(old, decayBundle(false, false));
  result = simRun(old + " --backend reference");
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "has no reference model and functions"))
      << result.output;
}

TEST_F(SimRun, ChecksAgainstTheReferenceExecutor) {
  std::string out = dir + "/check";
  std::string json = dir + "/check.json";
  Result result = simRun(bundle +
                         " --backend cpu --steps 25 --check "
                         "--dump " +
                         out + " --json " + json);
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string &text = result.output;
  for (const char *line :
       {"\ncheck against the reference executor (strategy hip, group size "
        "32, 25 base steps):\n",
        "\n  buffer X  max-abs 0.000e+00  max-ref 1.201e+00  rms-rel "
        "0.000e+00  tolerance 1.0e-10  pass\n",
        "\n  buffer V  max-abs 0.000e+00  max-ref 9.900e+01  rms-rel "
        "0.000e+00  tolerance 1.0e-04  pass\n",
        "\n  evaluations Decay  backend 1500  reference 1500  equal\n",
        "\n  evaluations Grow  backend 1500  reference 1500  equal\n",
        "\n  big steps  backend 15  reference 15  equal\n",
        "\n  big-step size 1  backend 9  reference 9  equal\n",
        "\n  big-step size 4  backend 1  reference 1  equal\n",
        "\ncheck: pass\n"})
    EXPECT_TRUE(contains(text, line)) << line << "\n" << text;
  EXPECT_TRUE(contains(readFile(out + "/X.check.npy"), "'shape': (100,)"));
  Json check = readJson(json)["check"];
  EXPECT_EQ(check["strategy"], "hip");
  EXPECT_EQ(check["group_size"], 32);
  EXPECT_EQ(check["steps"], 25);
  EXPECT_EQ(check["pass"], true);
  const Json &x = check["buffers"]["X"];
  EXPECT_EQ(x["max_abs"], 0.0);
  EXPECT_NEAR(x["max_reference"].get<double>(), 1.20089481, 1e-8);
  EXPECT_EQ(x["rms_rel"], 0.0);
  EXPECT_EQ(x["tolerance"], 1e-10);
  EXPECT_NEAR(x["limit"].get<double>(), 1.20089481e-10, 1e-18);
  EXPECT_EQ(x["non_finite"], Json::parse(R"({"backend": 0, "reference": 0})"));
  EXPECT_EQ(x["pass"], true);
  EXPECT_EQ(check["buffers"]["V"]["tolerance"], 1e-4);
  EXPECT_EQ(check["evaluations"],
            Json::parse(R"({"backend": {"Decay": 1500, "Grow": 1500},
                            "reference": {"Decay": 1500, "Grow": 1500},
                            "equal": true})"));
  EXPECT_EQ(check["big_steps"],
            Json::parse(R"({"backend": 15, "reference": 15, "equal": true})"));
  EXPECT_EQ(check["big_step_histogram"]["backend"],
            Json::parse(R"({"1": 9, "2": 3, "3": 2, "4": 1})"));
  EXPECT_EQ(check["big_step_histogram"]["equal"], true);
  EXPECT_EQ(check["failures"], Json::array());
  // Without --check the JSON says so.
  ASSERT_EQ(simRun(bundle + " --backend cpu --steps 2 --json " + json).status,
            0);
  EXPECT_TRUE(readJson(json)["check"].is_null());
}

TEST_F(SimRun, FailsTheCheckOnDifferentValues) {
  // A reference object that adds 1e-6 to item 3 in every evaluation.
  std::string wrong = dir + "/wrong.simb";
  writeFile(wrong, serialize(decayContents(false, true,
                                           SIM_TEST_DECAY_REFERENCE_WRONG_SO)));
  std::string json = dir + "/wrong.json";
  Result result = simRun(wrong +
                         " --backend cpu --strategy simple --steps 25 "
                         "--check --json " +
                         json);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(contains(result.output, "  buffer X  max-abs 1.983e-05  max-ref "
                                      "1.201e+00  rms-rel 2.158e-06  tolerance "
                                      "1.0e-10  FAIL\n"))
      << result.output;
  EXPECT_TRUE(contains(result.output,
                       "\ncheck: FAIL: buffer X exceeds the tolerance (max-abs "
                       "1.983e-05 > 1.201e-10)\n"))
      << result.output;
  Json check = readJson(json)["check"];
  EXPECT_EQ(check["pass"], false);
  EXPECT_EQ(check["failures"],
            Json::array({"buffer X exceeds the tolerance (max-abs 1.983e-05 > "
                         "1.201e-10)"}));

  // A looser tolerance lets it pass.
  result = simRun(wrong + " --backend cpu --strategy simple --steps 25 "
                          "--check --check-tolerance 1e-4");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "tolerance 1.0e-04  pass"))
      << result.output;
}

TEST_F(SimRun, FailsTheCheckOnNonFiniteValuesOnBothSides) {
  // Item 7 of X turns NaN at base step 4 on the backend and on the
  // reference executor alike: the run blew up, and the check says so.
  std::string json = dir + "/nan.json";
  Result result = simRun(bundle +
                         " --backend cpu --strategy simple --steps 20 "
                         "--set poison=4 --check --json " +
                         json);
  EXPECT_EQ(result.status, 1) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "  buffer X  max-abs nan  max-ref 1.329e+00  rms-rel "
                       "nan  tolerance 1.0e-10  FAIL  (non-finite: backend 1, "
                       "reference 1)\n"))
      << result.output;
  EXPECT_TRUE(contains(result.output, "  buffer V  max-abs 0.000e+00"))
      << result.output;
  EXPECT_TRUE(contains(result.output,
                       "\ncheck: FAIL: buffer X has 1 non-finite value on the "
                       "backend and 1 on the reference executor\n"))
      << result.output;
  Json check = readJson(json)["check"];
  EXPECT_EQ(check["pass"], false);
  EXPECT_TRUE(check["buffers"]["X"]["max_abs"].is_null());
  EXPECT_EQ(check["buffers"]["X"]["non_finite"],
            Json::parse(R"({"backend": 1, "reference": 1})"));
  EXPECT_EQ(check["buffers"]["X"]["pass"], false);
  EXPECT_EQ(check["buffers"]["V"]["pass"], true);
}

TEST_F(SimRun, FailsTheCheckOnDifferentWork) {
  // With Decay recorded as not estimating in the model, nothing bounds the
  // big step there: the reference takes big steps of max_steps, fewer than
  // the plan.
  schema::BundleT contents = decayContents();
  contents.reference->components[0]->stepping[2] =
      schema::Stepping(schema::Advance::WholeStep, false);
  std::string unbounded = dir + "/unbounded.simb";
  writeFile(unbounded, serialize(contents));
  Result result = simRun(unbounded + " --backend cpu --steps 25 --check");
  EXPECT_EQ(result.status, 1) << result.output;
  for (const char *line :
       {"  evaluations Decay  backend 1500  reference 700  DIFFER\n",
        "  big steps  backend 15  reference 7  DIFFER\n",
        "  big-step size 4  backend 1  reference 6  DIFFER\n",
        "check: FAIL: buffer V exceeds the tolerance (max-abs 8.000e+00 > "
        "9.900e-03); evaluations of Decay differ (1500 vs 700); evaluations "
        "of Grow differ (1500 vs 700); big steps differ (15 vs 7); big steps "
        "of size 1 differ (9 vs 1); big steps of size 2 differ (3 vs 0); big "
        "steps of size 3 differ (2 vs 0); big steps of size 4 differ (1 vs "
        "6)\n"})
    EXPECT_TRUE(contains(result.output, line)) << line << "\n" << result.output;
}

TEST_F(SimRun, NeverWritesOntoAnInputOrTwoOutputsOntoOneFile) {
  std::string before = readFile(bundle);
  std::string sub = dir + "/onto";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  ASSERT_EQ(symlink(dir.c_str(), (sub + "/up").c_str()), 0);
  for (std::string json :
       {bundle, dir + "/./decay.simb", dir + "/not-yet/../decay.simb",
        sub + "/up/decay.simb"}) {
    Result result = simRun(bundle + " --backend cpu --steps 2 --json " + json);
    EXPECT_EQ(result.status, 2) << json << ": " << result.output;
    EXPECT_TRUE(contains(result.output, "--json: '" + json +
                                            "' is the input '" + bundle + "'"))
        << result.output;
    EXPECT_FALSE(contains(result.output, "wall time")) << result.output;
  }
  EXPECT_EQ(readFile(bundle), before);
  EXPECT_FALSE(exists(dir + "/not-yet"));

  // A dump file onto the input: a bundle named X.npy in the dump folder.
  std::string inside = sub + "/X.npy";
  writeFile(inside, before);
  Result result = simRun(inside + " --backend cpu --steps 2 --dump " + sub);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "--dump (buffer 'X'): '" + sub + "/X.npy' is the input"))
      << result.output;
  EXPECT_EQ(readFile(inside), before);

  // --json onto a dump file.
  result = simRun(bundle + " --backend cpu --steps 2 --dump " + sub +
                  "/d --json " + sub + "/d/V.npy");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output, "is also the file of --json"))
      << result.output;
  EXPECT_FALSE(exists(sub + "/d"));

  // --json onto a directory, --dump onto a file.
  result = simRun(bundle + " --backend cpu --json " + sub);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "--json: '" + sub + "' is a directory, not a file"))
      << result.output;
  result = simRun(bundle + " --backend cpu --dump " + inside);
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(
      contains(result.output, "--dump: '" + inside + "' is not a directory"))
      << result.output;
}

TEST_F(SimRun, ReplacesSymlinksAtOutputPathsInsteadOfFollowingThem) {
  std::string sub = dir + "/links";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  std::string target = sub + "/precious";
  writeFile(target, "precious");
  std::string json = sub + "/run.json", dump = sub + "/dump";
  ASSERT_EQ(mkdir(dump.c_str(), 0755), 0);
  ASSERT_EQ(symlink(target.c_str(), json.c_str()), 0);
  ASSERT_EQ(symlink(target.c_str(), (dump + "/X.npy").c_str()), 0);
  Result result = simRun(bundle + " --backend cpu --steps 3 --json " + json +
                         " --dump " + dump);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(readFile(target), "precious");
  struct stat info;
  for (std::string path : {json, dump + "/X.npy"}) {
    ASSERT_EQ(lstat(path.c_str(), &info), 0);
    EXPECT_TRUE(S_ISREG(info.st_mode)) << path;
  }
  EXPECT_EQ(readJson(json)["steps"], 3);
  EXPECT_TRUE(contains(readFile(dump + "/X.npy"), "'shape': (100,)"));
}

TEST_F(SimRun, KeepsHostileBufferNamesInsideTheDumpFolder) {
  struct Case {
    std::string x, v;
    /// The file-name stems of X and V.
    std::string xStem, vStem;
  } cases[] = {
      {"../../x", "a/b", "%2E.%2F..%2Fx", "a%2Fb"},
      {".hidden", "\x01\xff\xfe", "%2Ehidden", "%01%FF%FE"},
      // X.reference's files would collide with X's reference file.
      {"q", "q.reference", "q", "q.reference-2"},
  };
  int n = 0;
  for (const Case &c : cases) {
    std::string sub = dir + "/hostile" + std::to_string(n++);
    ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
    std::string named = sub + "/named.simb";
    writeFile(named, decayBundleNamed(c.x, c.v));
    std::string dump = sub + "/deep/dump", json = sub + "/run.json";
    Result result = simRun("'" + named +
                           "' --backend cpu --steps 9 --reference exact "
                           "--check --dump " +
                           dump + " --json " + json);
    ASSERT_EQ(result.status, 0) << c.x << ": " << result.output;
    // Only the expected files, in the folder, and nothing beside it.
    std::vector<std::string> expected = {
        c.xStem + ".check.npy", c.xStem + ".npy", c.xStem + ".reference.npy",
        c.vStem + ".check.npy", c.vStem + ".npy"};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(listDirectory(dump), expected) << c.x;
    EXPECT_EQ(listDirectory(sub + "/deep"), std::vector<std::string>{"dump"});
    EXPECT_EQ(listDirectory(sub),
              (std::vector<std::string>{"deep", "named.simb", "run.json"}));
    EXPECT_FALSE(exists(dir + "/x.npy"));
    // The files hold the values: X after 9 base steps.
    EXPECT_NEAR(f64At(npyData(readFile(dump + "/" + c.xStem + ".npy")), 5),
                1.05 * std::pow(0.98, 9), 1e-12);
    // Valid JSON (invalid UTF-8 replaced), and where each buffer went.
    Json metrics = readJson(json);
    const Json &files = metrics["dump"]["files"];
    ASSERT_EQ(files.size(), 2u);
    EXPECT_EQ(files[0]["state"], c.xStem + ".npy");
    EXPECT_EQ(files[1]["state"], c.vStem + ".npy");
    EXPECT_EQ(files[1]["reference"], nullptr);
    EXPECT_EQ(metrics["check"]["pass"], true);
  }
  Json metrics = readJson(dir + "/hostile1/run.json");
  EXPECT_EQ(metrics["dump"]["files"][1]["buffer"],
            "\x01\xEF\xBF\xBD\xEF\xBF\xBD"); // U+FFFD twice
}

TEST_F(SimRun, StopsOnSigintAndWritesWhatIsComplete) {
  std::string sub = dir + "/sigint";
  std::string dump = sub + "/dump", json = sub + "/run.json";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  ASSERT_EQ(mkdir(dump.c_str(), 0755), 0);
  // Stale files of an earlier run, that this one will not write again.
  writeFile(dump + "/X.reference.npy", "stale");
  writeFile(dump + "/X.check.npy", "stale");
  writeFile(json, "stale");
  // k = 1e-6: X decays by 1 - 1e-8 per base step, still readable after
  // many.
  pid_t pid = spawnSimRun(SIM_RUN_PATH,
                          {bundle, "--backend", "cpu", "--strategy", "simple",
                           "--steps", "1000000000", "--set", "k=0.000001",
                           "--reference", "simple", "--check", "--dump", dump,
                           "--json", json, "--progress"},
                          sub + "/stdout", sub + "/stderr");
  ASSERT_GT(pid, 0);
  // The progress line (after 1 s; --progress, since stderr is a file): the
  // run is under way.
  ASSERT_TRUE(waitForText(sub + "/stderr", "base step"))
      << readFile(sub + "/stderr");
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);

  std::string out = readFile(sub + "/stdout");
  EXPECT_TRUE(contains(readFile(sub + "/stderr"),
                       "sim-run: interrupted by SIGINT; wrote what was "
                       "complete\n"));
  Json metrics = readJson(json);
  EXPECT_EQ(metrics["interrupted"], true);
  const Json &interruption = metrics["interruption"];
  EXPECT_EQ(interruption["signal"], "SIGINT");
  EXPECT_EQ(interruption["during"], "run");
  EXPECT_EQ(interruption["of"], 1000000000);
  EXPECT_EQ(interruption["skipped"], Json::array({"reference", "check"}));
  int64_t reached = interruption["base_step"];
  EXPECT_GT(reached, 0);
  EXPECT_LT(reached, 1 << 24);
  EXPECT_EQ(metrics["steps"], 1000000000);
  EXPECT_EQ(metrics["steps_done"], reached);
  // The counters cover the base steps done (simple: one per big step).
  EXPECT_EQ(metrics["big_steps"], reached);
  EXPECT_EQ(metrics["evaluations"]["Decay"], 100 * reached);
  EXPECT_TRUE(metrics["check"].is_null());
  EXPECT_EQ(metrics["error"], Json::object());
  EXPECT_TRUE(contains(out, "interrupted at base step " +
                                std::to_string(reached) + " of 1000000000\n"))
      << out;
  EXPECT_TRUE(contains(out, "error vs simple  not run (interrupted)")) << out;
  EXPECT_TRUE(contains(out, "check against the reference executor (strategy "
                            "simple, group size 32, 1000000000 base steps): "
                            "not run (interrupted)"))
      << out;
  EXPECT_FALSE(contains(out, "check: ")) << out;

  // The dump is the state at the base step reached: V's lane 0 counts
  // base steps.
  std::string v = npyData(readFile(dump + "/V.npy"));
  for (size_t item = 0; item < 100; ++item)
    ASSERT_EQ(f32At(v, item * 3), float(reached)) << item;
  double x5 = f64At(npyData(readFile(dump + "/X.npy")), 5);
  EXPECT_NEAR(x5 / (1.05 * std::pow(1 - 1e-8, double(reached))), 1, 1e-9);
  // No stale or temporary file.
  EXPECT_EQ(listDirectory(dump), (std::vector<std::string>{"V.npy", "X.npy"}));
  EXPECT_EQ(listDirectory(sub),
            (std::vector<std::string>{"dump", "run.json", "stderr", "stdout"}));
}

TEST_F(SimRun, KeepsTheOutputTimesAndACheckpointOnSigint) {
  std::string sub = dir + "/sigint-output";
  std::string npz = sub + "/series.npz", json = sub + "/run.json",
              checkpoint = sub + "/run.simc";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  pid_t pid = spawnSimRun(
      SIM_RUN_PATH,
      {bundle, "--backend", "cpu", "--strategy", "hip", "--steps", "1000000000",
       "--set", "k=0.000001", "--output-every", "1000", "--output", npz,
       "--checkpoint", checkpoint, "--json", json, "--progress"},
      sub + "/stdout", sub + "/stderr");
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(sub + "/stderr", "base step"))
      << readFile(sub + "/stderr");
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);

  Json metrics = readJson(json);
  EXPECT_EQ(metrics["interruption"]["during"], "run");
  int64_t reached = metrics["steps_done"];
  std::vector<int64_t> times = metrics["output"]["times"];
  ASSERT_GE(times.size(), 2u);
  for (size_t k = 0; k < times.size(); ++k)
    ASSERT_EQ(times[k], int64_t(k) * 1000);
  EXPECT_LE(times.back(), reached);
  EXPECT_GT(times.back() + 1000, reached);
  EXPECT_EQ(metrics["totals_per_output_time"].size(), times.size());
  // The checkpoint holds where the run stopped.
  EXPECT_EQ(metrics["checkpoint"]["base_step"], reached);

  // The .npz holds the output times completed: t, and V, whose lane 0
  // counts base steps, at each.
  std::map<std::string, std::string> entries = readNpz(npz);
  ASSERT_EQ(entries.count("t.npy"), 1u) << entries.size();
  std::string t = npyData(entries["t.npy"]);
  ASSERT_EQ(t.size(), times.size() * 8);
  for (size_t k = 0; k < times.size(); ++k) {
    int64_t at;
    std::memcpy(&at, t.data() + 8 * k, 8);
    EXPECT_EQ(at, times[k]);
  }
  std::string v = entries["buffer/V.npy"];
  EXPECT_EQ(npyShape(v), "(" + std::to_string(times.size()) + ", 100, 3)");
  EXPECT_TRUE(contains(v, "'descr': '<f4'"));
  std::string values = npyData(v);
  for (size_t k = 0; k < times.size(); ++k)
    ASSERT_EQ(f32At(values, k * 300 + 3 * 99), float(times[k])) << k;
  EXPECT_EQ(npyShape(entries["buffer/X.npy"]),
            "(" + std::to_string(times.size()) + ", 100)");
  for (const char *key :
       {"time.npy", "meta/scene.npy", "meta/strategy.npy", "meta/backend.npy"})
    EXPECT_EQ(entries.count(key), 1u) << key;
  EXPECT_EQ(entries.size(), 7u);
  // No temporary file.
  EXPECT_EQ(listDirectory(sub),
            (std::vector<std::string>{"run.json", "run.simc", "series.npz",
                                      "stderr", "stdout"}));

  // The checkpoint continues the run: V counts every base step.
  std::string restarted = sub + "/restarted";
  Result more = simRun(bundle + " --backend cpu --strategy hip --set " +
                       "k=0.000001 --restart " + checkpoint + " --steps " +
                       std::to_string(reached + 10) + " --dump " + restarted +
                       " --checkpoint " + checkpoint);
  ASSERT_EQ(more.status, 0) << more.output;
  EXPECT_TRUE(contains(more.output, "restarted from checkpoint '" + checkpoint +
                                        "' at base step " +
                                        std::to_string(reached)))
      << more.output;
  std::string after = npyData(readFile(restarted + "/V.npy"));
  EXPECT_EQ(f32At(after, 0), float(reached + 10));
}

TEST_F(SimRun, ChecksCheckpointsAndOutputsBeforeRunning) {
  std::string sub = dir + "/checkpoint-usage";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  std::string checkpoint = sub + "/a.simc", json = sub + "/run.json";
  Result made = simRun(bundle + " --backend cpu --steps 20 --set k=1.5 " +
                       "--checkpoint " + checkpoint);
  ASSERT_EQ(made.status, 0) << made.output;
  EXPECT_TRUE(contains(made.output, "checkpoint       " + checkpoint +
                                        " at base step 20 (1 written)"))
      << made.output;

  struct Case {
    std::string args;
    int status;
    std::string message;
  } cases[] = {
      // A checkpoint of other settings, strategy or time, refused before
      // anything runs.
      {"--set k=1.5 --restart " + checkpoint + " --strategy simple", 1,
       "sim-run: error: --restart: checkpoint '" + checkpoint +
           "' was written under strategy 'hip', this session runs "
           "'simple'"},
      {"--restart " + checkpoint, 1,
       "was written with k = 1.5, this session has k = 2"},
      {"--set k=1.5 --restart " + checkpoint + " --steps 10", 2,
       "--restart: checkpoint '" + checkpoint +
           "' is at base step 20, past --steps 10"},
      {"--set k=1.5 --restart " + bundle, 1,
       "it is a bundle, not a "
       "checkpoint"},
      {"--restart " + sub + "/missing.simc", 2,
       "cannot read the --restart checkpoint"},
      // Outputs never land on an input, the restart file included (but the
      // checkpoint may replace it: that is what it is for).
      {"--output-every 5 --output " + bundle, 2,
       "--output: '" + bundle + "' is the input"},
      {"--set k=1.5 --restart " + checkpoint + " --output-every 5 --output " +
           checkpoint,
       2, "--output: '" + checkpoint + "' is the input"},
      {"--output-every 5 --output " + sub + "/o --checkpoint " + sub + "/o", 2,
       "--checkpoint: '" + sub + "/o' is also the file of --output"},
      {"--checkpoint " + sub, 2, "is a directory, not a file"},
  };
  for (const Case &c : cases) {
    Result result =
        simRun(bundle + " --backend cpu " + c.args + " --json " + json);
    EXPECT_EQ(result.status, c.status) << c.args << "\n" << result.output;
    EXPECT_TRUE(contains(result.output, c.message)) << c.args << "\n"
                                                    << result.output;
    EXPECT_FALSE(exists(json)) << c.args;
  }
  // The checkpoint replaces the one the run restarted from.
  Result again =
      simRun(bundle + " --backend cpu --set k=1.5 --steps 30 " + "--restart " +
             checkpoint + " --checkpoint " + checkpoint + " --json " + json);
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(readJson(json)["checkpoint"]["base_step"], 30);
  EXPECT_EQ(readJson(json)["restart"]["base_step"], 20);
}

TEST_F(SimRun, StopsOnSigterm) {
  std::string sub = dir + "/sigterm", json = sub + "/run.json";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  pid_t pid = spawnSimRun(SIM_RUN_PATH,
                          {bundle, "--backend", "cpu", "--steps", "1000000000",
                           "--repeat", "2", "--json", json, "--progress"},
                          sub + "/stdout", sub + "/stderr");
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(waitForText(sub + "/stderr", "warm-up: base step"))
      << readFile(sub + "/stderr");
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  int status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 143);
  Json metrics = readJson(json);
  EXPECT_EQ(metrics["interrupted"], true);
  EXPECT_EQ(metrics["interruption"]["signal"], "SIGTERM");
  EXPECT_EQ(metrics["interruption"]["during"], "warm-up");
  EXPECT_EQ(metrics["interruption"]["run"], 0);
  EXPECT_EQ(metrics["wall_seconds_runs"], Json::array());
  EXPECT_TRUE(contains(readFile(sub + "/stdout"), "(in the warm-up)"));

  // A bundle is a regular file: a FIFO (or a device) is refused before
  // anything is read from it.
  std::string fifo = sub + "/slow.simb";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  Result refused = simRun(fifo + " --json " + sub + "/early.json");
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_TRUE(contains(refused.output, "it is not a regular file"))
      << refused.output;
  EXPECT_FALSE(exists(sub + "/early.json"));
}

TEST_F(SimRun, TakesTwoSignalsAtOnceAsOneRequest) {
  // GNU timeout sends SIGTERM to sim-run and then to its process group: one
  // request, which must still end with the checkpoint and the JSON. So that
  // the second one surely comes while sim-run is still at work, its output
  // rows go to a FIFO (of one page) that nobody reads until both were sent:
  // sim-run waits in a write, with the first signal recorded.
  std::string sub = dir + "/sigterm-twice", json = sub + "/run.json",
              checkpoint = sub + "/run.simc", fifo = sub + "/stdout";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  // Opened first (without waiting for a writer), so that sim-run's open
  // for writing does not wait.
  int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  ASSERT_GE(reader, 0);
  fcntl(reader, F_SETPIPE_SZ, 4096);
  pid_t pid = spawnSimRun(SIM_RUN_PATH,
                          {bundle, "--backend", "cpu", "--steps", "100000",
                           "--output-every", "1", "--checkpoint", checkpoint,
                           "--json", json},
                          fifo, sub + "/stderr");
  ASSERT_GT(pid, 0);
  // Full: what is there stops growing.
  int queued = -1, before = -2;
  for (int i = 0; i < 600 && (queued != before || queued < 2048); ++i) {
    before = queued;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    ASSERT_EQ(ioctl(reader, FIONREAD, &queued), 0);
  }
  ASSERT_GE(queued, 2048);
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  // Read the rows until sim-run closes its end.
  fcntl(reader, F_SETFL, 0);
  std::string out;
  char chunk[4096];
  ssize_t n;
  while ((n = read(reader, chunk, sizeof chunk)) > 0)
    out.append(chunk, size_t(n));
  close(reader);
  int status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_TRUE(contains(out, "interrupted at base step")) << out;
  EXPECT_TRUE(contains(readFile(sub + "/stderr"),
                       "sim-run: interrupted by SIGTERM; wrote what was "
                       "complete\n"))
      << readFile(sub + "/stderr");
  Json metrics = readJson(json);
  EXPECT_EQ(metrics["interruption"]["signal"], "SIGTERM");
  EXPECT_EQ(metrics["checkpoint"]["base_step"], metrics["steps_done"]);
  EXPECT_TRUE(exists(checkpoint));
}

TEST_F(SimRun, RefusesAJsonOfMoreOutputTimesThanMemoryHolds) {
  // --json holds every output time's time and totals until the end: 10^12
  // of them do not fit, and nothing runs (a run that started would grow
  // until the memory ran out).
  std::string sub = dir + "/json-memory", json = sub + "/run.json";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  pid_t pid =
      spawnSimRun(SIM_RUN_PATH,
                  {bundle, "--backend", "cpu", "--steps", "1000000000000",
                   "--output-every", "1", "--json", json},
                  sub + "/stdout", sub + "/stderr");
  ASSERT_GT(pid, 0);
  int status = waitFor(pid, 30);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::string err = readFile(sub + "/stderr");
  EXPECT_TRUE(contains(err, "sim-run: error: --json: 1000000000001 output "
                            "times of "))
      << err;
  EXPECT_TRUE(contains(err, "choose a larger --output-every")) << err;
  EXPECT_FALSE(exists(json));
  EXPECT_EQ(readFile(sub + "/stdout"), "");
}

TEST_F(SimRun, FailsWhenItCannotWriteItsReportButWritesItsFiles) {
  std::string sub = dir + "/stdout-gone";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  // A full disk: the report is lost, so the run is not a success.
  pid_t pid = spawnSimRun(SIM_RUN_PATH, {bundle, "--backend", "cpu"},
                          "/dev/full", sub + "/full.err");
  ASSERT_GT(pid, 0);
  int status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_TRUE(contains(readFile(sub + "/full.err"),
                       "sim-run: error: cannot write to standard output"))
      << readFile(sub + "/full.err");
  // A closed standard output (`>&-`), which no file sim-run opens may take.
  Result closed = shell("{ " + std::string(SIM_RUN_PATH) + " " + bundle +
                        " --backend cpu >&-; }");
  EXPECT_EQ(closed.status, 1) << closed.output;
  EXPECT_TRUE(contains(closed.output, "cannot write to standard output: it "
                                      "is closed"))
      << closed.output;
  // A reader that stopped reading (`| head`): the run goes on and its
  // files are written; before, SIGPIPE killed it at its first row.
  int pipeEnds[2];
  ASSERT_EQ(pipe(pipeEnds), 0);
  close(pipeEnds[0]);
  std::string npz = sub + "/rows.npz", json = sub + "/run.json",
              checkpoint = sub + "/run.simc";
  std::vector<std::string> all = {
      SIM_RUN_PATH,     bundle,    "--backend", "cpu", "--steps", "20",
      "--output-every", "1",       "--output",  npz,   "--json",  json,
      "--checkpoint",   checkpoint};
  std::vector<char *> argv;
  for (std::string &arg : all)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  std::string err = sub + "/pipe.err";
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t defaults;
  sigemptyset(&defaults);
  sigaddset(&defaults, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  ASSERT_EQ(posix_spawn(&pid, SIM_RUN_PATH, &actions, &attributes, argv.data(),
                        environ),
            0);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  close(pipeEnds[1]);
  status = waitFor(pid);
  ASSERT_TRUE(WIFEXITED(status)) << status;
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_TRUE(contains(readFile(err),
                       "cannot write to standard output: its reader "
                       "stopped reading"))
      << readFile(err);
  EXPECT_FALSE(readNpz(npz).empty()) << readFile(err);
  EXPECT_EQ(readJson(json)["steps"], 20);
  EXPECT_TRUE(exists(checkpoint));
  // A checkpoint that does not fit (a file size limit here) is named by
  // its path, not by the descriptor sim-run wrote it through (the limit
  // leaves room for the kernel objects, not for 10^6 items of state); the
  // report is written all the same.
  std::string big = sub + "/big.simc";
  Result tooLarge =
      shell("ulimit -f 20000; trap '' XFSZ; " + std::string(SIM_RUN_PATH) +
            " " + bundle +
            " --backend cpu --steps 2 --set range=1000000 --checkpoint " + big);
  EXPECT_EQ(tooLarge.status, 1) << tooLarge.output;
  EXPECT_TRUE(contains(tooLarge.output, "--checkpoint: checkpoint '" + big +
                                            "' of base step 2 was not "
                                            "written: File too large"))
      << tooLarge.output;
  EXPECT_TRUE(contains(tooLarge.output, "base step 2 not written: File too "
                                        "large"))
      << tooLarge.output;
  EXPECT_FALSE(exists(big));
}

TEST_F(SimRun, RemovesTheTemporaryBundleOnSignals) {
  std::string sub = dir + "/translate-signal";
  std::string tools = sub + "/tools", tmp = sub + "/tmp";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  ASSERT_EQ(mkdir(tools.c_str(), 0755), 0);
  ASSERT_EQ(mkdir(tmp.c_str(), 0755), 0);
  std::string simRun = tools + "/sim-run";
  ASSERT_EQ(shell("cp " + std::string(SIM_RUN_PATH) + " " + simRun).status, 0);
  std::string scene = sub + "/scene.mlir";
  writeFile(scene, "// a scene\n");
  std::string pidFile = sub + "/translate.pid";
  std::string translate = tools + "/sim-translate";
  std::vector<std::string> env = {"TMPDIR=" + tmp, "PATH=/nonexistent"};

  // sim-translate takes long; the first SIGINT reaches it too.
  writeFile(translate,
            "#!/bin/sh\necho $$ > '" + pidFile + "'\nexec sleep 30\n");
  chmod(translate.c_str(), 0755);
  pid_t pid = spawnSimRun(simRun, {scene, "--json", sub + "/run.json"},
                          sub + "/stdout", sub + "/stderr", env);
  ASSERT_TRUE(waitForText(pidFile, "\n"));
  EXPECT_EQ(listDirectory(tmp).size(), 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = waitFor(pid, 20);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_TRUE(contains(readFile(sub + "/stderr"),
                       "sim-run: interrupted by SIGINT while translating '" +
                           scene + "'; nothing was run"))
      << readFile(sub + "/stderr");
  EXPECT_EQ(listDirectory(tmp), std::vector<std::string>{});
  EXPECT_FALSE(exists(sub + "/run.json"));

  // One that ignores the signal: a second SIGINT kills sim-run, which
  // removes the temporary bundle first; but not one within the second
  // after the first, which is the same request sent twice.
  unlink(pidFile.c_str());
  writeFile(translate, "#!/bin/sh\ntrap '' INT TERM\necho $$ > '" + pidFile +
                           "'\nexec sleep 30\n");
  pid = spawnSimRun(simRun, {scene}, sub + "/stdout", sub + "/stderr", env);
  ASSERT_TRUE(waitForText(pidFile, "\n"));
  EXPECT_EQ(listDirectory(tmp).size(), 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  ASSERT_EQ(kill(pid, SIGINT), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  ASSERT_EQ(kill(pid, SIGTERM), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(waitpid(pid, &status, WNOHANG), 0) << "killed within the grace";
  EXPECT_EQ(listDirectory(tmp).size(), 1u);
  std::this_thread::sleep_for(std::chrono::milliseconds(1000));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  status = waitFor(pid, 20);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGINT) << status;
  EXPECT_EQ(listDirectory(tmp), std::vector<std::string>{});
  kill(std::stoi(readFile(pidFile)), SIGKILL);
}

//===----------------------------------------------------------------------===//
// Progress, warnings and compile-time settings
//===----------------------------------------------------------------------===//

namespace {

/// A long run of the decay scene (k = 1e-6 keeps X readable).
std::vector<std::string> longRun(const std::string &bundle) {
  return {bundle,    "--backend",  "cpu",   "--strategy", "simple",
          "--steps", "1000000000", "--set", "k=0.000001"};
}

} // namespace

TEST_F(SimRun, ShowsProgressOnATerminalWithinASecond) {
  std::string sub = dir + "/pty";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  int master = posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(grantpt(master), 0);
  ASSERT_EQ(unlockpt(master), 0);
  std::string terminal = ptsname(master);
  // stderr on the pseudo-terminal, stdout in a file.
  auto start = std::chrono::steady_clock::now();
  pid_t pid =
      spawnSimRun(SIM_RUN_PATH, longRun(bundle), sub + "/stdout", terminal);
  ASSERT_GT(pid, 0);
  fcntl(master, F_SETFL, fcntl(master, F_GETFL) | O_NONBLOCK);
  // Read until the line has appeared and been rewritten for a while (or
  // 20 s have passed).
  std::string seen;
  double appeared = -1, now = 0;
  while (now < 20 && (appeared < 0 || now < appeared + 0.7)) {
    char chunk[4096];
    ssize_t n = read(master, chunk, sizeof chunk);
    if (n > 0)
      seen.append(chunk, size_t(n));
    now =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    if (appeared < 0 && contains(seen, "base steps/s, ETA "))
      appeared = now;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = waitFor(pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << status;
  close(master);
  ASSERT_GE(appeared, 0) << seen;
  // After the first second of the run, with the sessions made and the
  // init check done before it: well within three.
  EXPECT_GE(appeared, 1.0) << seen;
  EXPECT_LT(appeared, 3.0) << seen;
  EXPECT_TRUE(contains(seen, "\rsim-run: base step ")) << seen;
  EXPECT_TRUE(contains(seen, " of 1000000000 (0%), ")) << seen;
  EXPECT_TRUE(contains(seen, "\033[K")) << seen;
}

TEST_F(SimRun, PrintsNoProgressWhenStderrIsAFile) {
  std::string sub = dir + "/quiet";
  ASSERT_EQ(mkdir(sub.c_str(), 0755), 0);
  pid_t pid = spawnSimRun(SIM_RUN_PATH, longRun(bundle), sub + "/stdout",
                          sub + "/stderr");
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(2500));
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = waitFor(pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 130) << status;
  std::string err = readFile(sub + "/stderr");
  EXPECT_FALSE(contains(err, "base step")) << err;
  EXPECT_FALSE(contains(err, "\r")) << err;
  // What it does say: the init check's warning and the interruption.
  EXPECT_TRUE(contains(err, "sim-run: warning: the init of buffer 'V'")) << err;
  EXPECT_TRUE(contains(err, "sim-run: interrupted by SIGINT")) << err;
}

TEST_F(SimRun, WarnsAboutNonFiniteResultsAndExitsWithStatus3) {
  std::string json = dir + "/nonfinite.json", dump = dir + "/nonfinite";
  Result result = simRun(bundle +
                         " --backend cpu --strategy simple --steps 20 "
                         "--set poison=4 --json " +
                         json + " --dump " + dump);
  EXPECT_EQ(result.status, 3) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "sim-run: warning: buffer 'X' holds 1 NaN or infinite "
                       "value at the end of the run (the first: nan at item "
                       "7)\n"))
      << result.output;
  EXPECT_TRUE(contains(result.output,
                       "sim-run: error: the run ended with NaN or infinite "
                       "values (--check-finite stops at the first and says "
                       "where it appeared)"))
      << result.output;
  // The report and the files are there all the same.
  EXPECT_TRUE(contains(result.output, "big steps        20")) << result.output;
  EXPECT_TRUE(exists(dump + "/X.npy"));
  Json metrics = readJson(json);
  EXPECT_EQ(metrics["non_finite"]["buffers"],
            Json::parse(R"({"X": {"count": 1, "item": 7, "lane": 0}})"));
  EXPECT_EQ(metrics["non_finite"]["totals"], Json::array());

  // Without NaN: an empty list, and status 0.
  result = simRun(bundle + " --backend cpu --steps 20 --json " + json);
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_EQ(readJson(json)["non_finite"],
            Json::parse(R"({"buffers": {}, "totals": []})"));
  // --check fails first: status 1.
  result = simRun(bundle + " --backend cpu --strategy simple --steps 20 "
                           "--set poison=4 --check");
  EXPECT_EQ(result.status, 1) << result.output;
}

TEST_F(SimRun, WarnsAboutAnInitThatDisagreesWithItsWriter) {
  std::string json = dir + "/init.json";
  Result result = simRun(bundle + " --backend cpu --steps 3 --json " + json);
  ASSERT_EQ(result.status, 0) << result.output;
  // V's lane 2 counts evaluations, also one with n = 0.
  EXPECT_TRUE(contains(result.output,
                       "sim-run: warning: the init of buffer 'V' disagrees "
                       "with its writer 'Grow' evaluated with n = 0 at t = 0\n"
                       "  largest difference 1.000e+00 at item 0, lane 2 "
                       "(init 0.000000000e+00, evaluate 1.000000000e+00); 100 "
                       "of 300 values differ by more than 1.0e-05 of the "
                       "largest, 9.900e+01\n"))
      << result.output;
  EXPECT_FALSE(contains(result.output, "init of buffer 'X'")) << result.output;
  Json check = readJson(json)["init_check"];
  EXPECT_EQ(check["ran"], true);
  EXPECT_EQ(check["items"], 100);
  EXPECT_EQ(check["buffers"]["X"]["consistent"], true);
  EXPECT_EQ(check["buffers"]["X"]["component"], "Decay");
  EXPECT_EQ(check["buffers"]["V"]["consistent"], false);
  EXPECT_EQ(check["buffers"]["V"]["count"], 100);
  EXPECT_EQ(check["buffers"]["V"]["item"], 0);
  EXPECT_EQ(check["buffers"]["V"]["lane"], 2);

  // --no-init-check: no check, no warning, and the JSON says why.
  result = simRun(bundle + " --backend cpu --steps 3 --no-init-check --json " +
                  json);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_FALSE(contains(result.output, "init of buffer")) << result.output;
  EXPECT_FALSE(contains(result.output, "init check")) << result.output;
  EXPECT_EQ(readJson(json)["init_check"]["skipped"], "--no-init-check");

  // One item of X off by 1e-6.
  std::string wrong = dir + "/wrong-init.simb";
  writeFile(wrong, serialize(decayContents(false, true,
                                           SIM_TEST_DECAY_REFERENCE_WRONG_SO)));
  result = simRun(wrong + " --backend cpu --steps 3");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "sim-run: warning: the init of buffer 'X' disagrees "
                       "with its writer 'Decay' evaluated with n = 0 at t = 0\n"
                       "  largest difference 1.000e-06 at item 3 (init "
                       "1.030000000e+00, evaluate 1.030001000e+00); 1 of 100 "
                       "values differ by more than 1.0e-12 of the largest, "
                       "1.990e+00\n"))
      << result.output;

  // A large range: part of it, and it says so.
  result = simRun(bundle + " --backend cpu --steps 1 --set range=100000");
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "sim-run: note: the init check evaluated 65536 of the "
                       "100000 items (the first 32768 and the last 32768)\n"))
      << result.output;

  // Without reference functions there is nothing to check with.
  std::string bare = dir + "/bare.simb";
  writeFile(bare, decayBundle(false, false));
  result = simRun(bare + " --backend cpu --steps 3 --json " + json);
  ASSERT_EQ(result.status, 0) << result.output;
  EXPECT_FALSE(contains(result.output, "init")) << result.output;
  EXPECT_EQ(readJson(json)["init_check"],
            Json::parse(R"({"ran": false, "skipped":
                            "the bundle has no reference functions"})"));
}

TEST_F(SimRun, TakesMaxStepsOnlyWhereItCanBeCompiledIn) {
  // A bundle has max_steps compiled in: only its own value goes.
  Result result = simRun(bundle + " --backend cpu --set max_steps=6");
  EXPECT_EQ(result.status, 2) << result.output;
  EXPECT_TRUE(contains(result.output,
                       "sim-run: error: --set max_steps=6: max_steps is fixed "
                       "when a scene is compiled (bundle '" +
                           bundle +
                           "' has 4): compile the scene with sim-translate "
                           "--sim-to-bundle --sim-set-params=max_steps=6, or "
                           "give sim-run the .mlir scene (see sim-run "
                           "--help)"))
      << result.output;
  result = simRun(bundle + " --backend cpu --steps 3 --set max_steps=4");
  EXPECT_EQ(result.status, 0) << result.output;

  // A .mlir scene is compiled with it: a stand-in sim-translate records
  // its arguments (the bundle it copies has max_steps 4, which a session
  // given max_steps=6 would refuse).
  auto [simRun, scene, args] = standInTranslate("compile-time");
  result = shell("PATH=/nonexistent " + simRun + " " + scene +
                 " --backend cpu --steps 4 --set max_steps=6 --set k=1");
  EXPECT_EQ(result.status, 0) << result.output;
  std::string given = readFile(args);
  EXPECT_TRUE(contains(given, " --sim-to-bundle -o ")) << given;
  EXPECT_TRUE(contains(given, " --sim-set-params=max_steps=6\n")) << given;
  EXPECT_FALSE(contains(given, "k=1")) << given;
  // Without one, the translation is as before.
  result = shell("PATH=/nonexistent " + simRun + " " + scene +
                 " --backend cpu --steps 4");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_FALSE(contains(readFile(args), "--sim-set-params")) << readFile(args);
}

TEST_F(SimRun, TranslatesOnlyTheStrategiesItRuns) {
  StandIn standIn = standInTranslate("strategies");
  auto translatedFor = [&](const std::string &options) {
    Result result =
        shell("PATH=/nonexistent " + standIn.simRun + " " + standIn.scene +
              " --backend cpu --steps 4 " + options);
    EXPECT_EQ(result.status, 0) << options << "\n" << result.output;
    return readFile(standIn.args);
  };
  // --strategy names the one strategy to compile.
  std::string given = translatedFor("--strategy hip");
  EXPECT_TRUE(contains(given, " --sim-strategies=hip\n")) << given;
  // --reference simple runs simple too.
  given = translatedFor("--strategy hip --reference simple");
  EXPECT_TRUE(contains(given, " --sim-strategies=simple,hip\n")) << given;
  given = translatedFor("--strategy simple --reference simple");
  EXPECT_TRUE(contains(given, " --sim-strategies=simple\n")) << given;
  // Without --strategy hip runs (as it would from a bundle of every
  // strategy), and only hip is compiled.
  given = translatedFor("");
  EXPECT_TRUE(contains(given, " --sim-strategies=hip\n")) << given;
  given = translatedFor("--reference simple");
  EXPECT_TRUE(contains(given, " --sim-strategies=simple,hip\n")) << given;
}

TEST(Dependencies, NoMlirLlvmOrCuda) {
  // The runtime must run where only libc and libstdc++ are installed.
  for (const char *binary : {SIM_RUN_PATH, SIM_RUNTIME_LIBRARY}) {
    Result result = shell(std::string("ldd ") + binary);
    if (result.status != 0)
      GTEST_SKIP() << "ldd is not available: " << result.output;
    for (const char *library : {"MLIR", "LLVM", "libcuda", "libcudart"})
      EXPECT_FALSE(contains(result.output, library))
          << binary << " links " << library << ":\n"
          << result.output;
  }
}
