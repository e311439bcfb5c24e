//===- Error.h - errors of the runtime ----------------------------*- C++
//-*-===//
//
// Internally the runtime reports a failure by throwing sim::rt::Error, which
// carries the C API status code and a message that names the problem. The C
// API (CApi.cpp) is the only place that catches: it turns the error into a
// status and sim_last_error(), so no exception crosses into C.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_ERROR_H
#define SIM_RUNTIME_ERROR_H

#include "sim/Runtime/sim_runtime.h"

#include <stdexcept>
#include <string>

namespace sim::rt {

class Error : public std::runtime_error {
public:
  Error(sim_status status, const std::string &message)
      : std::runtime_error(message), status(status) {}
  sim_status status;
};

[[noreturn]] inline void fail(sim_status status, const std::string &message) {
  throw Error(status, message);
}

} // namespace sim::rt

#endif // SIM_RUNTIME_ERROR_H
