//===- Checkpoint.cpp - writing, verifying and restoring checkpoints ------===//
//
// The layout (docs/Runtime.md, "Checkpoints"):
//
//   offset 0      the 32-byte header of BundleFormat.h with the magic
//                 "SIMCKPT\0", version 1, the CRC-32 of every byte after
//                 the header, and the file size
//   offset 32     the manifest: a size-prefixed FlatBuffer of
//                 runtime/schema/checkpoint.fbs
//   data start    the first multiple of 64 after the manifest: each
//                 buffer's host array at its State's offset from here,
//                 each on a multiple of 64, zeros between them
//
// Reading checks the file as a bundle is checked (magic, version, size,
// CRC, the FlatBuffers verifier, then every extent), and restarting checks
// that the checkpoint belongs to the session before it changes anything.
//
// A distributed session (Distribution.h) gathers its state on every rank
// (collectively, before any file is touched), and only rank 0 writes it: the
// file is the one a single process would write. Every rank reads the file
// on a restart and keeps its block. The ranks agree afterwards on whether
// every one of them succeeded, so that none goes on alone.
//
//===----------------------------------------------------------------------===//

#include "Checkpoint.h"

#include "Distribution.h"
#include "Error.h"
#include "Executor.h"
#include "VectorAlignment.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <limits>
#include <optional>
#include <random>
#include <set>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

