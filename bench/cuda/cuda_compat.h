//===- cuda_compat.h - CUDA, or a faithful emulation of it on the host ----===//
//
// The hand-written baseline is one CUDA source. nvcc compiles it for the GPU
// (sim-baseline-cuda); any C++20 compiler compiles the same source for the
// host (sim-baseline-host), where this header emulates what the kernels use:
// a launch runs the blocks one after another, each with one host thread per
// CUDA thread (a pool), so __syncthreads is a real barrier, __shared__
// memory is shared by the block's threads, and atomics are atomic. The host
// build is slow and exists to check the kernels' numbers against sim's CPU
// backend in CI, bit for bit, on a machine without a GPU.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_CUDA_COMPAT_H
#define SIM_BENCH_CUDA_COMPAT_H

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#ifdef __CUDACC__
#include <cuda_runtime.h>

#define SIM_CHECK_CUDA(call)                                                   \
  do {                                                                         \
    cudaError_t status_ = (call);                                              \
    if (status_ != cudaSuccess) {                                              \
      std::fprintf(stderr, "error: %s failed: %s (%s)\n", #call,               \
                   cudaGetErrorName(status_), cudaGetErrorString(status_));    \
      std::exit(1);                                                            \
    }                                                                          \
  } while (0)

namespace compat {

inline const char *backendName() { return "cuda"; }
inline const char *programName() { return "sim-baseline-cuda"; }

inline std::string deviceName() {
  int count = 0;
  if (cudaGetDeviceCount(&count) != cudaSuccess || count == 0) {
    std::fprintf(stderr, "error: no CUDA device (sim-baseline-host runs the "
                         "same kernels on the CPU)\n");
    std::exit(1);
  }
  cudaDeviceProp prop;
  SIM_CHECK_CUDA(cudaGetDeviceProperties(&prop, 0));
  return prop.name;
}

template <typename T> T *deviceAlloc(size_t count) {
  T *pointer = nullptr;
  SIM_CHECK_CUDA(cudaMalloc(&pointer, count * sizeof(T)));
  return pointer;
}
template <typename T> void deviceFree(T *pointer) {
  SIM_CHECK_CUDA(cudaFree(pointer));
}
template <typename T> void copyToHost(T *host, const T *device, size_t count) {
  SIM_CHECK_CUDA(
      cudaMemcpy(host, device, count * sizeof(T), cudaMemcpyDeviceToHost));
}
template <typename T>
void copyToDevice(T *device, const T *host, size_t count) {
  SIM_CHECK_CUDA(
      cudaMemcpy(device, host, count * sizeof(T), cudaMemcpyHostToDevice));
}

/// Launches `kernel` on the default stream and checks the launch.
template <typename... Params, typename... Args>
void launch(void (*kernel)(Params...), unsigned blocks, unsigned threads,
            size_t dynamicShared, Args... args) {
  kernel<<<blocks, threads, dynamicShared>>>(args...);
  SIM_CHECK_CUDA(cudaGetLastError());
}

/// Device time between two points of the default stream.
class Timer {
public:
  Timer() {
    SIM_CHECK_CUDA(cudaEventCreate(&start_));
    SIM_CHECK_CUDA(cudaEventCreate(&stop_));
  }
  ~Timer() {
    cudaEventDestroy(start_);
    cudaEventDestroy(stop_);
  }
  void start() { SIM_CHECK_CUDA(cudaEventRecord(start_)); }
  double stopSeconds() {
    SIM_CHECK_CUDA(cudaEventRecord(stop_));
    SIM_CHECK_CUDA(cudaEventSynchronize(stop_));
    float ms = 0;
    SIM_CHECK_CUDA(cudaEventElapsedTime(&ms, start_, stop_));
    return ms * 1e-3;
  }

private:
  cudaEvent_t start_, stop_;
};

} // namespace compat

