//===- DistributedTest.cpp - distributed sessions against one process -----===//
//
// The "ring" scene (kernels/ring.c: a distributed plan written by hand) on
// P ranks that are threads of this process, joined by a communicator of
// shared memory, against the same plan on one process: the same values bit
// for bit, evaluations, big steps and totals, for ranks that do not divide
// the range, blocks smaller than the halo, and every boundary rule. Then
// the refusals, and with mpirun (when it is here) sim-run --distributed.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "Reference.h"
#include "Session.h"
#include "TestBundle.h"
#include "TestUtil.h"

#include <gtest/gtest.h>

#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <mutex>
#include <thread>

using namespace sim::rt;
using namespace sim::test;

namespace {

/// P threads as ranks: every call waits for all of them (a barrier) and
/// reads what the others left in shared slots.
class ThreadWorld {
public:
  explicit ThreadWorld(int32_t ranks)
      : ranks(ranks), values(size_t(ranks)), sends(size_t(ranks)),
        sendBytes(size_t(ranks)), data(size_t(ranks)) {
    for (int32_t r = 0; r < ranks; ++r) {
      // Zeroed: the optional functions (exchange_begin/end) stay null.
      Rank rank{};
      rank.world = this;
      rank.comm.user = nullptr;
      rank.comm.rank = r;
      rank.comm.size = ranks;
      rank.comm.allreduce_min_i64 = &ThreadWorld::minimum;
      rank.comm.allreduce_sum_i64 = &ThreadWorld::sum;
      rank.comm.exchange = &ThreadWorld::exchange;
      rank.comm.allgather = &ThreadWorld::allgather;
      all.push_back(rank);
    }
    for (Rank &rank : all)
      rank.comm.user = &rank;
  }

  const sim_communicator *communicator(int32_t rank) {
    return &all[size_t(rank)].comm;
  }

  /// Runs `body(rank)` on every rank, each on its own thread.
  void run(const std::function<void(int32_t)> &body) {
    std::vector<std::thread> threads;
    for (int32_t r = 0; r < ranks; ++r)
      threads.emplace_back([&, r] { body(r); });
    for (std::thread &thread : threads)
      thread.join();
  }

private:
  struct Rank {
    ThreadWorld *world;
    sim_communicator comm;
  };

  void barrier() {
    std::unique_lock<std::mutex> lock(mutex);
    int64_t generation = this->generation;
    if (++arrived == ranks) {
      arrived = 0;
      ++this->generation;
      changed.notify_all();
      return;
    }
    changed.wait(lock, [&] { return this->generation != generation; });
  }

  static int reduce(void *user, int64_t *v, int32_t count, bool isSum) {
    Rank &rank = *static_cast<Rank *>(user);
    ThreadWorld &w = *rank.world;
    w.values[size_t(rank.comm.rank)].assign(v, v + count);
    w.barrier();
    for (int32_t i = 0; i < count; ++i) {
      int64_t result = w.values[0][size_t(i)];
      for (int32_t r = 1; r < w.ranks; ++r) {
        int64_t other = w.values[size_t(r)][size_t(i)];
        result = isSum ? result + other : std::min(result, other);
      }
      v[i] = result;
    }
    w.barrier();
    return 0;
  }
  static int minimum(void *user, int64_t *v, int32_t count) {
    return reduce(user, v, count, false);
  }
  static int sum(void *user, int64_t *v, int32_t count) {
    return reduce(user, v, count, true);
  }
  static int exchange(void *user, const void *const *send,
                      const size_t *sendBytes, void *const *recv,
                      const size_t *recvBytes) {
    Rank &rank = *static_cast<Rank *>(user);
    ThreadWorld &w = *rank.world;
    size_t me = size_t(rank.comm.rank);
    w.sends[me].assign(send, send + w.ranks);
    w.sendBytes[me].assign(sendBytes, sendBytes + w.ranks);
    w.barrier();
    int failed = 0;
    for (size_t from = 0; from < size_t(w.ranks); ++from) {
      if (from == me)
        continue;
      if (w.sendBytes[from][me] != recvBytes[from])
        failed = 1;
      else if (recvBytes[from])
        std::memcpy(recv[from], w.sends[from][me], recvBytes[from]);
    }
    w.barrier();
    return failed;
  }
  static int allgather(void *user, const void *data, const size_t *bytes,
                       void *out) {
    Rank &rank = *static_cast<Rank *>(user);
    ThreadWorld &w = *rank.world;
    w.data[size_t(rank.comm.rank)] = data;
    w.barrier();
    size_t at = 0;
    for (int32_t r = 0; r < w.ranks; ++r) {
      std::memcpy(static_cast<char *>(out) + at, w.data[size_t(r)],
                  bytes[size_t(r)]);
      at += bytes[size_t(r)];
    }
    w.barrier();
    return 0;
  }