namespace sim::rt {

namespace {

uint64_t alignUp(uint64_t value) {
  return (value + kCheckpointAlignment - 1) / kCheckpointAlignment *
         kCheckpointAlignment;
}

/// zlib's crc32 over any number of bytes (it takes at most UINT_MAX at a
/// time).
uint32_t crcUpdate(uint32_t crc, const uint8_t *data, size_t size) {
  while (size > 0) {
    size_t chunk = std::min<size_t>(size, size_t(1) << 30);
    crc = uint32_t(crc32(crc, data, uInt(chunk)));
    data += chunk;
    size -= chunk;
  }
  return crc;
}

schema::Value toSchema(const Value &value) {
  return schema::Value(value.i, value.f, value.type);
}

bool sameValue(const Value &a, const Value &b) {
  return a.type == b.type && a.bits() == b.bits();
}

/// The scene buffer called `name` (the state buffers are scene buffers).
const schema::BufferT &sceneBuffer(const Executor &executor,
                                   const std::string &name) {
  for (const auto &buffer : executor.scene().buffers)
    if (buffer->name == name)
      return *buffer;
  fail(SIM_ERROR_BACKEND, "'" + name + "' is not a buffer of the scene");
}

/// Writes all of `data` at the fd's offset.
void writeAll(int fd, const uint8_t *data, size_t size,
              const std::string &name) {
  while (size > 0) {
    ssize_t written = ::write(fd, data, size);
    if (written < 0 && errno == EINTR)
      continue;
    if (written <= 0)
      fail(SIM_ERROR_IO,
           "cannot write checkpoint '" + name + "': " + std::strerror(errno));
    data += written;
    size -= size_t(written);
  }
}

/// The communicator of a session on more than one rank, else null.
Communicator *ranksOf(Executor &executor) {
  Communicator *comm = executor.communicator();
  return comm && comm->size() > 1 ? comm : nullptr;
}

/// Runs `body` on every rank of `comm`, then agrees on whether it failed
/// anywhere: the rank that failed throws its error, the others an error
/// with its status naming the first rank that failed and `what`.
template <typename Body>
void agreeOn(Communicator *comm, const std::string &what, Body &&body) {
  if (!comm) {
    body();
    return;
  }
  std::optional<Error> error;
  try {
    body();
  } catch (const Error &caught) {
    error = caught;
  }
  // The first rank that failed, with its status.
  constexpr int64_t kStatuses = 64;
  int64_t failed = error ? int64_t(comm->rank()) * kStatuses + error->status
                         : std::numeric_limits<int64_t>::max();
  comm->minimum(&failed, 1);
  if (error)
    throw *error;
  if (failed != std::numeric_limits<int64_t>::max())
    fail(sim_status(failed % kStatuses),
         "rank " + std::to_string(failed / kStatuses) + " " + what +
             " (its message says why)");
}

/// Writes the checkpoint; a distributed session's state is `gathered`
/// already, a single process's is read as it is written.
void writeImage(Executor &executor, int fd, const std::string &name,
                const SessionState *gathered) {
  off_t start = lseek(fd, 0, SEEK_CUR);
  if (start < 0)
    fail(SIM_ERROR_IO, "cannot write checkpoint '" + name +
                           "': the file is not seekable (" +
                           std::strerror(errno) + ")");
  // The clock first: it initialises a session without a state and refuses
  // one that is not on a big-step boundary.
  std::vector<int64_t> clock =
      gathered ? gathered->clock : executor.checkpointClock();
  const Bundle &bundle = executor.sourceBundle();
  const Settings &settings = executor.currentSettings();
  bool reference = executor.backendKind() == SIM_BACKEND_REFERENCE;

  ckpt::CheckpointT manifest;
  manifest.bundle_crc = bundle.checksum;
  manifest.scene = executor.scene().name;
  manifest.strategy = executor.strategy();
  manifest.executor =
      reference ? ckpt::Executor::Reference : ckpt::Executor::Plan;
  manifest.group_size = executor.groupSize();
  manifest.range = settings.range;
  manifest.dt = std::make_unique<schema::Value>(toSchema(settings.dt));
  for (size_t p = 0; p < executor.scene().params.size(); ++p) {
    auto setting = std::make_unique<ckpt::SettingT>();
    setting->name = executor.scene().params[p]->name;
    setting->value =
        std::make_unique<schema::Value>(toSchema(settings.params[p]));
    manifest.params.push_back(std::move(setting));
  }
  manifest.time = executor.time();
  manifest.clock = clock;
  uint64_t offset = 0;
  std::vector<std::string> names = executor.stateBuffers();
  for (const std::string &buffer : names) {
    auto state = std::make_unique<ckpt::StateT>();
    state->name = buffer;
    state->element = std::make_unique<schema::Element>(
        *sceneBuffer(executor, buffer).element);
    state->offset = offset;
    state->bytes = executor.hostBytes(buffer);
    offset += alignUp(state->bytes);
    manifest.buffers.push_back(std::move(state));
  }
  manifest.producer =
      std::string("sim runtime, ") +
      (reference ? "reference executor"
                 : std::string("plan executor on ") +
                       sim_backend_name(executor.backendKind()));

  flatbuffers::FlatBufferBuilder builder;
  ckpt::FinishSizePrefixedCheckpointBuffer(
      builder, ckpt::Checkpoint::Pack(builder, &manifest));

  // The header last, once the CRC is known: zeros in its place until then.
  std::vector<uint8_t> placeholder(schema::kHeaderSize, 0);
  writeAll(fd, placeholder.data(), placeholder.size(), name);
  uint32_t crc = uint32_t(crc32(0L, Z_NULL, 0));
  uint64_t size = schema::kHeaderSize;
  auto emit = [&](const uint8_t *data, size_t bytes) {
    writeAll(fd, data, bytes, name);
    crc = crcUpdate(crc, data, bytes);
    size += bytes;
  };
  std::vector<uint8_t> zeros(kCheckpointAlignment, 0);
  auto pad = [&] { emit(zeros.data(), size_t(alignUp(size) - size)); };
  emit(builder.GetBufferPointer(), builder.GetSize());
  pad();
  std::vector<uint8_t> data;
  for (size_t b = 0; b < names.size(); ++b) {
    if (gathered) {
      emit(gathered->buffers[b].data(), gathered->buffers[b].size());
    } else {
      data.resize(executor.hostBytes(names[b]));
      executor.getBuffer(names[b], data.data(), data.size());
      emit(data.data(), data.size());
    }
    pad();
  }

  schema::Header header;
  header.version = kCheckpointVersion;
  header.checksum = crc;
  header.size = size;
  std::string encoded = schema::encodeHeader(header);
  std::memcpy(encoded.data(), kCheckpointMagic, sizeof kCheckpointMagic);
  if (pwrite(fd, encoded.data(), encoded.size(), start) !=
      ssize_t(encoded.size()))
    fail(SIM_ERROR_IO,
         "cannot write checkpoint '" + name + "': " + std::strerror(errno));
}

const char *kindOf(mode_t mode) {
  if (S_ISDIR(mode))
    return "a folder";
  if (S_ISFIFO(mode))
    return "a FIFO";
  if (S_ISSOCK(mode))
    return "a socket";
  if (S_ISCHR(mode))
    return "a character device";
  if (S_ISBLK(mode))
    return "a block device";
  return "not a regular file";
}

/// Refuses a path whose file a checkpoint cannot replace. The checkpoint is
/// written beside its path and renamed over it: a folder there cannot be
/// replaced, and a device, a FIFO or a socket, or a symlink to one or into
/// /proc (/dev/stdout), would become a regular file, which as root breaks
/// /dev/null for the whole machine. sim-run refuses these before it runs;
/// this covers every other client of the C API.
void checkReplaceable(const std::string &path) {
  struct stat info;
  if (lstat(path.c_str(), &info) != 0)
    return;
  std::string refused = "checkpoint path '" + path + "' ";
  std::string fix = "; a checkpoint replaces its file whole, so name a "
                    "regular file";
  if (S_ISDIR(info.st_mode))
    fail(SIM_ERROR_INVALID_ARGUMENT, refused + "names a folder, not a file");
  if (!S_ISLNK(info.st_mode)) {
    if (!S_ISREG(info.st_mode))
      fail(SIM_ERROR_INVALID_ARGUMENT, refused + "is " + kindOf(info.st_mode) +
                                           ", not a regular file" + fix);
    return;
  }
  char target[4096];
  ssize_t length = readlink(path.c_str(), target, sizeof target - 1);
  if (length > 0 &&
      std::string(target, size_t(length)).compare(0, 6, "/proc/") == 0)
    fail(SIM_ERROR_INVALID_ARGUMENT, refused + "is a symlink to '" +
                                         std::string(target, size_t(length)) +
                                         "', a process's file" + fix);
  if (stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) &&
      !S_ISDIR(info.st_mode))
    fail(SIM_ERROR_INVALID_ARGUMENT, refused + "is a symlink to " +
                                         kindOf(info.st_mode) +
                                         ", not to a regular file" + fix);
}

void writeFile(Executor &executor, const std::string &path,
               const SessionState *gathered) {
  checkReplaceable(path);
  size_t slash = path.rfind('/');
  std::string dir = slash == std::string::npos ? "."
                    : slash == 0               ? "/"
                                               : path.substr(0, slash);
  std::string base = slash == std::string::npos ? path : path.substr(slash + 1);
  if (base.empty())
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "checkpoint path '" + path + "' names a folder, not a file");
  // A new file beside the destination (O_EXCL, so never through a symlink
  // or onto another file), with 0666 less the umask like any new file.
  std::random_device random;
  std::string temporary;
  int fd = -1;
  for (int attempt = 0; attempt < 100 && fd < 0; ++attempt) {
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "%08x", unsigned(random()));
    temporary = dir + "/." + base + "." + suffix + ".tmp";
    fd = open(temporary.c_str(),
              O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC | O_NOFOLLOW, 0666);
    if (fd < 0 && errno != EEXIST)
      break;
  }
  if (fd < 0)
    fail(SIM_ERROR_IO, "cannot create a temporary file in '" + dir +
                           "' for checkpoint '" + path +
                           "': " + std::strerror(errno));
  try {
    writeImage(executor, fd, path, gathered);
    if (fsync(fd) != 0)
      fail(SIM_ERROR_IO, "cannot write checkpoint '" + path +
                             "' (fsync): " + std::strerror(errno));
    if (close(fd) != 0) {
      fd = -1;
      fail(SIM_ERROR_IO, "cannot write checkpoint '" + path +
                             "' (close): " + std::strerror(errno));
    }
    fd = -1;
    if (rename(temporary.c_str(), path.c_str()) != 0)
      fail(SIM_ERROR_IO, "cannot rename '" + temporary + "' to '" + path +
                             "': " + std::strerror(errno));
  } catch (...) {
    if (fd >= 0)
      close(fd);
    unlink(temporary.c_str());
    throw;
  }
  // The rename itself, on disk.
  int dirFd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    fsync(dirFd);
    close(dirFd);
  }
}

} // namespace

