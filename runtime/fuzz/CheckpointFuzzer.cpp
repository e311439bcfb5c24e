//===- CheckpointFuzzer.cpp - libFuzzer target of checkpoint restarts -----===//
//
// Feeds arbitrary bytes to the checkpoint reader (parseCheckpoint: header,
// CRC, FlatBuffers verifier, alignment, extents) and, when they parse, to
// restartFromCheckpoint on four sessions of the runtime tests' decay scene:
// the CPU backend and the reference executor, each under simple and hip.
// Any input must end in a restart or a sim::rt::Error; a crash, a hang, a
// sanitizer report or another exception is a bug. Two properties are
// checked as well (a violation aborts, which the fuzzer reports):
//
//  - a refused restart leaves the session as it was: its clock and every
//    buffer's bytes (docs/Runtime.md, "Checkpoints");
//  - a session that accepted a checkpoint holds its time and every one of
//    its buffers, and runs on from it: two base steps, which end in a run
//    or a clean error, never in a crash.
//
// As in BundleFuzzer.cpp, the first byte picks the mode: even, the rest is
// a whole file as it is; odd, the rest is what follows the header and the
// target writes the header and CRC for it, so that mutations get past the
// checksum.
//
// A checkpoint names its bundle by CRC-32, and the decay bundle embeds
// this build's kernel objects, so its CRC differs between builds. The
// sessions' bundle therefore claims a fixed CRC (kBundleCrc), which keeps
// the kept corpus (runtime/fuzz/corpus/checkpoint) able to pass that check
// in every build. With SIM_CHECKPOINT_FUZZ_SEEDS set to a folder, the
// target writes there, once, a good checkpoint of each session in the odd
// mode: utils/sanitize.sh seeds the fuzzer with them.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Checkpoint.h"
#include "Error.h"
#include "Executor.h"
#include "Reference.h"
#include "Session.h"
#include "TestBundle.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <unistd.h>
#include <vector>
#include <zlib.h>

namespace {

using namespace sim::rt;

/// The CRC-32 the sessions' bundle claims: any fixed value will do.
constexpr uint32_t kBundleCrc = 0x5eed5eed;

/// The bytes of a checkpoint of `executor`, through a temporary file (the
/// writer needs a seekable descriptor).
std::vector<uint8_t> checkpointBytes(Executor &executor) {
  std::FILE *file = std::tmpfile();
  if (!file)
    std::abort();
  writeCheckpoint(executor, fileno(file), "seed");
  std::vector<uint8_t> bytes(size_t(lseek(fileno(file), 0, SEEK_END)));
  if (pread(fileno(file), bytes.data(), bytes.size(), 0) !=
      ssize_t(bytes.size()))
    std::abort();
  std::fclose(file);
  return bytes;
}

struct Sessions {
  std::vector<std::unique_ptr<Executor>> all;

  Sessions() {
    std::string file = sim::test::decayBundle();
    std::shared_ptr<const Bundle> bundle = Bundle::parse(
        reinterpret_cast<const uint8_t *>(file.data()), file.size(), "decay");
    // Bundle::parse made it, not const: see kBundleCrc.
    const_cast<Bundle &>(*bundle).checksum = kBundleCrc;
    for (sim_backend backend : {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE})
      for (sim_strategy strategy : {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP}) {
        sim_session_options options;
        sim_session_options_init(&options);
        options.backend = backend;
        options.strategy = strategy;
        options.cpu_threads = 1;
        if (backend == SIM_BACKEND_REFERENCE)
          all.push_back(std::make_unique<ReferenceSession>(bundle, options));
        else
          all.push_back(std::make_unique<Session>(bundle, options));
        // A state that is not the initial one, so that a restart that
        // changed anything shows.
        all.back()->run(7);
      }
    if (const char *seeds = std::getenv("SIM_CHECKPOINT_FUZZ_SEEDS"))
      writeSeeds(seeds);
  }

  void writeSeeds(const std::string &folder) {
    for (size_t s = 0; s < all.size(); ++s) {
      std::vector<uint8_t> bytes = checkpointBytes(*all[s]);
      std::ofstream out(folder + "/decay-session" + std::to_string(s),
                        std::ios::binary);
      out.put('\1');
      out.write(reinterpret_cast<const char *>(bytes.data()) +
                    sim::bundle::kHeaderSize,
                std::streamsize(bytes.size() - sim::bundle::kHeaderSize));
    }
  }
};

Sessions &sessions() {
  static Sessions instance;
  return instance;
}

/// Whether `executor` now holds the time and every buffer of `file`.
bool restoredAll(Executor &executor, const CheckpointFile &file) {
  if (executor.time() != file.manifest.time)
    return false;
  // The session's buffers: a plan's checkpoint may hold more than the
  // reference executor keeps.
  for (const std::string &name : executor.stateBuffers()) {
    auto state =
        std::find_if(file.manifest.buffers.begin(), file.manifest.buffers.end(),
                     [&](const auto &state) { return state->name == name; });
    if (state == file.manifest.buffers.end())
      return false;
    std::vector<uint8_t> held(executor.hostBytes(name));
    executor.getBuffer(name, held.data(), held.size());
    if (held.size() != (*state)->bytes ||
        !std::equal(held.begin(), held.end(), file.data(**state)))
      return false;
  }
  return true;
}

std::vector<uint8_t> fileOf(const uint8_t *data, size_t size) {
  if (!(data[0] & 1))
    return std::vector<uint8_t>(data + 1, data + size);
  const uint8_t *payload = data + 1;
  size_t payloadSize = size - 1;
  sim::bundle::Header header;
  header.version = kCheckpointVersion;
  header.checksum =
      uint32_t(crc32(crc32(0L, Z_NULL, 0), payload, uInt(payloadSize)));
  header.size = sim::bundle::kHeaderSize + payloadSize;
  std::string encoded = sim::bundle::encodeHeader(header);
  std::copy(std::begin(kCheckpointMagic), std::end(kCheckpointMagic),
            encoded.begin());
  std::vector<uint8_t> file(encoded.begin(), encoded.end());
  file.insert(file.end(), payload, payload + payloadSize);
  return file;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  // The sessions first, even for an empty input: `replay /dev/null` with
  // SIM_CHECKPOINT_FUZZ_SEEDS set is how the seeds get written.
  Sessions &all = sessions();
  if (size == 0)
    return 0;
  std::optional<CheckpointFile> file;
  try {
    file = parseCheckpoint(fileOf(data, size), "fuzz");
  } catch (const Error &) {
    return 0; // A clean rejection.
  }
  for (const auto &session : all.all) {
    SessionState before = stateOf(*session);
    try {
      restartFromCheckpoint(*session, *file);
    } catch (const Error &) {
      if (!(stateOf(*session) == before)) {
        std::fprintf(stderr, "a refused restart changed the session\n");
        std::abort();
      }
      continue;
    }
    if (!restoredAll(*session, *file)) {
      std::fprintf(stderr, "an accepted restart did not restore the "
                           "checkpoint's time and buffers\n");
      std::abort();
    }
    try {
      session->run(2);
    } catch (const Error &) {
      // A clean error: the state holds, for example, a value the scene's
      // checks refuse.
    }
  }
  return 0;
}
