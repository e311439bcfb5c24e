//===- CheckpointTest.cpp - pauses, checkpoints and restarts --------------===//
//
// Through the C API, on the decay scene (whose num_steps depends on T, so a
// run that restores the buffers but not the clock takes other big steps):
// a run paused on a big-step boundary and continued takes the big steps of
// one run; a checkpoint restarts another session bit for bit, on the CPU
// backend and on the reference executor, with the whole clock; and every
// checkpoint that does not belong to the session, or is damaged, is
// refused with SIM_ERROR_CHECKPOINT and leaves the session as it was.
//
//===----------------------------------------------------------------------===//

#include "TestBundle.h"
#include "TestUtil.h"

#include "sim/Runtime/checkpoint_generated.h"
#include "sim/Runtime/sim_runtime.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <tuple>
#include <unistd.h>
#include <vector>
#include <zlib.h>

using namespace sim::test;

namespace {

/// A bundle file and sessions of it, closed at the end.
class Checkpoints : public ::testing::Test {
protected:
  void SetUp() override {
    dir = makeTempDir();
    path = dir + "/decay.simb";
    writeFile(path, decayBundle());
    ASSERT_EQ(sim_bundle_open(path.c_str(), &bundle), SIM_OK)
        << sim_last_error();
  }
  void TearDown() override {
    for (sim_session *session : sessions)
      sim_session_destroy(session);
    sim_bundle_close(bundle);
    std::system(("rm -rf '" + dir + "'").c_str());
  }

  sim_session *session(sim_strategy strategy, sim_backend backend,
                       const sim_bundle *from = nullptr,
                       int64_t groupSize = 0) {
    sim_session_options options;
    sim_session_options_init(&options);
    options.strategy = strategy;
    options.backend = backend;
    options.cpu_threads = 2;
    options.group_size = groupSize;
    sim_session *result = nullptr;
    EXPECT_EQ(sim_session_create(from ? from : bundle, &options, &result),
              SIM_OK)
        << sim_last_error();
    sessions.push_back(result);
    return result;
  }

  /// A checkpoint of a CPU hip session after 12 base steps, written to
  /// `file`: its bytes.
  std::string goodCheckpoint(const std::string &file) {
    sim_session *writer = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
    EXPECT_EQ(sim_session_run(writer, 12), SIM_OK) << sim_last_error();
    EXPECT_EQ(sim_session_checkpoint(writer, file.c_str()), SIM_OK)
        << sim_last_error();
    return readFile(file);
  }

  std::string dir, path;
  sim_bundle *bundle = nullptr;
  std::vector<sim_session *> sessions;
};

std::string bytesOf(sim_session *session, const char *buffer) {
  size_t bytes = 0;
  EXPECT_EQ(sim_session_buffer_bytes(session, buffer, &bytes), SIM_OK);
  std::string data(bytes, '\0');
  EXPECT_EQ(sim_session_get_buffer(session, buffer, data.data(), bytes),
            SIM_OK);
  return data;
}

/// What a run did: its counters.
struct Counts {
  int64_t bigSteps = 0, cuts = 0;
  std::vector<int64_t> evaluations, histogram;

