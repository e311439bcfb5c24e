//===- TestBundle.cpp - bundles for the runtime's tests -------------------===//

#include "TestBundle.h"

#include "sim/Runtime/BundleFormat.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <zlib.h>

namespace sim::test {

using namespace schema;

std::string withHeader(const std::string &payload) {
  uint32_t crc = uint32_t(crc32(0L, Z_NULL, 0));
  crc = uint32_t(crc32(crc, reinterpret_cast<const Bytef *>(payload.data()),
                       uInt(payload.size())));
  Header header;
  header.checksum = crc;
  header.size = kHeaderSize + payload.size();
  return encodeHeader(header) + payload;
}

std::string serialize(const BundleT &contents) {
  flatbuffers::FlatBufferBuilder builder;
  FinishBundleBuffer(builder, Bundle::Pack(builder, &contents));
  return withHeader(
      std::string(reinterpret_cast<const char *>(builder.GetBufferPointer()),
                  builder.GetSize()));
}

std::string readFile(const std::string &path) {
  std::ifstream file(path, std::ios::binary);
  if (!file)
    throw std::runtime_error("cannot read " + path);
  std::ostringstream contents;
  contents << file.rdbuf();
  return contents.str();
}

void writeFile(const std::string &path, const std::string &bytes) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(bytes.data(), std::streamsize(bytes.size()));
  if (!file)
    throw std::runtime_error("cannot write " + path);
}

