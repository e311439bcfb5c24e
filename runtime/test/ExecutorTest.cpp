//===- ExecutorTest.cpp - running plans on the CPU backend ----------------===//
//
// The executor end to end on the decay scene (kernels/decay.c): values
// after N base steps against the closed form, runs that end exactly at N,
// the big steps the device decided, the metrics, parameters, host arrays,
// the exact solution and the NaN/Inf check.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "Session.h"
#include "TestBundle.h"
#include "TestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

using namespace sim::rt;
using namespace sim::test;

namespace {

std::shared_ptr<const Bundle> decay() {
  static std::shared_ptr<const Bundle> bundle =
      parseBytes(decayBundle(), "decay.simb");
  return bundle;
}

sim_session_options cpuOptions(sim_strategy strategy, int threads = 3,
                               int64_t groupSize = 0) {
  sim_session_options options;
  sim_session_options_init(&options);
  options.strategy = strategy;
  options.backend = SIM_BACKEND_CPU;
  options.cpu_threads = threads;
  options.group_size = groupSize;
  return options;
}

std::vector<double> getX(Session &session) {
  std::vector<double> x(size_t(session.range()));
  session.getBuffer("X", x.data(), x.size() * sizeof(double));
  return x;
}

std::vector<float> getV(Session &session) {
  std::vector<float> v(size_t(session.range()) * 3);
  session.getBuffer("V", v.data(), v.size() * sizeof(float));
  return v;
}

/// x_i after `steps` base steps of x' = -k x with (1 - k dt) per step.
double expectedX(int64_t item, int64_t steps, double k = 2, double dt = 0.01) {
  return (1 + 0.01 * double(item)) * std::pow(1 - k * dt, double(steps));
}

void expectX(Session &session, int64_t steps, double k = 2, double dt = 0.01) {
  std::vector<double> x = getX(session);
  for (size_t i = 0; i < x.size(); ++i)
    ASSERT_NEAR(x[i], expectedX(int64_t(i), steps, k, dt),
                1e-12 * std::fabs(expectedX(int64_t(i), steps, k, dt)))
        << "item " << i;
}

} // namespace

TEST(Executor, SimpleRunMatchesTheClosedForm) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  EXPECT_EQ(session.backendKind(), SIM_BACKEND_CPU);
  // The test bundle carries generic x86-64 code only.
  EXPECT_EQ(session.device(), "CPU (3 threads, x86-64)");
  EXPECT_EQ(session.groupSize(), 32);
  session.run(37);
  EXPECT_EQ(session.time(), 37);
  expectX(session, 37);
  std::vector<float> v = getV(session);
  for (int64_t i = 0; i < session.range(); ++i) {
    EXPECT_EQ(v[3 * i + 0], 37.0f); // base steps
    EXPECT_EQ(v[3 * i + 1], float(i));
    EXPECT_EQ(v[3 * i + 2], 37.0f); // evaluations: one per base step
  }
  const sim_metrics &m = session.metrics;
  EXPECT_EQ(m.steps, 37);
  EXPECT_EQ(m.begin, 0);
  EXPECT_EQ(m.end, 37);
  EXPECT_EQ(m.big_steps, 37);
  EXPECT_EQ(session.histogram[1], 37);
  EXPECT_EQ(session.evaluations[0], 37 * 100);
  EXPECT_EQ(session.evaluations[1], 37 * 100);
  // 37 step phases of 3 launches in one batch, then finish.
  EXPECT_EQ(m.launches, 37 * 3 + 1);
  EXPECT_EQ(m.host_syncs, 2);
  EXPECT_EQ(m.graph_launches, 0);
  EXPECT_GE(m.wall_seconds, m.kernel_seconds);
  EXPECT_GT(m.kernel_seconds, 0);
}

