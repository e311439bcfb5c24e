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