  void add(sim_session *session) {
    sim_metrics metrics;
    EXPECT_EQ(sim_session_metrics(session, &metrics), SIM_OK);
    bigSteps += metrics.big_steps;
    cuts += sim_session_cut_big_steps(session);
    evaluations.resize(2, 0);
    for (int32_t c = 0; c < 2; ++c)
      evaluations[size_t(c)] += sim_session_evaluations(session, c);
    histogram.resize(5, 0);
    for (int64_t m = 1; m <= 4; ++m)
      histogram[size_t(m)] += sim_session_histogram(session, m);
  }
  bool operator==(const Counts &other) const {
    return bigSteps == other.bigSteps && cuts == other.cuts &&
           evaluations == other.evaluations && histogram == other.histogram;
  }
};

/// A checkpoint file's header (BundleFormat.h): magic, version, CRC-32,
/// size, reserved.
constexpr size_t kHeader = 32;

/// Writes the CRC-32 of everything after the header, and the file's size,
/// into its header: a file edited past the header as a hostile writer
/// would make it, which only the checks after the CRC's can refuse.
void reseal(std::string &bytes) {
  uint32_t crc =
      uint32_t(crc32(crc32(0L, Z_NULL, 0),
                     reinterpret_cast<const Bytef *>(bytes.data() + kHeader),
                     uInt(bytes.size() - kHeader)));
  std::memcpy(&bytes[12], &crc, sizeof crc);
  uint64_t size = bytes.size();
  std::memcpy(&bytes[16], &size, sizeof size);
}

/// The manifest of a checkpoint file (its size prefix and FlatBuffer),
/// copied to aligned memory, and where in the file its parts lie.
struct Manifest {
  explicit Manifest(const std::string &file) {
    uint32_t size;
    std::memcpy(&size, &file[kHeader], sizeof size);
    bytes.assign(file.begin() + kHeader, file.begin() + kHeader + 4 + size);
  }
  const sim::checkpoint::Checkpoint *root() const {
    return sim::checkpoint::GetSizePrefixedCheckpoint(bytes.data());
  }
  /// Where field `field` of the root lies in the copy; null where the
  /// file holds its default.
  const uint8_t *field(flatbuffers::voffset_t field) const {
    return reinterpret_cast<const flatbuffers::Table *>(root())->GetAddressOf(
        field);
  }
  /// The offset in the file of `at`, a pointer into the copy.
  size_t inFile(const void *at) const {
    return kHeader + size_t(static_cast<const uint8_t *>(at) - bytes.data());
  }

  std::vector<uint8_t> bytes;
};

const sim_backend kBackends[] = {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE};
const sim_strategy kStrategies[] = {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP};

} // namespace