//===----------------------------------------------------------------------===//
// Writing
//===----------------------------------------------------------------------===//

SessionState stateOf(Executor &executor) {
  SessionState state;
  state.clock = executor.checkpointClock();
  for (const std::string &buffer : executor.stateBuffers()) {
    state.buffers.emplace_back(executor.hostBytes(buffer));
    executor.getBuffer(buffer, state.buffers.back().data(),
                       state.buffers.back().size());
  }
  return state;
}

void writeCheckpoint(Executor &executor, int fd, const std::string &name) {
  Communicator *comm = ranksOf(executor);
  if (!comm) {
    writeImage(executor, fd, name, nullptr);
    return;
  }
  SessionState gathered = stateOf(executor);
  agreeOn(comm, "could not write checkpoint '" + name + "'", [&] {
    if (comm->rank() == 0)
      writeImage(executor, fd, name, &gathered);
  });
}

void writeCheckpointFile(Executor &executor, const std::string &path) {
  Communicator *comm = ranksOf(executor);
  if (!comm) {
    writeFile(executor, path, nullptr);
    return;
  }
  SessionState gathered = stateOf(executor);
  agreeOn(comm, "could not write checkpoint '" + path + "'", [&] {
    if (comm->rank() == 0)
      writeFile(executor, path, &gathered);
  });
}

