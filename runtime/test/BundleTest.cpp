//===- BundleTest.cpp - reading and rejecting bundles ---------------------===//
//
// A bundle is read only when its header, its CRC, its FlatBuffer and its
// cross-references are right; everything else is rejected with a message
// that names the problem (docs/Bundle.md). The tests damage bundles the
// ways files get damaged (truncated anywhere, bits flipped anywhere) and
// edit them the ways a careless or hostile writer would (every check of
// BundleVerifier.cpp, with a valid CRC).
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "TestBundle.h"
#include "TestUtil.h"

#include "sim/Runtime/BundleFormat.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <elf.h>
#include <functional>

using namespace sim::rt;
using namespace sim::test;

namespace {

/// The message of the error reading `bytes` raises (empty if none).
std::string errorOf(const std::string &bytes,
                    sim_status expected = SIM_ERROR_BUNDLE) {
  try {
    parseBytes(bytes);
  } catch (const Error &error) {
    EXPECT_EQ(error.status, expected) << error.what();
    return error.what();
  }
  return "";
}

/// The error of the decay bundle after `edit` (with a valid CRC: what the
/// verifier must catch).
std::string errorAfter(const std::function<void(schema::BundleT &)> &edit) {
  schema::BundleT contents = decayContents();
  edit(contents);
  return errorOf(serialize(contents));
}

schema::PlanT &hipPlan(schema::BundleT &contents) {
  return planOf(contents, Strategy::Hip);
}

/// The program header of the first segment of `type` in an ELF object.
Elf64_Phdr &segmentOf(std::vector<uint8_t> &object, uint32_t type) {
  Elf64_Ehdr header;
  std::memcpy(&header, object.data(), sizeof header);
  for (uint16_t i = 0; i < header.e_phnum; ++i) {
    auto *segment = reinterpret_cast<Elf64_Phdr *>(
        object.data() + header.e_phoff + i * sizeof(Elf64_Phdr));
    if (segment->p_type == type)
      return *segment;
  }
  throw std::runtime_error("no such segment");
}

/// The launch `index` of the step phase of `plan`.
schema::LaunchT &stepLaunch(schema::PlanT &plan, size_t index) {
  for (auto &phase : plan.phases)
    if (phase->kind == PhaseKind::Step)
      return *phase->body[index]->launch;
  throw std::runtime_error("no step phase");
}

} // namespace

TEST(Bundle, ReadsTheDecayBundle) {
  auto bundle = parseBytes(decayBundle(), "decay.simb");
  const schema::SceneT &scene = bundle->scene();
  EXPECT_EQ(scene.name, "decay");
  EXPECT_EQ(scene.range, 100);
  EXPECT_EQ(scene.dt->type(), ScalarType::F64);
  EXPECT_DOUBLE_EQ(scene.dt->float_value(), 0.01);
  EXPECT_EQ(scene.max_steps, 4);
  ASSERT_EQ(scene.params.size(), 2u);
  EXPECT_EQ(scene.params[1]->name, "poison");
  EXPECT_EQ(scene.params[1]->value->int_value(), -1);
  EXPECT_EQ(bundle->defaultTexts[1], "-1");
  EXPECT_EQ(bundle->elementTexts[1], "vector<3xf32>");
  EXPECT_EQ(bundle->interpTexts[0], "linear");

  const schema::PlanT *hip = bundle->plan(Strategy::Hip);
  ASSERT_TRUE(hip);
  EXPECT_TRUE(bundle->cpuCode(*hip));
  EXPECT_TRUE(hip->ptx.empty());
  EXPECT_FALSE(bundle->plan(Strategy::Traditional));
  EXPECT_EQ(bundle->strategies(),
            (std::vector<Strategy>{Strategy::Simple, Strategy::Hip}));
  EXPECT_EQ(hip->step_cap, 4u);
  const schema::PhaseT *step = findPhase(*hip, PhaseKind::Step);
  ASSERT_TRUE(step);
  std::vector<const schema::LaunchT *> launches = unrollPhase(*step);
  ASSERT_EQ(launches.size(), 4u);
  EXPECT_EQ(hip->kernels[launches[0]->kernel]->name, "estimate_Decay");
  EXPECT_EQ(hip->kernels[launches[1]->kernel]->name, "advance");
  EXPECT_EQ(launches[2]->component, 0);
  ASSERT_TRUE(bundle->reference());
  EXPECT_EQ(bundle->reference()->components[0]->stepping[2].estimates(), true);
}

