//===- CudaBackend.cpp - running the PTX of a bundle on a GPU -------------===//
//
// The driver is loaded with dlopen (CudaDriver.h) the first time a CUDA
// session is created. The backend JIT-compiles the strategy's PTX with
// cuModuleLoadDataEx (with log buffers, so a failure says why), keeps all
// work on one stream, and turns every failing driver call into a message
// with the call's name and the driver's error string.
//
//===----------------------------------------------------------------------===//

#include "Backend.h"
#include "CudaDriver.h"
#include "Error.h"

#include <cctype>
#include <climits>
#include <cstdlib>
#include <dlfcn.h>
#include <mutex>
#include <optional>

namespace sim::rt {
namespace cuda {

std::string Driver::message(CUresult result, const char *call) const {
  const char *name = nullptr, *text = nullptr;
  if (cuGetErrorName(result, &name) != CUDA_SUCCESS || !name)
    name = nullptr;
  if (cuGetErrorString(result, &text) != CUDA_SUCCESS || !text)
    text = nullptr;
  std::string message = std::string(call) + " failed: ";
  message += name ? name : "CUDA error " + std::to_string(result);
  if (text)
    message += std::string(" (") + text + ")";
  return message;
}

void Driver::check(CUresult result, const char *call) const {
  if (result != CUDA_SUCCESS)
    fail(SIM_ERROR_BACKEND, message(result, call));
}

namespace {

/// Loads the driver and initialises it. Any failure is remembered, so that
/// every session gets the same message without retrying.
struct LoadedDriver {
  Driver table;
  sim_status status = SIM_OK;
  std::string error;

  LoadedDriver() {
    const char *override = std::getenv("SIM_CUDA_DRIVER");
    const char *path = override && *override ? override : "libcuda.so.1";
    // The handle stays open for the life of the process: drivers do not
    // unload cleanly.
    void *library = dlopen(path, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
      status = SIM_ERROR_NO_DRIVER;
      error = override && *override
                  ? "no CUDA driver (" + std::string(path) +
                        " from SIM_CUDA_DRIVER: " + dlerror() + ")"
                  : "no CUDA driver (libcuda.so.1 not found)";
      return;
    }
    std::string missing;
#define SIM_CUDA_LOAD(field, symbol, params)                                   \
  table.field = reinterpret_cast<decltype(table.field)>(dlsym(library, symbol));
#define SIM_CUDA_REQUIRE(field, symbol, params)                                \
  if (!table.field)                                                            \
    missing += std::string(missing.empty() ? "" : ", ") + symbol;
    SIM_CUDA_REQUIRED_SYMBOLS(SIM_CUDA_LOAD)
    SIM_CUDA_OPTIONAL_SYMBOLS(SIM_CUDA_LOAD)
    SIM_CUDA_REQUIRED_SYMBOLS(SIM_CUDA_REQUIRE)
#undef SIM_CUDA_LOAD
#undef SIM_CUDA_REQUIRE
    if (!missing.empty()) {
      status = SIM_ERROR_NO_DRIVER;
      error = "the CUDA driver " + std::string(path) + " lacks " + missing +
              " (too old?)";
      return;
    }
    CUresult result = table.cuInit(0);
    if (result == CUDA_ERROR_STUB_LIBRARY) {
      status = SIM_ERROR_NO_DRIVER;
      error = "no CUDA driver (" + std::string(path) +
              " is the stub library of the CUDA toolkit)";
      return;
    }
    if (result == CUDA_ERROR_NO_DEVICE) {
      status = SIM_ERROR_NO_DEVICE;
      error = "no CUDA device";
      return;
    }
    if (result != CUDA_SUCCESS) {
      status = SIM_ERROR_NO_DEVICE;
      error = "no CUDA device (" + table.message(result, "cuInit") + ")";
      return;
    }
    int count = 0;
    result = table.cuDeviceGetCount(&count);
    if (result != CUDA_SUCCESS || count == 0) {
      status = SIM_ERROR_NO_DEVICE;
      error = "no CUDA device";
    }
  }
};

} // namespace

const Driver &driver() {
  static LoadedDriver loaded;
  if (loaded.status != SIM_OK)
    fail(loaded.status, loaded.error);
  return loaded.table;
}

std::optional<size_t> entryParamCount(const std::string &ptx,
                                      const std::string &name) {
  const std::string entry = ".entry " + name;
  for (size_t at = ptx.find(entry); at != std::string::npos;
       at = ptx.find(entry, at + 1)) {
    size_t open = at + entry.size();
    while (open < ptx.size() && std::isspace((unsigned char)ptx[open]))
      ++open;
    if (open >= ptx.size() || ptx[open] != '(')
      continue; // an entry whose name starts with `name`
    size_t close = ptx.find(')', open);
    if (close == std::string::npos)
      return std::nullopt;
    size_t count = 0;
    for (size_t param = ptx.find(".param", open); param < close;
         param = ptx.find(".param", param + 6))
      ++count;
    return count;
  }
  return std::nullopt;
}

} // namespace cuda

namespace {

using namespace cuda;

class CudaBackend final : public Backend {
public:
  explicit CudaBackend(int ordinal) : cu(driver()) {
    try {
      open(ordinal);
    } catch (...) {
      // A constructor that throws runs no destructor.
      close();
      throw;
    }
  }

