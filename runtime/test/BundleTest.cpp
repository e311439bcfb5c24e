//===- BundleTest.cpp - reading and rejecting bundles ---------------------===//
//
// Every malformation docs/Bundle.md lists is rejected with a message that
// names it, and the text sections parse into the structures the executor
// uses.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "TestBundle.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace sim::rt;
using namespace sim::test;

namespace {

/// The message of the error reading `bytes` raises (empty if none).
std::string errorOf(const std::string &bytes,
                    sim_status expected = SIM_ERROR_BUNDLE) {
  try {
    Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()), bytes.size(),
                  "test.simb");
  } catch (const Error &error) {
    EXPECT_EQ(error.status, expected) << error.what();
    return error.what();
  }
  return "";
}

std::string errorOf(const std::vector<Section> &sections) {
  return errorOf(writeBundle(sections));
}

/// The decay sections with the plan of `strategy` replaced.
std::vector<Section> withPlan(uint32_t strategy, const std::string &plan) {
  std::vector<Section> sections = decaySections();
  for (Section &section : sections)
    if (section.kind == kPlan && section.strategy == strategy)
      section.bytes = plan;
  return sections;
}

std::vector<Section> withScene(const std::string &scene) {
  std::vector<Section> sections = decaySections();
  sections[0].bytes = scene;
  return sections;
}

/// `text` with the first `from` replaced by `to`.
std::string replace(std::string text, const std::string &from,
                    const std::string &to) {
  size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return at == std::string::npos ? text : text.replace(at, from.size(), to);
}

} // namespace

TEST(Bundle, ReadsTheDecayBundle) {
  std::string bytes = decayBundle();
  auto bundle = Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                              bytes.size(), "decay.simb");
  const Scene &scene = bundle->scene;
  EXPECT_EQ(scene.name, "decay");
  EXPECT_EQ(scene.range, 100);
  EXPECT_EQ(scene.dt.type, ScalarType::F64);
  EXPECT_DOUBLE_EQ(scene.dt.f, 0.01);
  EXPECT_EQ(scene.maxSteps, 4);
  ASSERT_EQ(scene.params.size(), 2u);
  EXPECT_EQ(scene.params[1].name, "poison");
  EXPECT_EQ(scene.params[1].type, ScalarType::I32);
  EXPECT_EQ(scene.params[1].defaultValue.i, -1);
  ASSERT_EQ(scene.buffers.size(), 2u);
  EXPECT_TRUE(scene.buffers[0].exact);
  EXPECT_EQ(scene.buffers[1].type.lanes, 3);
  EXPECT_FALSE(scene.buffers[1].type.f64);

  const Bundle::StrategyCode &hip = bundle->code(Strategy::Hip);
  ASSERT_TRUE(hip.present);
  EXPECT_TRUE(hip.cpu.has_value());
  EXPECT_FALSE(hip.ptx.has_value());
  EXPECT_FALSE(bundle->code(Strategy::Traditional).present);
  const Plan &plan = hip.plan;
  EXPECT_EQ(plan.groupSize, 32);
  EXPECT_EQ(plan.clockSlots, 16);
  EXPECT_EQ(plan.histogramSlot, 10);
  ASSERT_EQ(plan.buffers.size(), 2u);
  EXPECT_EQ(plan.buffers[1].stride, 16);
  ASSERT_EQ(plan.components.size(), 2u);
  EXPECT_EQ(plan.components[0].evaluationSlot, 8);
  EXPECT_EQ(plan.components[1].writes, std::vector<int32_t>{1});
  const std::vector<Launch> &step = plan.phase(PhaseKind::Step);
  ASSERT_EQ(step.size(), 4u);
  EXPECT_EQ(step[0].kernel, "estimate_Decay");
  EXPECT_EQ(step[1].kernel, "advance");
  EXPECT_TRUE(step[1].single);
  EXPECT_EQ(step[2].component, 0);
  ASSERT_EQ(step[2].args.size(), 6u);
  EXPECT_EQ(step[2].args[3].kind, ArgKind::Param);
  EXPECT_EQ(step[2].args[3].index, 1);
  EXPECT_EQ(plan.kernelNames().size(), 8u);
}

