//===- CudaTest.cpp - the CUDA backend without and with a GPU -------------===//
//
// Without a driver (as on the build machines) CUDA must fail with one clear
// line and `auto` must fall back to the CPU. The stub libcuda.so of the
// CUDA toolkit exercises the dlopen/dlsym table and cuInit's error path.
// With a GPU, the decay scene's hand-written PTX (kernels/decay.cu) must
// give the CPU backend's numbers bit for bit; without one those tests skip.
//
//===----------------------------------------------------------------------===//

#include "Bundle.h"
#include "CudaDriver.h"
#include "Error.h"
#include "Session.h"
#include "TestBundle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <sys/wait.h>
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

TEST(Cuda, DeviceCountSaysWhyThereAreNone) {
  int32_t count = -1;
  sim_status status = sim_cuda_device_count(&count);
  if (haveDriver()) {
    if (status == SIM_OK)
      EXPECT_GT(count, 0);
    else
      EXPECT_EQ(status, SIM_ERROR_NO_DEVICE) << sim_last_error();
    return;
  }
  EXPECT_EQ(status, SIM_ERROR_NO_DRIVER);
  EXPECT_STREQ(sim_last_error(), "no CUDA driver (libcuda.so.1 not found)");
  EXPECT_EQ(count, -1);
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

TEST(Cuda, TheToolkitsStubLibraryIsNoDriver) {
  // The stub answers every call with CUDA_ERROR_STUB_LIBRARY. The driver is
  // loaded once per process, so this runs in sim-run.
  const char *stub = "/usr/local/cuda/lib64/stubs/libcuda.so";
  if (access(stub, R_OK) != 0)
    GTEST_SKIP() << "no CUDA toolkit stub at " << stub;
  std::string dir = makeTempDir();
  std::string bundle = dir + "/decay.simb";
  writeFile(bundle, decayBundle(/*ptx=*/true));
  std::string command = std::string("SIM_CUDA_DRIVER=") + stub + " " +
                        SIM_RUN_PATH + " " + bundle +
                        " --backend cuda --steps 1 2>&1";
  FILE *pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  char line[1024] = {};
  std::string output;
  while (fgets(line, sizeof line, pipe))
    output += line;
  int status = pclose(pipe);
  EXPECT_EQ(WEXITSTATUS(status), 1) << output;
  EXPECT_EQ(output, std::string("sim-run: error: no CUDA driver (") + stub +
                        " is the stub library of the CUDA toolkit)\n");
  std::remove(bundle.c_str());
  rmdir(dir.c_str());
}

//===----------------------------------------------------------------------===//
// With a GPU: the decay scene's PTX (kernels/decay.cu) against the CPU
//===----------------------------------------------------------------------===//

namespace {

/// The decay sections with the committed PTX of decay.cu (or `ptx` for
/// both strategies).
std::shared_ptr<const Bundle> decayWithRealPtx(const std::string &ptx = "") {
  schema::BundleT contents = decayContents();
  for (auto [strategy, name] :
       {std::pair{Strategy::Simple, "simple"}, {Strategy::Hip, "hip"}}) {
    schema::PlanT &plan = planOf(contents, strategy);
    plan.ptx = ptx.empty() ? readFile(std::string(SIM_TEST_KERNELS_DIR) +
                                      "/decay-" + name + ".ptx")
                           : ptx;
    plan.ptx_chip = "sm_90";
  }
  std::string bytes = serialize(contents);
  return Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                       bytes.size(), "decay-gpu.simb");
}

/// A CUDA session, or null when there is no driver or device.
std::unique_ptr<Session> cudaSession(std::shared_ptr<const Bundle> bundle,
                                     sim_strategy strategy,
                                     sim_session_options options = {}) {
  options.strategy = strategy;
  options.backend = SIM_BACKEND_CUDA;
  try {
    return std::make_unique<Session>(std::move(bundle), options);
  } catch (const Error &error) {
    if (error.status == SIM_ERROR_NO_DRIVER ||
        error.status == SIM_ERROR_NO_DEVICE)
      return nullptr;
    throw;
  }
}

template <typename T> std::vector<T> get(Session &session, const char *buffer) {
  std::vector<T> values(session.hostBytes(buffer) / sizeof(T));
  session.getBuffer(buffer, values.data(), values.size() * sizeof(T));
  return values;
}

} // namespace