TEST_F(Checkpoints, APausedRunContinuesAsOneRun) {
  for (sim_backend backend : kBackends) {
    SCOPED_TRACE(sim_backend_name(backend));
    sim_session *whole = session(SIM_STRATEGY_HIP, backend);
    ASSERT_EQ(sim_session_run(whole, 300), SIM_OK);
    Counts one;
    one.add(whole);

    sim_session *paused = session(SIM_STRATEGY_HIP, backend);
    Counts parts;
    int64_t stops = 0;
    // Pauses after 1, 7, 31, ... base steps: each lands on the first
    // boundary the host sees at or after it, never cutting a big step.
    for (int64_t pause : {1, 7, 31, 50, 100000}) {
      int64_t before = sim_session_time(paused);
      ASSERT_EQ(sim_session_run_pausing(paused, 300 - before, pause), SIM_OK)
          << sim_last_error();
      int64_t now = sim_session_time(paused);
      EXPECT_GE(now, std::min<int64_t>(before + pause, 300));
      EXPECT_EQ(sim_session_cut_big_steps(paused), now == 300 ? one.cuts : 0);
      parts.add(paused);
      ++stops;
    }
    EXPECT_EQ(sim_session_time(paused), 300);
    EXPECT_TRUE(parts == one);
    EXPECT_EQ(bytesOf(paused, "X"), bytesOf(whole, "X"));
    EXPECT_EQ(bytesOf(paused, "V"), bytesOf(whole, "V"));
    // A run cut at 152 (inside the big step from 151 to 154) instead takes
    // other big steps.
    sim_session *cut = session(SIM_STRATEGY_HIP, backend);
    Counts cutParts;
    ASSERT_EQ(sim_session_run(cut, 152), SIM_OK);
    EXPECT_EQ(sim_session_cut_big_steps(cut), 1);
    cutParts.add(cut);
    ASSERT_EQ(sim_session_run(cut, 148), SIM_OK);
    cutParts.add(cut);
    EXPECT_FALSE(cutParts == one);
    EXPECT_TRUE(bytesOf(cut, "V") != bytesOf(whole, "V"));

    EXPECT_EQ(sim_session_run_pausing(paused, 10, 0),
              SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_TRUE(contains(sim_last_error(), "cannot pause a run after 0"));
  }
}

TEST_F(Checkpoints, ARestartContinuesBitForBit) {
  for (sim_backend backend : kBackends)
    for (sim_strategy strategy : kStrategies) {
      SCOPED_TRACE(std::string(sim_backend_name(backend)) + " " +
                   sim_strategy_name(strategy));
      std::string file = dir + "/" + sim_backend_name(backend) + "-" +
                         sim_strategy_name(strategy) + ".simc";
      // The run that writes the checkpoint, on the boundary it pauses at.
      sim_session *writer = session(strategy, backend);
      ASSERT_EQ(sim_session_set(writer, "k", "1.5"), SIM_OK);
      ASSERT_EQ(sim_session_run_pausing(writer, 200, 37), SIM_OK);
      int64_t at = sim_session_time(writer);
      ASSERT_GE(at, 37);
      ASSERT_LT(at, 200);
      ASSERT_EQ(sim_session_checkpoint(writer, file.c_str()), SIM_OK)
          << sim_last_error();
      EXPECT_EQ(sim_session_time(writer), at);
      ASSERT_EQ(sim_session_run(writer, 200 - at), SIM_OK);
      Counts written;
      written.add(writer);

      // Another session, the same settings, restarted from it.
      sim_session *restarted = session(strategy, backend);
      ASSERT_EQ(sim_session_set(restarted, "k", "1.5"), SIM_OK);
      ASSERT_EQ(sim_session_restart(restarted, file.c_str()), SIM_OK)
          << sim_last_error();
      EXPECT_EQ(sim_session_time(restarted), at);
      ASSERT_EQ(sim_session_run(restarted, 200 - at), SIM_OK);
      Counts continued;
      continued.add(restarted);
      EXPECT_TRUE(continued == written);
      EXPECT_EQ(bytesOf(restarted, "X"), bytesOf(writer, "X"));
      EXPECT_EQ(bytesOf(restarted, "V"), bytesOf(writer, "V"));
      // The exact solution is at the restored time.
      std::string exact(800, '\0'), expected(800, '\0');
      ASSERT_EQ(sim_session_exact(restarted, "X", exact.data(), 800), SIM_OK);
      ASSERT_EQ(sim_session_exact(writer, "X", expected.data(), 800), SIM_OK);
      EXPECT_EQ(exact, expected);

      // The symptom of the issue: the buffers alone, without the clock,
      // continue from T = 0 and take other big steps.
      sim_session *buffersOnly = session(strategy, backend);
      ASSERT_EQ(sim_session_set(buffersOnly, "k", "1.5"), SIM_OK);
      sim_session *source = session(strategy, backend);
      ASSERT_EQ(sim_session_set(source, "k", "1.5"), SIM_OK);
      ASSERT_EQ(sim_session_restart(source, file.c_str()), SIM_OK);
      for (const char *buffer : {"X", "V"}) {
        std::string data = bytesOf(source, buffer);
        ASSERT_EQ(sim_session_set_buffer(buffersOnly, buffer, data.data(),
                                         data.size()),
                  SIM_OK);
      }
      ASSERT_EQ(sim_session_run(buffersOnly, 200 - at), SIM_OK);
      EXPECT_EQ(sim_session_time(buffersOnly), 200 - at);
      if (strategy == SIM_STRATEGY_HIP)
        EXPECT_TRUE(bytesOf(buffersOnly, "V") != bytesOf(writer, "V"));
    }
}

TEST_F(Checkpoints, HoldTheWholeClock) {
  // The checkpoint of the plan executor holds every clock slot: a restarted
  // session's next checkpoint is the same file, byte for byte, as the one
  // the writer makes at the same point.
  sim_session *writer = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  ASSERT_EQ(sim_session_run(writer, 23), SIM_OK);
  std::string first = dir + "/first.simc", second = dir + "/second.simc",
              third = dir + "/third.simc";
  ASSERT_EQ(sim_session_checkpoint(writer, first.c_str()), SIM_OK);
  sim_session *restarted = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  ASSERT_EQ(sim_session_restart(restarted, first.c_str()), SIM_OK);
  ASSERT_EQ(sim_session_checkpoint(restarted, second.c_str()), SIM_OK);
  EXPECT_EQ(readFile(first), readFile(second));
  ASSERT_EQ(sim_session_run(writer, 17), SIM_OK);
  ASSERT_EQ(sim_session_run(restarted, 17), SIM_OK);
  ASSERT_EQ(sim_session_checkpoint(writer, first.c_str()), SIM_OK);
  ASSERT_EQ(sim_session_checkpoint(restarted, third.c_str()), SIM_OK);
  EXPECT_EQ(readFile(first), readFile(third));
  // Into a file descriptor, from its offset.
  std::string viaFd = dir + "/fd.simc";
  int fd = open(viaFd.c_str(), O_RDWR | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(sim_session_checkpoint_fd(writer, fd), SIM_OK) << sim_last_error();
  close(fd);
  EXPECT_EQ(readFile(viaFd), readFile(first));
  // Only the temporary files' traces are gone.
  int entries = 0;
  for (const char *name :
       {"first.simc", "second.simc", "third.simc", "fd.simc", "decay.simb"})
    entries += access((dir + "/" + name).c_str(), F_OK) == 0;
  EXPECT_EQ(entries, 5);
  EXPECT_EQ(readFile(first).substr(0, 8), std::string("SIMCKPT\0", 8));
}

TEST_F(Checkpoints, ThePlanExecutorsRestartTheReferenceExecutor) {
  std::string file = dir + "/plan.simc";
  sim_session *cpu = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  ASSERT_EQ(sim_session_run_pausing(cpu, 100, 40), SIM_OK);
  ASSERT_EQ(sim_session_checkpoint(cpu, file.c_str()), SIM_OK);
  int64_t at = sim_session_time(cpu);
  sim_session *reference = session(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE);
  ASSERT_EQ(sim_session_restart(reference, file.c_str()), SIM_OK)
      << sim_last_error();
  EXPECT_EQ(sim_session_time(reference), at);
  ASSERT_EQ(sim_session_run(cpu, 100 - at), SIM_OK);
  ASSERT_EQ(sim_session_run(reference, 100 - at), SIM_OK);
  EXPECT_EQ(bytesOf(reference, "V"), bytesOf(cpu, "V"));
  EXPECT_EQ(sim_session_evaluations(reference, 0),
            sim_session_evaluations(cpu, 0));
  // Not the reverse: the reference executor keeps no device clock.
  std::string referenceFile = dir + "/reference.simc";
  ASSERT_EQ(sim_session_checkpoint(reference, referenceFile.c_str()), SIM_OK);
  sim_session *other = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  EXPECT_EQ(sim_session_restart(other, referenceFile.c_str()),
            SIM_ERROR_CHECKPOINT);
  EXPECT_TRUE(contains(sim_last_error(),
                       "was written by the reference executor, which keeps "
                       "no device clock"))
      << sim_last_error();
}

TEST_F(Checkpoints, RefuseWhatDoesNotBelongToTheSession) {
  std::string file = dir + "/hip.simc";
  sim_session *writer = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  ASSERT_EQ(sim_session_set(writer, "k", "1.5"), SIM_OK);
  ASSERT_EQ(sim_session_run(writer, 12), SIM_OK);
  ASSERT_EQ(sim_session_checkpoint(writer, file.c_str()), SIM_OK);

  // Another bundle of the same scene (another producer: another CRC), and
  // another scene.
  schema::BundleT contents = decayContents();
  contents.producer = "another compiler";
  std::string otherPath = dir + "/other.simb";
  writeFile(otherPath, serialize(contents));
  sim_bundle *other = nullptr;
  ASSERT_EQ(sim_bundle_open(otherPath.c_str(), &other), SIM_OK);
  contents.scene->name = "growth";
  std::string renamedPath = dir + "/renamed.simb";
  writeFile(renamedPath, serialize(contents));
  sim_bundle *renamed = nullptr;
  ASSERT_EQ(sim_bundle_open(renamedPath.c_str(), &renamed), SIM_OK);

  struct Case {
    std::string what;
    sim_session *session;
    std::string message;
  } cases[] = {
      {"another bundle", session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU, other),
       "belongs to another bundle of scene 'decay' (its bundle's CRC-32 is "
       "0x"},
      {"another scene", session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU, renamed),
       "is of scene 'decay', this session runs scene 'growth'"},
      {"another strategy", session(SIM_STRATEGY_SIMPLE, SIM_BACKEND_CPU),
       "was written under strategy 'hip', this session runs 'simple'"},
      {"another group size",
       session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU, nullptr, 64),
       "was written with group size 32, this session has 64"},
      {"another range", session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU),
       "was written at range 100, this session has range 50"},
      {"another parameter", session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU),
       "was written with k = 1.5, this session has k = 2"},
      {"another dt", session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU),
       "was written with dt 0.01, this session has dt 0.02"},
  };
  sim_bundle_close(other);
  sim_bundle_close(renamed);
  for (const Case &c : cases) {
    SCOPED_TRACE(c.what);
    if (c.what != "another parameter")
      ASSERT_EQ(sim_session_set(c.session, "k", "1.5"), SIM_OK);
    if (c.what == "another range")
      ASSERT_EQ(sim_session_set(c.session, "range", "50"), SIM_OK);
    if (c.what == "another dt")
      ASSERT_EQ(sim_session_set(c.session, "dt", "0.02"), SIM_OK);
    ASSERT_EQ(sim_session_run(c.session, 3), SIM_OK);
    std::string before = bytesOf(c.session, "V");
    EXPECT_EQ(sim_session_restart(c.session, file.c_str()),
              SIM_ERROR_CHECKPOINT);
    EXPECT_TRUE(
        contains(sim_last_error(), "checkpoint '" + file + "' " + c.message))
        << sim_last_error();
    // Refused before anything changed.
    EXPECT_EQ(sim_session_time(c.session), 3);
    EXPECT_EQ(bytesOf(c.session, "V"), before);
  }
  EXPECT_EQ(std::string(sim_status_name(SIM_ERROR_CHECKPOINT)),
            "bad checkpoint");
}

