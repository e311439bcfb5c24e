//===- Distribution.cpp - a range split over ranks, and its ghosts --------===//
//
// The decomposition and the ghost lists are computed by every rank for
// every rank from the same numbers, so the send list one rank builds for
// another is, element for element, the receive list that other rank builds:
// no rank ever has to tell another what it wants.
//
//===----------------------------------------------------------------------===//

#include "Distribution.h"
#include "Error.h"

#include <algorithm>
#include <cstring>

namespace sim::rt {

//===----------------------------------------------------------------------===//
// Communicator
//===----------------------------------------------------------------------===//

namespace {

int noReduce(void *, int64_t *, int32_t) { return 0; }

int noExchange(void *, const void *const *, const size_t *, void *const *,
               const size_t *) {
  return 0;
}

int copyGather(void *, const void *data, const size_t *bytes, void *out) {
  if (bytes[0])
    std::memcpy(out, data, bytes[0]);
  return 0;
}

} // namespace

Communicator::Communicator(const sim_communicator *given) {
  single.rank = 0;
  single.size = 1;
  single.allreduce_min_i64 = noReduce;
  single.allreduce_sum_i64 = noReduce;
  single.exchange = noExchange;
  single.allgather = copyGather;
  comm = given ? given : &single;
  if (!given)
    return;
  if (given->size < 1 || given->rank < 0 || given->rank >= given->size)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "the communicator says rank " + std::to_string(given->rank) + " of " +
             std::to_string(given->size) + " ranks");
  if (!given->allreduce_min_i64 || !given->allreduce_sum_i64 ||
      !given->exchange || !given->allgather)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "the communicator lacks one of its functions (allreduce_min_i64, "
         "allreduce_sum_i64, exchange, allgather)");
}

void Communicator::failed(const char *what) const {
  fail(SIM_ERROR_DISTRIBUTED, "rank " + std::to_string(rank()) + " of " +
                                  std::to_string(size()) + ": the " + what +
                                  " between the ranks failed");
}

void Communicator::minimum(int64_t *values, int32_t count) {
  ++allReduces;
  if (comm->allreduce_min_i64(comm->user, values, count) != 0)
    failed("all-reduce (minimum)");
}

void Communicator::sum(int64_t *values, int32_t count) {
  ++allReduces;
  if (comm->allreduce_sum_i64(comm->user, values, count) != 0)
    failed("all-reduce (sum)");
}

void Communicator::exchange(const void *const *send, const size_t *sendBytes,
                            void *const *recv, const size_t *recvBytes) {
  if (comm->exchange(comm->user, send, sendBytes, recv, recvBytes) != 0)
    failed("exchange of ghost items");
}

void Communicator::exchangeBegin(const void *const *send,
                                 const size_t *sendBytes, void *const *recv,
                                 const size_t *recvBytes) {
  if (!overlaps())
    return exchange(send, sendBytes, recv, recvBytes);
  if (comm->exchange_begin(comm->user, send, sendBytes, recv, recvBytes) != 0)
    failed("exchange of ghost items");
}

void Communicator::exchangeEnd() {
  if (overlaps() && comm->exchange_end(comm->user) != 0)
    failed("exchange of ghost items");
}

void Communicator::allgather(const void *data, const size_t *bytes, void *out) {
  if (comm->allgather(comm->user, data, bytes, out) != 0)
    failed("all-gather");
}

//===----------------------------------------------------------------------===//
// Decomposition
//===----------------------------------------------------------------------===//

Decomposition::Decomposition(int64_t range, int64_t groupSize, int32_t ranks)
    : range_(range), groupSize_(groupSize) {
  int64_t groups = this->groups();
  firsts.resize(size_t(ranks) + 1);
  for (int32_t r = 0; r <= ranks; ++r) {
    // r * groups reaches 2^31 * 2^40: past 64 bits.
    int64_t group = int64_t((__int128(r) * groups) / ranks);
    firsts[size_t(r)] = std::min(group * groupSize, range);
  }
}

std::string Decomposition::tooManyRanks() const {
  int64_t n = groups();
  return std::to_string(ranks()) + " ranks for a range of " +
         std::to_string(n) + (n == 1 ? " group" : " groups") + " of " +
         std::to_string(groupSize_) + (groupSize_ == 1 ? " item" : " items") +
         ": use at most " + std::to_string(n) + (n == 1 ? " rank" : " ranks") +
         (groupSize_ == 1 ? "" : " or a smaller group size");
}

int32_t Decomposition::owner(int64_t item) const {
  auto it = std::upper_bound(firsts.begin(), firsts.end() - 1, item);
  return int32_t(it - firsts.begin()) - 1;
}