  int32_t ranks;
  std::vector<Rank> all;
  std::mutex mutex;
  std::condition_variable changed;
  int32_t arrived = 0;
  int64_t generation = 0;
  std::vector<std::vector<int64_t>> values;
  std::vector<std::vector<const void *>> sends;
  std::vector<std::vector<size_t>> sendBytes;
  std::vector<const void *> data;
};

std::shared_ptr<const Bundle> ring(Boundary boundary) {
  return parseBytes(serialize(ringContents(boundary)), "ring.simb");
}

sim_session_options ringOptions(int64_t groupSize, const sim_communicator *comm,
                                bool checkFinite = false) {
  sim_session_options options;
  sim_session_options_init(&options);
  options.strategy = SIM_STRATEGY_HIP;
  options.backend = SIM_BACKEND_CPU;
  options.cpu_threads = 2;
  options.group_size = groupSize;
  options.communicator = comm;
  options.check_finite = checkFinite;
  return options;
}

/// What a run leaves: X, the counters, the total.
struct Outcome {
  std::vector<double> x;
  std::vector<int64_t> evaluations, histogram;
  int64_t bigSteps = 0, cuts = 0;
  double total = 0;
  sim_metrics metrics{};
};

Outcome runRing(Session &session, int64_t range, int64_t steps) {
  session.set("range", std::to_string(range));
  session.init();
  // Twice, so that the second run starts from a state the first left.
  session.run(steps / 2);
  session.run(steps - steps / 2);
  Outcome outcome;
  outcome.x.resize(size_t(range));
  session.getBuffer("X", outcome.x.data(), outcome.x.size() * 8);
  outcome.evaluations = session.evaluations;
  outcome.histogram = session.histogram;
  outcome.bigSteps = session.metrics.big_steps;
  outcome.cuts = session.cutBigSteps;
  outcome.total = session.totals()[0];
  outcome.metrics = session.metrics;
  return outcome;
}

void expectSame(const Outcome &one, const Outcome &many) {
  ASSERT_EQ(one.x.size(), many.x.size());
  EXPECT_EQ(std::memcmp(one.x.data(), many.x.data(), one.x.size() * 8), 0);
  for (size_t i = 0; i < one.x.size(); ++i)
    if (one.x[i] != many.x[i]) {
      ADD_FAILURE() << "item " << i << ": " << one.x[i] << " vs " << many.x[i];
      break;
    }
  EXPECT_EQ(one.evaluations, many.evaluations);
  EXPECT_EQ(one.histogram, many.histogram);
  EXPECT_EQ(one.bigSteps, many.bigSteps);
  EXPECT_EQ(one.cuts, many.cuts);
  EXPECT_EQ(one.total, many.total);
}

void checkRanks(Boundary boundary, int32_t ranks, int64_t range,
                int64_t groupSize, int64_t steps, bool checkFinite = false) {
  SCOPED_TRACE(std::string(boundaryName(boundary)) + ", " +
               std::to_string(ranks) + " ranks, range " +
               std::to_string(range) + ", group size " +
               std::to_string(groupSize));
  auto bundle = ring(boundary);
  Session single(bundle, ringOptions(groupSize, nullptr, checkFinite));
  Outcome one = runRing(single, range, steps);
  EXPECT_GT(one.evaluations[0], 0);
  ThreadWorld world(ranks);
  std::vector<Outcome> outcomes(static_cast<size_t>(ranks));
  std::vector<std::string> errors(static_cast<size_t>(ranks));
  world.run([&](int32_t r) {
    try {
      Session session(
          bundle, ringOptions(groupSize, world.communicator(r), checkFinite));
      outcomes[size_t(r)] = runRing(session, range, steps);
    } catch (const Error &error) {
      errors[size_t(r)] = error.what();
    }
  });
  for (int32_t r = 0; r < ranks; ++r) {
    SCOPED_TRACE("rank " + std::to_string(r));
    ASSERT_EQ(errors[size_t(r)], "");
    expectSame(one, outcomes[size_t(r)]);
    // One exchange of X per big step of the second run, one all-reduce of
    // the estimate per step phase at least.
    EXPECT_EQ(outcomes[size_t(r)].metrics.halo_exchanges,
              outcomes[size_t(r)].metrics.big_steps);
    EXPECT_GT(outcomes[size_t(r)].metrics.allreduces,
              outcomes[size_t(r)].metrics.big_steps);
  }
}

TEST(Distributed, SameAsOneProcess) {
  for (Boundary boundary : {Boundary::Wrap, Boundary::Clamp, Boundary::Zero}) {
    // Ranks that divide the range and ranks that do not.
    checkRanks(boundary, 2, 100, 4, 57);
    checkRanks(boundary, 3, 100, 4, 57);
    // Blocks of one item under a halo of 2: ghosts from ranks further
    // away (and under wrap, of the block itself).
    checkRanks(boundary, 3, 3, 1, 23);
    checkRanks(boundary, 4, 7, 1, 23);
  }
  // --check-finite: a batch per step phase, an agreement per launch.
  checkRanks(Boundary::Wrap, 3, 50, 4, 31, true);
}

/// The gather variant: Y is replicated, every item reads all of it, and
/// its exchange is an all-gather of the ranks' blocks. A setBuffer between
/// the runs stores every item of Y (and X's block and ghosts); getBuffer,
/// exact and totals gather the owners' blocks.
struct GatherOutcome {
  std::vector<double> x, y, exactY;
  std::vector<int64_t> evaluations;
  int64_t bigSteps = 0;
  double total = 0;
  sim_metrics metrics{};
};

GatherOutcome runGather(Session &session, int64_t range, int64_t steps) {
  session.set("range", std::to_string(range));
  session.init();
  session.run(steps / 2);
  std::vector<double> x(static_cast<size_t>(range)),
      y(static_cast<size_t>(range));
  session.getBuffer("X", x.data(), x.size() * 8);
  session.getBuffer("Y", y.data(), y.size() * 8);
  for (size_t i = 0; i < y.size(); i += 7) {
    x[i] += 0.5;
    y[i] += 0.125;
  }
  session.setBuffer("X", x.data(), x.size() * 8);
  session.setBuffer("Y", y.data(), y.size() * 8);
  session.run(steps - steps / 2);
  GatherOutcome outcome;
  outcome.x.resize(size_t(range));
  outcome.y.resize(size_t(range));
  outcome.exactY.resize(size_t(range));
  session.getBuffer("X", outcome.x.data(), outcome.x.size() * 8);
  session.getBuffer("Y", outcome.y.data(), outcome.y.size() * 8);
  session.exact("Y", outcome.exactY.data(), outcome.exactY.size() * 8);
  outcome.evaluations = session.evaluations;
  outcome.bigSteps = session.metrics.big_steps;
  outcome.total = session.totals()[0];
  outcome.metrics = session.metrics;
  return outcome;
}

void checkGather(int32_t ranks, int64_t range, int64_t groupSize, int64_t steps,
                 bool checkFinite = false) {
  SCOPED_TRACE(std::to_string(ranks) + " ranks, range " +
               std::to_string(range) + ", group size " +
               std::to_string(groupSize));
  auto bundle =
      parseBytes(serialize(ringContents(Boundary::Wrap, true)), "ring.simb");
  Session single(bundle, ringOptions(groupSize, nullptr, checkFinite));
  GatherOutcome one = runGather(single, range, steps);
  ASSERT_EQ(one.evaluations.size(), 2u);
  EXPECT_GT(one.evaluations[1], 0);
  // The kernels poison Y when their memref is not `range` items long.
  for (size_t i = 0; i < one.y.size(); ++i) {
    ASSERT_TRUE(std::isfinite(one.y[i])) << "item " << i;
    ASSERT_TRUE(std::isfinite(one.exactY[i])) << "item " << i;
  }
  // Every item of Y moved towards the mean of all of them.
  EXPECT_NE(one.y[1], 1.0 + 0.02 + 0.25 + (1 % 7 == 0 ? 0.125 : 0.0));
  ThreadWorld world(ranks);
  std::vector<GatherOutcome> outcomes(static_cast<size_t>(ranks));
  std::vector<std::string> errors(static_cast<size_t>(ranks));
  world.run([&](int32_t r) {
    try {
      Session session(
          bundle, ringOptions(groupSize, world.communicator(r), checkFinite));
      outcomes[size_t(r)] = runGather(session, range, steps);
    } catch (const Error &error) {
      errors[size_t(r)] = error.what();
    }
  });
  Decomposition split(range, groupSize, ranks);
  for (int32_t r = 0; r < ranks; ++r) {
    SCOPED_TRACE("rank " + std::to_string(r));
    ASSERT_EQ(errors[size_t(r)], "");
    const GatherOutcome &many = outcomes[size_t(r)];
    EXPECT_EQ(std::memcmp(one.x.data(), many.x.data(), one.x.size() * 8), 0);
    EXPECT_EQ(std::memcmp(one.y.data(), many.y.data(), one.y.size() * 8), 0);
    EXPECT_EQ(std::memcmp(one.exactY.data(), many.exactY.data(),
                          one.exactY.size() * 8),
              0);
    EXPECT_EQ(one.evaluations, many.evaluations);
    EXPECT_EQ(one.bigSteps, many.bigSteps);
    EXPECT_EQ(one.total, many.total);
    // X's ghosts and Y's all-gather, once per big step each; Y's bytes
    // are the rank's block of both halves, to every other rank.
    EXPECT_EQ(many.metrics.halo_exchanges, 2 * many.metrics.big_steps);
    GhostLists ghosts = ghostLists(split, r, 2, 2, 2, Boundary::Wrap);
    int64_t perBigStep =
        int64_t(ghosts.sent()) * 16 + (ranks - 1) * split.count(r) * 16;
    EXPECT_EQ(many.metrics.exchanged_bytes,
              perBigStep * many.metrics.big_steps);
  }
}

TEST(Distributed, ReplicatedBufferSameAsOneProcess) {
  checkGather(2, 100, 4, 57);
  checkGather(3, 100, 4, 57);
  // Blocks of one item.
  checkGather(4, 7, 1, 23);
  checkGather(3, 50, 4, 31, true);
}

/// Replicated memory on one process is `range` items; on P ranks too.
TEST(Distributed, ReplicatedBufferMemory) {
  auto ring = parseBytes(serialize(ringContents(Boundary::Wrap)), "r.simb");
  auto gather =
      parseBytes(serialize(ringContents(Boundary::Wrap, true)), "g.simb");
  ThreadWorld world(2);
  std::vector<int64_t> plain(2), replicated(2);
  world.run([&](int32_t r) {
    Session a(ring, ringOptions(4, world.communicator(r)));
    Session b(gather, ringOptions(4, world.communicator(r)));
    plain[size_t(r)] = a.memoryBytes(100);
    replicated[size_t(r)] = b.memoryBytes(100);
  });
  for (int32_t r = 0; r < 2; ++r)
    // Y: two halves and an exact array of 100 items of 8 bytes.
    EXPECT_EQ(replicated[size_t(r)] - plain[size_t(r)], 3 * 100 * 8);
}

TEST(Distributed, OneProcessWithoutCommunicatorRunsTheSameCode) {
  // The ring's wrap ghosts are local copies on one rank: without them the
  // ends of the range would read zeros.
  auto bundle = ring(Boundary::Wrap);
  Session single(bundle, ringOptions(4, nullptr));
  Outcome one = runRing(single, 10, 9);
  EXPECT_NE(one.x[0], one.x[1]);
  EXPECT_EQ(one.metrics.halo_exchanges, one.metrics.big_steps);
}

/// Sets a NaN into item 29 of `buffer` and runs with --check-finite on one
/// process and on 3 ranks: every rank stops with the message one process
/// gives, which contains `expected`.
static void expectEveryRankStops(const std::shared_ptr<const Bundle> &bundle,
                                 const std::string &buffer,
                                 const std::string &expected) {
  auto poisoned = [&](Session &session) {
    session.set("range", "50");
    std::vector<double> values(50);
    session.getBuffer(buffer, values.data(), values.size() * 8);
    values[29] = std::nan("");
    session.setBuffer(buffer, values.data(), values.size() * 8);
    try {
      session.run(10);
    } catch (const Error &error) {
      EXPECT_EQ(error.status, SIM_ERROR_NONFINITE);
      return std::string(error.what());
    }
    return std::string("no error");
  };
  Session single(bundle, ringOptions(4, nullptr, true));
  std::string one = poisoned(single);
  EXPECT_NE(one.find(expected), std::string::npos) << one;
  ThreadWorld world(3);
  std::vector<std::string> messages(3);
  world.run([&](int32_t r) {
    Session session(bundle, ringOptions(4, world.communicator(r), true));
    messages[size_t(r)] = poisoned(session);
  });
  for (const std::string &message : messages)
    EXPECT_EQ(message, one);
}

/// A NaN set into one rank's block: every rank stops with the message
/// one process gives (--check-finite), naming the global item.
TEST(Distributed, NonFiniteValuesStopEveryRank) {
  expectEveryRankStops(ring(Boundary::Wrap), "X", "(item 29)");
}

/// The same in a replicated buffer: each rank looks at its own items of
/// the whole array, and the ranks agree on the first non-finite one.
TEST(Distributed, NonFiniteReplicatedValuesStopEveryRank) {
  expectEveryRankStops(
      parseBytes(serialize(ringContents(Boundary::Wrap, true)), "ring.simb"),
      "Y", "in buffer 'Y'");
}

TEST(Distributed, TooManyRanks) {
  auto bundle = ring(Boundary::Wrap);
  ThreadWorld world(3);
  std::vector<std::string> errors(3);
  world.run([&](int32_t r) {
    try {
      Session session(bundle, ringOptions(256, world.communicator(r)));
      session.set("range", "300");
      session.init();
    } catch (const Error &error) {
      EXPECT_EQ(error.status, SIM_ERROR_DISTRIBUTED);
      errors[size_t(r)] = error.what();
    }
  });
  for (const std::string &error : errors)
    EXPECT_EQ(error, "3 ranks for a range of 2 groups of 256 items: use at "
                     "most 2 ranks or a smaller group size");
}

TEST(Distributed, RanksMustAgree) {
  auto bundle = ring(Boundary::Wrap);
  ThreadWorld world(2);
  std::vector<std::string> errors(2);
  world.run([&](int32_t r) {
    try {
      Session session(bundle, ringOptions(4, world.communicator(r)));
      // 8 items on rank 0 fit 2 ranks in groups of 4, 3 on rank 1 do not:
      // the ranks must agree before either splits its range.
      session.set("range", r == 0 ? "8" : "3");
      session.init();
    } catch (const Error &error) {
      EXPECT_EQ(error.status, SIM_ERROR_DISTRIBUTED);
      errors[size_t(r)] = error.what();
    }
  });
  for (const std::string &error : errors)
    EXPECT_EQ(error, "the ranks disagree on the range (from 3 to 8 over "
                     "the 2 ranks)");
}

TEST(Distributed, Refusals) {
  ThreadWorld world(1);
  // A plan made for one process.
  auto decay = parseBytes(decayBundle(), "decay.simb");
  try {
    Session session(decay, ringOptions(0, world.communicator(0)));
    FAIL() << "no error";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_BUNDLE);
    EXPECT_STREQ(error.what(),
                 "bundle 'decay.simb' was not compiled for distributed runs: "
                 "compile it with sim-translate --sim-distributed");
  }
  // CUDA takes a distributed plan like the CPU: what stops it here is what
  // CUDA lacks (no PTX in the hand-written bundle, or no driver), not the
  // communicator.
  auto bundle = ring(Boundary::Wrap);
  sim_session_options cuda = ringOptions(4, world.communicator(0));
  cuda.backend = SIM_BACKEND_CUDA;
  try {
    Session session(bundle, cuda);
  } catch (const Error &error) {
    EXPECT_NE(error.status, SIM_ERROR_DISTRIBUTED) << error.what();
  }
  // The reference executor follows every item in one process.
  sim_session_options reference = ringOptions(4, world.communicator(0));
  reference.backend = SIM_BACKEND_REFERENCE;
  try {
    ReferenceSession session(decay, reference);
    FAIL() << "no error";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_DISTRIBUTED);
    EXPECT_STREQ(error.what(),
                 "the reference executor runs on one process and takes no "
                 "communicator; distributed runs use the plan executor");
  }
}

