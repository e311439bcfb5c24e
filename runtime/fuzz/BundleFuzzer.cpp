//===- BundleFuzzer.cpp - libFuzzer target of the bundle reader -----------===//
//
// Feeds arbitrary bytes to the bundle reader (Bundle::parse: header, CRC,
// FlatBuffers verifier, cross-reference verifier, unpacking). Any input
// must end in a bundle or a sim::rt::Error; a crash, a hang, a sanitizer
// report or another exception is a bug.
//
// Random bytes almost never carry a right CRC-32, which would stop them at
// the header. So the first byte picks the mode: even, the rest is a whole
// file as it is; odd, the rest is the FlatBuffer and the target writes the
// header and CRC for it, which lets mutations reach the verifiers.
//
// Built with libFuzzer when SIM_ENABLE_FUZZERS is on (see
// docs/Testing.md); otherwise linked with ReplayMain.cpp, which runs the
// kept corpus (runtime/fuzz/corpus/bundle) as a regression test.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"

#include "sim/Runtime/BundleFormat.h"

#include <cstdint>
#include <string>
#include <zlib.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0)
    return 0;
  std::string file;
  if (data[0] & 1) {
    const uint8_t *payload = data + 1;
    size_t payloadSize = size - 1;
    sim::bundle::Header header;
    header.checksum =
        uint32_t(crc32(crc32(0L, Z_NULL, 0), payload, uInt(payloadSize)));
    header.size = sim::bundle::kHeaderSize + payloadSize;
    file = sim::bundle::encodeHeader(header) +
           std::string(reinterpret_cast<const char *>(payload), payloadSize);
  } else {
    file.assign(reinterpret_cast<const char *>(data + 1), size - 1);
  }
  try {
    auto bundle = sim::rt::Bundle::parse(
        reinterpret_cast<const uint8_t *>(file.data()), file.size(), "fuzz");
    // What the executors read first: every plan's phases unrolled.
    for (const auto &plan : bundle->contents.plans)
      for (const auto &phase : plan->phases)
        (void)sim::rt::unrollPhase(*phase).size();
  } catch (const sim::rt::Error &) {
    // A clean rejection.
  }
  return 0;
}