TEST(Executor, HipRunEndsExactlyAtNWithTheDevicesBigSteps) {
  for (int64_t steps : {1, 2, 5, 21, 53, 300}) {
    Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
    session.run(steps);
    EXPECT_EQ(session.time(), steps);
    EXPECT_EQ(session.metrics.end, steps);
    expectX(session, steps);
    std::vector<int64_t> sizes = decayBigSteps(0, steps, 4);
    std::vector<int64_t> histogram(5, 0);
    for (int64_t m : sizes)
      ++histogram[m];
    EXPECT_EQ(session.histogram, histogram) << steps << " steps";
    int64_t bigSteps = int64_t(sizes.size());
    EXPECT_EQ(session.metrics.big_steps, bigSteps);
    EXPECT_EQ(session.cutBigSteps, decayCuts(0, steps, 4)) << steps;
    EXPECT_EQ(session.evaluations[0], bigSteps * 100);
    EXPECT_EQ(session.evaluations[1], bigSteps * 100);
    std::vector<float> v = getV(session);
    EXPECT_EQ(v[0], float(steps));
    EXPECT_EQ(v[2], float(bigSteps));
    // Launched ahead: at least every big step's 4 launches, far fewer
    // host synchronisations than big steps.
    EXPECT_GE(session.metrics.launches, bigSteps * 4 + 1);
    EXPECT_GE(session.metrics.host_syncs, 2);
    if (steps >= 21)
      EXPECT_LT(session.metrics.host_syncs, bigSteps / 2);
  }
}

TEST(Executor, RunsContinueFromTheirEnd) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  session.run(10);
  session.run(15);
  EXPECT_EQ(session.time(), 25);
  EXPECT_EQ(session.metrics.begin, 10);
  EXPECT_EQ(session.metrics.end, 25);
  expectX(session, 25);
  std::vector<int64_t> sizes = decayBigSteps(10, 15, 4);
  EXPECT_EQ(session.metrics.big_steps, int64_t(sizes.size()));
  session.run(0);
  EXPECT_EQ(session.time(), 25);
  EXPECT_EQ(session.metrics.big_steps, 0);
  EXPECT_EQ(session.metrics.steps, 0);
  // init starts over.
  session.init();
  EXPECT_EQ(session.time(), 0);
  expectX(session, 0);
}

