//===- CApiTest.cpp - runs the C test of the C API ------------------------===//

#include "TestBundle.h"
#include "sim/Runtime/sim_runtime.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

extern "C" int sim_c_api_test(const char *path, char *message, size_t capacity);

using namespace sim::test;

namespace {

/// The decay bundle written to a fresh folder and opened; closed and
/// removed again at the end of the test.
struct OpenDecayBundle {
  OpenDecayBundle() : dir(makeTempDir()), path(dir + "/decay.simb") {
    writeFile(path, decayBundle());
    if (sim_bundle_open(path.c_str(), &bundle) != SIM_OK)
      ADD_FAILURE() << sim_last_error();
  }
  ~OpenDecayBundle() {
    sim_bundle_close(bundle);
    std::remove(path.c_str());
    rmdir(dir.c_str());
  }
  std::string dir, path;
  sim_bundle *bundle = nullptr;
};

/// A session of `bundle` with the default options but these (null, and a
/// failure of the test, if it cannot be made).
sim_session *createSession(sim_bundle *bundle, sim_strategy strategy,
                           sim_backend backend) {
  sim_session_options options;
  sim_session_options_init(&options);
  options.strategy = strategy;
  options.backend = backend;
  sim_session *session = nullptr;
  if (sim_session_create(bundle, &options, &session) != SIM_OK)
    ADD_FAILURE() << sim_last_error();
  return session;
}

} // namespace

TEST(CApi, WorksFromC) {
  std::string dir = makeTempDir();
  std::string path = dir + "/decay.simb";
  writeFile(path, decayBundle());
  char message[1024];
  EXPECT_EQ(sim_c_api_test(path.c_str(), message, sizeof message), 0)
      << message;
  std::remove(path.c_str());
  rmdir(dir.c_str());
}

