//===- Checkpoint.h - a session's state in a file ---------------*- C++ -*-===//
//
// A checkpoint holds what a session needs to continue a run exactly where
// it stands, on a big-step boundary: the clock (every slot of the plan
// executor's device clock; T for the reference executor), the state of
// every buffer, and what identifies the run it belongs to (the bundle's
// CRC-32, scene, strategy, group size, range, dt, every parameter). The
// manifest is a FlatBuffer of runtime/schema/checkpoint.fbs; the file
// layout and the refusals are in docs/Runtime.md, "Checkpoints".
//
// Both executors share this code through the Executor interface: the
// clock and the list of state buffers are theirs, the format, the checks
// and the buffers' bytes (sim_session_get_buffer's host arrays) are here.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_CHECKPOINT_H
#define SIM_RUNTIME_CHECKPOINT_H

#include "sim/Runtime/BundleFormat.h"
#include "sim/Runtime/checkpoint_generated.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sim::rt {

class Executor;

namespace ckpt = ::sim::checkpoint;

/// The file header: a bundle's header (BundleFormat.h) with this magic.
constexpr char kCheckpointMagic[8] = {'S', 'I', 'M', 'C', 'K', 'P', 'T', '\0'};
constexpr uint32_t kCheckpointVersion = 1;
/// The data area and every buffer in it start on a multiple of this.
constexpr uint64_t kCheckpointAlignment = 64;

/// What a checkpoint holds of a session: its clock (checkpointClock) and
/// the bytes of every state buffer, in stateBuffers' order. In a
/// distributed session every rank calls it and gets the whole state.
struct SessionState {
  std::vector<int64_t> clock;
  std::vector<std::vector<uint8_t>> buffers;

  bool operator==(const SessionState &other) const {
    return clock == other.clock && buffers == other.buffers;
  }
};
SessionState stateOf(Executor &executor);

/// Writes a checkpoint of `executor` to `fd`, from its current offset
/// (which must be seekable: the header is written last); `name` names the
/// file in messages. Initialises the session first if it has no state.
/// A distributed session's ranks all call it; only rank 0 writes (the
/// other ranks' `fd` and `path` are not touched).
void writeCheckpoint(Executor &executor, int fd, const std::string &name);

/// Writes a checkpoint to `path` atomically: a new file in the same
/// folder, fsync'ed and renamed over `path`, then the folder fsync'ed.
void writeCheckpointFile(Executor &executor, const std::string &path);

/// A checkpoint file read and verified: header, CRC-32, the manifest's
/// FlatBuffer and the extents of the buffers' bytes.
struct CheckpointFile {
  std::string name;
  ckpt::CheckpointT manifest;
  std::vector<uint8_t> bytes;
  uint64_t dataStart = 0;
  /// The CRC-32 of everything after the header, as the header gives it.
  uint32_t checksum = 0;

  const uint8_t *data(const ckpt::StateT &state) const {
    return bytes.data() + dataStart + state.offset;
  }
};

/// Reads and verifies `size` bytes; throws SIM_ERROR_CHECKPOINT naming the
/// first problem.
CheckpointFile parseCheckpoint(std::vector<uint8_t> bytes,
                               const std::string &name);
/// Reads a file and parses it; SIM_ERROR_IO when it cannot be read.
CheckpointFile readCheckpoint(const std::string &path);

/// Checks that `file` belongs to `executor`'s bundle, strategy and
/// settings and fits its state, then makes it the session's state (T, the
/// clock, every buffer). Nothing changes when a check fails
/// (SIM_ERROR_CHECKPOINT).
void restartFromCheckpoint(Executor &executor, const CheckpointFile &file);

/// readCheckpoint and restartFromCheckpoint. A distributed session's ranks
/// each read the file, and all fail when one cannot read or use it.
void restartFromCheckpointFile(Executor &executor, const std::string &path);

} // namespace sim::rt

#endif // SIM_RUNTIME_CHECKPOINT_H