  ~CudaBackend() override { close(); }

  void open(int ordinal) {
    int count = 0;
    cu.check(cu.cuDeviceGetCount(&count), "cuDeviceGetCount");
    if (ordinal < 0 || ordinal >= count)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "CUDA device " + std::to_string(ordinal) + " does not exist (" +
               std::to_string(count) + " device" + (count == 1 ? "" : "s") +
               ")");
    cu.check(cu.cuDeviceGet(&device_, ordinal), "cuDeviceGet");
    char name[256] = {};
    cu.check(cu.cuDeviceGetName(name, sizeof name - 1, device_),
             "cuDeviceGetName");
    int major = 0, minor = 0;
    cu.check(cu.cuDeviceGetAttribute(
                 &major, CU_DEVICE_ATTRIBUTE_COMPUTE_CAPABILITY_MAJOR, device_),
             "cuDeviceGetAttribute");
    cu.check(cu.cuDeviceGetAttribute(
                 &minor, CU_DEVICE_ATTRIBUTE_COMPUTE_CAPABILITY_MINOR, device_),
             "cuDeviceGetAttribute");
    description = std::string(name) + " (sm_" + std::to_string(major) +
                  std::to_string(minor) + ")";
    int sharedOptIn = 0;
    cu.check(cu.cuDeviceGetAttribute(
                 &sharedOptIn,
                 CU_DEVICE_ATTRIBUTE_MAX_SHARED_MEMORY_PER_BLOCK_OPTIN,
                 device_),
             "cuDeviceGetAttribute");
    maxSharedPerGroup = sharedOptIn;
    size_t total = 0;
    cu.check(cu.cuDeviceTotalMem(&total, device_), "cuDeviceTotalMem");
    totalMemory = int64_t(std::min<size_t>(total, INT64_MAX));
    // The primary context is the one the CUDA runtime and other libraries
    // in the process share.
    cu.check(cu.cuDevicePrimaryCtxRetain(&context, device_),
             "cuDevicePrimaryCtxRetain");
    retained = true;
    activate();
    // A non-blocking stream: nothing else in the process orders with it,
    // and every copy of this backend goes through it.
    cu.check(cu.cuStreamCreate(&stream, CU_STREAM_NON_BLOCKING),
             "cuStreamCreate");
    cu.check(cu.cuEventCreate(&start, CU_EVENT_DEFAULT), "cuEventCreate");
    cu.check(cu.cuEventCreate(&stop, CU_EVENT_DEFAULT), "cuEventCreate");
  }

  void close() {
    // Errors are ignored: a destructor has nobody to tell, and a sticky
    // error of an earlier kernel would fail every call here.
    if (context)
      cu.cuCtxSetCurrent(context);
    dropGraph();
    if (stream)
      cu.cuStreamSynchronize(stream);
    if (module)
      cu.cuModuleUnload(module);
    if (start)
      cu.cuEventDestroy(start);
    if (stop)
      cu.cuEventDestroy(stop);
    if (stream)
      cu.cuStreamDestroy(stream);
    if (retained)
      cu.cuDevicePrimaryCtxRelease(device_);
    module = nullptr;
    start = stop = nullptr;
    stream = nullptr;
    retained = false;
  }

  sim_backend kind() const override { return SIM_BACKEND_CUDA; }
  std::string device() const override { return description; }
  int64_t memoryBytes() const override { return totalMemory; }