//===----------------------------------------------------------------------===//
// The container
//===----------------------------------------------------------------------===//

TEST(Bundle, RejectsTruncatedFiles) {
  std::string bytes = decayBundle();
  EXPECT_NE(errorOf(bytes.substr(0, 10)).find("fewer than the 24-byte header"),
            std::string::npos);
  EXPECT_NE(errorOf(bytes.substr(0, bytes.size() / 2)).find("(truncated?)"),
            std::string::npos);
  EXPECT_NE(errorOf("").find("has 0 bytes"), std::string::npos);
}

TEST(Bundle, RejectsAWrongMagic) {
  std::string bytes = decayBundle();
  bytes[0] = 'X';
  EXPECT_NE(errorOf(bytes).find("not a sim bundle (wrong magic"),
            std::string::npos);
}

TEST(Bundle, RejectsAnUnknownVersion) {
  std::string bytes = decayBundle();
  putU32(bytes, 8, 2);
  EXPECT_NE(errorOf(bytes).find("format version 2 is not supported"),
            std::string::npos);
}

TEST(Bundle, RejectsASizeMismatch) {
  std::string bytes = decayBundle();
  std::string longer = bytes + std::string(8, '\0');
  EXPECT_NE(errorOf(longer).find("the header gives a file size of"),
            std::string::npos);
  putU64(bytes, 16, bytes.size() + 1);
  EXPECT_NE(errorOf(bytes).find("(truncated?)"), std::string::npos);
}

TEST(Bundle, RejectsATableBeyondTheFile) {
  std::string bytes = decayBundle();
  putU32(bytes, 12, 1000000);
  EXPECT_NE(errorOf(bytes).find(
                "the section table of 1000000 entries reaches past the end"),
            std::string::npos);
}

TEST(Bundle, RejectsSectionsOutOfBounds) {
  std::string bytes = decayBundle();
  // Section 1: its size runs past the end.
  putU64(bytes, 24 + 32 + 16, bytes.size());
  EXPECT_NE(errorOf(bytes).find("section 1 (plan) at offset"),
            std::string::npos);
  EXPECT_NE(errorOf(bytes).find("reaches past the end of the file"),
            std::string::npos);
  // An offset + size that overflows 64 bits.
  bytes = decayBundle();
  putU64(bytes, 24 + 8, 8);
  putU64(bytes, 24 + 16, ~uint64_t(0));
  EXPECT_NE(errorOf(bytes).find("reaches past the end"), std::string::npos);
}

TEST(Bundle, RejectsSectionsOverlappingTheTable) {
  std::string bytes = decayBundle();
  putU64(bytes, 24 + 8, 16);
  EXPECT_NE(errorOf(bytes).find("overlaps the header or the section table"),
            std::string::npos);
}

TEST(Bundle, RejectsMisalignedSections) {
  std::string bytes = decayBundle();
  uint64_t offset = 0;
  for (int i = 0; i < 8; ++i)
    offset |= uint64_t(uint8_t(bytes[24 + 8 + i])) << (8 * i);
  putU64(bytes, 24 + 8, offset + 1);
  putU64(bytes, 24 + 16, 8);
  EXPECT_NE(errorOf(bytes).find("not a multiple of 8"), std::string::npos);
}

TEST(Bundle, RejectsUnknownKindsAndStrategies) {
  std::vector<Section> sections = decaySections();
  sections.push_back({7, kSimple, "x"});
  EXPECT_NE(errorOf(sections).find("section 5 has unknown kind 7"),
            std::string::npos);
  sections = decaySections();
  sections.push_back({kPtx, 9, "x"});
  EXPECT_NE(errorOf(sections).find("section 5 (PTX) has unknown strategy 9"),
            std::string::npos);
  sections = decaySections();
  sections[0].strategy = kHip;
  EXPECT_NE(errorOf(sections).find("a scene section has none"),
            std::string::npos);
}

