//===- ReferenceTest.cpp - the reference model and the reference executor -===//
//
// The reference part of a bundle (its checks are in BundleTest.cpp) and the
// executor: on the decay scene it agrees with the CPU
// backend running the hand-written plan kernels (values, evaluations, big
// steps); on the probe scene (kernels/probe_reference.c) it reads through
// each interpolation and boundary rule exactly as docs/Reference.md says,
// and it names what it cannot serve.
//
//===----------------------------------------------------------------------===//

#include "Reference.h"
#include "Bundle.h"
#include "Error.h"
#include "Session.h"
#include "TestBundle.h"
#include "TestUtil.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace sim::rt;
using namespace sim::test;

namespace {

sim_session_options options(sim_strategy strategy, sim_backend backend,
                            int64_t groupSize = 0) {
  sim_session_options result;
  sim_session_options_init(&result);
  result.strategy = strategy;
  result.backend = backend;
  result.group_size = groupSize;
  result.cpu_threads = 1;
  return result;
}

template <typename T>
std::vector<T> values(Executor &session, const std::string &buffer) {
  std::vector<T> data(session.hostBytes(buffer) / sizeof(T));
  session.getBuffer(buffer, data.data(), data.size() * sizeof(T));
  return data;
}

} // namespace

//===----------------------------------------------------------------------===//
// The reference part of a bundle
//===----------------------------------------------------------------------===//

TEST(ReferenceModel, IsReadWhenPresent) {
  auto bundle = parseBytes(decayBundle());
  ASSERT_TRUE(bundle->reference());
  EXPECT_EQ(bundle->reference()->components.size(), 2u);
  EXPECT_FALSE(bundle->reference()->object.empty());
  EXPECT_FALSE(parseBytes(decayBundle(false, false))->reference());
}

//===----------------------------------------------------------------------===//
// The executor on the decay scene
//===----------------------------------------------------------------------===//

namespace {

/// Runs decay on `backend` in two runs (10 then 15 base steps) and returns
/// the session.
std::unique_ptr<Executor> runDecay(sim_strategy strategy, sim_backend backend,
                                   int64_t groupSize = 0,
                                   const std::string &bytes = decayBundle()) {
  auto bundle = parseBytes(bytes);
  std::unique_ptr<Executor> session;
  sim_session_options chosen = options(strategy, backend, groupSize);
  if (backend == SIM_BACKEND_REFERENCE)
    session = std::make_unique<ReferenceSession>(bundle, chosen);
  else
    session = std::make_unique<Session>(bundle, chosen);
  session->set("k", "1.5");
  session->run(10);
  session->run(15);
  return session;
}

void expectSameRun(Executor &reference, Executor &backend) {
  EXPECT_EQ(reference.time(), backend.time());
  std::vector<double> x = values<double>(reference, "X");
  std::vector<double> y = values<double>(backend, "X");
  ASSERT_EQ(x.size(), y.size());
  for (size_t i = 0; i < x.size(); ++i)
    EXPECT_NEAR(x[i], y[i], 1e-14) << "X item " << i;
  EXPECT_EQ(values<float>(reference, "V"), values<float>(backend, "V"));
  ASSERT_EQ(reference.numComponents(), backend.numComponents());
  for (size_t c = 0; c < reference.numComponents(); ++c) {
    EXPECT_EQ(reference.componentName(c), backend.componentName(c));
    EXPECT_EQ(reference.evaluations[c], backend.evaluations[c])
        << reference.componentName(c);
  }
  EXPECT_EQ(reference.metrics.big_steps, backend.metrics.big_steps);
  EXPECT_EQ(reference.histogram, backend.histogram);
  EXPECT_EQ(reference.cutBigSteps, backend.cutBigSteps);
}

} // namespace

