//===- TestBundle.cpp - bundles for the runtime's tests -------------------===//

#include "TestBundle.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sim::test {

void putU32(std::string &bytes, size_t offset, uint32_t value) {
  for (int i = 0; i < 4; ++i)
    bytes[offset + i] = char((value >> (8 * i)) & 0xff);
}

void putU64(std::string &bytes, size_t offset, uint64_t value) {
  for (int i = 0; i < 8; ++i)
    bytes[offset + i] = char((value >> (8 * i)) & 0xff);
}

std::string writeBundle(const std::vector<Section> &sections) {
  size_t offset = 24 + 32 * sections.size();
  std::string bytes(offset, '\0');
  std::string contents;
  for (size_t i = 0; i < sections.size(); ++i) {
    size_t at = offset + contents.size();
    size_t entry = 24 + 32 * i;
    putU32(bytes, entry, sections[i].kind);
    putU32(bytes, entry + 4, sections[i].strategy);
    putU64(bytes, entry + 8, at);
    putU64(bytes, entry + 16, sections[i].bytes.size());
    contents += sections[i].bytes;
    contents.append((8 - contents.size() % 8) % 8, '\0');
  }
  bytes += contents;
  bytes.replace(0, 8, std::string("SIMBNDL\0", 8));
  putU32(bytes, 8, 1);
  putU32(bytes, 12, uint32_t(sections.size()));
  putU64(bytes, 16, bytes.size());
  return bytes;
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

std::string decayScene() {
  return "# The runtime's test scene (kernels/decay.c).\n"
         "scene decay range 100 dt f64 0.01 max_steps 4\n"
         "param k f64 2\n"
         "param poison i32 -1\n"
         "buffer X f64 interp linear boundary clamp observed exact\n"
         "buffer V vector<3xf32> interp none boundary clamp observed\n"
         "strategies simple hip\n";
}

std::string decayPlan(uint32_t strategy) {
  bool hip = strategy == kHip;
  std::string plan = hip ? "plan hip" : "plan simple";
  plan += " group_size 32 clock_slots 16 histogram 10\n"
          "buffer X f64 stride 8 observed exact\n"
          "buffer V vector<3xf32> stride 16 observed\n"
          "component Decay evaluations 8 writes X\n"
          "component Grow evaluations 9 writes V\n"
          "phase init\n"
          "launch reset_clock single for - shared 0 0 args clock\n"
          "launch init_X items for - shared 0 0 args buffer:X range\n"
          "launch init_V items for - shared 0 0 args buffer:V range\n"
          "end\n"
          "phase step\n";
  if (hip)
    plan += "launch estimate_Decay items for - shared 0 0 args clock range\n";
  plan += "launch advance single for - shared 0 0 args clock\n"
          "launch evaluate_Decay items for Decay shared 0 0 args clock "
          "buffer:X param:k param:poison range dt\n"
          "launch evaluate_Grow items for Grow shared 0 0 args clock "
          "buffer:V range\n"
          "end\n"
          "phase finish\n"
          "launch advance single for - shared 0 0 args clock\n"
          "end\n"
          "phase exact\n"
          "launch exact_X items for - shared 0 0 args exact:X param:k range "
          "time\n"
          "end\n";
  return plan;
}

std::vector<Section> decaySections(bool ptx) {
  std::vector<Section> sections = {
      {kScene, kNoStrategy, decayScene()},
      {kPlan, kSimple, decayPlan(kSimple)},
      {kCpu, kSimple, readFile(SIM_TEST_DECAY_SIMPLE_SO)},
      {kPlan, kHip, decayPlan(kHip)},
      {kCpu, kHip, readFile(SIM_TEST_DECAY_HIP_SO)},
  };
  if (ptx)
    for (uint32_t strategy : {kSimple, kHip})
      sections.push_back(
          {kPtx, strategy, std::string("// not real PTX\n\0", 17)});
  return sections;
}

std::string decayReferenceModel() {
  return "# kernels/decay_reference.c\n"
         "reference decay\n"
         "param 0 k f64\n"
         "param 1 poison i32\n"
         "buffer 0 X f64 interp linear boundary clamp observed exact\n"
         "buffer 1 V vector<3xf32> interp none boundary clamp observed\n"
         "component 0 Decay substep in_kernel num_steps writes X reads X V\n"
         "component 1 Grow substep in_kernel writes V reads V\n"
         "schedule Decay Grow\n";
}

std::vector<Section> decayReferenceSections(const std::string &object) {
  return {{kReferenceModel, kNoStrategy, decayReferenceModel()},
          {kReferenceObject, kNoStrategy, readFile(object)}};
}

std::string decayBundle(bool ptx, bool reference) {
  std::vector<Section> sections = decaySections(ptx);
  if (reference)
    for (Section &section : decayReferenceSections())
      sections.push_back(std::move(section));
  return writeBundle(sections);
}

std::string probeScene() {
  return "scene probe range 4 dt f64 0.5 max_steps 4\n"
         "param cycle i32 0\n"
         "param read_none i32 0\n"
         "buffer D f64 interp linear boundary clamp\n"
         "buffer A f64 interp linear boundary clamp observed\n"
         "buffer C f64 interp cubic boundary wrap observed\n"
         "buffer H f64 interp hermite:D boundary zero observed\n"
         "buffer N f64 interp none boundary clamp\n"
         "buffer L f64 interp linear boundary clamp\n"
         "buffer RA vector<4xf64> interp linear boundary clamp observed\n"
         "buffer RC vector<4xf64> interp linear boundary clamp observed\n"
         "buffer RH vector<4xf64> interp linear boundary clamp observed\n"
         "buffer E vector<6xf64> interp linear boundary clamp observed\n"
         "strategies hip\n";
}

std::string probeModel() {
  return "reference probe\n"
         "param 0 cycle i32\n"
         "param 1 read_none i32\n"
         "buffer 0 D f64 interp linear boundary clamp\n"
         "buffer 1 A f64 interp linear boundary clamp observed\n"
         "buffer 2 C f64 interp cubic boundary wrap observed\n"
         "buffer 3 H f64 interp hermite:D boundary zero observed\n"
         "buffer 4 N f64 interp none boundary clamp\n"
         "buffer 5 L f64 interp linear boundary clamp\n"
         "buffer 6 RA vector<4xf64> interp linear boundary clamp observed\n"
         "buffer 7 RC vector<4xf64> interp linear boundary clamp observed\n"
         "buffer 8 RH vector<4xf64> interp linear boundary clamp observed\n"
         "buffer 9 E vector<6xf64> interp linear boundary clamp observed\n"
         "component 0 Source substep in_kernel writes D A C H N reads\n"
         "component 1 Sink substep in_kernel num_steps writes RA RC RH "
         "reads A C H N RA RC RH\n"
         "component 2 Edge substep in_kernel writes E L reads A C H\n"
         "schedule Source Sink Edge\n";
}

std::string probeBundle(const std::string &model) {
  // The plan only gives the group size (2: two groups of two items); its
  // kernels exist nowhere, and the reference executor needs none.
  std::string plan = "plan hip group_size 2 clock_slots 16 histogram 10\n"
                     "buffer A f64 stride 8 observed\n"
                     "component Source evaluations 8 writes A\n"
                     "phase init\nend\n"
                     "phase step\n"
                     "launch none single for - shared 0 0 args clock\n"
                     "end\n"
                     "phase finish\nend\n";
  return writeBundle(
      {{kScene, kNoStrategy, probeScene()},
       {kPlan, kHip, plan},
       {kReferenceModel, kNoStrategy, model},
       {kReferenceObject, kNoStrategy, readFile(SIM_TEST_PROBE_REFERENCE_SO)}});
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

std::string makeTempDir() {
  const char *tmp = std::getenv("TMPDIR");
  std::string path =
      std::string(tmp && *tmp ? tmp : "/tmp") + "/sim-runtime-test-XXXXXX";
  if (!mkdtemp(path.data()))
    throw std::runtime_error("mkdtemp failed");
  return path;
}

} // namespace sim::test