TEST(Bundle, RejectsMissingAndRepeatedSections) {
  std::vector<Section> sections = decaySections();
  sections.erase(sections.begin());
  EXPECT_NE(errorOf(sections).find("no scene section"), std::string::npos);

  sections = decaySections();
  sections.push_back(sections[0]);
  EXPECT_NE(errorOf(sections).find("repeated scene section"),
            std::string::npos);

  sections = decaySections();
  sections.push_back(sections[1]);
  EXPECT_NE(errorOf(sections).find("repeated plan section of strategy simple"),
            std::string::npos);

  sections = decaySections(/*ptx=*/true);
  sections.push_back(sections.back());
  EXPECT_NE(errorOf(sections).find("repeated PTX section of strategy hip"),
            std::string::npos);

  // The scene lists hip, but its plan is gone (with its code).
  sections = decaySections();
  sections.erase(sections.begin() + 3, sections.begin() + 5);
  EXPECT_NE(errorOf(sections).find(
                "the scene lists strategy 'hip' but there is no plan section"),
            std::string::npos);

  sections = decaySections();
  sections.push_back({kCpu, kTraditional, sections[2].bytes});
  EXPECT_NE(errorOf(sections).find(
                "CPU section of strategy 'traditional' without a plan"),
            std::string::npos);

  sections = withScene(
      replace(decayScene(), "strategies simple hip", "strategies simple"));
  EXPECT_NE(errorOf(sections).find("plan section of strategy 'hip', which the "
                                   "scene's 'strategies' record does not list"),
            std::string::npos);
}

TEST(Bundle, RejectsACpuSectionThatIsNotElf) {
  std::vector<Section> sections = decaySections();
  sections[2].bytes = std::string(100, 'x');
  EXPECT_NE(errorOf(sections).find(
                "CPU section of strategy 'simple' is not an ELF shared object"),
            std::string::npos);
}

TEST(Bundle, ReportsAMissingFile) {
  try {
    Bundle::read("/nonexistent/x.simb");
    FAIL() << "no error";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_IO);
    EXPECT_NE(std::string(error.what()).find("cannot open bundle"),
              std::string::npos);
  }
}

//===----------------------------------------------------------------------===//
// The scene text
//===----------------------------------------------------------------------===//

TEST(SceneText, RejectsWhatDoesNotParse) {
  struct Case {
    std::string from, to, message;
  } cases[] = {
      {"scene decay range 100", "scene decay range x",
       "scene section, line 2: range 'x' is not an integer"},
      {"range 100", "range 0", "range 0 is out of range"},
      {"dt f64 0.01", "dt f16 0.01", "dt type 'f16' is not f32 or f64"},
      {"dt f64 0.01", "dt f64 fast", "dt: 'fast' is not a f64 value"},
      {"max_steps 4\n", "max_steps 4 extra\n", "expected 'scene <name> range"},
      {"param k f64 2", "param k f16 2", "parameter type 'f16' is not one of"},
      {"param poison i32 -1", "param poison i32 99999999999",
       "parameter 'poison': '99999999999' is out of range for i32"},
      {"param poison i32 -1", "param k i32 -1",
       "parameter 'k' is declared twice"},
      {"param poison i32 -1", "param dt i32 -1",
       "a parameter named 'dt' clashes with the scene's dt"},
      {"buffer X f64", "buffer X f16", "element type 'f16' is not f32"},
      {"vector<3xf32>", "vector<0xf32>", "element type 'vector<0xf32>'"},
      {"interp linear", "interp quartic", "interpolation 'quartic' is not"},
      {"interp linear", "interp hermite:W",
       "interpolates with the derivative 'W', which is not a buffer"},
      {"boundary clamp observed exact", "boundary mirror observed exact",
       "boundary 'mirror' is not clamp, wrap or zero"},
      {"observed exact", "observed observed",
       "buffer flag 'observed' is "
       "repeated"},
      {"observed exact", "observed shiny", "unknown buffer flag 'shiny'"},
      {"strategies simple hip", "strategies simple fast",
       "unknown strategy 'fast'"},
      {"strategies simple hip", "strategies simple hip\nwhat is this",
       "line 8: unknown record 'what'"},
      {"# The runtime's test scene (kernels/decay.c).\nscene",
       "param k f64 2\nscene", "expected the 'scene' record first"},
  };
  for (const Case &c : cases) {
    std::string message =
        errorOf(withScene(replace(decayScene(), c.from, c.to)));
    EXPECT_NE(message.find(c.message), std::string::npos)
        << "for '" << c.to << "': " << message;
    EXPECT_EQ(message.rfind("bundle 'test.simb': scene section", 0), 0u)
        << message;
  }
}