TEST(Executor, CountsTheBigStepsTheEndOfARunCuts) {
  // num_steps at T is 1 + (T / 5) % 4: from 0 the big steps are 1 1 1 1 1
  // (to 5), 2 2 2 (to 11), 3 3 (to 17), 4 ...; a run to 6 cuts the 2 at 5
  // to 1, a run to 7 ends on a boundary.
  ASSERT_EQ(decayCuts(0, 6, 4), 1);
  ASSERT_EQ(decayCuts(0, 7, 4), 0);
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  session.run(6);
  EXPECT_EQ(session.cutBigSteps, 1);
  EXPECT_EQ(session.histogram[1], 6);
  session.init();
  session.run(7);
  EXPECT_EQ(session.cutBigSteps, 0);
  EXPECT_EQ(session.histogram[2], 1);
  // Every run of a chunked timeline that ends inside a big step counts one.
  session.init();
  int64_t cuts = 0;
  for (int64_t chunk = 0; chunk < 20; ++chunk) {
    session.run(3);
    cuts += session.cutBigSteps;
    EXPECT_EQ(session.cutBigSteps, decayCuts(chunk * 3, 3, 4)) << chunk;
  }
  EXPECT_GT(cuts, 5);
  // simple never cuts: every big step is one base step.
  Session simple(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  simple.run(7);
  EXPECT_EQ(simple.cutBigSteps, 0);
}

TEST(Executor, ResultsDoNotDependOnThreadsOrGroupSize) {
  Session reference(decay(), cpuOptions(SIM_STRATEGY_HIP, 1));
  reference.run(40);
  std::vector<double> x = getX(reference);
  std::vector<float> v = getV(reference);
  for (int threads : {2, 5})
    for (int64_t group : {1, 7, 32, 1000}) {
      Session session(decay(), cpuOptions(SIM_STRATEGY_HIP, threads, group));
      EXPECT_EQ(session.groupSize(), group);
      session.run(40);
      EXPECT_EQ(getX(session), x) << threads << " threads, groups of " << group;
      EXPECT_EQ(getV(session), v) << threads << " threads, groups of " << group;
      EXPECT_EQ(session.evaluations, reference.evaluations);
    }
}

TEST(Executor, LiveSessionsKeepTheirOwnKernels) {
  // Each session loads its CPU object from its own memfd; dlopen must not
  // take one for another (it matches loaded objects by path).
  auto hip = std::make_unique<Session>(decay(), cpuOptions(SIM_STRATEGY_HIP));
  Session simple(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  simple.run(8);
  EXPECT_EQ(simple.metrics.big_steps, 8);
  hip->run(8);
  EXPECT_EQ(hip->metrics.big_steps, int64_t(decayBigSteps(0, 8, 4).size()));
  hip.reset();
  Session again(decay(), cpuOptions(SIM_STRATEGY_HIP));
  again.run(8);
  EXPECT_EQ(again.metrics.big_steps, int64_t(decayBigSteps(0, 8, 4).size()));
  simple.run(8);
  EXPECT_EQ(simple.metrics.big_steps, 8);
}

TEST(Executor, RangeDtAndParametersAreRunTimeValues) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  session.run(5);
  session.set("range", "1037");
  EXPECT_EQ(session.range(), 1037);
  EXPECT_EQ(session.time(), 0); // a new range starts over
  session.set("k", "0.5");
  session.set("dt", "0.02");
  EXPECT_EQ(session.get("k"), "0.5");
  EXPECT_EQ(session.get("dt"), "0.02");
  EXPECT_EQ(session.get("range"), "1037");
  EXPECT_EQ(session.get("poison"), "-1");
  session.run(12);
  expectX(session, 12, 0.5, 0.02);
  EXPECT_EQ(session.evaluations[0], 12 * 1037);
  // Parameters change between runs without losing the state.
  session.set("k", "0");
  session.run(3);
  EXPECT_EQ(session.time(), 15);
  expectX(session, 12, 0.5, 0.02);
}

TEST(Executor, RejectsBadNamesAndValues) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  EXPECT_NE(
      errorOf([&] { session.set("kappa", "1"); }, SIM_ERROR_INVALID_ARGUMENT)
          .find("'kappa' is not range, dt or a parameter of scene "
                "'decay' (parameters: k, poison)"),
      std::string::npos);
  EXPECT_NE(
      errorOf([&] { session.set("poison", "1.5"); }, SIM_ERROR_INVALID_ARGUMENT)
          .find("parameter 'poison': '1.5' is not an integer (i32)"),
      std::string::npos);
  EXPECT_NE(
      errorOf([&] { session.set("range", "0"); }, SIM_ERROR_INVALID_ARGUMENT)
          .find("not a number of items from 1 to 2^40"),
      std::string::npos);
  // A value that rounds to 0 is refused, not run as 0; a hexadecimal one
  // too (strtod reads 0x10 as 16, an MLIR float literal as bits). A
  // subnormal value is a value.
  EXPECT_NE(
      errorOf([&] { session.set("k", "1e-400"); }, SIM_ERROR_INVALID_ARGUMENT)
          .find("parameter 'k': '1e-400' underflows to 0 in f64"),
      std::string::npos);
  EXPECT_NE(
      errorOf([&] { session.set("k", "-0x10"); }, SIM_ERROR_INVALID_ARGUMENT)
          .find("'-0x10' is hexadecimal; give an f64 value in decimal"),
      std::string::npos);
  session.set("k", "1e-310");
  session.set("k", "0");
  EXPECT_NE(errorOf([&] { session.run(-1); }, SIM_ERROR_INVALID_ARGUMENT)
                .find("cannot run -1 base steps"),
            std::string::npos);
  std::vector<double> x(99);
  EXPECT_NE(errorOf([&] { session.getBuffer("X", x.data(), 99 * 8); },
                    SIM_ERROR_INVALID_ARGUMENT)
                .find("a host array of buffer 'X' takes 800 bytes, not 792"),
            std::string::npos);
  EXPECT_NE(errorOf([&] { session.getBuffer("Y", x.data(), 8); },
                    SIM_ERROR_INVALID_ARGUMENT)
                .find("'Y' is not a buffer of the plan of strategy 'simple' "
                      "(buffers: X, V)"),
            std::string::npos);
}

