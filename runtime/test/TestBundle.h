//===- TestBundle.h - bundles for the runtime's tests -------------*- C++
//-*-===//
//
// No compiler-made bundle exists yet, so the tests write their own: a
// minimal writer of the format of docs/Bundle.md, and the texts of the
// "decay" test scene whose CPU kernels are hand-written in kernels/decay.c.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_TEST_TESTBUNDLE_H
#define SIM_RUNTIME_TEST_TESTBUNDLE_H

#include <cstdint>
#include <string>
#include <vector>

namespace sim::test {

struct Section {
  uint32_t kind;     // 1 scene, 2 plan, 3 PTX, 4 CPU, 5, 6 reference
  uint32_t strategy; // 0..3, 0xffffffff for the scene and reference
  std::string bytes;
};

constexpr uint32_t kScene = 1, kPlan = 2, kPtx = 3, kCpu = 4;
constexpr uint32_t kReferenceModel = 5, kReferenceObject = 6;
constexpr uint32_t kNoStrategy = 0xffffffffu;
constexpr uint32_t kSimple = 0, kTraditional = 1, kHip = 2, kHipCache = 3;

/// The bytes of a bundle holding `sections` in order, each 8-aligned.
std::string writeBundle(const std::vector<Section> &sections);

std::string readFile(const std::string &path);
void writeFile(const std::string &path, const std::string &bytes);

/// Little-endian stores into a bundle's bytes, to corrupt it.
void putU32(std::string &bytes, size_t offset, uint32_t value);
void putU64(std::string &bytes, size_t offset, uint64_t value);

/// The decay scene and its plans (simple and hip).
std::string decayScene();
std::string decayPlan(uint32_t strategy);
/// Its sections: scene, and plan and CPU code of simple and hip; with
/// `ptx`, a PTX section per strategy too (a placeholder text: enough for
/// the tests that never reach a driver).
std::vector<Section> decaySections(bool ptx = false);

/// The decay scene's reference model (kernels/decay_reference.c), and its
/// two sections with the object at `object` (default: the right one).
std::string decayReferenceModel();
std::vector<Section>
decayReferenceSections(const std::string &object = SIM_TEST_DECAY_REFERENCE_SO);
/// decaySections(ptx) and, with `reference`, decayReferenceSections().
std::string decayBundle(bool ptx = false, bool reference = true);

/// The "probe" scene of kernels/probe_reference.c: its scene text, a hip
/// plan without kernels (the reference executor needs none), its model,
/// and a bundle of them.
std::string probeScene();
std::string probeModel();
std::string probeBundle(const std::string &model = probeModel());

/// The reference of the decay scene: the big-step sizes the hip plan takes
/// from T to T + steps (num_steps(T) = 1 + (T / 5) % 4, capped at 4).
std::vector<int64_t> decayBigSteps(int64_t begin, int64_t steps, int64_t cap);

/// A fresh directory under $TMPDIR, removed by the caller if it wants.
std::string makeTempDir();

} // namespace sim::test

#endif // SIM_RUNTIME_TEST_TESTBUNDLE_H