namespace {

std::vector<uint8_t> readBytes(const std::string &path) {
  std::string bytes = readFile(path);
  return std::vector<uint8_t>(bytes.begin(), bytes.end());
}

std::unique_ptr<ParamT> param(const std::string &name, ScalarType type,
                              int64_t i, double f) {
  auto result = std::make_unique<ParamT>();
  result->name = name;
  result->value = std::make_unique<Value>(i, f, type);
  return result;
}

std::unique_ptr<BufferT> buffer(const std::string &name, ScalarType scalar,
                                uint16_t lanes, Interp interp,
                                Boundary boundary, bool observed,
                                bool exact = false, int32_t derivative = -1) {
  auto result = std::make_unique<BufferT>();
  result->name = name;
  result->element = std::make_unique<Element>(scalar, lanes);
  result->interp = interp;
  result->derivative = derivative;
  result->boundary = boundary;
  result->observed = observed;
  result->exact = exact;
  return result;
}

KernelParam memref(ScalarType scalar, uint16_t lanes, uint32_t stride) {
  return KernelParam(ParamType::Memref, Element(scalar, lanes), stride);
}

KernelParam scalar(ParamType type) { return KernelParam(type, Element(), 0); }

const KernelParam kClock = memref(ScalarType::I64, 1, 8);
const KernelParam kRange = scalar(ParamType::I64);

std::unique_ptr<KernelT> kernel(const std::string &name,
                                std::vector<KernelParam> params,
                                uint32_t clockSlots) {
  auto result = std::make_unique<KernelT>();
  result->name = name;
  result->params = std::move(params);
  result->clock_slots = clockSlots;
  return result;
}

std::unique_ptr<StepT> launch(uint32_t kernel, LaunchShape shape,
                              int32_t component, std::vector<Arg> args) {
  auto step = std::make_unique<StepT>();
  step->launch = std::make_unique<LaunchT>();
  step->launch->kernel = kernel;
  step->launch->shape = shape;
  step->launch->component = component;
  step->launch->args = std::move(args);
  return step;
}

std::unique_ptr<PhaseT> phase(PhaseKind kind,
                              std::vector<std::unique_ptr<StepT>> steps) {
  auto result = std::make_unique<PhaseT>();
  result->kind = kind;
  result->body = std::move(steps);
  return result;
}

template <typename T, typename... Rest>
std::vector<std::unique_ptr<T>> list(std::unique_ptr<T> first, Rest... rest) {
  std::vector<std::unique_ptr<T>> result;
  result.push_back(std::move(first));
  (result.push_back(std::move(rest)), ...);
  return result;
}

std::unique_ptr<ComponentT> component(const std::string &name,
                                      std::vector<uint32_t> writes,
                                      uint32_t evaluations, bool estimates) {
  auto result = std::make_unique<ComponentT>();
  result->name = name;
  result->writes = std::move(writes);
  result->evaluations = evaluations;
  result->advance = Advance::WholeStep;
  result->estimates = estimates;
  return result;
}

Arg arg(ArgKind kind, uint32_t index = 0) { return Arg(kind, index); }

/// The decay scene's plan of simple or hip (kernels/decay.c).
std::unique_ptr<PlanT> decayPlan(Strategy strategy, bool ptx) {
  bool hip = strategy == Strategy::Hip;
  auto plan = std::make_unique<PlanT>();
  plan->strategy = strategy;
  plan->group_size = 32;
  plan->step_cap = hip ? 4 : 1;
  plan->clock_slots = 16;
  plan->histogram = 10;
  for (auto [index, stride] : {std::pair{0u, 8u}, {1u, 16u}}) {
    auto planBuffer = std::make_unique<PlanBufferT>();
    planBuffer->buffer = index;
    planBuffer->stride = stride;
    plan->buffers.push_back(std::move(planBuffer));
  }
  plan->components.push_back(component("Decay", {0}, 8, hip));
  plan->components.push_back(component("Grow", {1}, 9, false));

  const uint32_t slots = plan->clock_slots;
  KernelParam x = memref(ScalarType::F64, 1, 8);
  KernelParam v = memref(ScalarType::F32, 3, 16);
  KernelParam f64 = scalar(ParamType::F64), i32 = scalar(ParamType::I32);
  enum : uint32_t {
    kReset,
    kInitX,
    kInitV,
    kAdvance,
    kEvaluateDecay,
    kEvaluateGrow,
    kExactX,
    kEstimateDecay
  };
  plan->kernels.push_back(kernel("reset_clock", {kClock}, slots));
  plan->kernels.push_back(kernel("init_X", {x, kRange}, slots));
  plan->kernels.push_back(kernel("init_V", {v, kRange}, slots));
  plan->kernels.push_back(kernel("advance", {kClock}, slots));
  plan->kernels.push_back(
      kernel("evaluate_Decay", {kClock, x, f64, i32, kRange, f64}, slots));
  plan->kernels.push_back(kernel("evaluate_Grow", {kClock, v, kRange}, slots));
  plan->kernels.push_back(kernel("exact_X", {x, f64, kRange, f64}, slots));
  if (hip)
    plan->kernels.push_back(kernel("estimate_Decay", {kClock, kRange}, slots));

  plan->phases.push_back(
      phase(PhaseKind::Init,
            list(launch(kReset, LaunchShape::Single, -1, {arg(ArgKind::Clock)}),
                 launch(kInitX, LaunchShape::Items, -1,
                        {arg(ArgKind::Buffer, 0), arg(ArgKind::Range)}),
                 launch(kInitV, LaunchShape::Items, -1,
                        {arg(ArgKind::Buffer, 1), arg(ArgKind::Range)}))));
  std::vector<std::unique_ptr<StepT>> step;
  if (hip)
    step.push_back(launch(kEstimateDecay, LaunchShape::Items, -1,
                          {arg(ArgKind::Clock), arg(ArgKind::Range)}));
  step.push_back(
      launch(kAdvance, LaunchShape::Single, -1, {arg(ArgKind::Clock)}));
  step.push_back(launch(kEvaluateDecay, LaunchShape::Items, 0,
                        {arg(ArgKind::Clock), arg(ArgKind::Buffer, 0),
                         arg(ArgKind::Param, 0), arg(ArgKind::Param, 1),
                         arg(ArgKind::Range), arg(ArgKind::Dt)}));
  step.push_back(launch(
      kEvaluateGrow, LaunchShape::Items, 1,
      {arg(ArgKind::Clock), arg(ArgKind::Buffer, 1), arg(ArgKind::Range)}));
  plan->phases.push_back(phase(PhaseKind::Step, std::move(step)));
  plan->phases.push_back(phase(
      PhaseKind::Finish,
      list(launch(kAdvance, LaunchShape::Single, -1, {arg(ArgKind::Clock)}))));
  plan->phases.push_back(
      phase(PhaseKind::Exact,
            list(launch(kExactX, LaunchShape::Items, -1,
                        {arg(ArgKind::Exact, 0), arg(ArgKind::Param, 0),
                         arg(ArgKind::Range), arg(ArgKind::Time)}))));

  if (ptx) {
    plan->ptx = "// not real PTX\n";
    plan->ptx_chip = "sm_90";
  }
  auto cpu = std::make_unique<CpuCodeT>();
  cpu->isa = "x86-64";
  cpu->object =
      readBytes(hip ? SIM_TEST_DECAY_HIP_SO : SIM_TEST_DECAY_SIMPLE_SO);
  plan->cpu.push_back(std::move(cpu));
  return plan;
}

/// `advance` and `estimates` of a component under every strategy.
std::vector<Stepping> stepping(Stepping simple, Stepping traditional,
                               Stepping hip) {
  // hip-cache and lts plan as hip here: nothing reads its own neighbours.
  return {simple, traditional, hip, hip, hip};
}

std::unique_ptr<RefComponentT> refComponent(const std::string &name,
                                            bool numSteps,
                                            std::vector<uint32_t> writes,
                                            std::vector<uint32_t> reads,
                                            std::vector<Stepping> steps) {
  auto result = std::make_unique<RefComponentT>();
  result->name = name;
  result->sub_stepping = SubStepping::InKernel;
  result->num_steps = numSteps;
  result->writes = std::move(writes);
  result->reads = std::move(reads);
  result->stepping = std::move(steps);
  return result;
}

} // namespace

