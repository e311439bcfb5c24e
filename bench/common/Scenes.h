//===- Scenes.h - the paper scenes of the hand-written baselines -*- C++
//-*-===//
//
// What both hand-written baselines (bench/cuda/baseline.cu, bench/cpu/
// baseline.cpp) compute, in one place: the components of gravity-like and
// PBD-like as examples/paper and python/simscene define them (which
// buffers each reads, and how it builds its load), the hash constants of
// their bodies and the run-time values. Plain C++17, so nvcc takes it too.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_BENCH_COMMON_SCENES_H
#define SIM_BENCH_COMMON_SCENES_H

#include <cstdint>
#include <tuple>

constexpr int kMaxBuffers = 7;
constexpr int kMaxComponents = 7;
constexpr int kMaxSteps = 3;
// Window reads span i-4..i+4.
constexpr int kHalo = 4;

constexpr uint64_t kGolden = 0x9E3779B97F4A7C15ull;
constexpr uint64_t kMixMul1 = 0xBF58476D1CE4E5B9ull;
constexpr uint64_t kMixMul2 = 0x94D049BB133111EBull;
constexpr uint64_t kKeyMul = 0xD6E8FEB86659FD93ull;
constexpr uint64_t kTimeMul = 0xFF51AFD7ED558CCDull;

/// How a component builds the four rows of its load from its reads (the
/// row choice of python/simscene/scenes.py).
enum class Pattern {
  PointOwn,      // [P, self, P*self, (P-self)/2], bias P; relaxes its state
  OneWindow,     // [mean W, W[i], W[i-1], W[i+1]], bias mean W
  TwoWindows,    // [mean A, mean B, A[i], B[i]], bias mean A
  TwoWindowsOwn, // as TwoWindows; relaxes its state
  WindowPoint,   // [mean A, A[i], B[i], A[i-1]], bias mean A
  WindowOwn,     // [mean A, A[i], self, A[i-1]], bias mean A; relaxes
};

template <int Index, Pattern P, int Writes, int A, int B = -1>
struct Component {
  static constexpr int index = Index;
  static constexpr Pattern pattern = P;
  static constexpr int writes = Writes;
  static constexpr int a = A;
  static constexpr int b = B;
  static constexpr bool own = P == Pattern::PointOwn ||
                              P == Pattern::TwoWindowsOwn ||
                              P == Pattern::WindowOwn;
  /// The buffers read in windows, which hip-cache keeps per group (shared
  /// memory on the GPU, values interpolated once per sub-step on the CPU).
  static constexpr int numCached =
      P == Pattern::PointOwn
          ? 0
          : (P == Pattern::TwoWindows || P == Pattern::TwoWindowsOwn ? 2 : 1);
};

// Component k writes buffer Bk. Component 0 reads the last buffer through
// the back edge and is the only one that bounds the hip big step.
struct GravityLike {
  static constexpr const char *name = "gravity_like";
  static constexpr int numBuffers = 3;
  static constexpr int observed = 2;
  using Components = std::tuple<Component<0, Pattern::PointOwn, 0, 2>,
                                Component<1, Pattern::OneWindow, 1, 0>,
                                Component<2, Pattern::TwoWindowsOwn, 2, 0, 1>>;
  /// Buffers the checked-in scene interpolates with #sim.cubic.
  static constexpr unsigned cubicInScene = 0;
};

struct PbdLike {
  static constexpr const char *name = "pbd_like";
  static constexpr int numBuffers = 7;
  static constexpr int observed = 6;
  using Components = std::tuple<Component<0, Pattern::PointOwn, 0, 6>,
                                Component<1, Pattern::OneWindow, 1, 0>,
                                Component<2, Pattern::WindowPoint, 2, 1, 0>,
                                Component<3, Pattern::OneWindow, 3, 2>,
                                Component<4, Pattern::OneWindow, 4, 3>,
                                Component<5, Pattern::TwoWindows, 5, 4, 3>,
                                Component<6, Pattern::WindowOwn, 6, 5>>;
  static constexpr unsigned cubicInScene = (1u << 3) | (1u << 4);
};

template <typename Scene>
constexpr int numComponents =
    std::tuple_size<typename Scene::Components>::value;

/// Run-time values: every kernel gets them by value.
struct Params {
  long long range;
  float dt;
  int rounds; // @L
  int dist;   // @dist
  int group;  // @group: items per hash group when dist = 1
  int maxSteps;
  unsigned cubic; // bit b: buffer b interpolates with the smoothstep
};

#endif // SIM_BENCH_COMMON_SCENES_H
