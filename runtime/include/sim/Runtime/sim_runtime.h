//===- sim_runtime.h - the C API of the sim runtime ---------------*- C -*-===//
//
// The one public header of the runtime that reads scene bundles
// (docs/Bundle.md) and runs them. It is plain C99, for C programs and
// Python's ctypes. So far it holds the status codes that the runtime's
// errors carry.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_SIM_RUNTIME_H
#define SIM_RUNTIME_SIM_RUNTIME_H

#include <stddef.h>
#include <stdint.h>

#if defined(SIM_RUNTIME_BUILDING)
#define SIM_API __attribute__((visibility("default")))
#else
#define SIM_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

//===----------------------------------------------------------------------===//
// Status and errors
//===----------------------------------------------------------------------===//

typedef enum sim_status {
  SIM_OK = 0,
  /// A null handle, an unknown name, a value that does not parse, a host
  /// array of the wrong size.
  SIM_ERROR_INVALID_ARGUMENT = 1,
  /// The file cannot be read.
  SIM_ERROR_IO = 2,
  /// The bundle is malformed or lacks what the request needs.
  SIM_ERROR_BUNDLE = 3,
  /// libcuda.so.1 cannot be loaded (or is the stub library).
  SIM_ERROR_NO_DRIVER = 4,
  /// The driver loaded but there is no usable CUDA device.
  SIM_ERROR_NO_DEVICE = 5,
  /// A backend call failed (a driver call, dlopen, a missing kernel).
  SIM_ERROR_BACKEND = 6,
  /// A run stopped at the first NaN or infinity (check_finite).
  SIM_ERROR_NONFINITE = 7,
  /// The kernels broke the clock contract of docs/Plan.md.
  SIM_ERROR_CLOCK = 8,
} sim_status;

#ifdef __cplusplus
}
#endif

#endif // SIM_RUNTIME_SIM_RUNTIME_H