  void checkSharedMemory(int kernel, int64_t perThread, int64_t fixed,
                         int64_t groupSize) const override {
    const Kernel &k = kernels[size_t(kernel)];
    int64_t available = maxSharedPerGroup - k.staticShared;
    if (maxSharedPerGroup <= 0 || perThread * groupSize + fixed <= available)
      return;
    // The largest group (a multiple of 32) whose caches fit, if any.
    int64_t fits =
        perThread > 0 ? (available - fixed) / perThread / 32 * 32 : 0;
    fail(SIM_ERROR_INVALID_ARGUMENT,
         "kernel '" + k.name + "' needs " +
             std::to_string(perThread * groupSize + fixed) +
             " bytes of shared memory in a group of " +
             std::to_string(groupSize) + " (hip-cache's caches: " +
             std::to_string(perThread) + " per thread and " +
             std::to_string(fixed) + " for the window's halo), more than the " +
             std::to_string(available) + " that " + description +
             " gives a group; " +
             (fits >= 32
                  ? "use --group-size " + std::to_string(fits) + " or less, or "
                  : std::string("use ")) +
             "strategy hip, which keeps no cache");
  }

  void checkGroupSize(int64_t groupSize) const override {
    // Kernels reduce per warp with every lane taking part.
    if (groupSize < 32 || groupSize > 1024 || groupSize % 32 != 0)
      fail(SIM_ERROR_INVALID_ARGUMENT,
           "group size " + std::to_string(groupSize) +
               " is not a multiple of 32 between 32 and 1024, as CUDA needs");
    // Once loaded: a kernel whose registers do not fit the group size on
    // this device would fail every launch (too many resources requested).
    for (const Kernel &kernel : kernels)
      if (kernel.maxThreads > 0 && groupSize > kernel.maxThreads)
        fail(SIM_ERROR_INVALID_ARGUMENT,
             "group size " + std::to_string(groupSize) + " is more than the " +
                 std::to_string(kernel.maxThreads) + " threads kernel '" +
                 kernel.name + "' can run in a group on " + description +
                 " (it needs " + std::to_string(kernel.registers) +
                 " registers per thread); use --group-size " +
                 std::to_string(kernel.maxThreads / 32 * 32) + " or less");
  }

  void activate() override {
    cu.check(cu.cuCtxSetCurrent(context), "cuCtxSetCurrent");
  }

  void load(const Bundle &, const schema::PlanT &plan) override {
    std::string what = std::string("the PTX of strategy '") +
                       strategyName(plan.strategy) + "'";
    std::string infoLog(16384, '\0'), errorLog(16384, '\0');
    CUjit_option options[] = {
        CU_JIT_INFO_LOG_BUFFER, CU_JIT_INFO_LOG_BUFFER_SIZE_BYTES,
        CU_JIT_ERROR_LOG_BUFFER, CU_JIT_ERROR_LOG_BUFFER_SIZE_BYTES};
    void *values[] = {
        infoLog.data(), reinterpret_cast<void *>(uintptr_t(infoLog.size())),
        errorLog.data(), reinterpret_cast<void *>(uintptr_t(errorLog.size()))};
    CUresult result =
        cu.cuModuleLoadDataEx(&module, plan.ptx.c_str(), 4, options, values);
    if (result != CUDA_SUCCESS) {
      module = nullptr;
      std::string log = errorLog.c_str();
      while (!log.empty() && (log.back() == '\n' || log.back() == ' '))
        log.pop_back();
      fail(SIM_ERROR_BACKEND, "cannot JIT-compile " + what + " for " +
                                  description + ": " +
                                  cu.message(result, "cuModuleLoadDataEx") +
                                  (log.empty() ? "" : "\nJIT log:\n" + log));
    }
    for (const auto &kernel : plan.kernels) {
      CUfunction function = nullptr;
      result = cu.cuModuleGetFunction(&function, module, kernel->name.c_str());
      if (result != CUDA_SUCCESS)
        fail(SIM_ERROR_BACKEND,
             what + " has no kernel '" + kernel->name + "' (" +
                 cu.message(result, "cuModuleGetFunction") + ")");
      checkParams(function, plan.ptx, *kernel, what);
      int maxThreads = 0, registers = 0, staticShared = 0;
      if (cu.cuFuncGetAttribute) {
        cu.check(cu.cuFuncGetAttribute(&staticShared,
                                       CU_FUNC_ATTRIBUTE_SHARED_SIZE_BYTES,
                                       function),
                 "cuFuncGetAttribute");
        cu.check(cu.cuFuncGetAttribute(&maxThreads,
                                       CU_FUNC_ATTRIBUTE_MAX_THREADS_PER_BLOCK,
                                       function),
                 "cuFuncGetAttribute");
        cu.check(cu.cuFuncGetAttribute(&registers, CU_FUNC_ATTRIBUTE_NUM_REGS,
                                       function),
                 "cuFuncGetAttribute");
      }
      kernels.push_back({function, 48 * 1024, kernel->name, maxThreads,
                         registers, staticShared});
    }
  }

