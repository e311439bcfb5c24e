//===- FloatMode.h - subnormals flushed to zero on a CPU thread -*- C++ -*-===//
//
// A bundle compiled with `sim-translate --sim-ftz` runs with subnormal
// values flushed to zero on every backend. The PTX says so in its
// instructions; on the CPU it is a mode of the thread (x86: the FTZ and DAZ
// bits of MXCSR), which the CPU backend and the reference executor set
// around the code they run and restore afterwards, so that the host code
// around them (norms, reports) keeps IEEE arithmetic.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_FLOATMODE_H
#define SIM_RUNTIME_FLOATMODE_H

#if defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace sim::rt {

/// While it lives, the calling thread flushes subnormal results to zero and
/// reads subnormal operands as zero, f32 and f64 alike, if `flush`.
class SubnormalScope {
public:
  explicit SubnormalScope(bool flush) : active(flush) {
#if defined(__x86_64__)
    if (active) {
      saved = _mm_getcsr();
      _mm_setcsr(saved | kFlushToZero | kDenormalsAreZero);
    }
#elif defined(__aarch64__)
    if (active) {
      __asm__ volatile("mrs %0, fpcr" : "=r"(saved));
      __asm__ volatile("msr fpcr, %0" ::"r"(saved | kFlushToZero));
    }
#endif
  }
  ~SubnormalScope() {
#if defined(__x86_64__)
    if (active)
      _mm_setcsr(saved);
#elif defined(__aarch64__)
    if (active)
      __asm__ volatile("msr fpcr, %0" ::"r"(saved));
#endif
  }
  SubnormalScope(const SubnormalScope &) = delete;
  SubnormalScope &operator=(const SubnormalScope &) = delete;

private:
#if defined(__x86_64__)
  static constexpr unsigned kFlushToZero = 1u << 15;
  static constexpr unsigned kDenormalsAreZero = 1u << 6;
  unsigned saved = 0;
#elif defined(__aarch64__)
  // FPCR.FZ flushes inputs and outputs alike.
  static constexpr unsigned long kFlushToZero = 1ul << 24;
  unsigned long saved = 0;
#endif
  bool active;
};

} // namespace sim::rt

#endif // SIM_RUNTIME_FLOATMODE_H