TEST(Executor, HostArraysAreTheCurrentStateWithoutPadding) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  size_t bytes = session.hostBytes("V");
  EXPECT_EQ(bytes, 100u * 12); // 3 packed lanes, not the 16-byte stride
  session.run(3);              // odd: the state is in half 1
  std::vector<double> x(100);
  for (size_t i = 0; i < x.size(); ++i)
    x[i] = double(i);
  session.setBuffer("X", x.data(), x.size() * 8);
  std::vector<float> v(300, 0.0f);
  session.setBuffer("V", v.data(), v.size() * 4);
  session.run(1);
  std::vector<double> after = getX(session);
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_DOUBLE_EQ(after[i], double(i) * (1 - 2 * 0.01));
  std::vector<float> grown = getV(session);
  EXPECT_EQ(grown[3 * 5 + 0], 1.0f);
  EXPECT_EQ(grown[3 * 5 + 1], 5.0f);
  EXPECT_EQ(grown[3 * 5 + 2], 1.0f);
}

TEST(Executor, EvaluatesTheExactSolutionAtTheCurrentTime) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  EXPECT_TRUE(session.hasExact("X"));
  EXPECT_FALSE(session.hasExact("V"));
  session.run(20);
  int64_t launches = session.metrics.launches;
  std::vector<double> exact(100);
  session.exact("X", exact.data(), exact.size() * 8);
  for (size_t i = 0; i < exact.size(); ++i)
    EXPECT_NEAR(exact[i], (1 + 0.01 * double(i)) * std::exp(-2 * 20 * 0.01),
                1e-14);
  // Not part of the run.
  EXPECT_EQ(session.metrics.launches, launches);
  std::vector<float> v(300);
  EXPECT_NE(errorOf([&] { session.exact("V", v.data(), v.size() * 4); },
                    SIM_ERROR_INVALID_ARGUMENT)
                .find("declares no exact solution of buffer 'V'"),
            std::string::npos);
}