BundleT decayContents(bool ptx, bool reference,
                      const std::string &referenceObject) {
  BundleT contents;
  contents.producer = "runtime/test/TestBundle.cpp";
  auto scene = std::make_unique<SceneT>();
  scene->name = "decay";
  scene->range = 100;
  scene->dt = std::make_unique<Value>(0, 0.01, ScalarType::F64);
  scene->max_steps = 4;
  scene->params.push_back(param("k", ScalarType::F64, 0, 2));
  scene->params.push_back(param("poison", ScalarType::I32, -1, 0));
  scene->buffers.push_back(buffer("X", ScalarType::F64, 1, Interp::Linear,
                                  Boundary::Clamp, true, true));
  scene->buffers.push_back(
      buffer("V", ScalarType::F32, 3, Interp::None, Boundary::Clamp, true));
  contents.scene = std::move(scene);
  contents.plans.push_back(decayPlan(Strategy::Simple, ptx));
  contents.plans.push_back(decayPlan(Strategy::Hip, ptx));
  if (!reference)
    return contents;

  // Decay reads V, which Grow writes later: it bounds the hip big step.
  auto model = std::make_unique<ReferenceT>();
  model->params = {0, 1};
  model->buffers = {0, 1};
  Stepping whole(Advance::WholeStep, false),
      estimating(Advance::WholeStep, true);
  model->components.push_back(refComponent(
      "Decay", true, {0}, {0, 1}, stepping(whole, estimating, estimating)));
  model->components.push_back(
      refComponent("Grow", false, {1}, {1}, stepping(whole, whole, whole)));
  model->step_caps = {1, 4, 4, 4, 4};
  model->object = readBytes(referenceObject);
  model->isa = "x86-64";
  contents.reference = std::move(model);
  return contents;
}

std::string decayBundle(bool ptx, bool reference) {
  return serialize(decayContents(ptx, reference));
}