TEST(Bundle, UnrollsRepeats) {
  schema::BundleT contents = decayContents();
  schema::PlanT &plan = hipPlan(contents);
  // The step phase's advance three times, twice over.
  for (auto &phase : plan.phases) {
    if (phase->kind != PhaseKind::Step)
      continue;
    auto inner = std::make_unique<schema::RepeatT>();
    inner->count = 3;
    inner->body.push_back(std::move(phase->body[1]));
    auto innerStep = std::make_unique<schema::StepT>();
    innerStep->repeat = std::move(inner);
    auto outer = std::make_unique<schema::RepeatT>();
    outer->count = 2;
    outer->body.push_back(std::move(innerStep));
    phase->body[1] = std::make_unique<schema::StepT>();
    phase->body[1]->repeat = std::move(outer);
  }
  auto bundle = parseBytes(serialize(contents));
  std::vector<const schema::LaunchT *> launches =
      unrollPhase(*findPhase(*bundle->plan(Strategy::Hip), PhaseKind::Step));
  ASSERT_EQ(launches.size(), 9u);
  for (size_t i = 1; i < 7; ++i)
    EXPECT_EQ(launches[i], launches[1]);
}

//===----------------------------------------------------------------------===//
// The file and its header
//===----------------------------------------------------------------------===//

TEST(Bundle, RejectsAWrongMagicVersionSizeOrReservedField) {
  std::string good = decayBundle();
  std::string bytes = good;
  bytes[0] = 'X';
  EXPECT_TRUE(contains(errorOf(bytes), "not a sim bundle (wrong magic"));
  EXPECT_TRUE(contains(errorOf("SIMB"), "the file has 4 bytes, too few"));

  schema::Header header =
      schema::decodeHeader(reinterpret_cast<const uint8_t *>(good.data()));
  auto withField = [&](auto change) {
    schema::Header edited = header;
    change(edited);
    return schema::encodeHeader(edited) + good.substr(schema::kHeaderSize);
  };
  for (uint32_t old : {1u, 2u, 3u, 4u, 5u, 6u})
    EXPECT_EQ(errorOf(withField([&](schema::Header &h) { h.version = old; })),
              "bundle 'test.simb': format version " + std::to_string(old) +
                  " is no longer supported: this runtime reads version 7; "
                  "recompile the scene with sim-translate --sim-to-bundle");
  EXPECT_TRUE(contains(
      errorOf(withField([](schema::Header &h) { h.version = 8; })),
      "format version 8 is not supported (this runtime reads version 7)"));
  EXPECT_TRUE(
      contains(errorOf(withField([](schema::Header &h) { h.size += 8; })),
               "the header gives a file size of"));
  EXPECT_TRUE(
      contains(errorOf(withField([](schema::Header &h) { h.reserved = 1; })),
               "the reserved header field is not zero"));
  EXPECT_TRUE(
      contains(errorOf(withField([](schema::Header &h) { h.checksum ^= 1; })),
               "the checksum does not match its contents"));
}

TEST(Bundle, RejectsEveryTruncation) {
  std::string bytes = decayBundle();
  // Every length of the header and the first kilobyte, then every 61st.
  for (size_t size = 0; size < bytes.size(); size += size < 1024 ? 1 : 61) {
    std::string message = errorOf(bytes.substr(0, size));
    EXPECT_FALSE(message.empty()) << size;
  }
}