//===----------------------------------------------------------------------===//
// Reading
//===----------------------------------------------------------------------===//

CheckpointFile parseCheckpoint(std::vector<uint8_t> bytes,
                               const std::string &name) {
  const std::string where = "checkpoint '" + name + "': ";
  auto error = [&](const std::string &message) {
    fail(SIM_ERROR_CHECKPOINT, where + message);
  };
  size_t size = bytes.size();
  const uint8_t *file = bytes.data();
  if (size < sizeof kCheckpointMagic)
    error("the file has " + std::to_string(size) +
          " bytes, too few for a checkpoint (truncated?)");
  if (std::memcmp(file, kCheckpointMagic, sizeof kCheckpointMagic) != 0)
    error(schema::hasMagic(file, size)
              ? "it is a bundle, not a checkpoint"
              : "not a sim checkpoint (wrong magic; expected "
                "\"SIMCKPT\\0\")");
  if (size < schema::kHeaderSize)
    error("the file has " + std::to_string(size) + " bytes, fewer than the " +
          std::to_string(schema::kHeaderSize) + "-byte header (truncated?)");
  schema::Header header = schema::decodeHeader(file);
  if (header.version != kCheckpointVersion)
    error("format version " + std::to_string(header.version) +
          " is not supported (this runtime reads version " +
          std::to_string(kCheckpointVersion) + ")");
  if (header.size != size)
    error("the header gives a file size of " + std::to_string(header.size) +
          " bytes but the file has " + std::to_string(size) +
          (header.size > size ? " (truncated?)" : ""));
  if (header.reserved != 0)
    error("the reserved header field is not zero (damaged?)");
  uint32_t crc =
      crcUpdate(uint32_t(crc32(0L, Z_NULL, 0)), file + schema::kHeaderSize,
                size - schema::kHeaderSize);
  if (crc != header.checksum)
    error("the checksum does not match its contents (CRC-32 " + crcText(crc) +
          ", the header says " + crcText(header.checksum) +
          "): the file is damaged");

  // The manifest: a 4-byte size, then the FlatBuffer.
  uint64_t left = size - schema::kHeaderSize;
  if (left < 4)
    error("the file ends before its manifest");
  uint64_t manifestBytes = 4 + uint64_t(file[32]) + (uint64_t(file[33]) << 8) +
                           (uint64_t(file[34]) << 16) +
                           (uint64_t(file[35]) << 24);
  if (manifestBytes > left)
    error("the manifest's size (" + std::to_string(manifestBytes) +
          " bytes) runs past the end of the file");
  // A root offset and the file identifier, at least, before the identifier
  // is looked at (the check reads them without a bound).
  if (manifestBytes <
      4 + sizeof(flatbuffers::uoffset_t) + flatbuffers::kFileIdentifierLength)
    error("the manifest has " + std::to_string(manifestBytes - 4) +
          " bytes, too few for a checkpoint FlatBuffer (damaged?)");
  // FlatBuffers reads scalars in place: an aligned copy.
  std::vector<uint8_t> aligned(file + schema::kHeaderSize,
                               file + schema::kHeaderSize + manifestBytes);
  flatbuffers::Verifier::Options options;
  options.max_depth = 16;
  options.max_tables = 1000000;
  flatbuffers::Verifier verifier(aligned.data(), aligned.size(), options);
  if (!ckpt::SizePrefixedCheckpointBufferHasIdentifier(aligned.data()))
    error("the manifest is not a checkpoint FlatBuffer (wrong identifier)");
  if (!ckpt::VerifySizePrefixedCheckpointBuffer(verifier))
    error("the manifest does not verify as a checkpoint FlatBuffer (an "
          "offset, length or nesting outside it)");
  const ckpt::Checkpoint *manifest =
      ckpt::GetSizePrefixedCheckpoint(aligned.data());
  if (!elementsAligned(manifest->clock()))
    error("the manifest does not verify as a checkpoint FlatBuffer: its "
          "int64 vector clock is not aligned to 8 bytes (damaged?)");
  // The verifier checks no enum's range: a value past the last would pass
  // every check below that compares with a known one (an executor that is
  // neither skips the clock's checks).
  if (manifest->executor() > ckpt::Executor::MAX)
    error("the manifest names executor " +
          std::to_string(int(manifest->executor())) +
          ", which this runtime does not know (damaged?)");
  if (manifest->strategy() > schema::Strategy::MAX)
    error("the manifest names strategy " +
          std::to_string(int(manifest->strategy())) +
          ", which this runtime does not know (damaged?)");
  CheckpointFile result;
  result.checksum = header.checksum;
  result.name = name;
  manifest->UnPackTo(&result.manifest);
  result.dataStart = alignUp(schema::kHeaderSize + manifestBytes);
  if (result.dataStart > size)
    error("the file ends before its data");
  uint64_t dataBytes = size - result.dataStart;
  for (const auto &state : result.manifest.buffers)
    if (state->offset > dataBytes || state->bytes > dataBytes - state->offset)
      error("the state of buffer '" + state->name + "' (" +
            std::to_string(state->bytes) + " bytes at " +
            std::to_string(state->offset) + ") runs past the end of the file");
  result.bytes = std::move(bytes);
  return result;
}