TEST(Distributed, VerifierChecksTheRecords) {
  auto expectBad = [](schema::BundleT contents, const std::string &message) {
    try {
      parseBytes(serialize(contents), "ring.simb");
      ADD_FAILURE() << "no error for: " << message;
    } catch (const Error &error) {
      EXPECT_EQ(error.status, SIM_ERROR_BUNDLE);
      EXPECT_NE(std::string(error.what()).find(message), std::string::npos)
          << error.what();
    }
  };
  schema::BundleT contents = ringContents(Boundary::Wrap);
  contents.plans[0]->buffers[0]->halo_above = 3;
  expectBad(std::move(contents), "buffer 'X' has a halo of 2 below and 3 "
                                 "above, wider than the plan's halo of 2");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->distributed.reset();
  contents.plans[0]->buffers[0]->halo_below = 0;
  contents.plans[0]->buffers[0]->halo_above = 0;
  expectBad(std::move(contents), "passes the block's first item, but the plan "
                                 "is not distributed");
  contents = ringContents(Boundary::Wrap);
  auto &step = contents.plans[0]->phases[1]->body;
  step[1]->launch->reduce_min = {16};
  expectBad(std::move(contents), "all-reduces clock slot 16, but the plan's "
                                 "clock has 16 slots");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange = {
      schema::Exchange(1, false)};
  expectBad(std::move(contents), "an exchanged buffer is 1, but there are "
                                 "only 1");
  contents = ringContents(Boundary::Wrap, true);
  contents.plans[0]->buffers[1]->halo_below = 1;
  expectBad(std::move(contents), "buffer 'Y' is replicated and has a halo (1 "
                                 "below, 0 above)");
  contents = ringContents(Boundary::Wrap, true);
  contents.plans[0]->distributed.reset();
  contents.plans[0]->buffers[0]->halo_below = 0;
  contents.plans[0]->buffers[0]->halo_above = 0;
  expectBad(std::move(contents),
            "buffer 'Y' is replicated, but the plan is not distributed");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange = {
      schema::Exchange(0, true)};
  expectBad(std::move(contents), "exchanges the snapshot of buffer 'X', "
                                 "which has none");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange_targets = {5};
  expectBad(std::move(contents), "a buffer whose target half it exchanges is "
                                 "5, but there are only");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange.clear();
  contents.plans[0]->phases[1]->body[2]->launch->exchange_targets = {0, 0};
  expectBad(std::move(contents), "exchanges buffer 'X' twice");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[1]->launch->reduce_max_levels = {7};
  expectBad(std::move(contents), "a component whose levels it all-reduces "
                                 "is 7, but there are only");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[1]->launch->reduce_max_levels = {0};
  expectBad(std::move(contents), "all-reduces the levels of component 'Mix', "
                                 "which does not take local time steps");
  // A level reach: only a component with levels has one.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->components[0]->level_reach = 5;
  expectBad(std::move(contents),
            "component 'Mix' has a level reach, but only a component that "
            "takes local time steps in a distributed plan has one");
  // Kept levels: only a component with levels keeps them.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->components[0]->keeps_levels = true;
  expectBad(std::move(contents),
            "component 'Mix' keeps its levels, but only a component that "
            "takes local time steps has levels");
  // A largest estimate: only a pair's writer that estimates has one, and
  // it has one.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->components[0]->largest_estimate = 3;
  expectBad(std::move(contents),
            "component 'Mix' has a largest estimate, but only a pair's writer "
            "that estimates the big step has one");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->components[0]->keeps_estimate = true;
  expectBad(std::move(contents), "component 'Mix' keeps its estimate, but has "
                                 "no largest estimate");
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->components[0]->advance = Advance::LocalFlux;
  contents.plans[0]->components[0]->estimates = true;
  expectBad(std::move(contents),
            "component 'Mix' estimates the big step as a pair's writer, but "
            "has no clock slots for its largest estimate");
  // The half a sub-step wrote: only a grid-wide sub-step's launch has one.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange.clear();
  contents.plans[0]->phases[1]->body[2]->launch->exchange_sub_step = {0};
  expectBad(std::move(contents),
            "exchanges the half a sub-step wrote, but it is not a launch of a "
            "component that takes grid-wide sub-steps");
  // The blocks a slot wrote: only a local time step's slot launch, in a
  // repeat, passing its component's levels, has them.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange.clear();
  contents.plans[0]->phases[1]->body[2]->launch->exchange_local_step = {0};
  expectBad(std::move(contents),
            "exchanges the blocks a slot wrote, but it is not a slot launch "
            "(in a repeat) of a component that takes local time steps");
  // The blocks a slot's fluxes are due in: only a flux writer's slot
  // launch, in a repeat, passing the levels of its reader, has them.
  contents = ringContents(Boundary::Wrap);
  contents.plans[0]->phases[1]->body[2]->launch->exchange.clear();
  contents.plans[0]->phases[1]->body[2]->launch->exchange_local_flux = {0};
  expectBad(std::move(contents),
            "exchanges the blocks a slot's fluxes are due in, but it is not a "
            "slot launch (in a repeat) of a flux writer passing the levels of "
            "one component that takes local time steps");
}

