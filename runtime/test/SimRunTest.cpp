//===- SimRunTest.cpp - the sim-run tool ----------------------------------===//
//
// Runs the sim-run binary as a user would: help, usage errors, a run with
// its table, the reference, .npy dumps, JSON, the NaN check, .mlir input
// through sim-translate, and the libraries it links.
//
//===----------------------------------------------------------------------===//

#include "TestBundle.h"
#include "TestUtil.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <dirent.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

using namespace sim::test;

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

class SimRun : public ::testing::Test {
protected:
  static void SetUpTestSuite() {
    dir = makeTempDir();
    bundle = dir + "/decay.simb";
    writeFile(bundle, decayBundle());
  }
  static void TearDownTestSuite() { shell("rm -rf '" + dir + "'"); }

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
        "--dump DIR", "--json FILE", "--check-finite"})
    EXPECT_TRUE(contains(result.output, option)) << option;
}

TEST_F(SimRun, RejectsBadUsage) {
  struct Case {
    std::string args, message;
  } cases[] = {
      {"", "sim-run: error: no input scene (see sim-run --help)"},
      {bundle + " --fast", "unknown option '--fast'"},
      {bundle + " --steps x", "--steps expects an integer >= 0, not 'x'"},
      {bundle + " --repeat 0", "--repeat expects an integer >= 1"},
      {bundle + " --strategy best", "unknown strategy 'best'"},
      {bundle + " --backend tpu", "unknown backend 'tpu'"},
      {bundle + " --set k", "--set expects NAME=VALUE, not 'k'"},
      {bundle + " --reference cubic", "--reference expects simple or exact"},
      {bundle + " --steps", "--steps expects a value"},
      {bundle + " --check-finite=yes", "--check-finite takes no value"},
      {bundle + " --check-tolerance 1e-3", "--check-tolerance needs --check"},
      {bundle + " --check --check-tolerance -1",
       "--check-tolerance expects a positive number, not '-1'"},
      {bundle + " other.simb", "more than one input"},
  };
  for (const Case &c : cases) {
    Result result = simRun(c.args);
    EXPECT_EQ(result.status, 2) << c.args << ": " << result.output;
    EXPECT_TRUE(contains(result.output, c.message))
        << c.args << ": " << result.output;
  }
}

TEST_F(SimRun, RunsAndPrintsTheTable) {
  Result result =
      simRun(bundle + " --backend cpu --steps 25 --threads 2 --set k=1");
  ASSERT_EQ(result.status, 0) << result.output;
  const std::string &out = result.output;
  EXPECT_TRUE(
      contains(out, "scene decay, strategy hip, backend cpu: CPU (2 threads)"))
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
  double x5;
  std::memcpy(&x5, x.data() + 10 + headerLength + 5 * 8, 8);
  EXPECT_NEAR(x5, 1.05 * std::pow(0.98, 7), 1e-12);

  std::string v = readFile(out + "/V.npy");
  size_t vHeader = uint8_t(v[8]) | uint8_t(v[9]) << 8;
  EXPECT_TRUE(contains(v.substr(10, vHeader),
                       "{'descr': '<f4', 'fortran_order': False, 'shape': "
                       "(100, 3), }"));
  EXPECT_EQ(v.size(), 10 + vHeader + 100 * 3 * 4);
  EXPECT_TRUE(contains(readFile(out + "/X.reference.npy"), "'shape': (100,)"));

  // Only the finished files: no temporaries left behind.
  std::vector<std::string> names;
  DIR *listing = opendir(out.c_str());
  ASSERT_NE(listing, nullptr);
  while (dirent *entry = readdir(listing))
    if (entry->d_name[0] != '.')
      names.push_back(entry->d_name);
  closedir(listing);
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"V.npy", "X.npy", "X.reference.npy"}));

  std::string metrics = readFile(json);
  for (const char *field :
       {"\"scene\": \"decay\"", "\"strategy\": \"simple\"",
        "\"backend\": \"cpu\"", "\"steps\": 7", "\"repeat\": 3",
        "\"big_steps\": 7", "\"big_step_histogram\": {\"1\": 7, \"2\": 0",
        "\"evaluations\": {\"Decay\": 700, \"Grow\": 700}",
        "\"reference\": \"exact\"", "\"error\": {\"X\": {\"max_abs\": ",
        "\"wall_seconds_runs\": [", "\"host_syncs\": 2"})
    EXPECT_TRUE(contains(metrics, field)) << field << "\n" << metrics;
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