TEST_F(Checkpoints, RefuseDamagedFiles) {
  std::string file = dir + "/good.simc", bad = dir + "/bad.simc";
  std::string good = goodCheckpoint(file);
  ASSERT_GT(good.size(), 2000u);
  sim_session *target = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  ASSERT_EQ(sim_session_run(target, 5), SIM_OK);
  std::string before = bytesOf(target, "X");

  auto refused = [&](const std::string &bytes, const std::string &message) {
    writeFile(bad, bytes);
    sim_status status = sim_session_restart(target, bad.c_str());
    bool ok = status == SIM_ERROR_CHECKPOINT &&
              contains(sim_last_error(), message) &&
              sim_session_time(target) == 5 && bytesOf(target, "X") == before;
    if (!ok)
      ADD_FAILURE() << "status " << status << ": " << sim_last_error()
                    << " (expected '" << message << "')";
    return ok;
  };
  // Every truncation.
  for (size_t size = 0; size < good.size(); ++size)
    if (!refused(good.substr(0, size),
                 size < 8    ? "too few for a checkpoint (truncated?)"
                 : size < 32 ? "fewer than the 32-byte header (truncated?)"
                             : "(truncated?)"))
      break;
  // One flipped bit in every byte, in turn: the header's fields or the
  // CRC-32 find each.
  for (size_t at = 0; at < good.size(); ++at) {
    std::string flipped = good;
    flipped[at] = char(flipped[at] ^ (1 << (at % 8)));
    if (!refused(flipped, at < 8    ? "not a sim checkpoint (wrong magic"
                          : at < 12 ? "format version"
                          : at < 16 ? "the file is damaged"
                          : at < 24 ? "bytes but the file has"
                          : at < 32 ? "the reserved header field"
                                    : "the file is damaged"))
      break;
  }
  EXPECT_TRUE(refused(good + "x",
                      "but the file has " + std::to_string(good.size() + 1)));
  // A manifest too short to hold a root offset and the identifier, with a
  // valid CRC: refused before the identifier is read (the checkpoint
  // fuzzer found that read past the copy of the manifest).
  for (uint32_t manifestSize = 0; manifestSize < 8; ++manifestSize) {
    std::string bytes = good.substr(0, kHeader) + std::string(64, '\0');
    std::memcpy(&bytes[kHeader], &manifestSize, sizeof manifestSize);
    reseal(bytes);
    EXPECT_TRUE(refused(bytes, "the manifest has " +
                                   std::to_string(manifestSize) +
                                   " bytes, too few for a checkpoint"));
  }
  EXPECT_TRUE(refused(readFile(path), "it is a bundle, not a checkpoint"));
  EXPECT_EQ(sim_session_restart(target, (dir + "/missing.simc").c_str()),
            SIM_ERROR_IO);
  EXPECT_TRUE(contains(sim_last_error(), "cannot open checkpoint"));
  // The good one still restarts.
  ASSERT_EQ(sim_session_restart(target, file.c_str()), SIM_OK);
  EXPECT_EQ(sim_session_time(target), 12);
}