  /// Checks that the PTX entry takes the parameters the kernel's record says:
  /// a memref as five 8-byte values, a scalar as itself. The count comes from
  /// the entry's declaration in the PTX and the sizes from the driver where
  /// it can tell (cuFuncGetParamInfo, CUDA 12.4+), asked only for parameters
  /// that exist (a failing call would be an API error to compute-sanitizer).
  void checkParams(CUfunction function, const std::string &ptx,
                   const schema::KernelT &kernel, const std::string &what) {
    std::vector<size_t> sizes;
    for (const schema::KernelParam &param : kernel.params) {
      if (param.type() == ParamType::Memref)
        sizes.insert(sizes.end(), 5, 8);
      else
        sizes.push_back(param.type() == ParamType::I32 ||
                                param.type() == ParamType::F32
                            ? 4
                            : 8);
    }
    auto mismatch = [&](const std::string &why) {
      fail(SIM_ERROR_BUNDLE,
           what + ": the PTX entry '" + kernel.name + "' does not take the " +
               std::to_string(sizes.size()) +
               " parameter values its kernel record says (" + why + ")");
    };
    std::optional<size_t> declared = cuda::entryParamCount(ptx, kernel.name);
    if (declared && *declared != sizes.size())
      mismatch("it declares " + std::to_string(*declared));
    if (!cu.cuFuncGetParamInfo)
      return;
    for (size_t i = 0; i < sizes.size(); ++i) {
      size_t offset = 0, size = 0;
      CUresult result = cu.cuFuncGetParamInfo(function, i, &offset, &size);
      if (result != CUDA_SUCCESS)
        mismatch("value " + std::to_string(i) + " is missing");
      if (size != sizes[i])
        mismatch("value " + std::to_string(i) + " has " + std::to_string(size) +
                 " bytes");
    }
  }

  DevicePtr allocate(size_t bytes) override {
    CUdeviceptr memory = 0;
    CUresult result = cu.cuMemAlloc(&memory, std::max<size_t>(bytes, 1));
    if (result != CUDA_SUCCESS)
      fail(SIM_ERROR_BACKEND, cu.message(result, "cuMemAlloc") + " for " +
                                  std::to_string(bytes) + " bytes");
    zero(memory, bytes);
    return memory;
  }
  void release(DevicePtr memory) override {
    // cuMemFree does not wait for kernels on a non-blocking stream.
    cu.cuStreamSynchronize(stream);
    cu.cuMemFree(memory);
  }
  void zero(DevicePtr memory, size_t bytes) override {
    cu.check(cu.cuMemsetD8Async(memory, 0, bytes, stream), "cuMemsetD8Async");
  }
  void write(DevicePtr to, const void *from, size_t bytes) override {
    // From pageable memory the call returns once the bytes are staged, so
    // `from` may be reused right away.
    cu.check(cu.cuMemcpyHtoDAsync(to, from, bytes, stream),
             "cuMemcpyHtoDAsync");
  }
  void read(void *to, DevicePtr from, size_t bytes) override {
    cu.check(cu.cuMemcpyDtoHAsync(to, from, bytes, stream),
             "cuMemcpyDtoHAsync");
    cu.check(cu.cuStreamSynchronize(stream), "cuStreamSynchronize");
  }

  // The staging memory of a distributed session's exchanges: page-locked,
  // so that its copies are the device's DMA transfers, queued on the
  // stream without a synchronisation each (readAsync) and without the
  // driver's own staging copy.
  void *allocateHost(size_t bytes) override {
    void *memory = nullptr;
    CUresult result = cu.cuMemHostAlloc(&memory, std::max<size_t>(bytes, 1),
                                        CU_MEMHOSTALLOC_PORTABLE);
    if (result != CUDA_SUCCESS)
      fail(SIM_ERROR_BACKEND, cu.message(result, "cuMemHostAlloc") + " for " +
                                  std::to_string(bytes) +
                                  " bytes of page-locked host memory");
    return memory;
  }
  void releaseHost(void *memory) override {
    // Nothing may still be copying from or into it.
    cu.cuStreamSynchronize(stream);
    cu.cuMemFreeHost(memory);
  }
  void readAsync(void *to, DevicePtr from, size_t bytes) override {
    cu.check(cu.cuMemcpyDtoHAsync(to, from, bytes, stream),
             "cuMemcpyDtoHAsync");
  }
  void finishCopies() override {
    cu.check(cu.cuStreamSynchronize(stream), "cuStreamSynchronize");
  }
  void copy(DevicePtr to, DevicePtr from, size_t bytes) override {
    cu.check(cu.cuMemcpyDtoDAsync(to, from, bytes, stream),
             "cuMemcpyDtoDAsync");
  }