//===----------------------------------------------------------------------===//
// Ghost lists
//===----------------------------------------------------------------------===//

size_t GhostLists::sent() const {
  size_t n = 0;
  for (const auto &list : send)
    n += list.size();
  return n;
}

size_t GhostLists::received() const {
  size_t n = 0;
  for (const auto &list : recv)
    n += list.size();
  return n;
}

int64_t ghostSource(int64_t item, int64_t range, Boundary boundary) {
  if (item >= 0 && item < range)
    return item;
  switch (boundary) {
  case Boundary::Clamp:
    return item < 0 ? 0 : range - 1;
  case Boundary::Wrap: {
    int64_t wrapped = item % range;
    return wrapped < 0 ? wrapped + range : wrapped;
  }
  case Boundary::Zero:
    return -1;
  }
  return -1;
}

namespace {

/// Calls `visit(u, s)` for every ghost item u of rank `rank` that has a
/// source item s, below the block first, then above it, each in item
/// order.
template <typename Visit>
void forEachGhost(const Decomposition &d, int32_t rank, int64_t below,
                  int64_t above, Boundary boundary, Visit &&visit) {
  int64_t first = d.first(rank), end = d.end(rank);
  auto one = [&](int64_t u) {
    int64_t s = ghostSource(u, d.range(), boundary);
    if (s >= 0)
      visit(u, s);
  };
  for (int64_t u = first - below; u < first; ++u)
    one(u);
  for (int64_t u = end; u < end + above; ++u)
    one(u);
}

} // namespace

GhostLists ghostLists(const Decomposition &d, int32_t rank, int64_t halo,
                      int64_t below, int64_t above, Boundary boundary) {
  GhostLists lists;
  int32_t ranks = d.ranks();
  lists.send.resize(size_t(ranks));
  lists.recv.resize(size_t(ranks));
  int64_t mine = d.first(rank);
  // What this rank receives or copies.
  forEachGhost(d, rank, below, above, boundary, [&](int64_t u, int64_t s) {
    int32_t owner = d.owner(s);
    int64_t to = u - mine + halo;
    if (owner == rank)
      lists.local.emplace_back(s - mine + halo, to);
    else
      lists.recv[size_t(owner)].push_back(to);
  });
  // What every other rank wants from this one, in that rank's order.
  for (int32_t peer = 0; peer < ranks; ++peer) {
    if (peer == rank || d.count(peer) == 0)
      continue;
    forEachGhost(d, peer, below, above, boundary, [&](int64_t, int64_t s) {
      if (d.owner(s) == rank)
        lists.send[size_t(peer)].push_back(s - mine + halo);
    });
  }
  return lists;
}

namespace {
/// The items of `rank`'s block and `reach` more on each side, as item
/// intervals inside the range (two where they wrap around it).
std::vector<std::pair<int64_t, int64_t>>
itemsNear(const Decomposition &d, int32_t rank, int64_t reach) {
  int64_t range = d.range();
  int64_t lo = d.first(rank) - reach, hi = d.end(rank) + reach;
  if (hi - lo >= range)
    return {{0, range}};
  if (lo < 0)
    return {{0, hi}, {lo + range, range}};
  if (hi > range)
    return {{0, hi - range}, {lo, range}};
  return {{lo, hi}};
}
} // namespace

std::vector<int64_t> levelBlocksFor(const Decomposition &d, int32_t sender,
                                    int32_t receiver, int64_t reach,
                                    int64_t blockItems) {
  std::vector<int64_t> blocks;
  if (d.count(sender) == 0 || d.count(receiver) == 0)
    return blocks;
  // The sender's levels_C writes codes into the blocks of its items and,
  // for a flux pair, into those of the readers of its interfaces, which
  // may lie on the receiver (an interface read by the item before it):
  // blocks within `reach` of its own block, which holds a flux pair's
  // reach. Every other block of its copy holds 0 at the exchange (its
  // limit_levels_C cleared them), so sending it changes nothing.
  auto mark = [&](const std::vector<std::pair<int64_t, int64_t>> &near,
                  std::vector<bool> &into) {
    into.assign(size_t((d.range() + blockItems - 1) / blockItems), false);
    for (auto [from, to] : near)
      for (int64_t block = from / blockItems;
           from < to && block <= (to - 1) / blockItems; ++block)
        into[size_t(block)] = true;
  };
  std::vector<bool> written, read;
  mark(itemsNear(d, sender, reach), written);
  mark(itemsNear(d, receiver, reach), read);
  for (size_t block = 0; block < written.size(); ++block)
    if (written[block] && read[block])
      blocks.push_back(int64_t(block));
  return blocks;
}

} // namespace sim::rt