BundleT ringContents(Boundary boundary, bool gather) {
  BundleT contents;
  contents.producer = "runtime/test/TestBundle.cpp";
  auto scene = std::make_unique<SceneT>();
  scene->name = "ring";
  scene->range = 100;
  scene->dt = std::make_unique<Value>(0, 0.01, ScalarType::F64);
  scene->max_steps = 4;
  scene->buffers.push_back(
      buffer("X", ScalarType::F64, 1, Interp::Linear, boundary, true));
  if (gather)
    scene->buffers.push_back(buffer("Y", ScalarType::F64, 1, Interp::Linear,
                                    Boundary::Clamp, true, true));
  auto total = std::make_unique<TotalT>();
  total->name = "sum_X";
  total->type = ScalarType::F64;
  scene->totals.push_back(std::move(total));
  contents.scene = std::move(scene);

  auto plan = std::make_unique<PlanT>();
  plan->strategy = Strategy::Hip;
  plan->group_size = 4;
  plan->step_cap = 4;
  plan->clock_slots = 16;
  plan->histogram = 10;
  plan->distributed = std::make_unique<DistributionT>();
  plan->distributed->halo = 2;
  auto planBuffer = std::make_unique<PlanBufferT>();
  planBuffer->buffer = 0;
  planBuffer->stride = 8;
  planBuffer->halo_below = 2;
  planBuffer->halo_above = 2;
  plan->buffers.push_back(std::move(planBuffer));
  plan->components.push_back(component("Mix", {0}, 8, true));
  plan->totals = {0};
  if (gather) {
    // Read at every item: whole on every rank, no halo.
    planBuffer = std::make_unique<PlanBufferT>();
    planBuffer->buffer = 1;
    planBuffer->stride = 8;
    planBuffer->replicated = true;
    plan->buffers.push_back(std::move(planBuffer));
    plan->components.push_back(component("Pull", {1}, 9, false));
  }

  const uint32_t slots = plan->clock_slots;
  KernelParam x = memref(ScalarType::F64, 1, 8);
  KernelParam i64 = scalar(ParamType::I64), f64 = scalar(ParamType::F64);
  enum : uint32_t {
    kReset,
    kInit,
    kEstimate,
    kAdvance,
    kEvaluate,
    kTotal,
    kInitY,
    kPull,
    kExactY
  };
  plan->kernels.push_back(kernel("reset_clock", {kClock}, slots));
  plan->kernels.push_back(kernel("init_X", {x, i64, i64, kRange}, slots));
  plan->kernels.push_back(
      kernel("estimate", {kClock, i64, i64, kRange}, slots));
  plan->kernels.push_back(kernel("advance", {kClock}, slots));
  plan->kernels.push_back(
      kernel("evaluate", {kClock, x, i64, i64, kRange, f64}, slots));
  plan->kernels.push_back(kernel(
      "total_X", {memref(ScalarType::F64, 1, 8), kClock, x, i64, i64, kRange},
      slots));
  if (gather) {
    plan->kernels.push_back(kernel("init_Y", {x, i64, i64, kRange}, slots));
    plan->kernels.push_back(
        kernel("pull", {kClock, x, i64, i64, kRange, f64}, slots));
    plan->kernels.push_back(
        kernel("exact_Y", {x, i64, i64, kRange, f64}, slots));
  }
  Arg first = arg(ArgKind::First), extent = arg(ArgKind::Extent);
  plan->phases.push_back(
      phase(PhaseKind::Init,
            list(launch(kReset, LaunchShape::Single, -1, {arg(ArgKind::Clock)}),
                 launch(kInit, LaunchShape::Items, -1,
                        {arg(ArgKind::Buffer, 0), first, extent,
                         arg(ArgKind::Range)}))));
  if (gather)
    // No exchange recorded: the session's refresh after init completes Y.
    plan->phases.back()->body.push_back(
        launch(kInitY, LaunchShape::Items, -1,
               {arg(ArgKind::Buffer, 1), first, extent, arg(ArgKind::Range)}));
  std::vector<std::unique_ptr<StepT>> step;
  step.push_back(
      launch(kEstimate, LaunchShape::Items, -1,
             {arg(ArgKind::Clock), first, extent, arg(ArgKind::Range)}));
  step.push_back(
      launch(kAdvance, LaunchShape::Single, -1, {arg(ArgKind::Clock)}));
  // The estimate slot, every rank's minimum, before advance decides.
  step.back()->launch->reduce_min = {4};
  step.push_back(launch(kEvaluate, LaunchShape::Items, 0,
                        {arg(ArgKind::Clock), arg(ArgKind::Buffer, 0), first,
                         extent, arg(ArgKind::Range), arg(ArgKind::Dt)}));
  step.back()->launch->exchange = {Exchange(0, false)};
  if (gather) {
    step.push_back(launch(kPull, LaunchShape::Items, 1,
                          {arg(ArgKind::Clock), arg(ArgKind::Buffer, 1), first,
                           extent, arg(ArgKind::Range), arg(ArgKind::Dt)}));
    // An all-gather of every rank's block of Y.
    step.back()->launch->exchange = {Exchange(1, false)};
  }
  plan->phases.push_back(phase(PhaseKind::Step, std::move(step)));
  plan->phases.push_back(phase(
      PhaseKind::Finish,
      list(launch(kAdvance, LaunchShape::Single, -1, {arg(ArgKind::Clock)}))));
  plan->phases.push_back(
      phase(PhaseKind::Total,
            list(launch(kTotal, LaunchShape::Items, -1,
                        {arg(ArgKind::Total, 0), arg(ArgKind::Clock),
                         arg(ArgKind::Buffer, 0), first, extent,
                         arg(ArgKind::Range)}))));
  if (gather)
    plan->phases.push_back(
        phase(PhaseKind::Exact,
              list(launch(kExactY, LaunchShape::Items, -1,
                          {arg(ArgKind::Exact, 1), first, extent,
                           arg(ArgKind::Range), arg(ArgKind::Time)}))));
  auto cpu = std::make_unique<CpuCodeT>();
  cpu->isa = "x86-64";
  cpu->object = readBytes(SIM_TEST_RING_SO);
  plan->cpu.push_back(std::move(cpu));
  contents.plans.push_back(std::move(plan));
  return contents;
}

