//===- Distribution.h - a range split over ranks, and its ghosts --*- C++
//-*-===//
//
// A distributed plan (plan.distributed, docs/Distributed.md) runs on P
// ranks, each holding a contiguous block of whole groups of the global
// range plus `halo` ghost items on each side. This file holds what does not
// depend on a device: the decomposition, the ghost lists of a buffer (which
// elements go to which rank, which come from which, which are copied
// locally), and the Communicator, which wraps a sim_communicator (or the
// one-rank communicator of a session without one) and turns its failures
// into SIM_ERROR_DISTRIBUTED.
//
// Elements are counted within one half of a buffer: global item i lives at
// element i - first + halo of the rank that owns it.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_DISTRIBUTION_H
#define SIM_RUNTIME_DISTRIBUTION_H

#include "Bundle.h"
#include "sim/Runtime/sim_runtime.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace sim::rt {

/// The collective calls of a distributed session. Without a
/// sim_communicator it is one rank, whose calls do nothing (allgather
/// copies), so that a distributed plan runs the same code on one process.
class Communicator {
public:
  /// `comm` may be null (one rank); it must outlive this object.
  explicit Communicator(const sim_communicator *comm);

  int32_t rank() const { return comm->rank; }
  int32_t size() const { return comm->size; }
  /// Whether a sim_communicator was given (sessions refuse some things,
  /// such as a non-distributed plan, only then).
  bool external() const { return comm != &single; }

  /// In place: each value's minimum (sum) over the ranks.
  void minimum(int64_t *values, int32_t count);
  void sum(int64_t *values, int32_t count);
  /// The sim_communicator's point-to-point exchange (arrays of size()
  /// entries).
  void exchange(const void *const *send, const size_t *sendBytes,
                void *const *recv, const size_t *recvBytes);
  /// The same in two halves where the sim_communicator can (else
  /// exchangeBegin exchanges and exchangeEnd does nothing); the arrays stay
  /// valid until exchangeEnd.
  void exchangeBegin(const void *const *send, const size_t *sendBytes,
                     void *const *recv, const size_t *recvBytes);
  void exchangeEnd();
  /// Whether exchangeBegin returns before the items arrived.
  bool overlaps() const { return comm->exchange_begin && comm->exchange_end; }
  /// Every rank's bytes[rank] bytes, in rank order into `out`.
  void allgather(const void *data, const size_t *bytes, void *out);

  /// All-reduce calls made so far (either kind).
  int64_t allReduces = 0;

private:
  [[noreturn]] void failed(const char *what) const;

  sim_communicator single{};
  const sim_communicator *comm;
};

/// How a range of `range` items in groups of `groupSize` is split over
/// `ranks` ranks: rank r holds the groups floor(r * NG / P) up to
/// floor((r + 1) * NG / P), NG = ceil(range / groupSize), so block sizes
/// differ by at most one group.
class Decomposition {
public:
  Decomposition(int64_t range, int64_t groupSize, int32_t ranks);

  int64_t range() const { return range_; }
  int64_t groupSize() const { return groupSize_; }
  int32_t ranks() const { return int32_t(firsts.size()) - 1; }
  int64_t groups() const { return (range_ + groupSize_ - 1) / groupSize_; }
  /// Whether every rank holds at least one group.
  bool fits() const { return groups() >= int64_t(ranks()); }
  /// The message of a decomposition that does not fit (every rank gives
  /// the same).
  std::string tooManyRanks() const;

  /// The items [first(r), end(r)) of rank r.
  int64_t first(int32_t rank) const { return firsts[size_t(rank)]; }
  int64_t end(int32_t rank) const { return firsts[size_t(rank) + 1]; }
  int64_t count(int32_t rank) const { return end(rank) - first(rank); }
  /// The rank that holds item `item` (0 <= item < range; with empty
  /// blocks, the last rank whose block starts at or before it).
  int32_t owner(int64_t item) const;

private:
  int64_t range_, groupSize_;
  std::vector<int64_t> firsts;
};

/// Where the ghost elements of one rank's block of a buffer come from,
/// for a buffer read `below` items below and `above` items above an item
/// under `boundary` (a block of `halo` ghost items on each side, halo >=
/// below and above). Elements are indices within one half.
struct GhostLists {
  /// Per rank: the elements this rank sends it, and the elements it
  /// receives from it, in the order they travel (the same on both sides).
  /// This rank's own lists are empty.
  std::vector<std::vector<int64_t>> send, recv;
  /// Ghosts whose item this rank holds: (from, to) elements.
  std::vector<std::pair<int64_t, int64_t>> local;

  /// Elements sent and received over all ranks.
  size_t sent() const;
  size_t received() const;
};

/// The ghost item that global item `item` (outside the block) reads under
/// `boundary` for a range of `range`: -1 when there is none (zero outside
/// the range: the kernels select 0 themselves).
int64_t ghostSource(int64_t item, int64_t range, Boundary boundary);

/// Local time steps: the level blocks (of `blockItems` items, ascending)
/// that hold items within `reach` items of rank `sender`'s block and items
/// within `reach` of rank `receiver`'s block, both around the range: the
/// blocks whose codes `sender` contributes to `receiver`'s levels (its own
/// items' codes, and a flux pair's codes for the readers of its interfaces,
/// which may lie on other ranks). Empty when either rank holds no item.
std::vector<int64_t> levelBlocksFor(const Decomposition &decomposition,
                                    int32_t sender, int32_t receiver,
                                    int64_t reach, int64_t blockItems);

/// The lists of rank `rank` (every rank's ghosts are computed, to know
/// what it must send).
GhostLists ghostLists(const Decomposition &decomposition, int32_t rank,
                      int64_t halo, int64_t below, int64_t above,
                      Boundary boundary);

} // namespace sim::rt

#endif // SIM_RUNTIME_DISTRIBUTION_H