TEST(ReferenceExecutor, AgreesWithThePlanKernelsOnDecay) {
  for (sim_strategy strategy : {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP}) {
    SCOPED_TRACE(sim_strategy_name(strategy));
    auto cpu = runDecay(strategy, SIM_BACKEND_CPU);
    auto reference = runDecay(strategy, SIM_BACKEND_REFERENCE);
    expectSameRun(*reference, *cpu);
    EXPECT_EQ(reference->groupSize(), 32);
  }
  // The bundle has no traditional or hip-cache plan; the decay scene takes
  // the same big steps under them as under hip (Decay bounds them, one
  // evaluation per item each).
  auto hip = runDecay(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  for (sim_strategy strategy :
       {SIM_STRATEGY_TRADITIONAL, SIM_STRATEGY_HIP_CACHE}) {
    SCOPED_TRACE(sim_strategy_name(strategy));
    expectSameRun(*runDecay(strategy, SIM_BACKEND_REFERENCE, 32), *hip);
  }
  // The second run, from 10 to 25: sizes 3 3 4 1 1 1 1 1.
  EXPECT_EQ(hip->metrics.big_steps, 8);
  EXPECT_EQ(hip->cutBigSteps, 0);
  // Runs that end inside a big step cut it, on both executors alike.
  for (sim_backend backend : {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE}) {
    auto bundle = parseBytes(decayBundle());
    std::unique_ptr<Executor> session;
    if (backend == SIM_BACKEND_REFERENCE)
      session = std::make_unique<ReferenceSession>(
          bundle, options(SIM_STRATEGY_HIP, backend, 0));
    else
      session = std::make_unique<Session>(
          bundle, options(SIM_STRATEGY_HIP, backend, 0));
    session->run(16); // the 3 at 14 cut to 2
    EXPECT_EQ(session->cutBigSteps, 1) << sim_backend_name(backend);
    session->run(2); // the 4 at 16 cut to 2
    EXPECT_EQ(session->cutBigSteps, 1) << sim_backend_name(backend);
  }
}

TEST(ReferenceExecutor, StopsWhenInterruptedAndKeepsItsMemoryLimit) {
  auto bundle = parseBytes(decayBundle());
  sim_session_options options;
  sim_session_options_init(&options);
  options.strategy = SIM_STRATEGY_HIP;
  options.backend = SIM_BACKEND_REFERENCE;
  options.max_memory = 1000;
  ReferenceSession session(bundle, options);
  EXPECT_TRUE(contains(errorOf([&] { session.run(5); }, SIM_ERROR_MEMORY_LIMIT),
                       "more than the limit of 1000 bytes"));
  session.set("range", "4");
  session.setProgress(
      [](void *user, int64_t done, int64_t) {
        if (done >= 7)
          static_cast<ReferenceSession *>(user)->interrupt();
      },
      &session);
  errorOf([&] { session.run(30); }, SIM_ERROR_INTERRUPTED);
  EXPECT_GE(session.time(), 7);
  EXPECT_LT(session.time(), 30);
  EXPECT_EQ(session.metrics.steps, session.time());
}

TEST(ReferenceExecutor, NeedsAGroupSizeWithoutAPlan) {
  auto bundle = parseBytes(decayBundle());
  EXPECT_TRUE(contains(
      errorOf(
          [&] {
            ReferenceSession(bundle, options(SIM_STRATEGY_TRADITIONAL,
                                             SIM_BACKEND_REFERENCE));
          },
          SIM_ERROR_INVALID_ARGUMENT),
      "has no plan for strategy 'traditional' to take the group size from"));
}

TEST(ReferenceExecutor, SetsParametersAndEvaluatesTheExactSolution) {
  auto bundle = parseBytes(decayBundle());
  ReferenceSession session(bundle,
                           options(SIM_STRATEGY_SIMPLE, SIM_BACKEND_REFERENCE));
  EXPECT_EQ(session.device(), "reference executor (CPU, 1 thread)");
  EXPECT_EQ(session.get("k"), "2");
  session.set("range", "10");
  session.set("dt", "0.02");
  session.run(5);
  EXPECT_EQ(session.time(), 5);
  std::vector<double> x = values<double>(session, "X");
  ASSERT_EQ(x.size(), 10u);
  EXPECT_NEAR(x[3], 1.03 * std::pow(1 - 2 * 0.02, 5), 1e-14);
  std::vector<double> exact(10);
  ASSERT_TRUE(session.hasExact("X"));
  EXPECT_FALSE(session.hasExact("V"));
  session.exact("X", exact.data(), exact.size() * sizeof(double));
  EXPECT_NEAR(exact[3], 1.03 * std::exp(-2 * 0.02 * 5), 1e-14);
  // A new range starts over.
  session.set("range", "20");
  EXPECT_EQ(session.time(), 5);
  EXPECT_EQ(values<double>(session, "X").size(), 20u);
  EXPECT_EQ(session.time(), 0);
  EXPECT_TRUE(contains(
      errorOf([&] { session.hostBytes("Q"); }, SIM_ERROR_INVALID_ARGUMENT),
      "'Q' is not a buffer of the reference model (buffers: "
      "X, V)"));
}

TEST(ReferenceExecutor, StopsAtTheFirstNonFiniteValue) {
  auto bundle = parseBytes(decayBundle());
  sim_session_options chosen =
      options(SIM_STRATEGY_SIMPLE, SIM_BACKEND_REFERENCE);
  chosen.check_finite = 1;
  ReferenceSession session(bundle, chosen);
  session.set("poison", "4");
  std::string message = errorOf([&] { session.run(20); }, SIM_ERROR_NONFINITE);
  EXPECT_EQ(message, "non-finite value nan in buffer 'X' (item 7) after the "
                     "reference evaluate of component 'Decay' at base step 4 "
                     "(big step of 1, sub-step from 4 to 5)");
  EXPECT_TRUE(session.nonFinite.found);
  EXPECT_EQ(session.nonFinite.baseStep, 4);
  EXPECT_EQ(session.nonFinite.component, "Decay");
  EXPECT_EQ(session.nonFinite.buffer, "X");
  EXPECT_EQ(session.nonFinite.item, 7);
  EXPECT_TRUE(std::isnan(session.nonFinite.value));
}

TEST(ReferenceExecutor, NamesAMissingFunction) {
  schema::BundleT contents = decayContents();
  contents.reference->components[1]->num_steps = true;
  auto bundle = parseBytes(serialize(contents));
  EXPECT_EQ(errorOf(
                [&] {
                  ReferenceSession(
                      bundle, options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
                },
                SIM_ERROR_BACKEND),
            "the reference functions do not export sim_ref_num_steps_1 (the "
            "num_steps body of component 'Grow')");
}

TEST(ReferenceExecutor, NeedsTheReferenceModel) {
  auto bundle = parseBytes(decayBundle(false, false));
  EXPECT_EQ(errorOf(
                [&] {
                  ReferenceSession(
                      bundle, options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
                },
                SIM_ERROR_BUNDLE),
            "bundle 'test.simb' has no reference model and functions");
}

TEST(ReferenceExecutor, StepsAsTheModelRecords) {
  // The records decide, not the executor: with Decay recorded as not
  // estimating under hip, nothing bounds the big step and it is always
  // max_steps; with a recorded cap of 2, never more than 2.
  schema::BundleT contents = decayContents();
  contents.reference->components[0]->stepping[2] =
      schema::Stepping(Advance::WholeStep, false);
  auto unbounded = std::make_unique<ReferenceSession>(
      parseBytes(serialize(contents)),
      options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
  unbounded->run(20);
  EXPECT_EQ(unbounded->histogram[4], 5);
  contents.reference->step_caps[2] = 2;
  auto capped = std::make_unique<ReferenceSession>(
      parseBytes(serialize(contents)),
      options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
  capped->run(20);
  EXPECT_EQ(capped->histogram[2], 10);
}

//===----------------------------------------------------------------------===//
// The executor on the probe scene
//===----------------------------------------------------------------------===//

namespace {

std::unique_ptr<ReferenceSession>
probe(sim_strategy strategy,
      const schema::BundleT &contents = probeContents()) {
  return std::make_unique<ReferenceSession>(
      parseBytes(serialize(contents)),
      options(strategy, SIM_BACKEND_REFERENCE,
              strategy == SIM_STRATEGY_HIP ? 0 : 2));
}

} // namespace

TEST(ReferenceExecutor, InterpolatesAtInteriorSubSteps) {
  // Under hip no component bounds the big step: m = max_steps = 4, and Sink
  // takes four sub-steps of 1, reading A, C and H at 1/4, 2/4, 3/4 and the
  // end of it. Item i goes from a = 2 + i to b = a + 8; H's derivative D
  // from 1 to 3, h = m dt = 2.
  auto session = probe(SIM_STRATEGY_HIP);
  session->run(4);
  EXPECT_EQ(session->metrics.big_steps, 1);
  EXPECT_EQ(session->histogram[4], 1);
  std::vector<double> ra = values<double>(*session, "RA");
  std::vector<double> rc = values<double>(*session, "RC");
  std::vector<double> rh = values<double>(*session, "RH");
  for (int i = 0; i < 4; ++i) {
    SCOPED_TRACE("item " + std::to_string(i));
    double a = 2 + i;
    // linear: a + 8 f.
    EXPECT_EQ(std::vector<double>(ra.begin() + 4 * i, ra.begin() + 4 * i + 4),
              (std::vector<double>{a + 2, a + 4, a + 6, a + 8}));
    // cubic: s = f f (3 - 2 f) = 0.15625, 0.5, 0.84375, 1.
    EXPECT_EQ(std::vector<double>(rc.begin() + 4 * i, rc.begin() + 4 * i + 4),
              (std::vector<double>{a + 1.25, a + 4, a + 6.75, a + 8}));
    // hermite at f = 1/2: (1 + 1)(1/4) a + (1/2)(1/4) 2 va + (1/4)(2) b +
    // (1/4)(-1/2) 2 vb = a/2 + 1/4 + b/2 - 3/4 = a + 3.5; likewise a + 1.25
    // and a + 6 at 1/4 and 3/4.
    EXPECT_EQ(std::vector<double>(rh.begin() + 4 * i, rh.begin() + 4 * i + 4),
              (std::vector<double>{a + 1.25, a + 3.5, a + 6, a + 8}));
  }
  // Sink sub-stepped group by group: 4 items x 4 sub-steps.
  EXPECT_EQ(session->evaluations, (std::vector<int64_t>{4, 16, 4}));

  // Under simple every big step is one base step: reads are at its end.
  auto simple = probe(SIM_STRATEGY_SIMPLE);
  simple->run(4);
  ra = values<double>(*simple, "RA");
  rh = values<double>(*simple, "RH");
  EXPECT_EQ(std::vector<double>(ra.begin() + 4, ra.begin() + 8),
            (std::vector<double>{5, 7, 9, 11}));
  EXPECT_EQ(std::vector<double>(rh.begin() + 4, rh.begin() + 8),
            (std::vector<double>{5, 7, 9, 11}));
  EXPECT_EQ(simple->evaluations, (std::vector<int64_t>{16, 16, 16}));
}

TEST(ReferenceExecutor, AppliesBoundaryRules) {
  // Edge reads A (clamp), C (wrap) and H (zero) at i - 1 and i + 1, at the
  // end of the big step, where item j holds 10 + j.
  auto session = probe(SIM_STRATEGY_HIP);
  session->run(4);
  std::vector<double> e = values<double>(*session, "E");
  EXPECT_EQ(std::vector<double>(e.begin(), e.begin() + 6),
            (std::vector<double>{10, 11, 13, 11, 0, 11}));
  EXPECT_EQ(std::vector<double>(e.begin() + 18, e.begin() + 24),
            (std::vector<double>{12, 13, 12, 10, 12, 0}));
  // D's init body read A, declared after it: 2 + i - 1 - i.
  EXPECT_EQ(session->get("range"), "4");
  session->init();
  EXPECT_EQ(values<double>(*session, "D"), (std::vector<double>{1, 1, 1, 1}));
}

TEST(ReferenceExecutor, RefusesReadsItCannotServe) {
  auto session = probe(SIM_STRATEGY_HIP);
  session->set("read_none", "1");
  EXPECT_EQ(errorOf([&] { session->run(4); }, SIM_ERROR_BACKEND),
            "evaluate of component 'Sink' reads buffer 'N' (item 0) at base "
            "step 1 inside the big step [0, 4], but it has interp(none): its "
            "value means nothing there");
  // At the end of a big step interp(none) has its value.
  auto simple = probe(SIM_STRATEGY_SIMPLE);
  simple->set("read_none", "1");
  simple->run(4);

  // H's derivative L is written by Edge, after Sink.
  schema::BundleT lateDerivative = probeContents();
  lateDerivative.scene->buffers[3]->derivative = 5; // L
  auto late = probe(SIM_STRATEGY_HIP, lateDerivative);
  EXPECT_EQ(errorOf([&] { late->run(4); }, SIM_ERROR_BACKEND),
            "evaluate of component 'Sink' reads buffer 'H' (item 0) at base "
            "step 1 inside the big step [0, 4], but its hermite derivative "
            "'L' has no value at the end of the big step yet (its writer "
            "'Edge' runs later)");

  // A body that reads what its component's 'reads' does not list.
  schema::BundleT withoutH = probeContents();
  withoutH.reference->components[1]->reads = {1, 2, 4, 6, 7, 8};
  auto undeclared = probe(SIM_STRATEGY_HIP, withoutH);
  EXPECT_TRUE(contains(errorOf([&] { undeclared->run(4); }, SIM_ERROR_BACKEND),
                       "evaluate of component 'Sink' reads buffer 'H' (item "
                       "0) at base step 1, which the model's 'reads' of the "
                       "component does not list"));
}

TEST(ReferenceExecutor, DetectsCyclesInInitReads) {
  auto session = probe(SIM_STRATEGY_HIP);
  session->set("cycle", "1");
  EXPECT_EQ(errorOf([&] { session->init(); }, SIM_ERROR_BUNDLE),
            "the init bodies read each other in a cycle: A[0] -> C[0] -> A[0]");
}

TEST(ReferenceExecutor, SubStepsGridSyncComponentsOverTheWholeRange) {
  // The same reads, one group of all four items: the same values.
  schema::BundleT gridWide = probeContents();
  gridWide.reference->components[1]->sub_stepping =
      schema::SubStepping::GridSync;
  gridWide.reference->components[1]->stepping[2] =
      schema::Stepping(Advance::GridSubSteps, false);
  auto session = probe(SIM_STRATEGY_HIP, gridWide);
  session->run(4);
  std::vector<double> rc = values<double>(*session, "RC");
  EXPECT_EQ(std::vector<double>(rc.begin() + 12, rc.begin() + 16),
            (std::vector<double>{6.25, 9, 11.75, 13}));
  EXPECT_EQ(session->evaluations, (std::vector<int64_t>{4, 16, 4}));
}

//===----------------------------------------------------------------------===//
// Probes: the init check and totals of the exact solution
//===----------------------------------------------------------------------===//

namespace {

/// One result of sim_session_check_init, with its names copied.
struct InitRow {
  std::string buffer, component;
  sim_init_check found;
};

/// The init check of a session of `bytes` on `backend` through the C API,
/// after the settings `sets`.
std::vector<InitRow>
checkInitOf(const std::string &bytes, sim_backend backend,
            const std::vector<std::pair<std::string, std::string>> &sets = {},
            double tolerance = 0, int64_t maxItems = 0) {
  std::vector<InitRow> rows;
  sim_bundle *bundle = nullptr;
  if (sim_bundle_open_memory(bytes.data(), bytes.size(), &bundle) != SIM_OK) {
    ADD_FAILURE() << sim_last_error();
    return rows;
  }
  sim_session_options chosen = options(SIM_STRATEGY_HIP, backend);
  sim_session *session = nullptr;
  EXPECT_EQ(sim_session_create(bundle, &chosen, &session), SIM_OK)
      << sim_last_error();
  sim_bundle_close(bundle);
  if (!session)
    return rows;
  for (const auto &[name, value] : sets)
    EXPECT_EQ(sim_session_set(session, name.c_str(), value.c_str()), SIM_OK);
  int32_t count = -1;
  EXPECT_EQ(sim_session_check_init(session, tolerance, maxItems, &count),
            SIM_OK)
      << sim_last_error();
  for (int32_t i = 0; i < count; ++i) {
    InitRow row;
    EXPECT_EQ(sim_session_init_check(session, i, &row.found), SIM_OK);
    row.buffer = row.found.buffer;
    row.component = row.found.component;
    row.found.buffer = row.found.component = nullptr;
    rows.push_back(row);
  }
  sim_session_destroy(session);
  return rows;
}

std::string wrongDecayBundle() {
  return serialize(
      decayContents(false, true, SIM_TEST_DECAY_REFERENCE_WRONG_SO));
}

} // namespace

TEST(InitCheck, FindsTheBufferWhoseInitDisagreesWithItsWriter) {
  for (sim_backend backend : {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE}) {
    SCOPED_TRACE(sim_backend_name(backend));
    std::vector<InitRow> rows = checkInitOf(decayBundle(), backend);
    ASSERT_EQ(rows.size(), 2u);
    // X: Decay multiplies by (1 - k dt) zero times, exactly.
    EXPECT_EQ(rows[0].buffer, "X");
    EXPECT_EQ(rows[0].component, "Decay");
    const sim_init_check &x = rows[0].found;
    EXPECT_EQ(x.items, 100);
    EXPECT_EQ(x.count, 0);
    EXPECT_EQ(x.max_abs, 0);
    EXPECT_DOUBLE_EQ(x.scale, 1.99);
    EXPECT_EQ(x.tolerance, 1e-12);
    EXPECT_EQ(x.non_finite, 0);
    EXPECT_EQ(x.non_finite_item, -1);
    EXPECT_FALSE(x.interpolated);
    // V: Grow counts its evaluation in lane 2, also with n = 0.
    EXPECT_EQ(rows[1].buffer, "V");
    EXPECT_EQ(rows[1].component, "Grow");
    const sim_init_check &v = rows[1].found;
    EXPECT_EQ(v.count, 100);
    EXPECT_EQ(v.max_abs, 1);
    EXPECT_EQ(v.item, 0);
    EXPECT_EQ(v.lane, 2);
    EXPECT_EQ(v.initial, 0);
    EXPECT_EQ(v.evaluated, 1);
    EXPECT_EQ(v.scale, 99);
    EXPECT_EQ(v.tolerance, 1e-5);
  }
}

TEST(InitCheck, FindsOneItemOffByTheTolerance) {
  // The wrong reference adds 1e-6 to item 3 of X in every evaluation.
  std::vector<InitRow> rows = checkInitOf(wrongDecayBundle(), SIM_BACKEND_CPU);
  ASSERT_EQ(rows.size(), 2u);
  const sim_init_check &x = rows[0].found;
  EXPECT_EQ(x.count, 1);
  EXPECT_EQ(x.item, 3);
  EXPECT_EQ(x.lane, 0);
  EXPECT_NEAR(x.max_abs, 1e-6, 1e-15);
  EXPECT_EQ(x.initial, 1.03);
  EXPECT_NEAR(x.evaluated, 1.03 + 1e-6, 1e-15);

  // A tolerance relative to the buffer's largest value: V's difference of
  // 1 is 1/99 of it.
  rows = checkInitOf(decayBundle(), SIM_BACKEND_CPU, {}, 0.02);
  EXPECT_EQ(rows[1].found.count, 0);
  EXPECT_EQ(rows[1].found.tolerance, 0.02);
  rows = checkInitOf(decayBundle(), SIM_BACKEND_CPU, {}, 0.01);
  EXPECT_EQ(rows[1].found.count, 100);
}

TEST(InitCheck, EvaluatesTheFirstAndLastItemsOfALargeRange) {
  // 10 of 100 items: 0-4 and 95-99, so item 3 is among them.
  std::vector<InitRow> rows =
      checkInitOf(wrongDecayBundle(), SIM_BACKEND_CPU, {}, 0, 10);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].found.items, 10);
  EXPECT_EQ(rows[0].found.item, 3);
  EXPECT_EQ(rows[1].found.count, 10);
  // 4 items: 0, 1, 98 and 99.
  rows = checkInitOf(wrongDecayBundle(), SIM_BACKEND_CPU, {}, 0, 4);
  EXPECT_EQ(rows[0].found.count, 0);
  EXPECT_DOUBLE_EQ(rows[0].found.scale, 1.99);
  EXPECT_EQ(rows[1].found.count, 4);
  // Above 2^20 items the initial states it reads are kept item by item:
  // 3 million items cost only those it evaluates.
  rows = checkInitOf(wrongDecayBundle(), SIM_BACKEND_CPU,
                     {{"range", "3000000"}}, 0, 8);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].found.items, 8);
  EXPECT_EQ(rows[0].found.count, 1);
  EXPECT_EQ(rows[0].found.item, 3);
  EXPECT_DOUBLE_EQ(rows[0].found.scale, 1.0 + 0.01 * 2999999);
}

TEST(InitCheck, UsesTheSessionsSettingsAndReportsNonFiniteValues) {
  // poison = 0: Decay yields NaN at item 7 from t = 0 on, also with n = 0.
  std::vector<InitRow> rows = checkInitOf(decayBundle(), SIM_BACKEND_REFERENCE,
                                          {{"poison", "0"}, {"range", "20"}});
  ASSERT_EQ(rows.size(), 2u);
  const sim_init_check &x = rows[0].found;
  EXPECT_EQ(x.items, 20);
  EXPECT_EQ(x.non_finite, 1);
  EXPECT_EQ(x.non_finite_item, 7);
  EXPECT_EQ(x.count, 0);
}

TEST(InitCheck, LeavesTheSessionsStateAsItWas) {
  auto bundle = parseBytes(decayBundle());
  ReferenceSession session(bundle,
                           options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
  session.run(10);
  std::vector<double> before = values<double>(session, "X");
  std::vector<InitCheck> rows = session.checkInit(0, 0);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].count, 100);
  EXPECT_EQ(session.time(), 10);
  EXPECT_EQ(values<double>(session, "X"), before);
  session.run(5);
  EXPECT_EQ(session.time(), 15);
}

