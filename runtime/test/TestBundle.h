//===- TestBundle.h - bundles for the runtime's tests -------------*- C++
//-*-===//
//
// The runtime's tests need no compiler: they build the contents of a bundle
// with the schema's object API (runtime/schema/bundle.fbs) and serialise
// them as sim-translate does (header, CRC-32, FlatBuffer). Two scenes:
// "decay", whose CPU kernels and reference functions are hand-written C
// (kernels/decay.c, kernels/decay_reference.c), and "probe", a scene for
// the reference executor alone (kernels/probe_reference.c).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_TEST_TESTBUNDLE_H
#define SIM_RUNTIME_TEST_TESTBUNDLE_H

#include "sim/Runtime/bundle_generated.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sim::test {

namespace schema = ::sim::bundle;

/// The bytes of a bundle file of `contents`: header, CRC and FlatBuffer.
std::string serialize(const schema::BundleT &contents);

/// The bytes of a bundle file whose FlatBuffer is `payload` as it is (the
/// header and CRC made for it).
std::string withHeader(const std::string &payload);

std::string readFile(const std::string &path);
void writeFile(const std::string &path, const std::string &bytes);

/// The decay scene with plans of simple and hip (CPU code of kernels/
/// decay.c; with `ptx`, a placeholder PTX text per plan, enough for the
/// tests that never reach a driver) and, with `reference`, the reference
/// model with the object at `referenceObject`.
schema::BundleT
decayContents(bool ptx = false, bool reference = true,
              const std::string &referenceObject = SIM_TEST_DECAY_REFERENCE_SO);
std::string decayBundle(bool ptx = false, bool reference = true);

/// The "ring" scene of kernels/ring.c: a distributed hip plan (halo 2,
/// group size 4) whose buffer X reads i-2 .. i+2 under `boundary`, with
/// an all-reduced estimate and an exchange per big step. With `gather`, a
/// second buffer Y (clamp, with an exact solution) that every item reads
/// at all items: replicated, an all-gather per big step.
schema::BundleT ringContents(schema::Boundary boundary, bool gather = false);

/// The "probe" scene of kernels/probe_reference.c: a hip plan whose
/// kernels exist nowhere (the reference executor needs none) and its
/// reference model.
schema::BundleT probeContents();
std::string probeBundle();

/// The plan of `strategy` in `contents`.
schema::PlanT &planOf(schema::BundleT &contents, schema::Strategy strategy);

/// The reference of the decay scene: the big-step sizes the hip plan takes
/// from T to T + steps (num_steps(T) = 1 + (T / 5) % 4, capped at 4).
std::vector<int64_t> decayBigSteps(int64_t begin, int64_t steps, int64_t cap);
/// Whether the last of those big steps is cut short by the end of the run
/// (smaller than num_steps and the cap would make it): 0 or 1.
int64_t decayCuts(int64_t begin, int64_t steps, int64_t cap);

/// A fresh directory under $TMPDIR, removed by the caller if it wants.
std::string makeTempDir();

} // namespace sim::test

#endif // SIM_RUNTIME_TEST_TESTBUNDLE_H
