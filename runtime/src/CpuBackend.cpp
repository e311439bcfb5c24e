//===- CpuBackend.cpp - running the CPU shared object of a bundle ---------===//
//
// The CPU section of a bundle is an ELF shared object exporting
// `sim_cpu_<kernel>(params, first_group, end_group, group_size)`
// (docs/Bundle.md), loaded from memory (SharedObject.h). An `items` launch
// splits its groups into contiguous ranges, a few per thread, dealt to a
// small pool of threads in turn (thread t runs ranges t, t + threads, ...):
// the work of a range can differ (under lts a stiff region's groups
// evaluate at every slot and the others seldom), and a thread keeps the
// same ranges, and so the same data in its caches, from launch to launch;
// the kernels update the clock with atomics, so concurrent disjoint ranges
// are what the ABI promises to support. Launches are synchronous, which
// makes reads, writes and timing trivial.
//
//===----------------------------------------------------------------------===//

#include "Backend.h"
#include "Error.h"
#include "Executor.h"
#include "FloatMode.h"
#include "LaunchSplit.h"
#include "SharedObject.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <system_error>
#include <thread>

#if defined(__x86_64__)
#include <cpuid.h>
#include <x86intrin.h>
#endif

namespace sim::rt {

namespace {

/// The clock of the kernel time: a launch reads it twice, and a run of
/// local time steps launches about once per base step, so its cost shows
/// (clock_gettime took about 28 ns on the machine of docs/benchmarks.md,
/// 4-8% of a heat rod's run under lts). On x86-64 with an invariant time
/// stamp counter (one rate on every core, whatever the frequency) it reads
/// the counter (about 11 ns), and converts ticks into seconds at the rate
/// measured against steady_clock since the backend was made; elsewhere it
/// is steady_clock.
class LaunchClock {
public:
  LaunchClock()
      : counter(hasInvariantCounter()), firstTicks(ticks()),
        firstTime(std::chrono::steady_clock::now()) {}

  uint64_t ticks() const {
#if defined(__x86_64__)
    if (counter)
      return __rdtsc();
#endif
    return uint64_t(std::chrono::duration_cast<std::chrono::nanoseconds>(
                        std::chrono::steady_clock::now().time_since_epoch())
                        .count());
  }

  /// Seconds per tick, as measured now.
  double secondsPerTick() const {
    if (!counter)
      return 1e-9;
    uint64_t sinceFirst = ticks() - firstTicks;
    double time = std::chrono::duration<double>(
                      std::chrono::steady_clock::now() - firstTime)
                      .count();
    return sinceFirst == 0 ? 0.0 : time / double(sinceFirst);
  }

private:
  static bool hasInvariantCounter() {
#if defined(__x86_64__)
    unsigned eax, ebx, ecx, edx;
    // CPUID 0x80000007, EDX bit 8: the counter runs at one rate in every
    // power state.
    return __get_cpuid(0x80000007, &eax, &ebx, &ecx, &edx) &&
           (edx & (1u << 8)) != 0;
#else
    return false;
#endif
  }

  bool counter;
  uint64_t firstTicks;
  std::chrono::steady_clock::time_point firstTime;
};

/// The largest group the CPU kernels take, and the most worker threads.
constexpr int64_t kMaxGroupSize = 4096;
constexpr int kMaxThreads = kMaxCpuThreads;

using KernelFn = void (*)(void **params, int64_t firstGroup, int64_t endGroup,
                          int64_t groupSize);

/// Runs a range of groups split over a fixed set of threads, the calling
/// thread included. One job at a time. Between jobs a worker first spins
/// for a few microseconds on the job counter, then sleeps on a condition
/// variable; the caller waits for the others the same way. Waking a
/// sleeping thread costs tens of microseconds (a futex round trip), more
/// than a small scene's whole kernel, and a run launches kernels back to
/// back, so most wake-ups find the thread still spinning.
class ThreadPool {
public:
  explicit ThreadPool(int threads) {
    if (threads < 1 || threads > kMaxThreads)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           std::to_string(threads) +
               " CPU threads: the CPU backend takes 1 to " +
               std::to_string(kMaxThreads));
    try {
      for (int i = 1; i < threads; ++i)
        workers.emplace_back([this, i] { work(i); });
    } catch (const std::system_error &error) {
      // A constructor that throws runs no destructor: stop the workers
      // started so far, or their std::thread objects terminate the process.
      stop();
      fail(SIM_ERROR_BACKEND, "cannot start " + std::to_string(threads) +
                                  " CPU threads (" + error.what() +
                                  "); ask for fewer");
    }
  }
  ~ThreadPool() { stop(); }