TEST_F(Checkpoints, RefuseAClockOffItsAlignment) {
  // FlatBuffers 2.0's verifier checks a vector's length prefix, not that
  // its 8-byte elements are aligned (VectorAlignment.h): the manifest's
  // clock moved 4 bytes on, its length prefix written over its first
  // value, with a valid CRC, is refused before anything reads it.
  std::string file = dir + "/good.simc", bad = dir + "/bad.simc";
  std::string bytes = goodCheckpoint(file);
  ASSERT_GT(bytes.size(), 2000u);
  Manifest manifest(bytes);
  const auto *clock = manifest.root()->clock();
  ASSERT_NE(clock, nullptr);
  ASSERT_GE(clock->size(), 2u);
  size_t fieldAt =
      manifest.inFile(manifest.field(sim::checkpoint::Checkpoint::VT_CLOCK));
  size_t elementsAt = manifest.inFile(clock->Data());
  uint32_t offset;
  std::memcpy(&offset, &bytes[fieldAt], sizeof offset);
  offset += 4;
  std::memcpy(&bytes[fieldAt], &offset, sizeof offset);
  uint32_t length = 1;
  std::memcpy(&bytes[elementsAt], &length, sizeof length);
  reseal(bytes);
  writeFile(bad, bytes);
  sim_session *target = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  EXPECT_EQ(sim_session_restart(target, bad.c_str()), SIM_ERROR_CHECKPOINT);
  EXPECT_TRUE(contains(sim_last_error(),
                       "its int64 vector clock is not aligned to 8 bytes"))
      << sim_last_error();
  ASSERT_EQ(sim_session_restart(target, file.c_str()), SIM_OK)
      << sim_last_error();
}

