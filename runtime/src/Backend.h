//===- Backend.h - what the executor needs from a device ----------*- C++
//-*-===//
//
// The executor (Session.cpp) runs a plan against this interface; the CUDA
// backend (CudaBackend.cpp) and the CPU backend (CpuBackend.cpp) implement
// it. Everything is ordered as issued, like one CUDA stream: a write or a
// launch happens after every launch before it, and a read waits for all of
// them (it is the host synchronisation the executor counts).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_BACKEND_H
#define SIM_RUNTIME_BACKEND_H

#include "Bundle.h"
#include "sim/Runtime/sim_runtime.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sim::rt {

/// A device address: a CUdeviceptr on CUDA, a host pointer on the CPU.
using DevicePtr = uint64_t;

class Backend {
public:
  virtual ~Backend() = default;

  virtual sim_backend kind() const = 0;
  /// The device in words, for reports.
  virtual std::string device() const = 0;
  /// Bytes of memory of the device (0 if unknown): the default memory
  /// limit of a session is three quarters of it.
  virtual int64_t memoryBytes() const = 0;
  /// Throws SIM_ERROR_INVALID_ARGUMENT if the device cannot run groups of
  /// this size.
  virtual void checkGroupSize(int64_t groupSize) const = 0;
  /// Throws SIM_ERROR_INVALID_ARGUMENT if a launch of loaded kernel
  /// `kernel` in groups of `groupSize` would ask for more shared memory
  /// (`perThread` bytes per thread plus `fixed`) than the device gives a
  /// group. Only a GPU has such a limit: the CPU kernels keep their
  /// caches on the stack.
  virtual void checkSharedMemory(int /*kernel*/, int64_t /*perThread*/,
                                 int64_t /*fixed*/,
                                 int64_t /*groupSize*/) const {}

  /// Loads the code of `plan` of `bundle` and resolves its kernels; a
  /// launch names a kernel by its index in `plan.kernels`.
  virtual void load(const Bundle &bundle, const schema::PlanT &plan) = 0;

  /// Device memory, zeroed.
  virtual DevicePtr allocate(size_t bytes) = 0;
  virtual void release(DevicePtr memory) = 0;
  virtual void zero(DevicePtr memory, size_t bytes) = 0;
  /// Copies to the device after everything issued before. `from` may be
  /// reused when the call returns, unless it is memory of allocateHost:
  /// that one only after finishCopies().
  virtual void write(DevicePtr to, const void *from, size_t bytes) = 0;
  /// Waits for everything issued before, then copies.
  virtual void read(void *to, DevicePtr from, size_t bytes) = 0;

  /// Host memory that `readAsync` and `write` move to and from the device
  /// fastest (page-locked on CUDA: no staging copy, and the copies run on
  /// the device's copy engine while the host goes on). The staging memory
  /// of a distributed session's exchanges.
  virtual void *allocateHost(size_t bytes) {
    return ::operator new(bytes ? bytes : 1);
  }
  virtual void releaseHost(void *memory) { ::operator delete(memory); }
  /// Starts copying `bytes` from the device into memory of allocateHost,
  /// after everything issued before; `to` holds them once finishCopies()
  /// returns.
  virtual void readAsync(void *to, DevicePtr from, size_t bytes) {
    read(to, from, bytes);
  }
  /// Waits for every copy issued before: those of readAsync, and writes
  /// from memory of allocateHost, which may read it until then.
  virtual void finishCopies() {}
  /// Copies `bytes` between two places of device memory (which do not
  /// overlap), after everything issued before.
  virtual void copy(DevicePtr to, DevicePtr from, size_t bytes) {
    std::vector<uint8_t> staged(bytes);
    read(staged.data(), from, bytes);
    write(to, staged.data(), bytes);
  }

  /// Runs `groups` groups of `groupSize` threads of a kernel; `params` is
  /// the cuLaunchKernel array of pointers to each parameter value.
  virtual void launch(int kernel, void **params, int64_t groups,
                      int64_t groupSize, int64_t sharedBytes) = 0;

  /// Whether `launch` returns only once the kernel has finished and `read`
  /// is a plain copy (the CPU), so that looking at the clock between two
  /// launches costs no synchronisation.
  virtual bool launchesSynchronously() const { return false; }

  /// Whether launchGroups runs a part of a launch's groups (the CPU).
  virtual bool launchesGroupRanges() const { return false; }
  /// Runs the groups `firstGroup .. firstGroup + groups` of a launch of
  /// `totalGroups` groups (as `launch` would run them), where
  /// launchesGroupRanges() says so.
  virtual void launchGroups(int kernel, void **params, int64_t firstGroup,
                            int64_t groups, int64_t groupSize) {
    (void)kernel, (void)params, (void)firstGroup, (void)groups, (void)groupSize;
  }

  /// Kernel time between the two calls; stopTimer waits for the device.
  virtual void startTimer() = 0;
  virtual double stopTimer() = 0;
  /// The kernel time between the two calls per kernel (indexed as the
  /// plan's kernels), for a backend that times every launch by itself (the
  /// CPU, whose launches are synchronous); empty where only the whole run
  /// is timed (CUDA: its events bracket the run, and an event pair per
  /// launch would change what it measures).
  virtual std::vector<double> kernelSeconds() const { return {}; }

  /// Recording a sequence of launches once and replaying it (CUDA graphs).
  virtual bool supportsGraphs() const { return false; }
  virtual void beginCapture() {}
  virtual void endCapture() {}
  virtual void replay() {}
  virtual void dropGraph() {}

  /// Makes the backend's device current on the calling thread.
  virtual void activate() {}
};

/// The most worker threads the CPU backend starts.
constexpr int kMaxCpuThreads = 1024;

/// Refuses (SIM_ERROR_INVALID_ARGUMENT) a session's `cpu_threads` below 0
/// or above kMaxCpuThreads, on whichever backend the session runs: 0 is
/// one per hardware thread, and a negative value is a mistake, not that.
void checkCpuThreads(int64_t threads);

/// `threads` workers (0: one per hardware thread).
std::unique_ptr<Backend> createCpuBackend(int threads);

/// Throws SIM_ERROR_NO_DRIVER or SIM_ERROR_NO_DEVICE when CUDA cannot be
/// used at all, so that `auto` can fall back to the CPU.
std::unique_ptr<Backend> createCudaBackend(int device);

} // namespace sim::rt

#endif // SIM_RUNTIME_BACKEND_H