TEST(Bundle, RejectsEveryFlippedBit) {
  // The CRC-32 detects every single-bit error; the header fields are
  // checked by value. Every bit of the header and of a sample of the rest.
  std::string good = decayBundle();
  size_t rejected = 0, tried = 0;
  for (size_t at = 0; at < good.size(); at += at < 64 ? 1 : 37) {
    for (int bit = 0; bit < 8; ++bit) {
      std::string bytes = good;
      bytes[at] = char(bytes[at] ^ (1 << bit));
      ++tried;
      rejected += !errorOf(bytes).empty();
    }
  }
  EXPECT_EQ(rejected, tried);
}

TEST(Bundle, RejectsABufferThatIsNotABundleFlatBuffer) {
  // Found by the fuzzer: a payload too short for the file identifier was
  // read past its end.
  for (size_t size : {0, 1, 4, 7})
    EXPECT_TRUE(contains(errorOf(withHeader(std::string(size, 'S'))),
                         "too few for a bundle FlatBuffer"))
        << size;
  // A right CRC over bytes that are no FlatBuffer of the schema.
  EXPECT_TRUE(contains(errorOf(withHeader(std::string(64, '\x01'))),
                       "the contents are not a bundle FlatBuffer"));
  // The right identifier, offsets pointing outside the buffer.
  std::string payload(64, '\0');
  payload[0] = 8; // root table at 8
  std::memcpy(&payload[4], "SIMB", 4);
  payload[8] = char(0xf0); // vtable offset far away
  payload[9] = char(0xff);
  EXPECT_TRUE(contains(errorOf(withHeader(payload)),
                       "do not verify as a bundle FlatBuffer"));
}

TEST(Bundle, RejectsAnInt64VectorOffItsAlignment) {
  // Found by the fuzzer (UBSan: a misaligned int64 load while unpacking):
  // FlatBuffers 2.0's verifier checks a vector's length prefix, not that
  // its 8-byte elements are aligned. A reference component's local_window
  // moved 4 bytes on, its length prefix written over the first element, so
  // that its one element sits 4 bytes off an 8-byte boundary, with a
  // valid CRC (VectorAlignment.h).
  schema::BundleT contents = decayContents();
  contents.reference->components[0]->local_window = {-1, 1};
  flatbuffers::FlatBufferBuilder builder;
  schema::FinishBundleBuffer(builder, schema::Bundle::Pack(builder, &contents));
  std::vector<uint8_t> payload(builder.GetBufferPointer(),
                               builder.GetBufferPointer() + builder.GetSize());
  // The same bytes in an aligned buffer, as the reader holds them.
  const schema::Bundle *root = schema::GetBundle(payload.data());
  const schema::RefComponent *component =
      root->reference()->components()->Get(0);
  // RefComponent inherits Table privately; the field's address is
  // Table's.
  const uint8_t *field =
      reinterpret_cast<const flatbuffers::Table *>(component)->GetAddressOf(
          schema::RefComponent::VT_LOCAL_WINDOW);
  ASSERT_NE(field, nullptr);
  size_t fieldAt = size_t(field - payload.data());
  size_t elementsAt =
      size_t(component->local_window()->Data() - payload.data());
  ASSERT_EQ(elementsAt % 8, 0u);
  flatbuffers::uoffset_t offset;
  std::memcpy(&offset, &payload[fieldAt], sizeof offset);
  offset += 4;
  std::memcpy(&payload[fieldAt], &offset, sizeof offset);
  flatbuffers::uoffset_t length = 1;
  std::memcpy(&payload[elementsAt], &length, sizeof length);
  std::string file = withHeader(std::string(payload.begin(), payload.end()));
  EXPECT_TRUE(contains(errorOf(file),
                       "the int64 vector local_window of reference component "
                       "0 is not aligned to 8 bytes"))
      << errorOf(file);
  // Unedited, the same contents read.
  EXPECT_EQ(errorOf(serialize(contents)), "");
}

TEST(Bundle, ReportsMissingAndSpecialFiles) {
  EXPECT_TRUE(contains(
      errorOf([] { Bundle::read("/nonexistent/x.simb"); }, SIM_ERROR_IO),
      "cannot open bundle '/nonexistent/x.simb'"));
  // A device never ends: it is refused before anything is read.
  EXPECT_TRUE(contains(errorOf([] { Bundle::read("/dev/zero"); }, SIM_ERROR_IO),
                       "it is not a regular file"));
  EXPECT_TRUE(contains(errorOf([] { Bundle::read("/tmp"); }, SIM_ERROR_IO),
                       "it is not a regular file"));
}