TEST(Executor, CheckFiniteStopsAtTheFirstNaN) {
  for (sim_strategy strategy : {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP}) {
    sim_session_options options = cpuOptions(strategy);
    options.check_finite = 1;
    Session session(decay(), options);
    session.set("poison", "10");
    std::string message =
        errorOf([&] { session.run(40); }, SIM_ERROR_NONFINITE);
    // hip's big steps start at 0 1 2 3 4 5 7 9 11: the first at or after
    // base step 10 is 11.
    int64_t at = strategy == SIM_STRATEGY_SIMPLE ? 10 : 11;
    EXPECT_TRUE(session.nonFinite.found);
    EXPECT_EQ(session.nonFinite.baseStep, at);
    EXPECT_EQ(session.nonFinite.component, "Decay");
    EXPECT_EQ(session.nonFinite.buffer, "X");
    EXPECT_EQ(session.nonFinite.kernel, "evaluate_Decay");
    EXPECT_EQ(session.nonFinite.item, 7);
    EXPECT_TRUE(std::isnan(session.nonFinite.value));
    EXPECT_NE(message.find("non-finite value nan in buffer 'X' (item 7) after "
                           "kernel 'evaluate_Decay' for component 'Decay' at "
                           "base step " +
                           std::to_string(at)),
              std::string::npos)
        << message;
    // The state stopped inside a big step: no run continues from it (the
    // next big step would start from buffers of two times), even after
    // the parameter is repaired; init starts over.
    session.set("poison", "1000");
    std::string again =
        errorOf([&] { session.run(8); }, SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(again.find("the last run stopped inside the big step from base "
                         "step " +
                         std::to_string(at)),
              std::string::npos)
        << again;
    session.init();
    session.run(8);
    EXPECT_EQ(session.time(), 8);
  }
  // Without the check the run completes, NaN and all.
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  session.set("poison", "10");
  session.run(40);
  EXPECT_TRUE(std::isnan(getX(session)[7]));
  EXPECT_FALSE(session.nonFinite.found);
}

TEST(Executor, ReportsProgressEarlyInARun) {
  // With a progress callback the first batch is 8 step phases, and later
  // ones take about a quarter of a second at most (here, with fast step
  // phases, up to 256): the first report comes early however long a big
  // step takes.
  Session session(decay(), cpuOptions(SIM_STRATEGY_SIMPLE));
  std::vector<int64_t> done;
  session.setProgress(
      [](void *user, int64_t steps, int64_t) {
        auto *calls = static_cast<std::vector<int64_t> *>(user);
        calls->push_back(steps);
      },
      &done);
  session.run(1000);
  ASSERT_GE(done.size(), 2u);
  EXPECT_EQ(done[0], 8);
  EXPECT_EQ(done.back(), 1000);
  // Without one, a batch is up to 256 step phases.
  session.setProgress(nullptr, nullptr);
  session.run(1000);
  EXPECT_EQ(session.metrics.host_syncs, 4 + 1);
}

TEST(Executor, ReportsProgressAfterEachSynchronisation) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  std::vector<std::pair<int64_t, int64_t>> calls;
  session.setProgress(
      [](void *user, int64_t done, int64_t total) {
        static_cast<std::vector<std::pair<int64_t, int64_t>> *>(user)
            ->push_back({done, total});
      },
      &calls);
  session.run(100);
  ASSERT_FALSE(calls.empty());
  EXPECT_EQ(int64_t(calls.size()), session.metrics.host_syncs - 1);
  EXPECT_EQ(calls.back(), std::make_pair(int64_t(100), int64_t(100)));
  for (size_t i = 1; i < calls.size(); ++i)
    EXPECT_GT(calls[i].first, calls[i - 1].first);
}

//===----------------------------------------------------------------------===//
// Sessions that cannot be made or run
//===----------------------------------------------------------------------===//

TEST(Executor, NamesTheCodeABackendLacks) {
  EXPECT_NE(
      errorOf([] { Session s(decay(), cpuOptions(SIM_STRATEGY_TRADITIONAL)); },
              SIM_ERROR_INVALID_ARGUMENT)
          .find("bundle 'decay.simb' has no plan for strategy "
                "'traditional' (it has: simple, hip)"),
      std::string::npos);
  sim_session_options cuda = cpuOptions(SIM_STRATEGY_HIP);
  cuda.backend = SIM_BACKEND_CUDA;
  EXPECT_NE(errorOf([&] { Session s(decay(), cuda); }, SIM_ERROR_BUNDLE)
                .find("bundle 'decay.simb' has no PTX for strategy 'hip'; the "
                      "CUDA backend needs it"),
            std::string::npos);

  schema::BundleT contents = decayContents();
  planOf(contents, Strategy::Hip).cpu.clear();
  auto noCpu = parseBytes(serialize(contents), "decay.simb");
  EXPECT_NE(errorOf([&] { Session s(noCpu, cpuOptions(SIM_STRATEGY_HIP)); },
                    SIM_ERROR_BUNDLE)
                .find("cannot run strategy 'hip' of bundle 'decay.simb' on the "
                      "CPU: it has no CPU kernels"),
            std::string::npos);
  // CPU code for another machine only is no CPU code for this one.
  planOf(contents, Strategy::Hip).cpu =
      std::move(decayContents().plans[1]->cpu);
  planOf(contents, Strategy::Hip).cpu[0]->isa = "riscv64";
  auto otherIsa = parseBytes(serialize(contents), "decay.simb");
  EXPECT_NE(errorOf([&] { Session s(otherIsa, cpuOptions(SIM_STRATEGY_HIP)); },
                    SIM_ERROR_BUNDLE)
                .find("it has CPU kernels for riscv64 only, and this CPU runs "
                      "none of them; recompile with sim-translate "
                      "--sim-cpu-isas=x86-64"),
            std::string::npos);
  sim_session_options automatic = cpuOptions(SIM_STRATEGY_HIP);
  automatic.backend = SIM_BACKEND_AUTO;
  EXPECT_NE(errorOf([&] { Session s(noCpu, automatic); }, SIM_ERROR_BUNDLE)
                .find("the bundle has no PTX for strategy 'hip', and it has no "
                      "CPU kernels"),
            std::string::npos);
}