TEST(InitCheck, StopsWhenTheSessionIsInterrupted) {
  // The check evaluates every item on the host, which takes a while on a
  // large scene: sim_session_interrupt ends it, as it ends a run.
  std::string bytes = decayBundle();
  sim_bundle *bundle = nullptr;
  ASSERT_EQ(sim_bundle_open_memory(bytes.data(), bytes.size(), &bundle),
            SIM_OK);
  sim_session_options chosen = options(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  sim_session *session = nullptr;
  ASSERT_EQ(sim_session_create(bundle, &chosen, &session), SIM_OK);
  int32_t count = -1;
  sim_session_interrupt(session);
  EXPECT_EQ(sim_session_check_init(session, 0, 0, &count),
            SIM_ERROR_INTERRUPTED);
  EXPECT_EQ(std::string(sim_last_error()), "interrupted during the init check");
  EXPECT_EQ(count, 0);
  sim_session_resume(session);
  EXPECT_EQ(sim_session_check_init(session, 0, 0, &count), SIM_OK);
  EXPECT_EQ(count, 2);
  sim_session_destroy(session);
  sim_bundle_close(bundle);
}

TEST(InitCheck, RefusesBadArgumentsAndBundlesWithoutAReference) {
  std::string bytes = decayBundle(false, false);
  sim_bundle *bundle = nullptr;
  ASSERT_EQ(sim_bundle_open_memory(bytes.data(), bytes.size(), &bundle),
            SIM_OK);
  sim_session_options chosen = options(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  sim_session *session = nullptr;
  ASSERT_EQ(sim_session_create(bundle, &chosen, &session), SIM_OK);
  int32_t count = -1;
  EXPECT_EQ(sim_session_check_init(session, 0, 0, &count), SIM_ERROR_BUNDLE);
  EXPECT_EQ(count, 0);
  EXPECT_EQ(std::string(sim_last_error()),
            "bundle '<memory>' has no reference model and functions");
  EXPECT_EQ(sim_session_check_init(session, -1, 0, &count),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sim_session_check_init(session, NAN, 0, &count),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sim_session_check_init(session, 0, -1, &count),
            SIM_ERROR_INVALID_ARGUMENT);
  sim_init_check found;
  EXPECT_EQ(sim_session_init_check(session, 0, &found),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(sim_last_error()),
            "init check result 0 is out of range (0 results)");
  sim_session_destroy(session);
  sim_bundle_close(bundle);
}

namespace {

/// The decay scene with two totals in its reference model: Mass, the sum
/// of X (which has an exact solution), and Steps, the sum of V's lane 0
/// (which has none).
std::string decayWithTotals() {
  schema::BundleT contents = decayContents();
  for (const char *name : {"Mass", "Steps"}) {
    auto total = std::make_unique<schema::TotalT>();
    total->name = name;
    total->type = schema::ScalarType::F64;
    contents.scene->totals.push_back(std::move(total));
  }
  for (uint32_t t = 0; t < 2; ++t) {
    auto total = std::make_unique<schema::RefTotalT>();
    total->total = t;
    total->reads = {t};
    contents.reference->totals.push_back(std::move(total));
  }
  return serialize(contents);
}

} // namespace

TEST(ExactTotals, SumTheBodyOverTheExactSolution) {
  std::string bytes = decayWithTotals();
  sim_bundle *bundle = nullptr;
  ASSERT_EQ(sim_bundle_open_memory(bytes.data(), bytes.size(), &bundle), SIM_OK)
      << sim_last_error();
  double expected = 0;
  for (int i = 0; i < 100; ++i)
    expected += (1.0 + 0.01 * i) * std::exp(-1.5 * 0.01 * 10);
  for (sim_backend backend : {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE}) {
    SCOPED_TRACE(sim_backend_name(backend));
    sim_session_options chosen = options(SIM_STRATEGY_HIP, backend);
    sim_session *session = nullptr;
    ASSERT_EQ(sim_session_create(bundle, &chosen, &session), SIM_OK)
        << sim_last_error();
    ASSERT_EQ(sim_session_set(session, "k", "1.5"), SIM_OK);
    ASSERT_EQ(sim_session_run(session, 10), SIM_OK);
    EXPECT_TRUE(sim_session_has_exact_total(session, "Mass"));
    EXPECT_FALSE(sim_session_has_exact_total(session, "Steps"));
    EXPECT_FALSE(sim_session_has_exact_total(session, "Q"));
    double value = 0;
    ASSERT_EQ(sim_session_exact_total(session, "Mass", &value), SIM_OK)
        << sim_last_error();
    EXPECT_NEAR(value, expected, 1e-12);
    EXPECT_EQ(sim_session_exact_total(session, "Steps", &value),
              SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(std::string(sim_last_error()),
              "total 'Steps' reads buffer 'V', which has no exact solution");
    EXPECT_EQ(sim_session_exact_total(session, "Q", &value),
              SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(std::string(sim_last_error()),
              "'Q' is not a total of scene 'decay'");
    // The state is untouched.
    EXPECT_EQ(sim_session_time(session), 10);
    if (backend == SIM_BACKEND_REFERENCE) {
      // The reference executor computes the totals of its state as well.
      EXPECT_EQ(sim_session_num_totals(session), 2);
      double steps = 0;
      ASSERT_EQ(sim_session_total(session, "Steps", &steps), SIM_OK);
      EXPECT_EQ(steps, 100 * 10);
    }
    sim_session_destroy(session);
  }
  sim_bundle_close(bundle);

  bytes = decayBundle(false, false);
  ASSERT_EQ(sim_bundle_open_memory(bytes.data(), bytes.size(), &bundle),
            SIM_OK);
  sim_session_options chosen = options(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  sim_session *session = nullptr;
  ASSERT_EQ(sim_session_create(bundle, &chosen, &session), SIM_OK);
  double value = 0;
  EXPECT_EQ(sim_session_exact_total(session, "Mass", &value),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(std::string(sim_last_error()),
            "bundle '<memory>' has no reference model to tell which buffers "
            "total 'Mass' reads");
  sim_session_destroy(session);
  sim_bundle_close(bundle);
}

TEST(Settings, MaxStepsIsFixedInTheBundle) {
  auto bundle = parseBytes(decayBundle(), "decay.simb");
  Session session(bundle, options(SIM_STRATEGY_HIP, SIM_BACKEND_CPU));
  EXPECT_EQ(session.get("max_steps"), "4");
  session.set("max_steps", "4");
  EXPECT_EQ(errorOf([&] { session.set("max_steps", "6"); },
                    SIM_ERROR_INVALID_ARGUMENT),
            "max_steps is fixed when a scene is compiled (bundle "
            "'decay.simb' has 4): compile the scene with sim-translate "
            "--sim-to-bundle --sim-set-params=max_steps=6, or give sim-run "
            "the .mlir scene");
  EXPECT_TRUE(contains(errorOf([&] { session.set("max_steps", "x"); },
                               SIM_ERROR_INVALID_ARGUMENT),
                       "max_steps"));
}