//===----------------------------------------------------------------------===//
// Cross-references (BundleVerifier.cpp)
//===----------------------------------------------------------------------===//

TEST(BundleVerifier, ChecksTheScene) {
  struct Case {
    std::function<void(schema::BundleT &)> edit;
    const char *message;
  };
  const Case cases[] = {
      {[](auto &c) { c.scene->range = 0; },
       "scene 'decay' has a range of 0 items, not 1 to 2^40"},
      {[](auto &c) { c.scene->range = (int64_t(1) << 40) + 1; },
       "has a range of 1099511627777 items"},
      {[](auto &c) {
         c.scene->dt = std::make_unique<schema::Value>(0, 0.0, ScalarType::F64);
       },
       "has dt 0, not a positive finite number"},
      {[](auto &c) {
         c.scene->dt = std::make_unique<schema::Value>(0, NAN, ScalarType::F64);
       },
       "has dt nan, not a positive finite number"},
      {[](auto &c) {
         c.scene->dt =
             std::make_unique<schema::Value>(0, 1e-320, ScalarType::F64);
       },
       "which is subnormal in f64"},
      {[](auto &c) {
         c.scene->dt =
             std::make_unique<schema::Value>(0, 1e-40, ScalarType::F32);
       },
       "which is subnormal in f32"},
      {[](auto &c) {
         c.scene->dt = std::make_unique<schema::Value>(0, 1, ScalarType::I32);
       },
       "has a dt of type 0, not f32 or f64"},
      {[](auto &c) { c.scene->max_steps = 0; }, "has max_steps 0"},
      {[](auto &c) { c.scene->params[1]->name = "k"; },
       "parameter 'k' is declared twice"},
      {[](auto &c) { c.scene->params[1]->name = "dt"; },
       "parameter 'dt' clashes with the scene's own dt"},
      {[](auto &c) {
         c.scene->params[1]->value = std::make_unique<schema::Value>(
             int64_t(1) << 40, 0.0, ScalarType::I32);
       },
       "has the i32 value 1099511627776, which does not fit"},
      {[](auto &c) {
         c.scene->params[0]->value =
             std::make_unique<schema::Value>(0, 0.0, ScalarType(9));
       },
       "parameter 'k' has no value of a known type"},
      {[](auto &c) { c.scene->buffers[1]->name = "X"; },
       "buffer 'X' is declared twice"},
      {[](auto &c) {
         c.scene->buffers[1]->element =
             std::make_unique<schema::Element>(ScalarType::I32, 3);
       },
       "buffer 'V' has element scalar type 0, not f32 or f64"},
      {[](auto &c) {
         c.scene->buffers[1]->element =
             std::make_unique<schema::Element>(ScalarType::F32, 0);
       },
       "buffer 'V' has 0 lanes, not 1 to 64"},
      {[](auto &c) { c.scene->buffers[0]->interp = Interp(7); },
       "buffer 'X' has interpolation 7"},
      {[](auto &c) { c.scene->buffers[0]->boundary = Boundary(3); },
       "buffer 'X' has boundary rule 3"},
      {[](auto &c) { c.scene->buffers[0]->derivative = 1; },
       "buffer 'X' names a derivative but is not interpolated by hermite"},
      {[](auto &c) {
         c.scene->buffers[0]->interp = Interp::Hermite;
         c.scene->buffers[0]->derivative = 5;
       },
       "buffer 'X': its hermite derivative is 5, but there are only 2"},
      {[](auto &c) {
         c.scene->buffers[0]->interp = Interp::Hermite;
         c.scene->buffers[0]->derivative = 1;
       },
       "interpolates with the derivative 'V', whose element type differs"},
      {[](auto &c) { c.scene->buffers[1]->precision_bytes = 2; },
       "buffer 'V' derives from floats of 2 bytes, not 4 or 8"},
  };
  for (const Case &c : cases)
    EXPECT_TRUE(contains(errorAfter(c.edit), c.message)) << c.message;
}