TEST_F(Checkpoints, RefuseAnEnumValueTheRuntimeDoesNotKnow) {
  // The FlatBuffers verifier checks no enum's range. An executor past the
  // last passed every check that compares it with a known one, and so
  // skipped the clock's (the checkpoint fuzzer found a plan session that
  // accepted a clock at another base step than the file's).
  sim_session *reference = session(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE);
  ASSERT_EQ(sim_session_run(reference, 12), SIM_OK) << sim_last_error();
  std::string file = dir + "/reference.simc", bad = dir + "/bad.simc";
  ASSERT_EQ(sim_session_checkpoint(reference, file.c_str()), SIM_OK)
      << sim_last_error();
  std::string good = readFile(file);
  // The byte of a scalar field the file holds (not a default), set to
  // `value`, with the CRC made for it.
  auto withField = [&](flatbuffers::voffset_t field, uint8_t value) {
    std::string bytes = good;
    Manifest manifest(bytes);
    const uint8_t *at = manifest.field(field);
    EXPECT_NE(at, nullptr);
    if (at) {
      bytes[manifest.inFile(at)] = char(value);
      reseal(bytes);
    }
    return bytes;
  };
  sim_session *target = session(SIM_STRATEGY_HIP, SIM_BACKEND_REFERENCE);
  ASSERT_EQ(sim_session_run(target, 5), SIM_OK);
  for (auto [field, value, message] :
       {std::tuple(sim::checkpoint::Checkpoint::VT_EXECUTOR, 2,
                   "the manifest names executor 2, which this runtime does "
                   "not know (damaged?)"),
        std::tuple(sim::checkpoint::Checkpoint::VT_STRATEGY, 9,
                   "the manifest names strategy 9, which this runtime does "
                   "not know (damaged?)")}) {
    writeFile(bad, withField(field, uint8_t(value)));
    EXPECT_EQ(sim_session_restart(target, bad.c_str()), SIM_ERROR_CHECKPOINT);
    EXPECT_TRUE(contains(sim_last_error(), message)) << sim_last_error();
    EXPECT_EQ(sim_session_time(target), 5);
  }
  ASSERT_EQ(sim_session_restart(target, file.c_str()), SIM_OK)
      << sim_last_error();
  EXPECT_EQ(sim_session_time(target), 12);
}