#define SIM_DYNAMIC_SHARED(type, name)                                         \
  extern __shared__ unsigned char name##_bytes_[];                             \
  type *name = reinterpret_cast<type *>(name##_bytes_)

#else // host emulation

#include <algorithm>
#include <atomic>
#include <barrier>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#define __global__
#define __device__
#define __host__
#define __forceinline__ inline
// Blocks run one at a time, so one static object per kernel is the block's.
#define __shared__ static
#define __restrict__

struct uint3 {
  unsigned x = 0, y = 0, z = 0;
};
struct dim3 {
  unsigned x = 1, y = 1, z = 1;
};
struct float4 {
  float x, y, z, w;
};
inline float4 make_float4(float x, float y, float z, float w) {
  return {x, y, z, w};
}

namespace compat {
struct ThreadState {
  uint3 thread, block;
  dim3 blockSize, gridSize;
  std::barrier<> *blockBarrier = nullptr;
  unsigned char *dynamicShared = nullptr;
};
inline thread_local ThreadState threadState;
} // namespace compat

#define threadIdx (compat::threadState.thread)
#define blockIdx (compat::threadState.block)
#define blockDim (compat::threadState.blockSize)
#define gridDim (compat::threadState.gridSize)

inline void __syncthreads() {
  compat::threadState.blockBarrier->arrive_and_wait();
}
inline int atomicMin(int *address, int value) {
  std::atomic_ref<int> ref(*address);
  int old = ref.load();
  while (value < old && !ref.compare_exchange_weak(old, value)) {
  }
  return old;
}
inline unsigned long long atomicAdd(unsigned long long *address,
                                    unsigned long long value) {
  return std::atomic_ref<unsigned long long>(*address).fetch_add(value);
}

#define SIM_DYNAMIC_SHARED(type, name)                                         \
  type *name = reinterpret_cast<type *>(compat::threadState.dynamicShared)

namespace compat {

inline const char *backendName() { return "host"; }
inline const char *programName() { return "sim-baseline-host"; }
inline std::string deviceName() { return "host emulation of the CUDA kernels"; }

template <typename T> T *deviceAlloc(size_t count) {
  return static_cast<T *>(std::calloc(count ? count : 1, sizeof(T)));
}
template <typename T> void deviceFree(T *pointer) { std::free(pointer); }
template <typename T> void copyToHost(T *host, const T *device, size_t count) {
  std::memcpy(host, device, count * sizeof(T));
}
template <typename T>
void copyToDevice(T *device, const T *host, size_t count) {
  std::memcpy(device, host, count * sizeof(T));
}

/// One host thread per CUDA thread of a block, kept across launches.
class BlockPool {
public:
  explicit BlockPool(unsigned threads)
      : barrier_(std::make_unique<std::barrier<>>(threads)) {
    for (unsigned t = 0; t < threads; ++t)
      workers_.emplace_back([this, t] { work(t, 0); });
  }
  ~BlockPool() {
    {
      std::unique_lock<std::mutex> lock(mutex_);
      stop_ = true;
      ++generation_;
    }
    wake_.notify_all();
    for (std::thread &worker : workers_)
      worker.join();
  }

  /// Runs `body` once per thread of one block.
  void run(const std::function<void(unsigned)> &body) {
    unsigned threads = (unsigned)workers_.size();
    {
      std::unique_lock<std::mutex> lock(mutex_);
      body_ = &body;
      remaining_ = threads;
      ++generation_;
    }
    wake_.notify_all();
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [&] { return remaining_ == 0; });
  }

  std::barrier<> *barrier() { return barrier_.get(); }

private:
  // `seen`: the generation the pool had when the worker was made (0), so a
  // task posted before the worker first waits is not missed.
  void work(unsigned thread, uint64_t seen) {
    while (true) {
      const std::function<void(unsigned)> *body;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return generation_ != seen; });
        seen = generation_;
        if (stop_)
          return;
        body = body_;
      }
      (*body)(thread);
      std::unique_lock<std::mutex> lock(mutex_);
      if (--remaining_ == 0)
        done_.notify_one();
    }
  }

  std::vector<std::thread> workers_;
  std::unique_ptr<std::barrier<>> barrier_;
  std::mutex mutex_;
  std::condition_variable wake_, done_;
  const std::function<void(unsigned)> *body_ = nullptr;
  size_t remaining_ = 0;
  uint64_t generation_ = 0;
  bool stop_ = false;
};

/// The pool of blocks of `threads` threads (one per block size used).
inline BlockPool &blockPool(unsigned threads) {
  static std::mutex mutex;
  static std::vector<std::unique_ptr<BlockPool>> pools(1025);
  std::lock_guard<std::mutex> lock(mutex);
  if (!pools.at(threads))
    pools[threads] = std::make_unique<BlockPool>(threads);
  return *pools[threads];
}

template <typename... Params, typename... Args>
void launch(void (*kernel)(Params...), unsigned blocks, unsigned threads,
            size_t dynamicShared, Args... args) {
  std::vector<unsigned char> shared(dynamicShared);
  BlockPool &pool = blockPool(threads);
  for (unsigned block = 0; block < blocks; ++block) {
    std::function<void(unsigned)> body = [&](unsigned thread) {
      ThreadState &state = threadState;
      state.thread = {thread, 0, 0};
      state.block = {block, 0, 0};
      state.blockSize = {threads, 1, 1};
      state.gridSize = {blocks, 1, 1};
      state.blockBarrier = pool.barrier();
      state.dynamicShared = shared.data();
      kernel(args...);
    };
    pool.run(body);
  }
}

class Timer {
public:
  void start() { start_ = std::chrono::steady_clock::now(); }
  double stopSeconds() {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() -
                                         start_)
        .count();
  }

private:
  std::chrono::steady_clock::time_point start_;
};

} // namespace compat

#endif // __CUDACC__

#endif // SIM_BENCH_CUDA_COMPAT_H
