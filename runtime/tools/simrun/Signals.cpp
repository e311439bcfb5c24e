//===- Signals.cpp - SIGINT and SIGTERM in sim-run ------------------------===//
//
// Everything the handler touches is a lock-free atomic or a buffer that an
// atomic flag publishes, and it calls only async-signal-safe functions:
// sim_session_interrupt (an atomic store), clock_gettime, kill, unlink,
// sigaction and raise.
//
//===----------------------------------------------------------------------===//

#include "Signals.h"

#include "Options.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

namespace simrun {

namespace {

constexpr int kSlots = 8;

std::atomic<int> firstSignal{0};
/// When the first signal came: CLOCK_MONOTONIC in nanoseconds, 0 until the
/// first handler has read the clock, -1 where the clock could not be read.
std::atomic<int64_t> firstSignalAt{0};
/// Handlers running now; an unregistering thread waits for 0.
std::atomic<int> handlersRunning{0};
std::atomic<sim_session *> sessions[kSlots];
std::atomic<pid_t> child{0};

struct TemporarySlot {
  std::atomic<bool> used{false};
  char path[PATH_MAX];
};
TemporarySlot temporaries[kSlots];

static_assert(std::atomic<int>::is_always_lock_free &&
                  std::atomic<bool>::is_always_lock_free &&
                  std::atomic<sim_session *>::is_always_lock_free &&
                  std::atomic<pid_t>::is_always_lock_free &&
                  std::atomic<int64_t>::is_always_lock_free,
              "the signal handler needs lock-free atomics");

void waitForHandlers() {
  while (handlersRunning.load() != 0)
    sched_yield();
}

/// CLOCK_MONOTONIC in nanoseconds (at least 1), or -1 where it cannot be
/// read. clock_gettime is async-signal-safe.
int64_t monotonicNow() {
  timespec now;
  if (clock_gettime(CLOCK_MONOTONIC, &now) != 0)
    return -1;
  return std::max<int64_t>(1, int64_t(now.tv_sec) * 1000000000 + now.tv_nsec);
}

/// Whether a signal after the first is part of the same request: GNU
/// timeout sends SIGTERM to sim-run and then to its process group, and a
/// shell or a job runner may pass one Ctrl-C on twice. Those come within
/// kSignalGraceNanoseconds of the first; killing sim-run for them would
/// lose the checkpoint, JSON and outputs the first one asked it to write.
bool sameRequest(int64_t now) {
  int64_t first = firstSignalAt.load();
  // 0: the first handler has not stored its time yet, so it runs right
  // now. An unknown time (-1) keeps the second signal's documented effect.
  if (first == 0)
    return true;
  return first > 0 && now > 0 && now - first < kSignalGraceNanoseconds;
}

void handle(int signal) {
  int savedErrno = errno;
  handlersRunning.fetch_add(1);
  // Read before the first signal is claimed, so that a second one that
  // interrupts this handler finds either no time yet or this one.
  int64_t now = monotonicNow();
  int none = 0;
  if (firstSignal.compare_exchange_strong(none, signal)) {
    firstSignalAt.store(now);
    for (std::atomic<sim_session *> &slot : sessions)
      if (sim_session *session = slot.load())
        sim_session_interrupt(session);
    if (pid_t pid = child.load())
      kill(pid, signal);
    handlersRunning.fetch_sub(1);
    errno = savedErrno;
    return;
  }
  if (sameRequest(now)) {
    handlersRunning.fetch_sub(1);
    errno = savedErrno;
    return;
  }
  // A second request: clean up and die of it.
  for (TemporarySlot &slot : temporaries)
    if (slot.used.load())
      unlink(slot.path);
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = SIG_DFL;
  sigemptyset(&action.sa_mask);
  sigaction(signal, &action, nullptr);
  // SA_NODEFER: the signal is not blocked in its handler, so this ends
  // the process here.
  raise(signal);
  _exit(kExitSignalBase + signal);
}

} // namespace

void installSignalHandlers() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = handle;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART | SA_NODEFER;
  for (int signal : {SIGINT, SIGTERM}) {
    // A signal the parent ignores (a background job's SIGINT) stays
    // ignored.
    struct sigaction previous;
    if (sigaction(signal, nullptr, &previous) == 0 &&
        previous.sa_handler == SIG_IGN)
      continue;
    sigaction(signal, &action, nullptr);
  }
}

int receivedSignal() { return firstSignal.load(); }

const char *signalName(int signal) {
  switch (signal) {
  case SIGINT:
    return "SIGINT";
  case SIGTERM:
    return "SIGTERM";
  }
  return "a signal";
}

void registerSession(sim_session *session) {
  for (std::atomic<sim_session *> &slot : sessions) {
    sim_session *empty = nullptr;
    if (slot.compare_exchange_strong(empty, session)) {
      // A signal that came before the slot was filled found nothing here.
      if (interrupted())
        sim_session_interrupt(session);
      return;
    }
  }
  runError("more than " + std::to_string(kSlots) + " sessions at a time");
}

void unregisterSession(sim_session *session) {
  for (std::atomic<sim_session *> &slot : sessions) {
    sim_session *expected = session;
    if (slot.compare_exchange_strong(expected, nullptr))
      break;
  }
  waitForHandlers();
}

int registerTemporary(const char *path) {
  if (std::strlen(path) >= PATH_MAX)
    return -1;
  for (int i = 0; i < kSlots; ++i) {
    TemporarySlot &slot = temporaries[i];
    if (slot.used.load())
      continue;
    // Only the main thread registers, so a free slot stays free here; the
    // handler reads the path only once `used` says it is complete.
    std::strcpy(slot.path, path);
    slot.used.store(true);
    return i;
  }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot < 0 || slot >= kSlots)
    return;
  temporaries[slot].used.store(false);
  waitForHandlers();
}

BlockSignals::BlockSignals() {
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, &previous);
}

BlockSignals::~BlockSignals() {
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

void setChild(pid_t pid) {
  child.store(pid);
  waitForHandlers();
}

} // namespace simrun