TEST(Cuda, RunsTheDecaySceneLikeTheCpu) {
  auto bundle = decayWithRealPtx();
  for (sim_strategy strategy : {SIM_STRATEGY_SIMPLE, SIM_STRATEGY_HIP})
    for (int graph : {0, 1}) {
      sim_session_options options{};
      options.cuda_graph = graph;
      std::unique_ptr<Session> gpu = cudaSession(bundle, strategy, options);
      if (!gpu)
        GTEST_SKIP() << "no CUDA driver or device";
      SCOPED_TRACE(std::string(strategyName(Strategy(strategy))) +
                   (graph ? " with a graph" : ""));
      sim_session_options cpuOptions{};
      cpuOptions.strategy = strategy;
      cpuOptions.backend = SIM_BACKEND_CPU;
      Session cpu(bundle, cpuOptions);
      for (Session *session : {gpu.get(), &cpu}) {
        session->set("range", "10000");
        session->run(53);
        session->run(20);
      }
      EXPECT_EQ(gpu->time(), 73);
      EXPECT_EQ(gpu->metrics.end, 73);
      EXPECT_EQ(get<double>(*gpu, "X"), get<double>(cpu, "X"));
      EXPECT_EQ(get<float>(*gpu, "V"), get<float>(cpu, "V"));
      EXPECT_EQ(gpu->histogram, cpu.histogram);
      EXPECT_EQ(gpu->evaluations, cpu.evaluations);
      EXPECT_EQ(gpu->metrics.big_steps, cpu.metrics.big_steps);
      EXPECT_EQ(gpu->metrics.launches, cpu.metrics.launches);
      EXPECT_EQ(gpu->metrics.graph_launches > 0, graph == 1);
      EXPECT_GT(gpu->metrics.kernel_seconds, 0);
      std::vector<double> exactGpu(10000), exactCpu(10000);
      gpu->exact("X", exactGpu.data(), exactGpu.size() * 8);
      cpu.exact("X", exactCpu.data(), exactCpu.size() * 8);
      for (size_t i = 0; i < exactGpu.size(); ++i)
        ASSERT_NEAR(exactGpu[i], exactCpu[i], 1e-15 * std::fabs(exactCpu[i]));
      // Host arrays go in, too.
      std::vector<double> x(10000, 1.0);
      gpu->setBuffer("X", x.data(), x.size() * 8);
      gpu->run(1);
      EXPECT_DOUBLE_EQ(get<double>(*gpu, "X")[9999], 1 - 2 * 0.01);
    }
}

TEST(Cuda, ChecksForNonFiniteValuesOnTheGpu) {
  sim_session_options options{};
  options.check_finite = 1;
  std::unique_ptr<Session> gpu =
      cudaSession(decayWithRealPtx(), SIM_STRATEGY_SIMPLE, options);
  if (!gpu)
    GTEST_SKIP() << "no CUDA driver or device";
  gpu->set("poison", "10");
  EXPECT_THROW(gpu->run(40), Error);
  EXPECT_TRUE(gpu->nonFinite.found);
  EXPECT_EQ(gpu->nonFinite.baseStep, 10);
  EXPECT_EQ(gpu->nonFinite.item, 7);
  EXPECT_EQ(gpu->nonFinite.component, "Decay");
}

TEST(Cuda, RejectsGroupSizesThatAreNotWarpMultiples) {
  sim_session_options options{};
  options.group_size = 48;
  try {
    if (!cudaSession(decayWithRealPtx(), SIM_STRATEGY_HIP, options))
      GTEST_SKIP() << "no CUDA driver or device";
    FAIL() << "group size 48 accepted";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(error.what())
                  .find("group size 48 is not a multiple "
                        "of 32"),
              std::string::npos);
  }
}

TEST(Cuda, RejectsAGroupSizeAboveAKernelsThreadLimit) {
  // Every entry of the real PTX limited to 64 threads, as a kernel with
  // many registers is: the driver says so, and a group of 128 is refused
  // before any launch fails.
  std::string ptx =
      readFile(std::string(SIM_TEST_KERNELS_DIR) + "/decay-hip.ptx");
  for (size_t entry = ptx.find(".entry"); entry != std::string::npos;
       entry = ptx.find(".entry", entry + 1)) {
    size_t body = ptx.find("\n{", entry);
    ASSERT_NE(body, std::string::npos);
    ptx.insert(body + 1, ".maxntid 64, 1, 1\n");
  }
  sim_session_options options{};
  options.group_size = 128;
  try {
    if (!cudaSession(decayWithRealPtx(ptx), SIM_STRATEGY_HIP, options))
      GTEST_SKIP() << "no CUDA driver or device";
    FAIL() << "group size 128 accepted for kernels of at most 64 threads";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_INVALID_ARGUMENT);
    EXPECT_NE(std::string(error.what())
                  .find("group size 128 is more than the 64 threads kernel"),
              std::string::npos)
        << error.what();
  }
  options.group_size = 64;
  EXPECT_NO_THROW(
      cudaSession(decayWithRealPtx(ptx), SIM_STRATEGY_HIP, options));
}