  void launch(int kernel, void **params, int64_t groups, int64_t groupSize,
              int64_t sharedBytes) override {
    Kernel &k = kernels[kernel];
    if (sharedBytes > INT_MAX)
      fail(SIM_ERROR_INVALID_ARGUMENT, "a launch asks for " +
                                           std::to_string(sharedBytes) +
                                           " bytes of shared memory");
    if (sharedBytes > k.sharedLimit) {
      // Beyond 48 KiB of dynamic shared memory a kernel must opt in.
      cu.check(cu.cuFuncSetAttribute(
                   k.function, CU_FUNC_ATTRIBUTE_MAX_DYNAMIC_SHARED_SIZE_BYTES,
                   int(sharedBytes)),
               "cuFuncSetAttribute");
      k.sharedLimit = sharedBytes;
    }
    // Kernels loop over the range with a grid stride, so capping the grid
    // is correct.
    unsigned grid = unsigned(std::min<int64_t>(groups, INT_MAX));
    cu.check(cu.cuLaunchKernel(k.function, grid, 1, 1, unsigned(groupSize), 1,
                               1, unsigned(sharedBytes), stream, params,
                               nullptr),
             "cuLaunchKernel");
  }

  void startTimer() override {
    cu.check(cu.cuEventRecord(start, stream), "cuEventRecord");
  }
  double stopTimer() override {
    cu.check(cu.cuEventRecord(stop, stream), "cuEventRecord");
    cu.check(cu.cuEventSynchronize(stop), "cuEventSynchronize");
    float milliseconds = 0;
    cu.check(cu.cuEventElapsedTime(&milliseconds, start, stop),
             "cuEventElapsedTime");
    return milliseconds / 1000.0;
  }

  bool supportsGraphs() const override { return cu.hasGraphs(); }
  void beginCapture() override {
    dropGraph();
    cu.check(
        cu.cuStreamBeginCapture(stream, CU_STREAM_CAPTURE_MODE_THREAD_LOCAL),
        "cuStreamBeginCapture");
  }
  void endCapture() override {
    cu.check(cu.cuStreamEndCapture(stream, &graph), "cuStreamEndCapture");
    cu.check(cu.cuGraphInstantiateWithFlags(&graphExec, graph, 0),
             "cuGraphInstantiateWithFlags");
  }
  void replay() override {
    cu.check(cu.cuGraphLaunch(graphExec, stream), "cuGraphLaunch");
  }
  void dropGraph() override {
    if (graphExec)
      cu.cuGraphExecDestroy(graphExec);
    if (graph)
      cu.cuGraphDestroy(graph);
    graphExec = nullptr;
    graph = nullptr;
  }

private:
  struct Kernel {
    CUfunction function;
    int64_t sharedLimit;
    std::string name;
    /// The most threads a group of this kernel may have on the device, as
    /// its registers allow (0: unknown), and its registers per thread.
    int maxThreads, registers;
    /// Its shared memory of fixed size (the warp minima of a group).
    int staticShared;
  };

  const Driver &cu;
  CUdevice device_ = 0;
  int64_t totalMemory = 0;
  /// The shared memory a group may have, static and dynamic, once a kernel
  /// opts in (227 KiB on sm_90, 64 KiB on sm_75).
  int64_t maxSharedPerGroup = 0;
  std::string description;
  CUcontext context = nullptr;
  bool retained = false;
  CUstream stream = nullptr;
  CUevent start = nullptr, stop = nullptr;
  CUmodule module = nullptr;
  std::vector<Kernel> kernels;
  CUgraph graph = nullptr;
  CUgraphExec graphExec = nullptr;
};

} // namespace

std::unique_ptr<Backend> createCudaBackend(int device) {
  return std::make_unique<CudaBackend>(device);
}

} // namespace sim::rt