TEST(BundleVerifier, ChecksPlansAndTheirClocks) {
  struct Case {
    std::function<void(schema::BundleT &)> edit;
    const char *message;
  };
  const Case cases[] = {
      {[](auto &c) { c.plans[1]->strategy = Strategy::Simple; },
       "there are two plans of strategy 'simple'"},
      {[](auto &c) { c.plans[1]->strategy = Strategy(5); },
       "a plan has unknown strategy 5"},
      {[](auto &c) { hipPlan(c).group_size = 0; },
       "the plan of strategy 'hip' is made for groups of 0"},
      {[](auto &c) { hipPlan(c).step_cap = 5; },
       "caps big steps at 5 base steps, not 1 to max_steps (4)"},
      {[](auto &c) { planOf(c, Strategy::Simple).step_cap = 0; },
       "caps big steps at 0 base steps, not 1 to max_steps (4)"},
      {[](auto &c) { hipPlan(c).histogram = 12; },
       "puts the histogram of big-step sizes at slot 12, which with "
       "max_steps 4 does not fit"},
      {[](auto &c) { hipPlan(c).clock_slots = uint32_t(1) << 30; },
       "asks for a clock of 1073741824 slots"},
      {[](auto &c) { hipPlan(c).components[1]->evaluations = 8; },
       "component 'Grow''s evaluation counter uses clock slot 8, which "
       "another counter uses too"},
      {[](auto &c) { hipPlan(c).components[1]->evaluations = 3; },
       "uses clock slot 3, outside the free slots 8 to 9"},
      {[](auto &c) { hipPlan(c).components[1]->evaluations = 10; },
       "uses clock slot 10, outside the free slots 8 to 9"},
      {[](auto &c) {
         hipPlan(c).components[1]->advance = Advance::GridSubSteps;
         hipPlan(c).components[1]->sub_clock = 8;
       },
       "component 'Grow''s sub-step clock uses clock slot 8 to 11"},
      {[](auto &c) {
         hipPlan(c).components[1]->advance = Advance::LocalSteps;
         hipPlan(c).components[1]->sub_clock = 8;
       },
       "component 'Grow''s sub-step clock uses clock slot 8 to 13"},
      {[](auto &c) { hipPlan(c).components[1]->writes = {0}; },
       "buffer 'X' is written by both 'Decay' and 'Grow'"},
      {[](auto &c) { hipPlan(c).components[1]->writes = {}; },
       "component 'Grow' writes no buffer"},
      {[](auto &c) { hipPlan(c).components[1]->writes = {2}; },
       "a buffer component 'Grow' writes is 2, but there are only 2"},
      {[](auto &c) { hipPlan(c).components[1]->name = "Decay"; },
       "component 'Decay' is declared twice"},
      {[](auto &c) { hipPlan(c).components[1]->advance = Advance(5); },
       "component 'Grow' advances in an unknown way (5)"},
      {[](auto &c) { hipPlan(c).buffers[1]->buffer = 0; },
       "buffer 'X' is listed twice"},
      {[](auto &c) { hipPlan(c).buffers[1]->buffer = 9; },
       "a buffer's scene buffer is 9, but there are only 2"},
      {[](auto &c) { hipPlan(c).buffers[1]->stride = 8; },
       "buffer 'V' has a stride of 8 bytes, which cannot hold its elements "
       "(vector<3xf32>)"},
      {[](auto &c) { hipPlan(c).totals = {0}; },
       "the plan of strategy 'hip': a total is 0, but there are only 0"},
  };
  for (const Case &c : cases)
    EXPECT_TRUE(contains(errorAfter(c.edit), c.message)) << c.message;
}