TEST_F(SimRun, ReportsBadBundlesAndSettings) {
  std::string bad = dir + "/bad.simb";
  writeFile(bad, "not a bundle at all, but long enough");
  Result result = simRun(bad);
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "sim-run: error: bundle '" + bad +
                                          "': not a sim bundle (wrong magic"))
      << result.output;
  result = simRun(bundle + " --set speed=3");
  EXPECT_EQ(result.status, 1);
  EXPECT_TRUE(contains(result.output, "--set speed=3: 'speed' is not range, dt "
                                      "or a parameter of scene 'decay'"))
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
  Result translated = shell("PATH=/nonexistent " + simRun + " " + scene +
                            " --backend cpu --steps 4");
  EXPECT_EQ(translated.status, 0) << translated.output;
  EXPECT_TRUE(contains(translated.output, "scene decay, strategy hip"))
      << translated.output;

  writeFile(translate, "#!/bin/sh\necho 'error: no such op' >&2\nexit 1\n");
  Result failed = shell("PATH=/nonexistent " + simRun + " " + scene);
  EXPECT_EQ(failed.status, 1);
  EXPECT_TRUE(contains(failed.output, "error: no such op")) << failed.output;
  EXPECT_TRUE(
      contains(failed.output, "sim-run: error: sim-translate failed on '" +
                                  scene + "' (exit status 1)"))
      << failed.output;
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
  std::string metrics = readFile(json);
  for (const char *field :
       {"\"check\": {\n    \"strategy\": \"hip\",\n    \"group_size\": "
        "32,\n    \"steps\": 25,\n    \"pass\": true,",
        "\"buffers\": {\"X\": {\"max_abs\": 0, \"max_reference\": "
        "1.20089481, \"rms_rel\": 0, \"tolerance\": 1e-10, \"limit\": "
        "1.20089481e-10, \"same_non_finite\": 0, \"pass\": true}, "
        "\"V\": {",
        "\"evaluations\": {\"backend\": {\"Decay\": 1500, \"Grow\": 1500}, "
        "\"reference\": {\"Decay\": 1500, \"Grow\": 1500}, \"equal\": true}",
        "\"big_steps\": {\"backend\": 15, \"reference\": 15, \"equal\": "
        "true}",
        "\"big_step_histogram\": {\"backend\": {\"1\": 9, \"2\": 3, \"3\": 2, "
        "\"4\": 1}, \"reference\": {\"1\": 9, ",
        "\"failures\": []"})
    EXPECT_TRUE(contains(metrics, field)) << field << "\n" << metrics;
  // Without --check the JSON says so.
  ASSERT_EQ(simRun(bundle + " --backend cpu --steps 2 --json " + json).status,
            0);
  EXPECT_TRUE(contains(readFile(json), "\"check\": null"));
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
  std::string metrics = readFile(json);
  EXPECT_TRUE(contains(metrics, "\"pass\": false")) << metrics;
  EXPECT_TRUE(contains(metrics, "\"failures\": [\"buffer X exceeds the "
                                "tolerance (max-abs 1.983e-05 > 1.201e-10)\"]"))
      << metrics;

  // A looser tolerance lets it pass.
  result = simRun(wrong + " --backend cpu --strategy simple --steps 25 "
                          "--check --check-tolerance 1e-4");
  EXPECT_EQ(result.status, 0) << result.output;
  EXPECT_TRUE(contains(result.output, "tolerance 1.0e-04  pass"))
      << result.output;
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