TEST(Executor, AutoRunsOnTheCpuWithoutPtx) {
  sim_session_options options = cpuOptions(SIM_STRATEGY_HIP);
  options.backend = SIM_BACKEND_AUTO;
  Session session(decay(), options);
  EXPECT_EQ(session.backendKind(), SIM_BACKEND_CPU);
  EXPECT_EQ(session.backendNote(), "the bundle has no PTX for strategy 'hip'");
}

TEST(Executor, NamesAMissingKernel) {
  schema::BundleT contents = decayContents();
  planOf(contents, Strategy::Simple).kernels[3]->name = "nowhere";
  auto bundle = parseBytes(serialize(contents), "decay.simb");
  EXPECT_NE(errorOf([&] { Session s(bundle, cpuOptions(SIM_STRATEGY_SIMPLE)); },
                    SIM_ERROR_BACKEND)
                .find("the CPU kernels of strategy 'simple' do not export "
                      "sim_cpu_nowhere (kernel 'nowhere' of the plan)"),
            std::string::npos);
}

TEST(Executor, RejectsKernelsThatStallTheClock) {
  // A step phase without `advance` never moves T: the executor must stop
  // rather than spin.
  schema::BundleT contents = decayContents();
  for (auto &phase : planOf(contents, Strategy::Simple).phases)
    if (phase->kind == PhaseKind::Step)
      phase->body.erase(phase->body.begin());
  auto bundle = parseBytes(serialize(contents), "decay.simb");
  Session session(bundle, cpuOptions(SIM_STRATEGY_SIMPLE));
  EXPECT_NE(errorOf([&] { session.run(5); }, SIM_ERROR_CLOCK)
                .find("the step phase made no progress at base step 0 of a run "
                      "to 5"),
            std::string::npos);
}

TEST(Executor, RejectsGroupSizesTheCpuCannotRun) {
  for (int64_t groupSize : {int64_t(-4), int64_t(4097), int64_t(1) << 19})
    EXPECT_TRUE(contains(
        errorOf(
            [&] {
              Session s(decay(), cpuOptions(SIM_STRATEGY_HIP, 1, groupSize));
            },
            SIM_ERROR_INVALID_ARGUMENT),
        "group size " + std::to_string(groupSize) +
            " is not between 1 and 4096, as the CPU backend needs"));
}

TEST(Executor, RejectsThreadCountsOutsideItsRange) {
  EXPECT_TRUE(contains(
      errorOf([] { Session s(decay(), cpuOptions(SIM_STRATEGY_HIP, 5000)); },
              SIM_ERROR_INVALID_ARGUMENT),
      "5000 CPU threads: the CPU backend takes 1 to 1024"));
}