/// mpirun -n N sim-run --distributed against sim-run on one process: the
/// --dump files and the counters of --json.
TEST(Distributed, SimRunWithMpirun) {
  if (std::system("command -v mpirun > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "no mpirun";
  std::string dir = makeTempDir();
  std::string bundlePath = dir + "/ring.simb";
  writeFile(bundlePath, serialize(ringContents(Boundary::Wrap)));
  auto run = [&](const std::string &prefix, const std::string &name,
                 const std::string &extra) {
    std::string out = dir + "/" + name;
    std::string command = prefix + " " + SIM_RUN_PATH + " " + bundlePath +
                          " --strategy hip --steps 41 --set range=37 "
                          "--threads 1 --no-init-check --dump " +
                          out + " --json " + out + ".json " + extra + " > " +
                          out + ".log 2>&1";
    return std::system(command.c_str());
  };
  // In a sanitizer build (utils/sanitize.sh) the ranks leave Open MPI's own
  // allocations to LeakSanitizer: utils/lsan-openmpi.supp suppresses them
  // and says why the other two settings (which nothing else reads).
  std::string mpirun = "env OMPI_ALLOW_RUN_AS_ROOT=1 "
                       "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
                       "LSAN_OPTIONS=suppressions=" SIM_TEST_LSAN_OPENMPI
                       ":fast_unwind_on_malloc=0 "
                       "OMPI_MCA_mca_component_disable_dlclose=1 mpirun "
                       "--oversubscribe -n ";
  ASSERT_EQ(run("", "one", "--backend cpu"), 0) << readFile(dir + "/one.log");
  for (int ranks : {2, 3}) {
    std::string name = "ranks" + std::to_string(ranks);
    ASSERT_EQ(run(mpirun + std::to_string(ranks), name, "--distributed"), 0)
        << readFile(dir + "/" + name + ".log");
    EXPECT_EQ(readFile(dir + "/one/X.npy"),
              readFile(dir + "/" + name + "/X.npy"));
    std::string json = readFile(dir + "/" + name + ".json");
    EXPECT_NE(json.find("\"ranks\": " + std::to_string(ranks)),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"halo_exchanges\""), std::string::npos);
    std::string log = readFile(dir + "/" + name + ".log");
    EXPECT_NE(log.find("halo exchanges"), std::string::npos) << log;
  }
  // Checkpoints: 3 ranks write the file one process writes, and 2 ranks
  // restart from it to the values of one run.
  auto steps = [&](const std::string &prefix, const std::string &args) {
    std::string command = prefix + " " + SIM_RUN_PATH + " " + bundlePath +
                          " --strategy hip --set range=37 --threads 1 "
                          "--no-init-check " +
                          args + " > " + dir + "/steps.log 2>&1";
    return std::system(command.c_str());
  };
  ASSERT_EQ(
      steps("", "--backend cpu --steps 17 --checkpoint " + dir + "/one.ckpt"),
      0);
  ASSERT_EQ(steps(mpirun + "3", "--distributed --steps 17 --checkpoint " + dir +
                                    "/three.ckpt"),
            0)
      << readFile(dir + "/steps.log");
  EXPECT_EQ(readFile(dir + "/one.ckpt"), readFile(dir + "/three.ckpt"));
  ASSERT_EQ(steps(mpirun + "2", "--distributed --steps 41 --restart " + dir +
                                    "/three.ckpt --dump " + dir + "/restart"),
            0)
      << readFile(dir + "/steps.log");
  EXPECT_EQ(readFile(dir + "/one/X.npy"), readFile(dir + "/restart/X.npy"));

  // Too many ranks: every rank fails, nothing hangs.
  std::string log;
  int status = run(mpirun + "3", "bad", "--distributed --group-size 32");
  EXPECT_NE(status, 0);
  log = readFile(dir + "/bad.log");
  // Rank 0 says it, once.
  EXPECT_NE(log.find("sim-run: rank 0: 3 ranks for a range of 2 groups of 32 "
                     "items: use at most 2 ranks or a smaller group size"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find("sim-run: rank 1:"), std::string::npos) << log;
  EXPECT_EQ(log.find("sim-run: rank 2:"), std::string::npos) << log;

  // A bundle made for one process.
  writeFile(dir + "/decay.simb", decayBundle());
  status =
      std::system((mpirun + "2 " + SIM_RUN_PATH + " " + dir +
                   "/decay.simb --distributed > " + dir + "/decay.log 2>&1")
                      .c_str());
  EXPECT_NE(status, 0);
  log = readFile(dir + "/decay.log");
  EXPECT_NE(log.find("sim-run: rank 0: bundle '" + dir +
                     "/decay.simb' was not compiled for distributed runs: "
                     "compile it with sim-translate --sim-distributed"),
            std::string::npos)
      << log;
}

} // namespace