TEST(SceneText, AcceptsCommentsBlankLinesAndCrLf) {
  std::string scene = "\n# c\n\r\n" + replace(decayScene(), "\n", "\r\n");
  EXPECT_EQ(errorOf(withScene(scene)), "");
}

//===----------------------------------------------------------------------===//
// The plan text
//===----------------------------------------------------------------------===//

TEST(PlanText, RejectsWhatDoesNotParse) {
  struct Case {
    std::string from, to, message;
  } cases[] = {
      {"plan hip", "plan simple",
       "the plan is for strategy 'simple' but its section is for 'hip'"},
      {"group_size 32", "group_size 0", "group_size 0 is out of range"},
      {"clock_slots 16 histogram 10", "clock_slots 12 histogram 10",
       "histogram slot 10 is out of range [8, 7]"},
      {"histogram 10", "histogram", "expected 'plan <strategy> group_size"},
      {"buffer X f64 stride 8", "buffer Q f64 stride 8",
       "buffer 'Q' is not a buffer of scene 'decay'"},
      {"buffer X f64 stride 8", "buffer X f32 stride 8",
       "buffer 'X' has element type f32 but the scene says f64"},
      {"vector<3xf32> stride 16", "vector<3xf32> stride 8",
       "stride 8 is out of range [12,"},
      {"component Decay evaluations 8", "component Decay evaluations 99",
       "evaluations slot 99 is out of range"},
      {"writes X", "writes Y",
       "component 'Decay' writes 'Y', which is not a "
       "plan buffer"},
      {"phase init", "phase boot", "unknown phase 'boot'"},
      {"phase finish", "phase init", "phase 'init' is repeated"},
      {"for Decay", "for Nobody",
       "is for 'Nobody', which is not a plan "
       "component"},
      {"items for Decay", "many for Decay", "launch shape 'many' is not"},
      {"param:k param:poison", "param:k param:zeta",
       "argument 'param:zeta' names no parameter of scene 'decay'"},
      {"args exact:X", "args snapshot:X", "buffer 'X' has no snapshot"},
      {"args clock buffer:V", "args clock buffer:W",
       "argument 'buffer:W' names no plan buffer"},
      {"range dt\n", "range dt speed\n", "unknown argument 'speed'"},
      {"shared 0 0 args clock\nend\nphase exact",
       "shared 0 0 args clock\nphase exact",
       "'phase' inside phase 'finish' (missing 'end'?)"},
      {"time\nend\n", "time\n", "phase 'exact' is not closed with 'end'"},
      {"phase finish\nlaunch advance single for - shared 0 0 args clock\nend\n",
       "", "no 'finish' phase"},
      {"component Grow", "repeat 2\ncomponent Grow",
       "'repeat' outside a phase"},
      {"component Grow",
       "launch advance single for - shared 0 0 args clock\n"
       "component Grow",
       "'launch' outside a phase"},
      {"component Grow", "end\ncomponent Grow",
       "'end' without an open phase or repeat"},
      {"shared 0 0 args clock range", "shared 0 x args clock range",
       "fixed shared bytes 'x' is not an integer"},
  };
  for (const Case &c : cases) {
    std::string message =
        errorOf(withPlan(kHip, replace(decayPlan(kHip), c.from, c.to)));
    EXPECT_NE(message.find(c.message), std::string::npos)
        << "for '" << c.to << "': " << message;
    EXPECT_EQ(
        message.rfind("bundle 'test.simb': plan section of strategy hip", 0),
        0u)
        << message;
  }
}