  int size() const { return int(workers.size()) + 1; }

  /// Calls `fn(params, first, end, groupSize)` on disjoint ranges covering
  /// groups `offset .. offset + groups` and returns when all are done: the
  /// ranges of LaunchSplit::partsFor (finer where the kernel's work is
  /// `uneven`), dealt to the threads that take part (the caller is thread
  /// 0) in turn. Groups are independent and the
  /// clock's counters are integer atomics, so which thread runs which range
  /// changes no result.
  /// With `flushSubnormals`, every part runs with subnormals flushed to
  /// zero (SubnormalScope).
  void run(KernelFn fn, void **params, int64_t groups, int64_t groupSize,
           bool flushSubnormals, int64_t offset = 0, bool uneven = false) {
    int64_t threads = std::min<int64_t>(size(), groups);
    if (threads <= 1) {
      SubnormalScope mode(flushSubnormals);
      fn(params, offset, offset + groups, groupSize);
      return;
    }
    int64_t parts = LaunchSplit::partsFor(groups, threads, uneven);
    {
      std::lock_guard<std::mutex> lock(mutex);
      job = {fn,    params,          groups, groupSize,
             parts, flushSubnormals, offset, threads};
      pending.store(int(threads) - 1, std::memory_order_relaxed);
      // Publishes the job to the spinning workers (acquire in work()).
      generation.fetch_add(1, std::memory_order_release);
    }
    wake.notify_all();
    runParts(0);
    if (spinUntil(
            [this] { return pending.load(std::memory_order_acquire) == 0; }))
      return;
    std::unique_lock<std::mutex> lock(mutex);
    done.wait(lock,
              [this] { return pending.load(std::memory_order_acquire) == 0; });
  }

private:
  void stop() {
    {
      std::lock_guard<std::mutex> lock(mutex);
      stopping.store(true, std::memory_order_release);
    }
    wake.notify_all();
    for (std::thread &worker : workers)
      worker.join();
    workers.clear();
  }

  struct Job {
    KernelFn fn;
    void **params;
    int64_t groups, groupSize, parts;
    bool flushSubnormals;
    int64_t offset;
    /// The threads that take part, the caller included.
    int64_t threads;
  };

  /// Runs the job's parts dealt to thread `thread`.
  void runParts(int64_t thread) {
    SubnormalScope mode(job.flushSubnormals);
    for (int64_t part = thread; part < job.parts; part += job.threads) {
      int64_t first = job.offset + job.groups * part / job.parts;
      int64_t end = job.offset + job.groups * (part + 1) / job.parts;
      job.fn(job.params, first, end, job.groupSize);
    }
  }

