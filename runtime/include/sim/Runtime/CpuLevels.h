//===- CpuLevels.h - which x86-64 levels this CPU runs ----------*- C++ -*-===//
//
// A bundle's CPU kernels come as one shared object per x86-64 psABI level
// (docs/Bundle.md). The runtime runs the highest level the CPU has
// (runtime/src/Bundle.cpp), and `sim-translate --sim-cpu-isas=host`
// compiles for that very level (lib/Target/CPU/CPUKernels.cpp): both ask
// this header, so the two cannot disagree about what the CPU runs.
// Header-only, C++17, no dependency.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_CPULEVELS_H
#define SIM_RUNTIME_CPULEVELS_H

#include <string>

namespace sim::bundle {

/// Whether this CPU, and its operating system, which must save the wider
/// registers, runs code of x86-64 level `level` ("x86-64" to "x86-64-v4");
/// false for any other name, and on a CPU that is not x86-64.
inline bool cpuRunsLevel(const std::string &level) {
#if defined(__x86_64__)
  __builtin_cpu_init();
  if (level == "x86-64")
    return true;
  if (level == "x86-64-v2")
    return __builtin_cpu_supports("x86-64-v2");
  if (level == "x86-64-v3")
    return __builtin_cpu_supports("x86-64-v3");
  if (level == "x86-64-v4")
    return __builtin_cpu_supports("x86-64-v4");
#endif
  (void)level;
  return false;
}

} // namespace sim::bundle

#endif // SIM_RUNTIME_CPULEVELS_H