TEST(PlanText, ReadsTotals) {
  std::string plan =
      replace(decayPlan(kHip), "component Grow evaluations 9 writes V\n",
              "component Grow evaluations 9 writes V\ntotal Energy f64\n"
              "total Count f32\n") +
      "phase total\nlaunch total_Energy items for - shared 0 0 args clock "
      "buffer:X total:Energy range\nlaunch total_Count items for - shared 0 "
      "0 args total:Count range\nend\n";
  std::string bytes = writeBundle(withPlan(kHip, plan));
  auto bundle = Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                              bytes.size(), "t");
  const Plan &parsed = bundle->code(Strategy::Hip).plan;
  ASSERT_EQ(parsed.totals.size(), 2u);
  EXPECT_EQ(parsed.totals[0].name, "Energy");
  EXPECT_EQ(parsed.totals[0].type, ScalarType::F64);
  EXPECT_EQ(parsed.totals[1].type, ScalarType::F32);
  EXPECT_TRUE(parsed.hasPhase[int(PhaseKind::Total)]);
  const std::vector<Launch> &totals = parsed.phase(PhaseKind::Total);
  ASSERT_EQ(totals.size(), 2u);
  EXPECT_EQ(totals[0].args[2].kind, ArgKind::Total);
  EXPECT_EQ(totals[0].args[2].index, 0);
  EXPECT_EQ(totals[1].args[0].index, 1);

  struct Case {
    std::string from, to, message;
  } cases[] = {
      {"total Energy f64", "total Energy f16",
       "total type 'f16' is not f32 or f64"},
      {"total Energy f64", "total Energy i32",
       "total type 'i32' is not f32 or f64"},
      {"total Count f32", "total Energy f32",
       "total 'Energy' is declared twice"},
      {"total Energy f64", "total Energy", "expected 'total <name> <f32|f64>'"},
      {"args total:Count", "args total:Mass",
       "argument 'total:Mass' names no plan total"},
  };
  for (const Case &c : cases) {
    std::string message = errorOf(withPlan(kHip, replace(plan, c.from, c.to)));
    EXPECT_NE(message.find(c.message), std::string::npos)
        << "for '" << c.to << "': " << message;
  }
}

TEST(PlanText, UnrollsRepeats) {
  std::string plan =
      replace(decayPlan(kHip),
              "launch evaluate_Grow items for Grow shared 0 0 args clock "
              "buffer:V range\n",
              "repeat 3\nlaunch evaluate_Grow items for Grow shared 0 0 args "
              "clock buffer:V range\nrepeat 2\nlaunch advance single for - "
              "shared 4 8 args clock\nend\nend\n");
  std::string bytes = writeBundle(withPlan(kHip, plan));
  auto bundle = Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                              bytes.size(), "t");
  const std::vector<Launch> &step =
      bundle->code(Strategy::Hip).plan.phase(PhaseKind::Step);
  // estimate, advance, evaluate_Decay, then 3 x (evaluate_Grow, 2 x advance).
  ASSERT_EQ(step.size(), 3u + 3 * 3);
  EXPECT_EQ(step[3].kernel, "evaluate_Grow");
  EXPECT_EQ(step[4].kernel, "advance");
  EXPECT_EQ(step[4].sharedPerThread, 4);
  EXPECT_EQ(step[4].sharedFixed, 8);
  EXPECT_EQ(step[11].kernel, "advance");
}

TEST(PlanText, BoundsUnrolling) {
  std::string plan = replace(
      decayPlan(kHip), "launch advance single for - shared 0 0 args clock\n",
      "repeat 1048576\nrepeat 1048576\nlaunch advance single for - shared 0 "
      "0 args clock\nend\nend\n");
  EXPECT_NE(errorOf(withPlan(kHip, plan)).find("unrolls to more than"),
            std::string::npos);
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