TEST(BundleVerifier, ChecksEveryLaunchAgainstItsKernel) {
  struct Case {
    std::function<void(schema::BundleT &)> edit;
    const char *message;
  };
  const Case cases[] = {
      // Fewer arguments than the kernel takes (a kernel would read past
      // its parameters).
      {[](auto &c) { stepLaunch(hipPlan(c), 2).args.pop_back(); },
       "the launch of 'evaluate_Decay' passes 5 arguments, but the kernel "
       "takes 6"},
      // Swapped element types: V where the kernel takes X.
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[1] = schema::Arg(ArgKind::Buffer, 1);
       },
       "argument 1 passes memref<?xvector<3xf32>> (stride 16), but the "
       "kernel's parameter is memref<?xf64> (stride 8)"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[2] = schema::Arg(ArgKind::Param, 1);
       },
       "argument 2 passes i32, but the kernel's parameter is f64"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[2] = schema::Arg(ArgKind::Clock, 0);
       },
       "argument 2 passes memref<?xi64> (stride 8), but the kernel's "
       "parameter is f64"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[1] = schema::Arg(ArgKind::Snapshot, 0);
       },
       "passes the snapshot of buffer 'X', which has none"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 3).args[1] = schema::Arg(ArgKind::Exact, 1);
       },
       "passes the exact solution of buffer 'V', which has none"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[1] = schema::Arg(ArgKind::Buffer, 7);
       },
       "argument 1's buffer is 7, but there are only 2"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[2] = schema::Arg(ArgKind::Param, 9);
       },
       "argument 2's parameter is 9, but there are only 2"},
      {[](auto &c) {
         stepLaunch(hipPlan(c), 2).args[0] = schema::Arg(ArgKind(12), 0);
       },
       "argument 0 has unknown kind 12"},
      // A kernel made with another element stride than the plan's buffer.
      {[](auto &c) {
         hipPlan(c).kernels[2]->params[0] = schema::KernelParam(
             ParamType::Memref, schema::Element(ScalarType::F32, 3), 12);
       },
       "argument 0 passes memref<?xvector<3xf32>> (stride 16), but the "
       "kernel's parameter is memref<?xvector<3xf32>> (stride 12)"},
      {[](auto &c) { stepLaunch(hipPlan(c), 2).shared_fixed = 64; },
       "asks for 0 bytes of shared memory per thread and 64 fixed, but the "
       "kernel needs 0 and 0"},
      {[](auto &c) { hipPlan(c).kernels[4]->clock_slots = 12; },
       "kernel 'evaluate_Decay' was made for a clock of 12 slots, but the "
       "plan's has 16"},
      {[](auto &c) { stepLaunch(hipPlan(c), 2).kernel = 40; },
       "a launch's kernel is 40, but there are only 8"},
      {[](auto &c) { stepLaunch(hipPlan(c), 2).component = 2; },
       "its component is 2, but there are only 2"},
      {[](auto &c) { stepLaunch(hipPlan(c), 2).shape = LaunchShape(2); },
       "has unknown shape 2"},
      {[](auto &c) { hipPlan(c).kernels[4]->name = "../evaluate"; },
       "kernel '../evaluate' is not named by an identifier"},
      {[](auto &c) { hipPlan(c).kernels[5]->name = "advance"; },
       "kernel 'advance' is declared twice"},
      {[](auto &c) {
         hipPlan(c).kernels[4]->params[1] =
             schema::KernelParam(ParamType(9), schema::Element(), 0);
       },
       "parameter 1 has unknown type 9"},
  };
  for (const Case &c : cases)
    EXPECT_TRUE(contains(errorAfter(c.edit), c.message)) << c.message;
}

