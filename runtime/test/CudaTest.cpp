//===- CudaTest.cpp - the CUDA backend without a GPU ----------------------===//
//
// Without a driver (as on the build machines) CUDA must fail with one clear
// line and `auto` must fall back to the CPU.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "Error.h"
#include "Session.h"
#include "TestBundle.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <dlfcn.h>
#include <unistd.h>

using namespace sim::rt;
using namespace sim::test;

namespace {

/// Whether libcuda.so.1 can be loaded at all (a driver is installed).
bool haveDriver() {
  if (const char *override = std::getenv("SIM_CUDA_DRIVER");
      override && *override)
    return true;
  void *library = dlopen("libcuda.so.1", RTLD_NOW | RTLD_LOCAL);
  return library != nullptr;
}

std::shared_ptr<const Bundle> decayWithPtx() {
  std::string bytes = decayBundle(/*ptx=*/true);
  return Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                       bytes.size(), "decay-ptx.simb");
}

sim_session_options options(sim_backend backend) {
  sim_session_options options;
  sim_session_options_init(&options);
  options.backend = backend;
  return options;
}

} // namespace

TEST(Cuda, WithoutADriverFailsWithOneClearLine) {
  if (haveDriver())
    GTEST_SKIP() << "a CUDA driver is installed";
  try {
    Session session(decayWithPtx(), options(SIM_BACKEND_CUDA));
    FAIL() << "the CUDA backend started without a driver";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_NO_DRIVER);
    EXPECT_STREQ(error.what(), "no CUDA driver (libcuda.so.1 not found)");
  }
}

TEST(Cuda, AutoFallsBackToTheCpuWithoutADriver) {
  if (haveDriver())
    GTEST_SKIP() << "a CUDA driver is installed";
  Session session(decayWithPtx(), options(SIM_BACKEND_AUTO));
  EXPECT_EQ(session.backendKind(), SIM_BACKEND_CPU);
  EXPECT_EQ(session.backendNote(), "no CUDA driver (libcuda.so.1 not found)");
  session.run(10);
  EXPECT_EQ(session.time(), 10);
}