TEST_F(Checkpoints, NeedABigStepBoundary) {
  // A run stopped by a NaN inside a big step leaves no boundary to write.
  sim_session_options options;
  sim_session_options_init(&options);
  options.backend = SIM_BACKEND_CPU;
  options.check_finite = 1;
  sim_session *checked = nullptr;
  ASSERT_EQ(sim_session_create(bundle, &options, &checked), SIM_OK);
  sessions.push_back(checked);
  ASSERT_EQ(sim_session_set(checked, "poison", "9"), SIM_OK);
  ASSERT_EQ(sim_session_run(checked, 40), SIM_ERROR_NONFINITE);
  std::string file = dir + "/inside.simc";
  EXPECT_EQ(sim_session_checkpoint(checked, file.c_str()),
            SIM_ERROR_CHECKPOINT);
  EXPECT_TRUE(contains(sim_last_error(), "the state is inside a big step"))
      << sim_last_error();
  EXPECT_NE(access(file.c_str(), F_OK), 0);
  // After init it is on one again.
  ASSERT_EQ(sim_session_init(checked), SIM_OK);
  EXPECT_EQ(sim_session_checkpoint(checked, file.c_str()), SIM_OK);
  // A folder is no checkpoint path.
  EXPECT_EQ(sim_session_checkpoint(checked, (dir + "/").c_str()),
            SIM_ERROR_INVALID_ARGUMENT);
}

TEST_F(Checkpoints, NeverReplaceWhatIsNotARegularFile) {
  // A checkpoint is renamed over its path: a FIFO, a device or a socket
  // there (or a symlink to one, or into /proc as /dev/stdout is) would
  // become a regular file, which as root breaks /dev/null for the machine.
  sim_session *writer = session(SIM_STRATEGY_HIP, SIM_BACKEND_CPU);
  std::string fifo = dir + "/fifo.simc", toNull = dir + "/null.simc",
              toProc = dir + "/stdout.simc", folder = dir + "/folder";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0644), 0);
  ASSERT_EQ(symlink("/dev/null", toNull.c_str()), 0);
  ASSERT_EQ(symlink("/proc/self/fd/1", toProc.c_str()), 0);
  ASSERT_EQ(mkdir(folder.c_str(), 0755), 0);
  struct Refused {
    std::string path, message;
  };
  for (const Refused &refused :
       {Refused{fifo, "is a FIFO, not a regular file"},
        Refused{toNull, "is a symlink to a character device"},
        Refused{toProc, "a process's file"},
        Refused{folder, "names a folder, not a file"}}) {
    EXPECT_EQ(sim_session_checkpoint(writer, refused.path.c_str()),
              SIM_ERROR_INVALID_ARGUMENT)
        << refused.path;
    EXPECT_TRUE(contains(sim_last_error(), refused.message))
        << sim_last_error();
  }
  struct stat info;
  ASSERT_EQ(lstat(fifo.c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
  ASSERT_EQ(lstat(toNull.c_str(), &info), 0);
  EXPECT_TRUE(S_ISLNK(info.st_mode));
  ASSERT_EQ(lstat(folder.c_str(), &info), 0);
  EXPECT_TRUE(S_ISDIR(info.st_mode));
  // A symlink to a regular file is replaced, as sim-run's outputs are.
  std::string target = dir + "/target.simc", link = dir + "/link.simc";
  writeFile(target, "old");
  ASSERT_EQ(symlink(target.c_str(), link.c_str()), 0);
  EXPECT_EQ(sim_session_checkpoint(writer, link.c_str()), SIM_OK)
      << sim_last_error();
  ASSERT_EQ(lstat(link.c_str(), &info), 0);
  EXPECT_TRUE(S_ISREG(info.st_mode));
  EXPECT_EQ(readFile(target), "old");
}