TEST(BundleVerifier, ChecksPhasesAndCode) {
  struct Case {
    std::function<void(schema::BundleT &)> edit;
    const char *message;
  };
  auto repeat = [](schema::PlanT &plan, uint32_t count, uint32_t depth) {
    for (auto &phase : plan.phases) {
      if (phase->kind != PhaseKind::Step)
        continue;
      std::unique_ptr<schema::StepT> step = std::move(phase->body[1]);
      for (uint32_t d = 0; d < depth; ++d) {
        auto block = std::make_unique<schema::RepeatT>();
        block->count = count;
        block->body.push_back(std::move(step));
        step = std::make_unique<schema::StepT>();
        step->repeat = std::move(block);
      }
      phase->body[1] = std::move(step);
    }
  };
  const Case cases[] = {
      {[](auto &c) { hipPlan(c).phases.erase(hipPlan(c).phases.begin() + 2); },
       "the plan of strategy 'hip' has no finish phase"},
      {[](auto &c) { hipPlan(c).phases[2]->kind = PhaseKind::Step; },
       "has two step phases"},
      {[](auto &c) { hipPlan(c).phases[2]->kind = PhaseKind(8); },
       "has a phase of unknown kind 8"},
      {[](auto &c) { hipPlan(c).phases[1]->body.clear(); },
       "phase step launches nothing"},
      // A small file that unrolls to 2^40 launches.
      {[&](auto &c) { repeat(hipPlan(c), 1 << 20, 2); },
       "repeats its launches more than 4194304 times"},
      {[&](auto &c) { repeat(hipPlan(c), 0, 1); }, "repeats a block 0 times"},
      {[](auto &c) {
         auto both = std::make_unique<schema::StepT>();
         both->repeat = std::make_unique<schema::RepeatT>();
         hipPlan(c).phases[1]->body.push_back(std::move(both));
         hipPlan(c).phases[1]->body.back()->launch =
             std::make_unique<schema::LaunchT>(
                 *hipPlan(c).phases[1]->body[1]->launch);
       },
       "has a step that is not exactly one of a launch and a repeat"},
      {[](auto &c) { hipPlan(c).ptx_chip = "sm_90"; },
       "names the chip 'sm_90' of PTX it does not have"},
      {[](auto &c) {
         hipPlan(c).cpu.push_back(
             std::make_unique<schema::CpuCodeT>(*hipPlan(c).cpu[0]));
       },
       "has two CPU objects for 'x86-64'"},
      {[](auto &c) { hipPlan(c).cpu[0]->object.resize(40); },
       "the CPU kernels (x86-64) of the plan of strategy 'hip' are not a "
       "loadable shared object: the 40 bytes are too few for an ELF header"},
      {[](auto &c) { hipPlan(c).cpu[0]->object[0] = 'X'; }, "no ELF magic"},
      // Every program header of a truncated object reaches outside it.
      {[](auto &c) {
         std::vector<uint8_t> &object = hipPlan(c).cpu[0]->object;
         object.resize(object.size() / 2);
       },
       "reaches past the end of its"},
      // With the CRC recomputed, edited program headers crashed the
      // dynamic loader: a loadable segment turned into an unknown type, one
      // grown over the next, a PT_PHDR (here PT_GNU_RELRO: this object is
      // GNU ld's, which writes none) that points elsewhere.
      {[](auto &c) {
         segmentOf(hipPlan(c).cpu[0]->object, PT_LOAD).p_type = 0x99000001;
       },
       "has type 2566914049, which no shared object of sim-translate has"},
      {[](auto &c) {
         segmentOf(hipPlan(c).cpu[0]->object, PT_LOAD).p_memsz += 1 << 17;
       },
       "inside or before the loadable segment before it"},
      {[](auto &c) {
         segmentOf(hipPlan(c).cpu[0]->object, PT_GNU_RELRO).p_vaddr +=
             uint64_t(1) << 44;
       },
       "lies outside the loadable segments or elsewhere in the file"},
      {[](auto &c) {
         segmentOf(hipPlan(c).cpu[0]->object, PT_DYNAMIC).p_offset += 8;
       },
       "lies outside the loadable segments or elsewhere in the file"},
  };
  for (const Case &c : cases)
    EXPECT_TRUE(contains(errorAfter(c.edit), c.message)) << c.message;
}

