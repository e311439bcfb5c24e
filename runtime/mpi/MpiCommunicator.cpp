//===- MpiCommunicator.cpp - a sim_communicator over MPI ------------------===//
//
// Each function is one MPI call (or a few non-blocking ones and a
// Waitall); MPI's errors return (MPI_ERRORS_RETURN) so that the session
// fails with SIM_ERROR_DISTRIBUTED and sim-run aborts every rank with a
// message, instead of MPI's default handler killing the job without one.
//
//===----------------------------------------------------------------------===//

#include "MpiCommunicator.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <mpi.h>
#include <vector>

namespace sim::mpi {

namespace {

/// SIM_MPI_MAX_MESSAGE on this rank: its byte count, the default
/// (INT_MAX) when unset, or 0 when it is not a number from 1 to INT_MAX.
size_t parseMaxMessage(const char *text) {
  if (!text || !*text)
    return size_t(INT_MAX);
  char *end = nullptr;
  errno = 0;
  unsigned long long value = std::strtoull(text, &end, 10);
  if (*end != '\0' || errno == ERANGE || value == 0 ||
      value > (unsigned long long)INT_MAX || *text == '-' || *text == '+' ||
      std::isspace((unsigned char)*text))
    return 0;
  return size_t(value);
}

/// The most bytes one MPI message carries: MPI counts are ints, so a
/// longer transfer goes as several messages of at most this many bytes.
/// SIM_MPI_MAX_MESSAGE lowers it (tests split small transfers with it).
/// Set by agreeOnMaxMessage before the first transfer.
size_t messageLimit = size_t(INT_MAX);
size_t maxMessage() { return messageLimit; }

/// Reads SIM_MPI_MAX_MESSAGE on every rank and agrees on it: a rank that
/// splits a transfer into pieces makes other collective calls than one
/// that does not, so ranks with different limits (mpirun passes a
/// variable to other machines only with -x) would wait for each other
/// forever. A value that is not a byte count, or that differs between the
/// ranks, stops them all with a message (status 2, a usage error).
void agreeOnMaxMessage(int rank) {
  const char *text = std::getenv("SIM_MPI_MAX_MESSAGE");
  size_t limit = parseMaxMessage(text);
  long long mine[2] = {(long long)limit, -(long long)limit}, all[2] = {0, 0};
  MPI_Allreduce(mine, all, 2, MPI_LONG_LONG, MPI_MIN, MPI_COMM_WORLD);
  long long lowest = all[0], highest = -all[1];
  if (lowest > 0 && lowest == highest) {
    messageLimit = limit;
    return;
  }
  if (limit == 0)
    std::fprintf(stderr,
                 "sim-run: error: SIM_MPI_MAX_MESSAGE='%s' (rank %d) is not "
                 "a number of bytes from 1 to %d\n",
                 text, rank, INT_MAX);
  else if (lowest > 0 && rank == 0)
    std::fprintf(stderr,
                 "sim-run: error: the ranks disagree on SIM_MPI_MAX_MESSAGE "
                 "(from %lld to %lld bytes; unset is %d): set it alike on "
                 "every rank (mpirun -x SIM_MPI_MAX_MESSAGE passes it to "
                 "other machines)\n",
                 lowest, highest, INT_MAX);
  std::fflush(stderr);
  MPI_Barrier(MPI_COMM_WORLD);
  MPI_Abort(MPI_COMM_WORLD, 2);
  std::exit(2);
}

int allreduce(int64_t *values, int32_t count, MPI_Op op) {
  return MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_INT64_T, op,
                       MPI_COMM_WORLD) == MPI_SUCCESS
             ? 0
             : 1;
}

int allreduceMin(void *, int64_t *values, int32_t count) {
  return allreduce(values, count, MPI_MIN);
}

int allreduceSum(void *, int64_t *values, int32_t count) {
  return allreduce(values, count, MPI_SUM);
}

/// The requests of the exchange under way (exchangeBegin to exchangeEnd).
std::vector<MPI_Request> pending;

/// Calls `send(offset, bytes)` for each piece of at most maxMessage()
/// bytes of a transfer of `total` bytes, in order; stops at the first
/// MPI error. Both sides of a transfer split the same byte count alike, and
/// MPI matches the messages of two ranks on one tag (and the broadcasts of
/// one root) in the order they were posted, so the i-th piece sent is the
/// i-th piece received.
template <typename Send> int inPieces(size_t total, Send send) {
  const size_t limit = maxMessage();
  for (size_t done = 0; done < total; done += limit)
    if (send(done, int(std::min(limit, total - done))) != MPI_SUCCESS)
      return 1;
  return 0;
}

/// Posts the receives, then the sends, of one exchange into `requests`.
int post(const void *const *send, const size_t *sendBytes, void *const *recv,
         const size_t *recvBytes, std::vector<MPI_Request> &requests) {
  int size = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  requests.clear();
  requests.reserve(2 * size_t(size));
  // Receives first, so that every send finds its receive posted.
  for (int r = 0; r < size; ++r)
    if (inPieces(recvBytes[r], [&](size_t at, int bytes) {
          requests.emplace_back();
          return MPI_Irecv(static_cast<char *>(recv[r]) + at, bytes, MPI_BYTE,
                           r, 0, MPI_COMM_WORLD, &requests.back());
        }) != 0)
      return 1;
  for (int r = 0; r < size; ++r)
    if (inPieces(sendBytes[r], [&](size_t at, int bytes) {
          requests.emplace_back();
          return MPI_Isend(static_cast<const char *>(send[r]) + at, bytes,
                           MPI_BYTE, r, 0, MPI_COMM_WORLD, &requests.back());
        }) != 0)
      return 1;
  return 0;
}

int wait(std::vector<MPI_Request> &requests) {
  int status = MPI_Waitall(int(requests.size()), requests.data(),
                           MPI_STATUSES_IGNORE) == MPI_SUCCESS
                   ? 0
                   : 1;
  requests.clear();
  return status;
}

int exchange(void *, const void *const *send, const size_t *sendBytes,
             void *const *recv, const size_t *recvBytes) {
  std::vector<MPI_Request> requests;
  if (post(send, sendBytes, recv, recvBytes, requests) != 0)
    return 1;
  return wait(requests);
}

int exchangeBegin(void *, const void *const *send, const size_t *sendBytes,
                  void *const *recv, const size_t *recvBytes) {
  if (!pending.empty())
    return 1; // One exchange under way at a time.
  return post(send, sendBytes, recv, recvBytes, pending);
}

int exchangeEnd(void *) { return wait(pending); }

int allgather(void *, const void *data, const size_t *bytes, void *out) {
  int size = 0, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  std::vector<int> counts(static_cast<size_t>(size)),
      displacements(static_cast<size_t>(size));
  size_t offset = 0;
  for (int r = 0; r < size; ++r) {
    // MPI_Allgatherv takes int counts and displacements: a gathered array
    // longer than maxMessage() goes as MPI_Bcasts of each rank's share,
    // in pieces of at most maxMessage() bytes, instead.
    if (offset + bytes[r] > maxMessage()) {
      size_t at = 0;
      for (int from = 0; from < size; ++from) {
        char *target = static_cast<char *>(out) + at;
        if (from == rank && bytes[from])
          std::copy(static_cast<const char *>(data),
                    static_cast<const char *>(data) + bytes[from], target);
        if (inPieces(bytes[from], [&](size_t done, int piece) {
              return MPI_Bcast(target + done, piece, MPI_BYTE, from,
                               MPI_COMM_WORLD);
            }) != 0)
          return 1;
        at += bytes[from];
      }
      return 0;
    }
    counts[size_t(r)] = int(bytes[r]);
    displacements[size_t(r)] = int(offset);
    offset += bytes[r];
  }
  return MPI_Allgatherv(data, counts[size_t(rank)], MPI_BYTE, out,
                        counts.data(), displacements.data(), MPI_BYTE,
                        MPI_COMM_WORLD) == MPI_SUCCESS
             ? 0
             : 1;
}

} // namespace