CheckpointFile readCheckpoint(const std::string &path) {
  int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0)
    fail(SIM_ERROR_IO,
         "cannot open checkpoint '" + path + "': " + std::strerror(errno));
  struct stat info;
  if (fstat(fd, &info) != 0 || !S_ISREG(info.st_mode)) {
    close(fd);
    fail(SIM_ERROR_IO,
         "cannot read checkpoint '" + path + "': it is not a regular file");
  }
  std::vector<uint8_t> bytes(size_t(info.st_size));
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0) {
      int error = errno;
      close(fd);
      fail(SIM_ERROR_IO,
           "cannot read checkpoint '" + path + "': " + std::strerror(error));
    }
    if (n == 0)
      break; // Shrunk while reading: the header check reports it.
    done += size_t(n);
  }
  close(fd);
  bytes.resize(done);
  return parseCheckpoint(std::move(bytes), path);
}

//===----------------------------------------------------------------------===//
// Restarting
//===----------------------------------------------------------------------===//

namespace {

/// What a verified checkpoint restores.
struct Restart {
  std::vector<int64_t> clock;
  std::vector<std::string> names;
  std::vector<const ckpt::StateT *> states;
};

/// Checks that `file` belongs to the session; changes nothing.
Restart checkRestart(Executor &executor, const CheckpointFile &file) {
  const ckpt::CheckpointT &m = file.manifest;
  const Bundle &bundle = executor.sourceBundle();
  const schema::SceneT &scene = executor.scene();
  const Settings &settings = executor.currentSettings();
  bool planSession = executor.backendKind() != SIM_BACKEND_REFERENCE;
  const std::string where = "checkpoint '" + file.name + "' ";
  auto refuse = [&](const std::string &message) {
    fail(SIM_ERROR_CHECKPOINT, where + message);
  };
  auto here = [&](const std::string &what) { return ", this session " + what; };

  // What the run belongs to.
  if (m.scene != scene.name)
    refuse("is of scene '" + m.scene + "'" + here("runs scene '") + scene.name +
           "'");
  if (m.bundle_crc != bundle.checksum)
    refuse("belongs to another bundle of scene '" + scene.name +
           "' (its bundle's CRC-32 is " + crcText(m.bundle_crc) +
           ", that of '" + bundle.name + "' is " + crcText(bundle.checksum) +
           "): the scene was compiled again or differently");
  if (planSession && m.executor == ckpt::Executor::Reference)
    refuse("was written by the reference executor, which keeps no device "
           "clock; restart it on the reference executor");
  if (m.strategy != executor.strategy())
    refuse(std::string("was written under strategy '") +
           strategyName(m.strategy) + "'" + here("runs '") +
           strategyName(executor.strategy()) + "'");
  if (m.group_size != executor.groupSize())
    refuse("was written with group size " + std::to_string(m.group_size) +
           here("has ") + std::to_string(executor.groupSize()) +
           " (the group size decides the sub-steps)");
  if (m.range != settings.range)
    refuse("was written at range " + std::to_string(m.range) +
           here("has range ") + std::to_string(settings.range));
  Value dt = Value::of(*m.dt);
  if (!sameValue(dt, settings.dt))
    refuse("was written with dt " + dt.text() + here("has dt ") +
           settings.dt.text());
  for (const auto &setting : m.params)
    if (bundle.findParam(setting->name) < 0)
      refuse("sets parameter '" + setting->name + "', which scene '" +
             scene.name + "' does not declare");
  for (size_t p = 0; p < scene.params.size(); ++p) {
    const std::string &param = scene.params[p]->name;
    auto it = std::find_if(m.params.begin(), m.params.end(),
                           [&](const auto &s) { return s->name == param; });
    if (it == m.params.end())
      refuse("has no value of parameter '" + param + "'");
    Value value = Value::of(*(*it)->value);
    if (!sameValue(value, settings.params[p]))
      refuse("was written with " + param + " = " + value.text() +
             here("has " + param + " = ") + settings.params[p].text());
  }

  // The clock: on a big-step boundary, and the plan's.
  if (m.time < 0)
    refuse("is at base step " + std::to_string(m.time) + " (damaged?)");
  std::vector<int64_t> clock = m.clock;
  if (m.executor == ckpt::Executor::Plan) {
    if (clock.size() <= size_t(kSlotParity) || clock[kSlotBegin] != m.time)
      refuse("has a clock that does not hold its time (damaged?)");
    if (clock[kSlotSize] != 0 || (clock[kSlotParity] & ~int64_t(1)) != 0)
      refuse("is not on a big-step boundary (m = " +
             std::to_string(clock[kSlotSize]) +
             ", parity = " + std::to_string(clock[kSlotParity]) + ")");
  }
  size_t slots = executor.clockSlots();
  if (planSession && clock.size() != slots)
    refuse("has a clock of " + std::to_string(clock.size()) +
           " slots, the plan's has " + std::to_string(slots));
  if (!planSession)
    clock.clear();
  // The slots the next run reads before it decides anything (docs/Plan.md,
  // "The clock"): on a big-step boundary the end is where the last run
  // stopped, no estimate is pending, and the estimate hint is an item of
  // the range. A crafted value would change the run silently (an estimate
  // of 1 makes the first big step 1 base step; a negative one moves T
  // backwards) or name a group outside the range. The counters (big steps,
  // cuts, evaluations, histogram) count modulo 2^64, and the sub-step clocks
  // are set by advance before any kernel reads them: any value will do.
  if (!clock.empty()) {
    auto slotText = [&](int64_t slot, const char *name) {
      return "has clock slot " + std::to_string(slot) + " (" + name +
             ") = " + std::to_string(clock[size_t(slot)]);
    };
    if (clock[kSlotEnd] < m.time)
      refuse(slotText(kSlotEnd, "the end of the run") +
             ", before its base step " + std::to_string(m.time) +
             " (damaged?)");
    if (clock[kSlotEstimate] != std::numeric_limits<int64_t>::max())
      refuse(slotText(kSlotEstimate, "the pending estimate") +
             ", but on a big-step boundary no estimate is pending (" +
             std::to_string(std::numeric_limits<int64_t>::max()) +
             ") (damaged?)");
    if (clock[kSlotEstimateHint] < 0 ||
        clock[kSlotEstimateHint] >= settings.range)
      refuse(slotText(kSlotEstimateHint, "the estimate hint") +
             ", not an item of the range of " + std::to_string(settings.range) +
             " (damaged?)");
  }

  // Every buffer of the state once (a second copy would be ignored), and
  // nothing else when the executor is the same kind.
  std::set<std::string> held;
  for (const auto &state : m.buffers)
    if (!held.insert(state->name).second)
      refuse("holds buffer '" + state->name + "' twice (damaged?)");
  std::vector<std::string> names = executor.stateBuffers();
  std::vector<const ckpt::StateT *> states;
  for (const std::string &name : names) {
    auto it = std::find_if(m.buffers.begin(), m.buffers.end(),
                           [&](const auto &s) { return s->name == name; });
    if (it == m.buffers.end())
      refuse("has no state of buffer '" + name + "'");
    const ckpt::StateT &state = **it;
    const schema::Element &element = *sceneBuffer(executor, name).element;
    if (*state.element != element)
      refuse("holds buffer '" + name + "' as " + elementText(*state.element) +
             ", the scene declares " + elementText(element));
    if (state.bytes != executor.hostBytes(name))
      refuse("holds " + std::to_string(state.bytes) + " bytes of buffer '" +
             name + "', a state of range " + std::to_string(settings.range) +
             " takes " + std::to_string(executor.hostBytes(name)));
    states.push_back(&state);
  }
  bool sameKind = planSession == (m.executor == ckpt::Executor::Plan);
  if (sameKind)
    for (const auto &state : m.buffers)
      if (std::find(names.begin(), names.end(), state->name) == names.end())
        refuse("holds buffer '" + state->name + "', which this session's " +
               (planSession ? "plan" : "reference model") + " does not have");

  return {clock, names, states};
}

void applyRestart(Executor &executor, const CheckpointFile &file,
                  const Restart &restart) {
  executor.restoreClock(file.manifest.time, restart.clock);
  for (size_t b = 0; b < restart.names.size(); ++b)
    executor.setBuffer(restart.names[b], file.data(*restart.states[b]),
                       size_t(restart.states[b]->bytes));
}

} // namespace