TEST(CApi, RefusesUnknownEnumerationValues) {
  // A C caller or ctypes may pass any int: each is a value of the
  // enumeration (a fixed type in C++; in a sanitizer build, utils/
  // sanitize.sh, reading one outside the range of an unfixed type is
  // reported as undefined), and the functions name or refuse it.
  for (int32_t value : {-1, 77, INT32_MIN, INT32_MAX}) {
    EXPECT_STREQ(sim_strategy_name(sim_strategy(value)), "unknown");
    EXPECT_STREQ(sim_status_name(sim_status(value)), "unknown status");
  }
  EXPECT_STREQ(sim_strategy_name(sim_strategy(5)), "unknown");
  EXPECT_STREQ(sim_backend_name(sim_backend(-1)), "unknown");
  OpenDecayBundle decay;
  sim_bundle *bundle = decay.bundle;
  ASSERT_NE(bundle, nullptr);
  EXPECT_EQ(sim_bundle_has_strategy(bundle, sim_strategy(-1)), 0);
  sim_session_options options;
  sim_session_options_init(&options);
  sim_session *session = nullptr;
  options.strategy = sim_strategy(77);
  EXPECT_EQ(sim_session_create(bundle, &options, &session),
            SIM_ERROR_INVALID_ARGUMENT);
  options.strategy = SIM_STRATEGY_SIMPLE;
  options.backend = sim_backend(-9);
  EXPECT_EQ(sim_session_create(bundle, &options, &session),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(session, nullptr);
}

TEST(CApi, RefusesCpuThreadCountsOutsideTheBackendsRange) {
  // cpu_threads 0 is one thread per hardware thread; a negative value was
  // taken as that too, silently, and a huge one started that many threads
  // (or failed on the CPU only). Every backend refuses both, naming the
  // value and the range, before it starts anything.
  OpenDecayBundle decay;
  sim_bundle *bundle = decay.bundle;
  ASSERT_NE(bundle, nullptr);
  for (sim_backend backend :
       {SIM_BACKEND_CPU, SIM_BACKEND_AUTO, SIM_BACKEND_REFERENCE})
    for (int32_t threads : {-1, INT32_MIN, 1025, INT32_MAX}) {
      sim_session_options options;
      sim_session_options_init(&options);
      options.strategy = SIM_STRATEGY_SIMPLE;
      options.backend = backend;
      options.cpu_threads = threads;
      sim_session *session = nullptr;
      EXPECT_EQ(sim_session_create(bundle, &options, &session),
                SIM_ERROR_INVALID_ARGUMENT)
          << sim_backend_name(backend) << " " << threads;
      EXPECT_EQ(session, nullptr);
      EXPECT_NE(std::string(sim_last_error())
                    .find(std::to_string(threads) +
                          " CPU threads: the CPU backend takes 1 to 1024, or "
                          "0 for one per hardware thread"),
                std::string::npos)
          << sim_last_error();
    }
  // 0 (all) and a count are taken.
  for (int32_t threads : {0, 2}) {
    sim_session_options options;
    sim_session_options_init(&options);
    options.strategy = SIM_STRATEGY_SIMPLE;
    options.backend = SIM_BACKEND_CPU;
    options.cpu_threads = threads;
    sim_session *session = nullptr;
    EXPECT_EQ(sim_session_create(bundle, &options, &session), SIM_OK)
        << threads << ": " << sim_last_error();
    sim_session_destroy(session);
  }
}

namespace {

/// What the progress callback of CApi.ReadsButDoesNotChangeARunningSession
/// tried, and the statuses it got.
struct CallbackCalls {
  sim_session *session = nullptr;
  bool destroy = false;
  int calls = 0;
  std::vector<std::pair<std::string, sim_status>> statuses;
  std::string lastMessage;
  sim_status readStatus = SIM_OK;
};

void changeFromCallback(void *user, int64_t, int64_t) {
  auto &calls = *static_cast<CallbackCalls *>(user);
  if (calls.calls++ > 0)
    return;
  sim_session *session = calls.session;
  if (calls.destroy) {
    sim_session_destroy(session);
    return;
  }
  // Reading is allowed between host synchronisations.
  size_t bytes = 0;
  calls.readStatus = sim_session_buffer_bytes(session, "X", &bytes);
  std::vector<char> data(bytes);
  if (calls.readStatus == SIM_OK)
    calls.readStatus =
        sim_session_get_buffer(session, "X", data.data(), data.size());
  // Changing is not: each would leave the running loop stepping a state
  // that is gone or another run's.
  calls.statuses.emplace_back("set", sim_session_set(session, "range", "64"));
  calls.lastMessage = sim_last_error();
  calls.statuses.emplace_back(
      "set_buffer",
      sim_session_set_buffer(session, "X", data.data(), data.size()));
  calls.statuses.emplace_back("init", sim_session_init(session));
  calls.statuses.emplace_back("run", sim_session_run(session, 4));
  calls.statuses.emplace_back("run_pausing",
                              sim_session_run_pausing(session, 4, 2));
  calls.statuses.emplace_back("checkpoint",
                              sim_session_checkpoint(session, "/dev/null"));
  calls.statuses.emplace_back("restart",
                              sim_session_restart(session, "/dev/null"));
}

} // namespace

TEST(CApi, ReadsButDoesNotChangeARunningSession) {
  OpenDecayBundle decay;
  sim_bundle *bundle = decay.bundle;
  ASSERT_NE(bundle, nullptr);
  for (sim_backend backend : {SIM_BACKEND_CPU, SIM_BACKEND_REFERENCE}) {
    SCOPED_TRACE(sim_backend_name(backend));
    sim_session_options options;
    sim_session_options_init(&options);
    options.strategy = SIM_STRATEGY_HIP;
    options.backend = backend;
    for (bool destroy : {false, true}) {
      sim_session *session = nullptr;
      ASSERT_EQ(sim_session_create(bundle, &options, &session), SIM_OK)
          << sim_last_error();
      CallbackCalls calls;
      calls.session = session;
      calls.destroy = destroy;
      sim_session_set_progress(session, &changeFromCallback, &calls);
      sim_status status = sim_session_run(session, 200);
      EXPECT_GT(calls.calls, 0);
      if (destroy) {
        // The run stopped and took the session with it.
        EXPECT_EQ(status, SIM_ERROR_INTERRUPTED);
        EXPECT_NE(std::string(sim_last_error())
                      .find("the session was destroyed during its run"),
                  std::string::npos)
            << sim_last_error();
        continue;
      }
      EXPECT_EQ(status, SIM_OK) << sim_last_error();
      EXPECT_EQ(calls.readStatus, SIM_OK);
      for (auto &[call, callStatus] : calls.statuses)
        EXPECT_EQ(callStatus, SIM_ERROR_INVALID_ARGUMENT) << call;
      EXPECT_EQ(calls.lastMessage,
                "sim_session_set: the session's run is in progress (a "
                "progress callback may read the session or interrupt the "
                "run, not change it)");
      // The run went on as if nothing had been asked, and the session is
      // usable afterwards.
      EXPECT_EQ(sim_session_time(session), 200);
      EXPECT_EQ(sim_session_set(session, "range", "64"), SIM_OK)
          << sim_last_error();
      sim_session_destroy(session);
    }
  }
}

TEST(CApi, ProfilesTheKernelsOfTheLastRun) {
  // Per kernel of the plan: its launches in the last run and, on the CPU
  // (which times every launch), their kernel time. The launches add up to
  // the run's, the times to its kernel time; the reference executor has no
  // kernels.
  OpenDecayBundle decay;
  sim_bundle *bundle = decay.bundle;
  ASSERT_NE(bundle, nullptr);
  for (sim_strategy strategy : {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP}) {
    sim_session *session = createSession(bundle, strategy, SIM_BACKEND_CPU);
    ASSERT_NE(session, nullptr);
    int32_t kernels = sim_session_num_kernels(session);
    ASSERT_GT(kernels, 0);
    for (int64_t steps : {int64_t(25), int64_t(7), int64_t(0)}) {
      ASSERT_EQ(sim_session_run(session, steps), SIM_OK) << sim_last_error();
      sim_metrics metrics;
      ASSERT_EQ(sim_session_metrics(session, &metrics), SIM_OK);
      int64_t launches = 0;
      double seconds = 0;
      for (int32_t k = 0; k < kernels; ++k) {
        sim_kernel_profile profile;
        ASSERT_EQ(sim_session_kernel_profile(session, k, &profile), SIM_OK)
            << sim_last_error();
        ASSERT_NE(profile.name, nullptr);
        EXPECT_GT(std::string(profile.name).size(), 0u);
        EXPECT_GE(profile.launches, 0);
        EXPECT_GE(profile.seconds, 0) << profile.name;
        launches += profile.launches;
        seconds += profile.seconds;
      }
      EXPECT_EQ(launches, metrics.launches) << steps;
      EXPECT_NEAR(seconds, metrics.kernel_seconds,
                  1e-9 + 1e-9 * metrics.kernel_seconds)
          << steps;
      if (steps > 0)
        EXPECT_GT(launches, 0);
    }
    sim_kernel_profile profile;
    EXPECT_EQ(sim_session_kernel_profile(session, kernels, &profile),
              SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(sim_last_error()).find("the session's plan has"),
              std::string::npos)
        << sim_last_error();
    EXPECT_EQ(sim_session_kernel_profile(session, -1, &profile),
              SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_EQ(sim_session_kernel_profile(session, 0, nullptr),
              SIM_ERROR_INVALID_ARGUMENT);
    sim_session_destroy(session);
  }
  sim_session *reference =
      createSession(bundle, SIM_STRATEGY_SIMPLE, SIM_BACKEND_REFERENCE);
  ASSERT_NE(reference, nullptr);
  ASSERT_EQ(sim_session_run(reference, 5), SIM_OK) << sim_last_error();
  EXPECT_EQ(sim_session_num_kernels(reference), 0);
  sim_kernel_profile profile;
  EXPECT_EQ(sim_session_kernel_profile(reference, 0, &profile),
            SIM_ERROR_INVALID_ARGUMENT);
  EXPECT_EQ(sim_session_num_kernels(nullptr), 0);
  sim_session_destroy(reference);
}
