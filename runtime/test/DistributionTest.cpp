//===- DistributionTest.cpp - decomposition and ghost lists ---------------===//
//
// Distribution.h without MPI: the blocks of every rank, the message for too
// many ranks, and the ghost lists of every (halo, boundary) applied to all
// ranks at once in one process (a fake exchange that moves what the lists
// say), which must give every ghost element the item its boundary rule
// names: wrap and clamp across the first and last rank, blocks smaller than
// the halo, ranks that do not divide the range.
//
//===----------------------------------------------------------------------===//

#include "Distribution.h"
#include "Error.h"

#include <gtest/gtest.h>

#include <cstring>

using namespace sim::rt;

namespace {

TEST(Distribution, LevelBlocksAreThoseNearTheSenderAndTheReceiver) {
  // Against the definition, item by item: the level blocks of 32 items
  // that hold an item within `reach` of the sender's block (whose codes
  // its levels_C writes: its items' and its interfaces' readers') and an
  // item within `reach` of the receiver's block, around the range; ranks
  // of fewer items than a block, reaches past either end and past the
  // whole range.
  for (int64_t range : {37, 200, 1003})
    for (int64_t group : {7, 32})
      for (int32_t ranks : {2, 3, 5}) {
        Decomposition d(range, group, ranks);
        if (!d.fits())
          continue;
        for (int64_t reach : {1, 33, 161, 600})
          for (int32_t sender = 0; sender < ranks; ++sender)
            for (int32_t receiver = 0; receiver < ranks; ++receiver) {
              auto nearTo = [&](int32_t rank) {
                std::vector<bool> near(size_t(range), false);
                for (int64_t k = d.first(rank) - reach; k < d.end(rank) + reach;
                     ++k)
                  near[size_t(((k % range) + range) % range)] = true;
                return near;
              };
              std::vector<bool> written = nearTo(sender),
                                read = nearTo(receiver);
              std::vector<int64_t> expected;
              for (int64_t block = 0; block * 32 < range; ++block) {
                bool writes = false, reads = false;
                for (int64_t i = block * 32;
                     i < std::min(range, block * 32 + 32); ++i) {
                  writes = writes || written[size_t(i)];
                  reads = reads || read[size_t(i)];
                }
                if (writes && reads)
                  expected.push_back(block);
              }
              EXPECT_EQ(levelBlocksFor(d, sender, receiver, reach, 32),
                        expected)
                  << "range " << range << " group " << group << " ranks "
                  << ranks << " reach " << reach << " from " << sender << " to "
                  << receiver;
            }
      }
}

TEST(Distribution, BlocksAreWholeGroupsThatDifferByAtMostOne) {
  // 10 groups of 4 (the last one of 2 items) over 3 ranks: 3, 3, 4 groups.
  Decomposition d(38, 4, 3);
  EXPECT_TRUE(d.fits());
  EXPECT_EQ(d.groups(), 10);
  EXPECT_EQ(d.first(0), 0);
  EXPECT_EQ(d.end(0), 12);
  EXPECT_EQ(d.first(1), 12);
  EXPECT_EQ(d.end(1), 24);
  EXPECT_EQ(d.first(2), 24);
  EXPECT_EQ(d.end(2), 38);
  for (int64_t item = 0; item < 38; ++item)
    EXPECT_EQ(d.owner(item), item < 12 ? 0 : item < 24 ? 1 : 2) << item;
  for (int32_t ranks = 1; ranks <= 7; ++ranks) {
    Decomposition split(1000, 16, ranks);
    int64_t least = 1 << 30, most = 0;
    for (int32_t r = 0; r < ranks; ++r) {
      EXPECT_EQ(split.first(r) % 16, 0);
      if (r + 1 < ranks) {
        least = std::min(least, split.count(r) / 16);
        most = std::max(most, split.count(r) / 16);
      }
    }
    EXPECT_EQ(split.end(ranks - 1), 1000);
    EXPECT_LE(most - least, 1);
  }
}

TEST(Distribution, HugeRangesDoNotOverflow) {
  // ranks * groups is 2^60 here, and 2^62 for the largest range with
  // 2^22 ranks.
  Decomposition d(int64_t(1) << 40, 1, 1 << 20);
  EXPECT_EQ(d.count(0), int64_t(1) << 20);
  EXPECT_EQ(d.end((1 << 20) - 1), int64_t(1) << 40);
  Decomposition odd((int64_t(1) << 40) - 3, 1, 3);
  EXPECT_EQ(odd.end(2), (int64_t(1) << 40) - 3);
  EXPECT_EQ(odd.count(0), odd.count(1));
}

TEST(Distribution, TooManyRanks) {
  Decomposition d(300, 256, 3);
  EXPECT_FALSE(d.fits());
  EXPECT_EQ(d.tooManyRanks(),
            "3 ranks for a range of 2 groups of 256 items: use at most 2 "
            "ranks or a smaller group size");
  EXPECT_EQ(Decomposition(5, 8, 2).tooManyRanks(),
            "2 ranks for a range of 1 group of 8 items: use at most 1 rank "
            "or a smaller group size");
  EXPECT_EQ(Decomposition(3, 1, 4).tooManyRanks(),
            "4 ranks for a range of 3 groups of 1 item: use at most 3 ranks");
}

TEST(Distribution, GhostSource) {
  EXPECT_EQ(ghostSource(-1, 10, Boundary::Clamp), 0);
  EXPECT_EQ(ghostSource(12, 10, Boundary::Clamp), 9);
  EXPECT_EQ(ghostSource(-1, 10, Boundary::Wrap), 9);
  EXPECT_EQ(ghostSource(-23, 10, Boundary::Wrap), 7);
  EXPECT_EQ(ghostSource(25, 10, Boundary::Wrap), 5);
  EXPECT_EQ(ghostSource(-1, 10, Boundary::Zero), -1);
  EXPECT_EQ(ghostSource(10, 10, Boundary::Zero), -1);
  EXPECT_EQ(ghostSource(4, 10, Boundary::Zero), 4);
}

/// Every rank's block of one half as plain items: each owned element holds
/// its global item, each ghost -7; then the lists of every rank are applied
/// as an exchange would, and every ghost must hold its source item.
void checkExchange(int64_t range, int64_t group, int32_t ranks, int64_t halo,
                   int64_t below, int64_t above, Boundary boundary) {
  SCOPED_TRACE("range " + std::to_string(range) + ", group " +
               std::to_string(group) + ", " + std::to_string(ranks) +
               " ranks, halo " + std::to_string(halo) + " (" +
               std::to_string(below) + ", " + std::to_string(above) + "), " +
               boundaryName(boundary));
  Decomposition d(range, group, ranks);
  ASSERT_TRUE(d.fits());
  std::vector<std::vector<int64_t>> blocks(static_cast<size_t>(ranks));
  std::vector<GhostLists> lists;
  for (int32_t r = 0; r < ranks; ++r) {
    std::vector<int64_t> &block = blocks[size_t(r)];
    block.assign(size_t(d.count(r) + 2 * halo), -7);
    for (int64_t i = 0; i < d.count(r); ++i)
      block[size_t(halo + i)] = d.first(r) + i;
    lists.push_back(ghostLists(d, r, halo, below, above, boundary));
  }
  for (int32_t r = 0; r < ranks; ++r) {
    EXPECT_TRUE(lists[size_t(r)].send[size_t(r)].empty());
    EXPECT_TRUE(lists[size_t(r)].recv[size_t(r)].empty());
    for (auto [from, to] : lists[size_t(r)].local)
      blocks[size_t(r)][size_t(to)] = blocks[size_t(r)][size_t(from)];
    for (int32_t q = 0; q < ranks; ++q) {
      if (q == r)
        continue;
      // What r sends q is what q receives from r, element for element.
      const std::vector<int64_t> &send = lists[size_t(r)].send[size_t(q)];
      const std::vector<int64_t> &recv = lists[size_t(q)].recv[size_t(r)];
      ASSERT_EQ(send.size(), recv.size()) << r << " -> " << q;
      for (size_t k = 0; k < send.size(); ++k)
        blocks[size_t(q)][size_t(recv[k])] = blocks[size_t(r)][size_t(send[k])];
    }
  }
  for (int32_t r = 0; r < ranks; ++r)
    for (int64_t e = 0; e < d.count(r) + 2 * halo; ++e) {
      int64_t u = d.first(r) + e - halo;
      bool ghost = e < halo || e >= halo + d.count(r);
      bool reached = u >= d.first(r) - below && u < d.end(r) + above;
      int64_t want = !ghost    ? u
                     : reached ? ghostSource(u, range, boundary)
                               : -1;
      if (want < 0)
        want = -7;
      EXPECT_EQ(blocks[size_t(r)][size_t(e)], want)
          << "rank " << r << ", element " << e << " (item " << u << ")";
    }
}

TEST(Distribution, GhostListsFillEveryGhost) {
  for (Boundary boundary : {Boundary::Clamp, Boundary::Wrap, Boundary::Zero}) {
    // Neighbours only.
    checkExchange(100, 8, 3, 4, 4, 4, boundary);
    // Uneven reads, a halo wider than the buffer's.
    checkExchange(100, 8, 3, 6, 1, 3, boundary);
    // Blocks of one group of 2 items under a halo of 5: ghosts from ranks
    // further away, and from this rank itself under wrap.
    checkExchange(7, 2, 4, 5, 5, 5, boundary);
    // One rank: local copies only.
    checkExchange(10, 4, 1, 3, 3, 3, boundary);
    // A range smaller than the halo: items wrap more than once.
    checkExchange(3, 1, 3, 7, 7, 7, boundary);
  }
}

TEST(Distribution, OneRankCommunicator) {
  Communicator comm(nullptr);
  EXPECT_EQ(comm.rank(), 0);
  EXPECT_EQ(comm.size(), 1);
  EXPECT_FALSE(comm.external());
  int64_t values[2] = {3, -4};
  comm.minimum(values, 2);
  comm.sum(values, 2);
  EXPECT_EQ(values[0], 3);
  EXPECT_EQ(values[1], -4);
  EXPECT_EQ(comm.allReduces, 2);
  char out[4] = {};
  size_t bytes[1] = {3};
  comm.allgather("abc", bytes, out);
  EXPECT_STREQ(out, "abc");
}

int failing(void *, int64_t *, int32_t) { return 1; }
int fine(void *, int64_t *, int32_t) { return 0; }
int noExchange(void *, const void *const *, const size_t *, void *const *,
               const size_t *) {
  return 0;
}
int noGather(void *, const void *, const size_t *, void *) { return 0; }

TEST(Distribution, CommunicatorFailures) {
  sim_communicator given{};
  given.rank = 1;
  given.size = 2;
  given.allreduce_min_i64 = failing;
  given.allreduce_sum_i64 = fine;
  given.exchange = noExchange;
  given.allgather = noGather;
  Communicator comm(&given);
  EXPECT_TRUE(comm.external());
  int64_t value = 0;
  try {
    comm.minimum(&value, 1);
    FAIL() << "no error";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_DISTRIBUTED);
    EXPECT_STREQ(error.what(), "rank 1 of 2: the all-reduce (minimum) "
                               "between the ranks failed");
  }
  sim_communicator bad = given;
  bad.rank = 2;
  EXPECT_THROW(Communicator{&bad}, Error);
  bad = given;
  bad.exchange = nullptr;
  EXPECT_THROW(Communicator{&bad}, Error);
}

} // namespace