TEST(BundleVerifier, ChecksTheReferenceModel) {
  struct Case {
    std::function<void(schema::BundleT &)> edit;
    const char *message;
  };
  const Case cases[] = {
      {[](auto &c) {
         c.reference->params = {0, 0};
       },
       "the reference model lists parameter 'k' twice"},
      {[](auto &c) { c.reference->params = {5}; },
       "the reference model: a parameter is 5, but there are only 2"},
      {[](auto &c) {
         c.reference->buffers = {0, 0};
       },
       "the reference model lists buffer 'X' twice"},
      {[](auto &c) { c.reference->components[1]->writes = {0}; },
       "buffer 'X' is written by both 'Decay' and 'Grow'"},
      {[](auto &c) {
         c.reference->components[1]->reads = {1, 1};
       },
       "component 'Grow' lists a read of 'V' twice"},
      {[](auto &c) { c.reference->components[1]->reads = {4}; },
       "component 'Grow': a buffer it reads is 4, but there are only 2"},
      {[](auto &c) { c.reference->components[1]->name = "Decay"; },
       "component 'Decay' is declared twice"},
      {[](auto &c) { c.reference->components[1]->stepping.pop_back(); },
       "says how it steps under 4 strategies, not 5"},
      {[](auto &c) {
         c.reference->components[1]->stepping[2] =
             schema::Stepping(Advance::GroupSubSteps, false);
       },
       "component 'Grow' under hip estimates or sub-steps, but it has no "
       "num_steps"},
      {[](auto &c) {
         c.reference->components[1]->stepping[4] =
             schema::Stepping(Advance::LocalFlux, false);
       },
       "component 'Grow' under lts writes the fluxes of a flux pair without "
       "a window [lo, hi] with lo <= hi"},
      {[](auto &c) {
         c.reference->components[1]->stepping[4] =
             schema::Stepping(Advance::LocalFlux, false);
         c.reference->components[1]->flux_window = {1, 0};
       },
       "component 'Grow' under lts writes the fluxes of a flux pair without "
       "a window [lo, hi] with lo <= hi"},
      {[](auto &c) {
         c.reference->components[0]->sub_stepping = schema::SubStepping(4);
       },
       "component 'Decay' has an unknown sub-stepping verdict"},
      {[](auto &c) { c.reference->step_caps.pop_back(); },
       "gives the largest big step of 4 strategies, not 5"},
      {[](auto &c) { c.reference->step_caps[0] = 9; },
       "caps big steps under simple at 9 base steps, not 1 to max_steps (4)"},
      {[](auto &c) {
         auto w = std::make_unique<schema::BufferT>(*c.scene->buffers[0]);
         w->name = "W";
         w->exact = false;
         c.scene->buffers.push_back(std::move(w));
         c.scene->buffers[0]->interp = Interp::Hermite;
         c.scene->buffers[0]->derivative = 2;
       },
       "buffer 'X' interpolates with the derivative 'W', which is not a "
       "buffer of the model"},
      {[](auto &c) { c.reference->object.resize(10); },
       "the reference functions are not a loadable shared object"},
  };
  for (const Case &c : cases)
    EXPECT_TRUE(contains(errorAfter(c.edit), c.message)) << c.message;
}

//===----------------------------------------------------------------------===//
// Values
//===----------------------------------------------------------------------===//

TEST(Values, ParseAndPrintBackExactly) {
  EXPECT_EQ(parseValue(ScalarType::F64, "0.1", "x").text(),
            "0.10000000000000001");
  EXPECT_EQ(parseValue(ScalarType::F32, "0.1", "x").text(), "0.100000001");
  EXPECT_EQ(parseValue(ScalarType::I32, "-7", "x").bits(), 0xfffffff9u);
  EXPECT_EQ(parseValue(ScalarType::Index, "123", "x").bits(), 123u);
  float f = 1.5f;
  uint32_t bits;
  std::memcpy(&bits, &f, 4);
  EXPECT_EQ(parseValue(ScalarType::F32, "1.5", "x").bits(), bits);
  for (const char *bad : {"", " 1", "1 ", "1x", "0x"})
    EXPECT_THROW(parseValue(ScalarType::I64, bad, "x"), Error) << bad;
  EXPECT_THROW(parseValue(ScalarType::F32, "1e39", "x"), Error);
}
