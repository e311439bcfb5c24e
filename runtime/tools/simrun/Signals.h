//===- Signals.h - SIGINT and SIGTERM in sim-run ----------------*- C++ -*-===//
//
// The first SIGINT or SIGTERM asks every live session to stop at its next
// host synchronisation (sim_session_interrupt, which is async-signal-safe)
// and forwards the signal to a running sim-translate; sim-run then writes
// what is complete, skips what has not started and exits with 128 + the
// signal. A second signal removes the temporary files registered here and
// kills the process the default way, unless it comes within
// kSignalGraceNanoseconds of the first: then it is the same request
// delivered twice (GNU timeout signals the process and then its group) and
// is ignored.
//
// The registries are small arrays of atomics, read by the handler on
// whichever thread the signal lands; removing an entry waits until no
// handler is reading it, so a session is never interrupted after it is
// destroyed.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUN_SIGNALS_H
#define SIM_RUN_SIGNALS_H

#include "sim/Runtime/sim_runtime.h"

#include <csignal>
#include <cstdint>
#include <sys/types.h>

namespace simrun {

/// How long after the first SIGINT or SIGTERM another one counts as the
/// same request (ignored) rather than a second one (kills): 1 second.
constexpr int64_t kSignalGraceNanoseconds = 1000000000;

/// Installs the handler for SIGINT and SIGTERM, unless the process started
/// with the signal ignored.
void installSignalHandlers();

/// The first signal received (SIGINT or SIGTERM), or 0.
int receivedSignal();
inline bool interrupted() { return receivedSignal() != 0; }
/// "SIGINT" or "SIGTERM".
const char *signalName(int signal);

/// A session the handler interrupts; one that registers after the first
/// signal is interrupted at once. At most 8 at a time.
void registerSession(sim_session *session);
void unregisterSession(sim_session *session);

/// A file the handler removes before the process dies of a second signal
/// (the temporary bundle, an output's temporary file). Returns the slot for
/// unregisterTemporary; -1 when all 8 slots are taken (sim-run never has
/// more than two) or the path is too long.
int registerTemporary(const char *path);
void unregisterTemporary(int slot);

/// Holds SIGINT and SIGTERM back on this thread while it lives (a signal
/// meanwhile waits, and is handled when it ends). Around creating a
/// temporary file and registering it, so that a second signal cannot leave
/// it behind unregistered; and around creating a session, so that the
/// threads the runtime starts (CPU workers, the CUDA driver's) inherit the
/// block and every signal is handled on the main thread.
class BlockSignals {
public:
  BlockSignals();
  ~BlockSignals();
  BlockSignals(const BlockSignals &) = delete;
  BlockSignals &operator=(const BlockSignals &) = delete;

private:
  sigset_t previous;
};

/// The child process (sim-translate) the first signal is forwarded to; 0:
/// none.
void setChild(pid_t pid);

} // namespace simrun

#endif // SIM_RUN_SIGNALS_H