BundleT probeContents() {
  BundleT contents;
  auto scene = std::make_unique<SceneT>();
  scene->name = "probe";
  scene->range = 4;
  scene->dt = std::make_unique<Value>(0, 0.5, ScalarType::F64);
  scene->max_steps = 4;
  scene->params.push_back(param("cycle", ScalarType::I32, 0, 0));
  scene->params.push_back(param("read_none", ScalarType::I32, 0, 0));
  auto f64 = [&](const std::string &name, Interp interp, Boundary boundary,
                 bool observed, int32_t derivative = -1) {
    scene->buffers.push_back(buffer(name, ScalarType::F64, 1, interp, boundary,
                                    observed, false, derivative));
  };
  f64("D", Interp::Linear, Boundary::Clamp, false);
  f64("A", Interp::Linear, Boundary::Clamp, true);
  f64("C", Interp::Cubic, Boundary::Wrap, true);
  f64("H", Interp::Hermite, Boundary::Zero, true, 0);
  f64("N", Interp::None, Boundary::Clamp, false);
  f64("L", Interp::Linear, Boundary::Clamp, false);
  for (const char *name : {"RA", "RC", "RH"})
    scene->buffers.push_back(buffer(name, ScalarType::F64, 4, Interp::Linear,
                                    Boundary::Clamp, true));
  scene->buffers.push_back(
      buffer("E", ScalarType::F64, 6, Interp::Linear, Boundary::Clamp, true));
  contents.scene = std::move(scene);

  // The plan only gives the group size (2: two groups of two items); its
  // kernel exists nowhere, and the reference executor needs none.
  auto plan = std::make_unique<PlanT>();
  plan->strategy = Strategy::Hip;
  plan->group_size = 2;
  plan->step_cap = 4;
  plan->clock_slots = 16;
  plan->histogram = 10;
  auto planBuffer = std::make_unique<PlanBufferT>();
  planBuffer->buffer = 1;
  planBuffer->stride = 8;
  plan->buffers.push_back(std::move(planBuffer));
  plan->components.push_back(component("Source", {0}, 8, false));
  plan->kernels.push_back(kernel("none", {kClock}, 16));
  plan->phases.push_back(phase(PhaseKind::Init, {}));
  plan->phases.push_back(
      phase(PhaseKind::Step,
            list(launch(0, LaunchShape::Single, -1, {arg(ArgKind::Clock)}))));
  plan->phases.push_back(phase(PhaseKind::Finish, {}));
  contents.plans.push_back(std::move(plan));

  // Source writes D A C H N; Sink (num_steps, in no back edge: it
  // sub-steps under hip) reads them; Edge writes E and L after both.
  auto model = std::make_unique<ReferenceT>();
  model->params = {0, 1};
  for (uint32_t b = 0; b < 10; ++b)
    model->buffers.push_back(b);
  Stepping whole(Advance::WholeStep, false),
      estimating(Advance::WholeStep, true),
      group(Advance::GroupSubSteps, false);
  model->components.push_back(refComponent("Source", false, {0, 1, 2, 3, 4}, {},
                                           stepping(whole, whole, whole)));
  model->components.push_back(refComponent("Sink", true, {6, 7, 8},
                                           {1, 2, 3, 4, 6, 7, 8},
                                           stepping(whole, estimating, group)));
  model->components.push_back(refComponent("Edge", false, {9, 5}, {1, 2, 3},
                                           stepping(whole, whole, whole)));
  model->step_caps = {1, 4, 4, 4, 4};
  model->object = readBytes(SIM_TEST_PROBE_REFERENCE_SO);
  model->isa = "x86-64";
  contents.reference = std::move(model);
  return contents;
}

std::string probeBundle() { return serialize(probeContents()); }

PlanT &planOf(BundleT &contents, Strategy strategy) {
  for (auto &plan : contents.plans)
    if (plan->strategy == strategy)
      return *plan;
  throw std::runtime_error("no plan of that strategy");
}

std::vector<int64_t> decayBigSteps(int64_t begin, int64_t steps, int64_t cap) {
  std::vector<int64_t> sizes;
  for (int64_t t = begin, end = begin + steps; t < end;) {
    int64_t m = std::min({1 + (t / 5) % 4, cap, end - t});
    sizes.push_back(m);
    t += m;
  }
  return sizes;
}

int64_t decayCuts(int64_t begin, int64_t steps, int64_t cap) {
  int64_t t = begin;
  std::vector<int64_t> sizes = decayBigSteps(begin, steps, cap);
  if (sizes.empty())
    return 0;
  for (size_t i = 0; i + 1 < sizes.size(); ++i)
    t += sizes[i];
  return sizes.back() < std::min(1 + (t / 5) % 4, cap) ? 1 : 0;
}

std::string makeTempDir() {
  const char *tmp = std::getenv("TMPDIR");
  std::string path =
      std::string(tmp && *tmp ? tmp : "/tmp") + "/sim-runtime-test-XXXXXX";
  if (!mkdtemp(path.data()))
    throw std::runtime_error("mkdtemp failed");
  return path;
}

} // namespace sim::test