  /// Spins until `ready()` holds or about 20 microseconds have passed;
  /// returns whether it holds.
  template <typename Ready> static bool spinUntil(Ready &&ready) {
    for (int i = 0; i < kSpins; ++i) {
      if (ready())
        return true;
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
    return ready();
  }

  void work(int index) {
    uint64_t seen = 0;
    for (;;) {
      auto changed = [&] {
        return stopping.load(std::memory_order_acquire) ||
               generation.load(std::memory_order_acquire) != seen;
      };
      spinUntil(changed);
      // The job and its counter under the lock, as one snapshot: the caller
      // may already be filling in the next job for the workers that take
      // no part in this one.
      std::unique_lock<std::mutex> lock(mutex);
      wake.wait(lock, changed);
      if (stopping.load(std::memory_order_relaxed))
        return;
      seen = generation.load(std::memory_order_relaxed);
      bool mine = index < job.threads;
      lock.unlock();
      if (!mine)
        continue;
      runParts(index);
      if (pending.fetch_sub(1, std::memory_order_acq_rel) == 1) {
        // The caller may be asleep on `done`: take the lock so that it
        // either sees the count or is already waiting when notified.
        std::lock_guard<std::mutex> lock(mutex);
        done.notify_one();
      }
    }
  }

  std::vector<std::thread> workers;
  std::mutex mutex;
  std::condition_variable wake, done;
  Job job{};
  /// About 20 microseconds of spinning (a pause is some tens of cycles).
  static constexpr int kSpins = 1 << 11;
  std::atomic<int> pending{0};
  std::atomic<uint64_t> generation{0};
  std::atomic<bool> stopping{false};
};

class CpuBackend final : public Backend {
public:
  explicit CpuBackend(int threads)
      : pool(threads > 0
                 ? threads
                 : std::clamp<int>(int(std::thread::hardware_concurrency()), 1,
                                   kMaxThreads)) {}

  sim_backend kind() const override { return SIM_BACKEND_CPU; }

  std::string device() const override {
    return "CPU (" + std::to_string(pool.size()) +
           (pool.size() == 1 ? " thread" : " threads") +
           (isa.empty() ? "" : ", " + isa) + ")";
  }

  int64_t memoryBytes() const override { return physicalMemoryBytes(); }

  void checkGroupSize(int64_t groupSize) const override {
    // A kernel keeps per-lane variables of a group on its thread's stack.
    if (groupSize < 1 || groupSize > kMaxGroupSize)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "group size " + std::to_string(groupSize) +
               " is not between 1 and " + std::to_string(kMaxGroupSize) +
               ", as the CPU backend needs");
  }

  void load(const Bundle &bundle, const schema::PlanT &plan) override {
    std::string what = std::string("the CPU kernels of strategy '") +
                       strategyName(plan.strategy) + "'";
    const schema::CpuCodeT *code = bundle.cpuCode(plan);
    if (!code)
      fail(SIM_ERROR_BUNDLE, "cannot load " + what + " of bundle '" +
                                 bundle.name + "': " + missingIsaMessage(plan));
    isa = code->isa;
    flushSubnormals = bundle.flushesSubnormals();
    library = std::make_unique<SharedObject>(code->object, what);
    for (const auto &kernel : plan.kernels) {
      std::string symbol = "sim_cpu_" + kernel->name;
      void *address = library->find(symbol);
      if (!address)
        fail(SIM_ERROR_BACKEND, what + " do not export " + symbol +
                                    " (kernel '" + kernel->name +
                                    "' of the plan)");
      kernels.push_back(reinterpret_cast<KernelFn>(address));
      unevenGroups.push_back(kernel->uneven_groups);
    }
  }

  DevicePtr allocate(size_t bytes) override {
    // 64-byte alignment: a cache line, and enough for any vector element.
    void *memory =
        std::aligned_alloc(64, (std::max<size_t>(bytes, 1) + 63) / 64 * 64);
    if (!memory)
      fail(SIM_ERROR_BACKEND, "cannot allocate " + std::to_string(bytes) +
                                  " bytes of host memory");
    std::memset(memory, 0, bytes);
    return reinterpret_cast<DevicePtr>(memory);
  }
  void release(DevicePtr memory) override {
    std::free(reinterpret_cast<void *>(memory));
  }
  void zero(DevicePtr memory, size_t bytes) override {
    std::memset(reinterpret_cast<void *>(memory), 0, bytes);
  }
  void write(DevicePtr to, const void *from, size_t bytes) override {
    std::memcpy(reinterpret_cast<void *>(to), from, bytes);
  }
  void read(void *to, DevicePtr from, size_t bytes) override {
    std::memcpy(to, reinterpret_cast<const void *>(from), bytes);
  }
  void copy(DevicePtr to, DevicePtr from, size_t bytes) override {
    std::memcpy(reinterpret_cast<void *>(to),
                reinterpret_cast<const void *>(from), bytes);
  }