TEST(Executor, RejectsTimeStepsThatAreNotPositiveAndFinite) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  for (const char *dt : {"nan", "inf", "-inf", "0", "-1"})
    EXPECT_TRUE(contains(
        errorOf([&] { session.set("dt", dt); }, SIM_ERROR_INVALID_ARGUMENT),
        "is not a positive finite time step"))
        << dt;
  // A nonzero value that rounds to 0 says so.
  EXPECT_TRUE(contains(
      errorOf([&] { session.set("dt", "1e-400"); }, SIM_ERROR_INVALID_ARGUMENT),
      "'1e-400' underflows to 0 in f64"));
  // A subnormal one is refused too: t + dt would not advance t.
  for (const char *dt : {"1e-320", "4.9e-324", "2.2250738585072e-308"})
    EXPECT_TRUE(contains(
        errorOf([&] { session.set("dt", dt); }, SIM_ERROR_INVALID_ARGUMENT),
        std::string("dt: ") + dt +
            " is subnormal in f64 (below 2.2250738585072014e-308, the "
            "smallest normal value): too small for t + dt to advance t"))
        << dt;
  EXPECT_EQ(session.get("dt"), "0.01");
  session.set("dt", "2.2250738585072014e-308");
  EXPECT_EQ(session.get("dt"), "2.2250738585072014e-308");
  session.set("dt", "0.01");
  for (const char *range : {"0", "-3", "1099511627777"})
    EXPECT_TRUE(contains(errorOf([&] { session.set("range", range); },
                                 SIM_ERROR_INVALID_ARGUMENT),
                         "is not a number of items from 1 to 2^40"))
        << range;
}

TEST(Executor, RefusesAStateAboveTheMemoryLimit) {
  sim_session_options options = cpuOptions(SIM_STRATEGY_HIP);
  options.max_memory = 4096;
  Session session(decay(), options);
  EXPECT_EQ(session.memoryLimit(), 4096);
  // 100 items: clock, X (2 x 8 bytes, exact 8) and V (2 x 16) per item.
  EXPECT_GT(session.memoryBytes(100), 4096);
  std::string message =
      errorOf([&] { session.run(3); }, SIM_ERROR_MEMORY_LIMIT);
  EXPECT_TRUE(contains(message, "range 100 needs "));
  EXPECT_TRUE(contains(message, "more than the limit of 4.00 KiB"));
  session.set("range", "10");
  session.run(3);
  EXPECT_EQ(session.time(), 3);
  // A range too large for any memory is refused before it is taken.
  Session unlimited(decay(), cpuOptions(SIM_STRATEGY_HIP));
  EXPECT_GT(unlimited.memoryLimit(), 0);
  EXPECT_TRUE(contains(errorOf([&] { unlimited.set("range", "1099511627776"); },
                               SIM_ERROR_MEMORY_LIMIT),
                       "range 1099511627776 needs"));
  EXPECT_EQ(unlimited.range(), 100);
}

TEST(Executor, StopsAnInterruptedRunOnABigStepBoundary) {
  Session session(decay(), cpuOptions(SIM_STRATEGY_HIP));
  // Asked before the run: it stops where it starts.
  session.interrupt();
  EXPECT_TRUE(contains(errorOf([&] { session.run(50); }, SIM_ERROR_INTERRUPTED),
                       "interrupted at base step 0 of a run from 0 to 50"));
  EXPECT_EQ(session.time(), 0);
  EXPECT_EQ(session.metrics.steps, 0);
  session.resume();
  // Asked during the run (from the progress callback, after the first
  // batch, which with a callback is 8 step phases): the state is the one at
  // the boundary reached, and a later run continues from there.
  session.setProgress(
      [](void *user, int64_t done, int64_t) {
        if (done >= 5)
          static_cast<Session *>(user)->interrupt();
      },
      &session);
  errorOf([&] { session.run(200); }, SIM_ERROR_INTERRUPTED);
  int64_t reached = session.time();
  EXPECT_GE(reached, 5);
  EXPECT_LT(reached, 200);
  EXPECT_EQ(session.metrics.steps, reached);
  EXPECT_EQ(session.metrics.end, reached);
  expectX(session, reached);
  session.setProgress(nullptr, nullptr);
  session.resume();
  session.run(200 - reached);
  EXPECT_EQ(session.time(), 200);
  expectX(session, 200);
}