World::World(int *argc, char ***argv) {
  int initialized = 0;
  MPI_Initialized(&initialized);
  if (!initialized) {
    int provided = 0;
    MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    owns = true;
  }
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  // The ranks that share this machine (and its GPUs), in rank order.
  MPI_Comm local;
  if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank_,
                          MPI_INFO_NULL, &local) == MPI_SUCCESS) {
    MPI_Comm_rank(local, &localRank_);
    MPI_Comm_free(&local);
  }
  comm.user = nullptr;
  comm.rank = rank_;
  comm.size = size_;
  comm.allreduce_min_i64 = allreduceMin;
  comm.allreduce_sum_i64 = allreduceSum;
  comm.exchange = exchange;
  comm.allgather = allgather;
  comm.exchange_begin = exchangeBegin;
  comm.exchange_end = exchangeEnd;
}

World::~World() {
  if (owns)
    MPI_Finalize();
}

void World::abort(int status) {
  MPI_Abort(MPI_COMM_WORLD, status ? status : 1);
  std::exit(status ? status : 1);
}

} // namespace sim::mpi

extern "C" {

__attribute__((visibility("default"))) void *
sim_mpi_open(int *argc, char ***argv, sim_mpi_world_info *info) {
  auto *world = new sim::mpi::World(argc, argv);
  // Read, checked and agreed on now, not at the first exchange.
  sim::mpi::agreeOnMaxMessage(world->rank());
  info->communicator = world->communicator();
  info->rank = world->rank();
  info->size = world->size();
  info->local_rank = world->localRank();
  return world;
}

__attribute__((visibility("default"))) void sim_mpi_close(void *world) {
  delete static_cast<sim::mpi::World *>(world);
}

__attribute__((visibility("default"))) void sim_mpi_abort(int status) {
  sim::mpi::World::abort(status);
}

} // extern "C"