  void launch(int kernel, void **params, int64_t groups, int64_t groupSize,
              int64_t) override {
    // Workgroup memory is the object's business on the CPU: the ABI passes
    // no shared-memory size.
    run(kernel, params, 0, groups, groupSize);
  }

  bool launchesSynchronously() const override { return true; }
  bool launchesGroupRanges() const override { return true; }
  void launchGroups(int kernel, void **params, int64_t firstGroup,
                    int64_t groups, int64_t groupSize) override {
    run(kernel, params, firstGroup, groups, groupSize);
  }

  void startTimer() override {
    kernelTicks = 0;
    ticksPerKernel.assign(kernels.size(), 0);
  }
  double stopTimer() override {
    // One rate for the run and its kernels, so that theirs add up to it.
    timerSecondsPerTick = clock.secondsPerTick();
    return double(kernelTicks) * timerSecondsPerTick;
  }
  std::vector<double> kernelSeconds() const override {
    std::vector<double> seconds;
    seconds.reserve(ticksPerKernel.size());
    for (uint64_t ticks : ticksPerKernel)
      seconds.push_back(double(ticks) * timerSecondsPerTick);
    return seconds;
  }

private:
  /// Groups `first` to `first + groups` of a launch: on the calling
  /// thread alone when there is one group or one thread, or when the
  /// kernel's launches have run faster that way (LaunchSplit); else split
  /// over the pool.
  void run(int kernel, void **params, int64_t first, int64_t groups,
           int64_t groupSize) {
    uint64_t start = clock.ticks();
    LaunchSplit::Mode mode = LaunchSplit::Alone;
    if (groups > 1 && pool.size() > 1)
      mode = split.choose(size_t(kernel));
    if (mode == LaunchSplit::Alone) {
      SubnormalScope scope(flushSubnormals);
      kernels[kernel](params, first, first + groups, groupSize);
    } else {
      pool.run(kernels[kernel], params, groups, groupSize, flushSubnormals,
               first, unevenGroups[size_t(kernel)]);
    }
    uint64_t ticks = clock.ticks() - start;
    if (groups > 1 && pool.size() > 1)
      split.record(size_t(kernel), mode, ticks, groups);
    kernelTicks += ticks;
    if (size_t(kernel) < ticksPerKernel.size())
      ticksPerKernel[size_t(kernel)] += ticks;
  }

  ThreadPool pool;
  LaunchSplit split;
  std::unique_ptr<SharedObject> library;
  /// The instruction-set level of the loaded kernels ("x86-64-v3", ...).
  std::string isa;
  /// The bundle's floating-point mode (sim-translate --sim-ftz).
  bool flushSubnormals = false;
  std::vector<KernelFn> kernels;
  /// Per kernel: the bundle's Kernel.uneven_groups (LaunchSplit::partsFor).
  std::vector<bool> unevenGroups;
  LaunchClock clock;
  uint64_t kernelTicks = 0;
  /// kernelTicks by kernel (launches outside a timed run are not counted).
  std::vector<uint64_t> ticksPerKernel;
  /// The clock's rate when stopTimer converted kernelTicks.
  double timerSecondsPerTick = 0;
};

} // namespace

void checkCpuThreads(int64_t threads) {
  if (threads < 0 || threads > kMaxCpuThreads)
    fail(SIM_ERROR_INVALID_ARGUMENT,
         std::to_string(threads) + " CPU threads: the CPU backend takes 1 to " +
             std::to_string(kMaxCpuThreads) +
             ", or 0 for one per hardware thread (sim_session_options."
             "cpu_threads, sim-run --threads)");
}

std::unique_ptr<Backend> createCpuBackend(int threads) {
  checkCpuThreads(threads);
  return std::make_unique<CpuBackend>(threads);
}

} // namespace sim::rt