TEST(Cuda, RejectsCachesLargerThanTheGroupsSharedMemory) {
  // hip-cache's caches ask for shared memory per thread of a group: 4 KiB
  // per thread in groups of 256 is 1 MiB, more than any GPU gives a group.
  // The session says so when it is made, with the largest group that
  // fits, rather than failing at the first launch of the run.
  schema::BundleT contents = decayContents();
  schema::PlanT &plan = planOf(contents, Strategy::Hip);
  plan.ptx = readFile(std::string(SIM_TEST_KERNELS_DIR) + "/decay-hip.ptx");
  plan.ptx_chip = "sm_90";
  std::function<void(std::vector<std::unique_ptr<schema::StepT>> &)> widen =
      [&](std::vector<std::unique_ptr<schema::StepT>> &steps) {
        for (auto &step : steps) {
          if (step->launch && step->launch->shape != LaunchShape::Single) {
            step->launch->shared_per_thread = 4096;
            // The kernel's record says the same, as the verifier checks.
            plan.kernels[step->launch->kernel]->shared_per_thread = 4096;
          }
          if (step->repeat)
            widen(step->repeat->body);
        }
      };
  for (auto &phase : plan.phases)
    widen(phase->body);
  std::string bytes = serialize(contents);
  auto bundle = Bundle::parse(reinterpret_cast<const uint8_t *>(bytes.data()),
                              bytes.size(), "decay-shared.simb");
  sim_session_options options{};
  options.group_size = 256;
  try {
    if (!cudaSession(bundle, SIM_STRATEGY_HIP, options))
      GTEST_SKIP() << "no CUDA driver or device";
    FAIL() << "1 MiB of shared memory per group accepted";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_INVALID_ARGUMENT);
    std::string message = error.what();
    EXPECT_NE(message.find("bytes of shared memory in a group of 256"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("use --group-size 32 or less"), std::string::npos)
        << message;
  }
}

TEST(Cuda, ReportsAJitFailureWithTheDriversLog) {
  try {
    if (!cudaSession(decayWithRealPtx(".version 9.0\n.target sm_90\n"
                                      ".address_size 64\nthis is not PTX\n"),
                     SIM_STRATEGY_HIP))
      GTEST_SKIP() << "no CUDA driver or device";
    FAIL() << "broken PTX loaded";
  } catch (const Error &error) {
    EXPECT_EQ(error.status, SIM_ERROR_BACKEND);
    std::string message = error.what();
    EXPECT_NE(message.find("cannot JIT-compile the PTX of strategy 'hip'"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("cuModuleLoadDataEx failed: CUDA_ERROR_"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("JIT log:"), std::string::npos) << message;
  }
}

// The runtime counts a kernel's parameters from the PTX entry's declaration
// (asking the driver about a parameter past the last would be an API error
// that compute-sanitizer reports); no GPU needed.
TEST(Cuda, EntryParamCountReadsThePtxDeclaration) {
  std::string ptx = ".visible .entry substep_C10(\n"
                    "\t.param .u64 .ptr .align 1 substep_C10_param_0,\n"
                    "\t.param .u32 substep_C10_param_1\n)\n{\n}\n"
                    ".visible .entry substep_C1 (\n"
                    "\t.param .f64 substep_C1_param_0,\n"
                    "\t.param .u64 substep_C1_param_1,\n"
                    "\t.param .u64 substep_C1_param_2\n)\n{\n"
                    "\tld.param.f64 %fd1, [substep_C1_param_0];\n}\n"
                    ".visible .entry evaluate_none()\n{\n}\n";
  EXPECT_EQ(cuda::entryParamCount(ptx, "substep_C10"), 2u);
  EXPECT_EQ(cuda::entryParamCount(ptx, "substep_C1"), 3u);
  EXPECT_EQ(cuda::entryParamCount(ptx, "evaluate_none"), 0u);
  EXPECT_EQ(cuda::entryParamCount(ptx, "substep_C"), std::nullopt);
  EXPECT_EQ(cuda::entryParamCount(ptx + ".entry cut(", "cut"), std::nullopt);
}
