//===- ReferenceTest.cpp - the reference model and the reference executor -===//
//
// The model text against each malformation, the reference sections of a
// bundle, and the executor: on the decay scene it agrees with the CPU
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

/// `text` with the first `from` replaced by `to`.
std::string replace(std::string text, const std::string &from,
                    const std::string &to) {
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

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

Scene decayScene_() { return parseScene(decayScene()); }

} // namespace

//===----------------------------------------------------------------------===//
// The model text
//===----------------------------------------------------------------------===//

TEST(ReferenceModelText, ParsesTheDecayModel) {
  ReferenceModel model =
      parseReferenceModel(decayReferenceModel(), decayScene_());
  EXPECT_EQ(model.scene, "decay");
  ASSERT_EQ(model.params.size(), 2u);
  EXPECT_EQ(model.params[1].name, "poison");
  EXPECT_EQ(model.params[1].sceneParam, 1);
  ASSERT_EQ(model.buffers.size(), 2u);
  EXPECT_EQ(model.buffers[0].interp, Interp::Linear);
  EXPECT_TRUE(model.buffers[0].exact);
  EXPECT_EQ(model.buffers[1].type.lanes, 3);
  EXPECT_EQ(model.buffers[1].interp, Interp::None);
  EXPECT_EQ(model.buffers[0].writer, 0);
  EXPECT_EQ(model.buffers[1].writer, 1);
  ASSERT_EQ(model.components.size(), 2u);
  EXPECT_TRUE(model.components[0].numSteps);
  EXPECT_FALSE(model.components[1].numSteps);
  EXPECT_EQ(model.components[0].reads, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(model.schedule, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(model.components[1].position, 1);

  ReferenceModel probe =
      parseReferenceModel(probeModel(), parseScene(probeScene()));
  EXPECT_EQ(probe.buffers[3].interp, Interp::Hermite);
  EXPECT_EQ(probe.buffers[3].derivative, 0);
  EXPECT_EQ(probe.buffers[2].boundary, Boundary::Wrap);
  EXPECT_EQ(probe.buffers[3].boundary, Boundary::Zero);
  EXPECT_TRUE(probe.components[0].reads.empty());
  EXPECT_EQ(probe.buffers[5].writer, 2);
}

TEST(ReferenceModelText, ReadsTotals) {
  std::string text =
      replace(decayReferenceModel(), "schedule Decay Grow\n",
              "total 0 Energy f64 reads X V\ntotal 1 Count f32 reads\n"
              "schedule Decay Grow\n");
  ReferenceModel model = parseReferenceModel(text, decayScene_());
  ASSERT_EQ(model.totals.size(), 2u);
  EXPECT_EQ(model.totals[0].name, "Energy");
  EXPECT_EQ(model.totals[0].type, ScalarType::F64);
  EXPECT_EQ(model.totals[0].reads, (std::vector<int32_t>{0, 1}));
  EXPECT_EQ(model.totals[1].type, ScalarType::F32);
  EXPECT_TRUE(model.totals[1].reads.empty());

  struct Case {
    std::string from, to, message;
  } cases[] = {
      {"total 1 Count", "total 0 Count", "total index 0 is out of order"},
      {"Count f32", "Count i64", "total type 'i64' is not f32 or f64"},
      {"total 1 Count", "total 1 Energy", "total 'Energy' is declared twice"},
      {"f64 reads X V", "f64 reads X W",
       "total 'Energy' reads 'W', which is not a buffer declared before it"},
      {"Energy f64 reads", "Energy f64 sees", "expected 'reads'"},
  };
  for (const Case &c : cases) {
    std::string message = errorOf(
        [&] {
          parseReferenceModel(replace(text, c.from, c.to), decayScene_());
        },
        SIM_ERROR_BUNDLE);
    EXPECT_TRUE(contains(message, c.message)) << c.message << "\n" << message;
  }
}

TEST(ReferenceModelText, RejectsWhatDoesNotParse) {
  const std::string model = decayReferenceModel();
  struct Case {
    std::string text, message;
  } cases[] = {
      {replace(model, "reference decay\n", ""),
       "line 2: expected the 'reference' record first, found 'param'"},
      {replace(model, "reference decay", "reference rod"),
       "line 2: the model is of scene 'rod' but the bundle's scene is 'decay'"},
      {replace(model, "param 1 poison", "param 0 poison"),
       "line 4: param index 0 is out of order (expected 1"},
      {replace(model, "param 1 poison i32", "param 1 poison f32"),
       "line 4: parameter 'poison' has type f32 but the scene says i32"},
      {replace(model, "param 1 poison", "param 1 speed"),
       "line 4: parameter 'speed' is not a parameter of scene 'decay'"},
      {replace(model, "buffer 1 V", "buffer 2 V"),
       "line 6: buffer index 2 is out of order (expected 1"},
      {replace(model, "buffer 1 V vector<3xf32>", "buffer 1 V vector<3xi32>"),
       "line 6: element type 'vector<3xi32>' is not f32, f64"},
      {replace(model, "buffer 1 V vector<3xf32>", "buffer 1 V vector<4xf32>"),
       "line 6: buffer 'V' has element type vector<4xf32> but the scene says "
       "vector<3xf32>"},
      {replace(model, "buffer 1 V", "buffer 1 X"),
       "line 6: buffer 'X' is declared twice"},
      {replace(model, "interp none", "interp spline"),
       "line 6: interpolation 'spline' is not linear, cubic, hermite:<buffer> "
       "or none"},
      {replace(model, "boundary clamp observed\n", "boundary mirror\n"),
       "line 6: boundary 'mirror' is not clamp, wrap or zero"},
      {replace(model, "observed exact", "observed observed"),
       "line 5: buffer flag 'observed' is repeated"},
      {replace(model, "interp linear", "interp hermite:W"),
       "line 5: buffer 'X' interpolates with the derivative 'W', which is "
       "not a buffer of the model"},
      {replace(model, "interp linear", "interp hermite:V"),
       "line 5: buffer 'X' interpolates with the derivative 'V', whose "
       "element type vector<3xf32> differs from f64"},
      {replace(model, "reads X V", "reads X W"),
       "line 7: component 'Decay' reads 'W', which is not a buffer declared "
       "before it"},
      {replace(model, "writes X reads", "writes Y reads"),
       "line 7: component 'Decay' writes 'Y', which is not a buffer"},
      {replace(model, "writes X reads", "writes reads"),
       "line 7: component 'Decay' writes no buffer"},
      {replace(model, "reads X V", "X V"), "line 7: expected 'reads'"},
      {replace(model, "reads X V", "reads X X"),
       "line 7: component 'Decay' lists 'X' twice in 'reads'"},
      {replace(model, "substep in_kernel num_steps", "substep warp"),
       "line 7: substep 'warp' is not in_kernel or grid_sync"},
      {replace(model, "writes V reads V", "writes X reads V"),
       "line 8: buffer 'X' is written by both 'Decay' and 'Grow'"},
      {replace(model, "component 1 Grow", "component 0 Grow"),
       "line 8: component index 0 is out of order"},
      {replace(model, "component 1 Grow", "component 1 Decay"),
       "line 8: component 'Decay' is declared twice"},
      {replace(model, "schedule Decay Grow\n", ""), "no 'schedule' record"},
      {replace(model, "schedule Decay Grow", "schedule Decay"),
       "line 9: component 'Grow' is not in the schedule"},
      {replace(model, "schedule Decay Grow", "schedule Decay Grow Decay"),
       "line 9: schedule names 'Decay' twice"},
      {replace(model, "schedule Decay Grow", "schedule Decay Grow Shrink"),
       "line 9: schedule names 'Shrink', which is not a component"},
      {model + "param 2 k f64\n",
       "line 10: 'param' after 'schedule', which comes last"},
      {replace(model, "schedule", "order"), "line 9: unknown record 'order'"},
      {"", "no 'reference' record"},
  };
  for (const Case &c : cases) {
    std::string message = errorOf(
        [&] { parseReferenceModel(c.text, decayScene_()); }, SIM_ERROR_BUNDLE);
    EXPECT_TRUE(contains(message, "reference model section"))
        << c.message << "\n"
        << message;
    EXPECT_TRUE(contains(message, c.message)) << c.message << "\n" << message;
  }
}

//===----------------------------------------------------------------------===//
// The reference sections of a bundle
//===----------------------------------------------------------------------===//

TEST(ReferenceSections, AreReadWhenBothArePresent) {
  auto bundle = parseBytes(decayBundle());
  ASSERT_TRUE(bundle->reference.has_value());
  EXPECT_EQ(bundle->reference->components.size(), 2u);
  ASSERT_TRUE(bundle->referenceObject.has_value());
  EXPECT_FALSE(parseBytes(decayBundle(false, false))->reference.has_value());
}

TEST(ReferenceSections, AreRejectedWhenMalformed) {
  auto error = [](const std::vector<Section> &sections) {
    return errorOf([&] { parseBytes(writeBundle(sections)); },
                   SIM_ERROR_BUNDLE);
  };
  std::vector<Section> base = decaySections();
  std::vector<Section> reference = decayReferenceSections();

  std::vector<Section> sections = base;
  sections.push_back(reference[0]);
  EXPECT_TRUE(contains(error(sections),
                       "a reference model section without a reference object "
                       "section (docs/Reference.md: both or neither)"));
  sections = base;
  sections.push_back(reference[1]);
  EXPECT_TRUE(contains(error(sections),
                       "a reference object section without a reference model "
                       "section"));

  sections = base;
  sections.insert(sections.end(), {reference[0], reference[1], reference[0]});
  EXPECT_TRUE(contains(error(sections), "repeated reference model section"));

  sections = base;
  sections.insert(sections.end(), {reference[0], reference[1]});
  sections[5].strategy = kHip;
  EXPECT_TRUE(contains(error(sections),
                       "section 5 (reference model) has strategy 2 but a "
                       "reference model section has none (0xffffffff)"));

  sections = base;
  sections.insert(sections.end(), {reference[0], reference[1]});
  sections[6].bytes = std::string(100, 'x');
  EXPECT_TRUE(contains(error(sections),
                       "reference object section is not an ELF shared object"));

  sections = base;
  sections.insert(
      sections.end(),
      {{kReferenceModel, kNoStrategy, "reference decay\n"}, reference[1]});
  EXPECT_TRUE(contains(error(sections),
                       "bundle 'test.simb': reference model section: no "
                       "'schedule' record"));

  sections = base;
  sections.push_back({7, kNoStrategy, "x"});
  EXPECT_TRUE(contains(error(sections), "section 5 has unknown kind 7"));
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
  std::vector<Section> sections = decaySections();
  sections.push_back(
      {kReferenceModel, kNoStrategy,
       replace(decayReferenceModel(), "Grow substep in_kernel writes",
               "Grow substep in_kernel num_steps writes")});
  sections.push_back(decayReferenceSections()[1]);
  auto bundle = parseBytes(writeBundle(sections));
  EXPECT_EQ(errorOf(
                [&] {
                  ReferenceSession(
                      bundle, options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
                },
                SIM_ERROR_BACKEND),
            "the reference functions do not export sim_ref_num_steps_1 (the "
            "num_steps body of component 'Grow')");
}

TEST(ReferenceExecutor, NeedsTheReferenceSections) {
  auto bundle = parseBytes(decayBundle(false, false));
  EXPECT_EQ(errorOf(
                [&] {
                  ReferenceSession(
                      bundle, options(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE));
                },
                SIM_ERROR_BUNDLE),
            "bundle 'test.simb' has no reference sections (made before the "
            "reference executor existed; rebuild it with sim-translate "
            "--sim-to-bundle)");
}

//===----------------------------------------------------------------------===//
// The executor on the probe scene
//===----------------------------------------------------------------------===//

namespace {

std::unique_ptr<ReferenceSession>
probe(sim_strategy strategy, const std::string &model = probeModel()) {
  return std::make_unique<ReferenceSession>(
      parseBytes(probeBundle(model)),
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
  auto late =
      probe(SIM_STRATEGY_HIP, replace(probeModel(), "hermite:D", "hermite:L"));
  EXPECT_EQ(errorOf([&] { late->run(4); }, SIM_ERROR_BACKEND),
            "evaluate of component 'Sink' reads buffer 'H' (item 0) at base "
            "step 1 inside the big step [0, 4], but its hermite derivative "
            "'L' has no value at the end of the big step yet (its writer "
            "'Edge' runs later)");

  // A body that reads what its component's 'reads' does not list.
  auto undeclared =
      probe(SIM_STRATEGY_HIP, replace(probeModel(), "reads A C H N RA RC RH",
                                      "reads A C N RA RC RH"));
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
  auto session =
      probe(SIM_STRATEGY_HIP, replace(probeModel(), "Sink substep in_kernel",
                                      "Sink substep grid_sync"));
  session->run(4);
  std::vector<double> rc = values<double>(*session, "RC");
  EXPECT_EQ(std::vector<double>(rc.begin() + 12, rc.begin() + 16),
            (std::vector<double>{6.25, 9, 11.75, 13}));
  EXPECT_EQ(session->evaluations, (std::vector<int64_t>{4, 16, 4}));
}