void restartFromCheckpoint(Executor &executor, const CheckpointFile &file) {
  Restart restart;
  agreeOn(ranksOf(executor), "refused checkpoint '" + file.name + "'",
          [&] { restart = checkRestart(executor, file); });
  // Only now: the state.
  applyRestart(executor, file, restart);
}

void restartFromCheckpointFile(Executor &executor, const std::string &path) {
  std::optional<CheckpointFile> file;
  Restart restart;
  // Each rank names its own file, which need not be this one's.
  agreeOn(ranksOf(executor),
          "could not read or use the checkpoint it was given", [&] {
            file = readCheckpoint(path);
            restart = checkRestart(executor, *file);
          });
  // Each rank restores its own items from its own file: files of one
  // base step of different runs (a stale copy on one node's disk) would
  // pass every check above and mix two states silently.
  if (Communicator *comm = ranksOf(executor)) {
    int64_t both[2] = {int64_t(file->checksum), -int64_t(file->checksum)};
    comm->minimum(both, 2);
    if (both[0] != -both[1])
      fail(SIM_ERROR_CHECKPOINT,
           "the ranks restart from different checkpoints (CRC-32 from " +
               crcText(uint32_t(both[0])) + " to " +
               crcText(uint32_t(-both[1])) + " over the " +
               std::to_string(comm->size()) + " ranks; this rank's is '" +
               path + "'): give every rank a copy of the same checkpoint");
  }
  applyRestart(executor, *file, restart);
}

} // namespace sim::rt
