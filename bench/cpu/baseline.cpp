//===- baseline.cpp - Hand-written CPU code of the paper's two scenes -----===//
//
// What a user would write for a multi-core CPU instead of sim: the
// gravity-like and PBD-like scenes of examples/paper with the four
// algorithms (simple, traditional, hip = the paper's HIP-NoCache, hip-cache
// = HIP), by hand, in C++ with OpenMP threads over groups and SIMD across
// the items of a group. bench/run compares sim's CPU backend with it, time
// and numbers (test/Bench/cpu-baseline.test checks it bit for bit).
//
// The semantics are those of the hand-written CUDA (bench/cuda/baseline.cu),
// which test/Bench/baseline.test checks bit for bit against sim: the same
// scene tables, hash, init, rows, rounds, interpolation fraction and
// weights, group-minimum sub-step rule and clock. What differs is how the
// work maps onto the machine:
//
//  - Layout. Every buffer half is structure-of-arrays: one array per vector
//    lane, so kChunk consecutive items of one lane fill one SIMD register.
//    Each lane array carries copies of its first and last item before and
//    after it (kHalo on the left, kHalo + kChunk on the right), so window
//    reads need no clamp: the copy holds what the clamp would read. Whoever
//    writes item 0 or range - 1 refreshes the copies.
//  - SIMD. Every loop over the items of a chunk is a `#pragma omp simd` loop
//    with the four rows, four lanes and the window unrolled in its body, so
//    the compiler maps items to SIMD lanes (-O3 -march=native); the L rounds
//    run over a chunk held in local arrays. tanh is glibc's tanhf algorithm
//    written to vectorise (GlibcTanh.h), bit for bit glibc's values, as
//    sim's CPU kernels compute it (--sim-expand-tanh).
//  - Threads. One OpenMP parallel region per run; the clock is an ordinary
//    struct that one thread advances between barriers (`omp single`), and
//    every kernel of sim is a work-shared loop over groups.
//  - hip-cache interpolates the window buffers once per sub-step for the
//    group and its halo into a local array; hip interpolates at every read.
//
// Arithmetic is sim's operation for operation: built with -ffp-contract=off
// and without -ffast-math, std::fma where the scene has vector.fma.
//
//===----------------------------------------------------------------------===//

#include "../common/BaselineOptions.h"
#include "../common/Outputs.h"
#include "../common/RunJson.h"
#include "../common/Scenes.h"
#include "GlibcTanh.h"

#include <omp.h>
#include <xmmintrin.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

//===----------------------------------------------------------------------===//
// The scenes (bench/common/Scenes.h), and what the CPU adds
//===----------------------------------------------------------------------===//

constexpr int kLanes = 4;
// Items evaluated together: one AVX-512 register of floats per lane and row
// (two AVX2 registers, four SSE ones).
constexpr int kChunk = 16;

struct Clock {
  long long T = 0, m = 0, end = 0;
  int parity = 0;
  int estimate = INT_MAX; // minimum num_steps for the next big step
  unsigned long long bigSteps = 0;
  unsigned long long histogram[kMaxSteps + 1] = {};
  unsigned long long evaluations[kMaxComponents] = {};
};

inline uint64_t splitmix64(uint64_t z) {
  z = (z ^ (z >> 30)) * kMixMul1;
  z = (z ^ (z >> 27)) * kMixMul2;
  return z ^ (z >> 31);
}

/// The init body of buffer `seed` at item i, lane `lane`: a float in [-1, 1).
inline float initValue(int seed, long long i, int lane) {
  uint64_t x =
      (4ull * (uint64_t)i + lane) * kKeyMul ^ (uint64_t)(seed + 1) * kGolden;
  float u = (float)(splitmix64(x) >> 40);
  return std::fma(u, 1.1920928955078125e-7f, -1.0f);
}

/// The num_steps body of component c, clamped to [1, max_steps].
inline int numSteps(int c, long long i, long long t, const Params &p) {
  int n;
  if (p.dist == 3) {
    n = 1;
  } else if (p.dist == 4) {
    n = p.maxSteps;
  } else {
    uint64_t group = (uint64_t)(p.group > 1 ? p.group : 1);
    uint64_t key = p.dist == 0   ? 0
                   : p.dist == 1 ? (uint64_t)i / group
                                 : (uint64_t)i;
    uint64_t x =
        (uint64_t)(c + 1) * kGolden ^ key * kKeyMul ^ (uint64_t)t * kTimeMul;
    n = (int)(splitmix64(x) % 3 + 1);
  }
  return n < 1 ? 1 : (n > p.maxSteps ? p.maxSteps : n);
}

/// The smallest num_steps of component c over items [first, end) at t,
/// stopping early once it reaches `floor` (nothing is smaller than 1, and a
/// caller that clamps the result to `floor` cannot tell smaller values
/// apart).
inline int minSteps(int c, long long first, long long end, long long t,
                    const Params &p, int floor) {
  int least = INT_MAX;
  for (long long chunk = first; chunk < end && least > floor; chunk += kChunk) {
    long long last = std::min(end, chunk + kChunk);
    int mine = INT_MAX;
#pragma omp simd reduction(min : mine)
    for (long long i = chunk; i < last; ++i)
      mine = std::min(mine, numSteps(c, i, t, p));
    least = std::min(least, mine);
  }
  return least;
}

//===----------------------------------------------------------------------===//
// Buffers
//===----------------------------------------------------------------------===//

/// One half of a buffer: kLanes arrays of `range` items, each with copies of
/// its end items around it (see the file comment).
struct Half {
  float *lane[kLanes];
};

/// Allocates and owns every buffer of a scene, two halves each.
class Storage {
public:
  static constexpr long long kLeft = kHalo;
  static constexpr long long kRight = kHalo + kChunk;

  Storage(int buffers, long long range) : range_(range) {
    // Lane arrays start on a cache line.
    stride_ = (kLeft + range + kRight + 15) / 16 * 16;
    size_t floats = (size_t)buffers * 2 * kLanes * stride_;
    memory_.reset(static_cast<float *>(
        std::aligned_alloc(64, (floats * sizeof(float) + 63) / 64 * 64)));
    if (!memory_) {
      std::fprintf(stderr, "error: cannot allocate %zu bytes\n",
                   floats * sizeof(float));
      std::exit(1);
    }
    std::memset(memory_.get(), 0, floats * sizeof(float));
    for (int b = 0; b < buffers; ++b)
      for (int h = 0; h < 2; ++h)
        for (int l = 0; l < kLanes; ++l)
          halves_[b][h].lane[l] = memory_.get() +
                                  ((size_t)(b * 2 + h) * kLanes + l) * stride_ +
                                  kLeft;
  }

  const Half &half(int buffer, int h) const { return halves_[buffer][h]; }

  /// Copies the end items of [first, end) of `half` into the copies around
  /// the lane arrays, when the range holds an end item.
  void refreshEnds(const Half &half, long long first, long long end) const {
    for (int l = 0; l < kLanes; ++l) {
      float *lane = half.lane[l];
      if (first == 0)
        for (long long k = 1; k <= kLeft; ++k)
          lane[-k] = lane[0];
      if (end == range_)
        for (long long k = 0; k < kRight; ++k)
          lane[range_ + k] = lane[range_ - 1];
    }
  }

private:
  struct Free {
    void operator()(float *p) const { std::free(p); }
  };
  long long range_;
  long long stride_ = 0;
  std::unique_ptr<float, Free> memory_;
  Half halves_[kMaxBuffers][2] = {};
};

//===----------------------------------------------------------------------===//
// Readers: where a read's value comes from
//===----------------------------------------------------------------------===//

// A reader hands out, per buffer and lane, a view: a small value whose
// call operator gives that lane at item j. Views are taken outside the loops
// over items, so the pointers they hold stay in registers.

/// A lane of one half, read directly.
struct DirectView {
  const float *lane;
  float operator()(long long j) const { return lane[j]; }
};

/// One half of every buffer: the state at T (back edge) or at T + m.
struct HalfReader {
  const float *lane[kMaxBuffers][kLanes];
  template <int B> DirectView view(int l) const { return {lane[B][l]}; }
};

/// The weights of the value at T and at T + m at fraction f of the big
/// step, as sim's interpolation attributes compute them.
struct Weights {
  float beginLinear, endLinear, beginCubic, endCubic;
  explicit Weights(float f) {
    beginLinear = 1.0f - f;
    endLinear = f;
    float twoF = 2.0f * f;
    float s = (f * f) * (3.0f - twoF);
    beginCubic = 1.0f - s;
    endCubic = s;
  }
};

/// A lane interpolated between the value at T and at T + m.
struct InterpolatedView {
  const float *source, *target;
  float begin, end;
  float operator()(long long j) const {
    return begin * source[j] + end * target[j];
  }
};

/// Interpolated between the halves (every buffer a later component reads
/// was written earlier in the step in these scenes).
struct InterpolatingReader {
  const float *source[kMaxBuffers][kLanes];
  const float *target[kMaxBuffers][kLanes];
  float begin[kMaxBuffers], end[kMaxBuffers];

  void setWeights(const Weights &w, unsigned cubic, int buffers) {
    for (int b = 0; b < buffers; ++b) {
      bool smooth = (cubic >> b) & 1;
      begin[b] = smooth ? w.beginCubic : w.beginLinear;
      end[b] = smooth ? w.endCubic : w.endLinear;
    }
  }
  template <int B> InterpolatedView view(int l) const {
    return {source[B][l], target[B][l], begin[B], end[B]};
  }
};

/// A lane of the hip-cache window: slot 0 holds item `first`.
struct CachedView {
  const float *slots;
  long long first;
  float operator()(long long j) const { return slots[j - first]; }
};

/// hip-cache: the window buffers of the component come from the group's
/// cache, filled once per sub-step for its items and the halo.
template <typename Comp> struct CachingReader {
  const InterpolatingReader &global;
  const float *cache[2][kLanes];
  long long first; // the item in slot 0: the group's first minus the halo
  template <int B> auto view(int l) const {
    if constexpr (B == Comp::a && Comp::numCached >= 1)
      return CachedView{cache[0][l], first};
    else if constexpr (B == Comp::b && Comp::numCached == 2)
      return CachedView{cache[1][l], first};
    else
      return global.template view<B>(l);
  }
};

//===----------------------------------------------------------------------===//
// One chunk of items
//===----------------------------------------------------------------------===//

/// A chunk's values: [lane][item of the chunk].
using ChunkValues = float[kLanes][kChunk];

/// Evaluates component `Comp` at items i0 .. i0 + kChunk - 1 (items past the
/// range compute on the copies of the last item and are not stored):
/// `self[l][j]` is the own state of item i0 + j, and the new values go to
/// `out` (which may be `self`).
template <typename Comp, typename Reader>
inline void evaluateChunk(const Reader &read, long long i0,
                          const ChunkValues &self, int n, const Params &p,
                          ChunkValues &out) {
  constexpr int A = Comp::a, B = Comp::b;
  constexpr Pattern P = Comp::pattern;
  // The matrix M = rows / 4, [row][lane][item]; X starts as M.
  alignas(64) float m[4][kLanes][kChunk];
  alignas(64) float x[4][kLanes][kChunk];
  alignas(64) float bias[kLanes][kChunk];

  for (int l = 0; l < kLanes; ++l) {
    auto a = read.template view<A>(l);
    auto b = [&] {
      if constexpr (B >= 0)
        return read.template view<B>(l);
      else
        return a; // unused
    }();
#pragma omp simd
    for (int j = 0; j < kChunk; ++j) {
      long long i = i0 + j;
      float r0, r1, r2, r3;
      if constexpr (P == Pattern::PointOwn) {
        float point = a(i);
        r0 = point;
        r1 = self[l][j];
        r2 = point * self[l][j];
        r3 = 0.5f * (point - self[l][j]);
      } else {
        const float ninth = 0.111111112f;
        float sumA = 0.0f, sumB = 0.0f;
        for (int k = -kHalo; k <= kHalo; ++k) {
          sumA = sumA + a(i + k);
          if constexpr (P == Pattern::TwoWindows || P == Pattern::TwoWindowsOwn)
            sumB = sumB + b(i + k);
        }
        float meanA = ninth * sumA;
        r0 = meanA;
        if constexpr (P == Pattern::OneWindow) {
          r1 = a(i);
          r2 = a(i - 1);
          r3 = a(i + 1);
        } else if constexpr (P == Pattern::TwoWindows ||
                             P == Pattern::TwoWindowsOwn) {
          r1 = ninth * sumB;
          r2 = a(i);
          r3 = b(i);
        } else if constexpr (P == Pattern::WindowPoint) {
          r1 = a(i);
          r2 = b(i);
          r3 = a(i - 1);
        } else {
          static_assert(P == Pattern::WindowOwn, "a pattern without rows");
          r1 = a(i);
          r2 = self[l][j];
          r3 = a(i - 1);
        }
      }
      bias[l][j] = r0;
      m[0][l][j] = x[0][l][j] = 0.25f * r0;
      m[1][l][j] = x[1][l][j] = 0.25f * r1;
      m[2][l][j] = x[2][l][j] = 0.25f * r2;
      m[3][l][j] = x[3][l][j] = 0.25f * r3;
    }
  }

  // L rounds of X := M X. Row r of X is a vec4 (lanes); M's entry (r, c) is
  // lane c of row r of M.
  for (int round = 0; round < p.rounds; ++round) {
#pragma omp simd
    for (int j = 0; j < kChunk; ++j) {
      float y[4][kLanes];
      for (int r = 0; r < 4; ++r)
        for (int l = 0; l < kLanes; ++l)
          y[r][l] = std::fma(m[r][3][j], x[3][l][j],
                             std::fma(m[r][2][j], x[2][l][j],
                                      std::fma(m[r][1][j], x[1][l][j],
                                               m[r][0][j] * x[0][l][j])));
      for (int r = 0; r < 4; ++r)
        for (int l = 0; l < kLanes; ++l)
          x[r][l][j] = y[r][l];
    }
  }

  // The sum of X's rows plus the bias, then glibc's tanhf in SIMD lanes.
  alignas(64) float target[kLanes][kChunk];
#pragma omp simd
  for (int j = 0; j < kChunk; ++j)
    for (int l = 0; l < kLanes; ++l)
      target[l][j] =
          (((x[0][l][j] + x[1][l][j]) + x[2][l][j]) + x[3][l][j]) + bias[l][j];
  for (int l = 0; l < kLanes; ++l) {
#pragma omp simd
    for (int j = 0; j < kChunk; ++j)
      target[l][j] = glibcTanhf(target[l][j]);
  }

  if constexpr (!Comp::own) {
    std::memcpy(out, target, sizeof target);
  } else {
    float h = (float)n * p.dt;
    h = h < 1.0f ? h : 1.0f;
#pragma omp simd
    for (int j = 0; j < kChunk; ++j)
      for (int l = 0; l < kLanes; ++l)
        out[l][j] = std::fma(h, target[l][j] - self[l][j], self[l][j]);
  }
}

/// Loads items i0 .. i0 + kChunk - 1 of `half` into `values`.
inline void loadChunk(const Half &half, long long i0, ChunkValues &values) {
  for (int l = 0; l < kLanes; ++l)
    std::memcpy(values[l], half.lane[l] + i0, sizeof values[l]);
}

/// Stores the first `count` items of `values` at i0 in `half`.
inline void storeChunk(const Half &half, long long i0, int count,
                       const ChunkValues &values) {
  for (int l = 0; l < kLanes; ++l)
    std::memcpy(half.lane[l] + i0, values[l], count * sizeof(float));
}

//===----------------------------------------------------------------------===//
// The simulation
//===----------------------------------------------------------------------===//

// Lts: the scenes here read no buffer of their own at other items, so no
// component takes local time steps and lts plans what hip plans (docs/
// Model.md, "Local time stepping"): it runs as Hip.
using sim::bench::median;
using sim::bench::Strategy;
using sim::bench::strategyName;
using sim::bench::writeNpy;

struct Options : sim::bench::SceneOptions {
  int threads = 0; // 0: OpenMP's default (every core)
  /// Flush subnormals to zero (MXCSR FTZ and DAZ on every thread), as a
  /// bundle compiled with sim-translate --sim-ftz computes.
  bool ftz = false;
  /// --fma-peak: measure the f32 FMA peak instead of running a scene.
  bool fmaPeak = false;
};

struct RunMetrics {
  double seconds = 0;
  unsigned long long launches = 0;
  Clock clock{};
};

/// What one thread keeps across the sub-steps of a group: the state of its
/// items and, for hip-cache, the interpolated windows.
struct Scratch {
  std::vector<float> state; // kLanes x padded group
  std::vector<float> cache; // 2 x kLanes x (group + 2 halo)
  long long stateStride = 0, slice = 0;
  explicit Scratch(int groupSize) {
    stateStride = (groupSize + kChunk - 1) / kChunk * kChunk;
    slice = (stateStride + 2 * kHalo + 15) / 16 * 16;
    state.assign(kLanes * stateStride, 0.0f);
    cache.assign(2 * kLanes * slice, 0.0f);
  }
};

template <typename Scene> class Simulation {
public:
  Simulation(const Options &options)
      : options_(options), p_(options.params),
        storage_(Scene::numBuffers, options.params.range) {
    p_.cubic = options.interp == "cubic" ? (1u << Scene::numBuffers) - 1
                                         : Scene::cubicInScene;
    groups_ = (p_.range + options.groupSize - 1) / options.groupSize;
  }

  /// Runs `steps` base steps from the initial state.
  RunMetrics run(long long steps) {
    applyFlushMode();
    init();
    RunMetrics metrics;
    Clock &clock = metrics.clock;
    clock.end = steps;
    Strategy s = options_.strategy;
    int cap = s == Strategy::Simple ? 1 : p_.maxSteps;
    bool estimates = s != Strategy::Simple;
    // Traditional estimates every component, hip only component 0 (the
    // only one that reads through the back edge).
    int estimated = s == Strategy::Traditional ? numComponents<Scene> : 1;
    unsigned long long launches = 0;

    auto start = std::chrono::steady_clock::now();
#pragma omp parallel
    {
      applyFlushMode();
      Scratch scratch(options_.groupSize);
      for (;;) {
        // Commit the big step that just ended and decide the next one.
#pragma omp single
        {
          if (clock.m > 0) {
            clock.T += clock.m;
            clock.parity ^= 1;
            clock.bigSteps += 1;
            clock.histogram[clock.m] += 1;
          }
          clock.estimate = INT_MAX;
          launches += 1;
        }
        // The minimum num_steps at T of the estimated components: each
        // thread's minimum over its groups, then the minimum of those.
        if (estimates && clock.T < clock.end) {
          int least = INT_MAX;
#pragma omp for schedule(static) nowait
          for (long long g = 0; g < groups_; ++g) {
            auto [first, end] = groupItems(g);
            for (int c = 0; c < estimated; ++c)
              least = std::min(
                  least, minSteps(c, first, end, clock.T, p_, /*floor=*/1));
          }
#pragma omp atomic compare
          if (least < clock.estimate)
            clock.estimate = least;
#pragma omp barrier
#pragma omp single nowait
          launches += 1;
        }
#pragma omp single
        {
          long long left = clock.end - clock.T;
          clock.m =
              left > 0
                  ? std::min<long long>(std::min(clock.estimate, cap), left)
                  : 0;
        }
        if (clock.m == 0)
          break;
        forEachComponent([&](auto component) {
          using Comp = decltype(component);
          if constexpr (Comp::index == 0) {
            evaluateKernel<Comp>(clock);
          } else {
            if (s == Strategy::Simple || s == Strategy::Traditional)
              evaluateKernel<Comp>(clock);
            else if (s == Strategy::Hip || s == Strategy::Lts)
              substepKernel<Comp, false>(clock, scratch);
            else
              substepKernel<Comp, true>(clock, scratch);
          }
#pragma omp single nowait
          launches += 1;
        });
      }
    }
    metrics.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count();
    metrics.launches = launches;
    if (clock.T != steps || clock.m != 0) {
      std::fprintf(stderr,
                   "error: the run ended at T = %lld, m = %lld, not at %lld\n",
                   clock.T, clock.m, steps);
      std::exit(1);
    }
    parity_ = clock.parity;
    return metrics;
  }

  /// The observed buffer at the current T, `range` x 4 floats.
  std::vector<float> observed() const {
    const Half &half = storage_.half(Scene::observed, parity_);
    std::vector<float> values(kLanes * p_.range);
    for (long long i = 0; i < p_.range; ++i)
      for (int l = 0; l < kLanes; ++l)
        values[kLanes * i + l] = half.lane[l][i];
    return values;
  }

private:
  std::pair<long long, long long> groupItems(long long g) const {
    long long first = g * options_.groupSize;
    return {first, std::min(first + options_.groupSize, p_.range)};
  }

  template <typename F> static void forEachComponent(F &&f) {
    forEachComponentImpl(std::forward<F>(f),
                         std::make_index_sequence<numComponents<Scene>>{});
  }
  template <typename F, size_t... I>
  static void forEachComponentImpl(F &&f, std::index_sequence<I...>) {
    (f(std::tuple_element_t<I, typename Scene::Components>{}), ...);
  }

  /// FTZ and DAZ in this thread's MXCSR under --ftz, as sim's CPU workers
  /// set them for a --sim-ftz bundle; IEEE subnormals otherwise.
  void applyFlushMode() const {
    constexpr unsigned kFlushBits = 0x8040; // FTZ (bit 15), DAZ (bit 6)
    if (options_.ftz)
      _mm_setcsr(_mm_getcsr() | kFlushBits);
    else
      _mm_setcsr(_mm_getcsr() & ~kFlushBits);
  }

  /// Every buffer's half 0 from its init body; half 1 zero.
  void init() {
    for (int b = 0; b < Scene::numBuffers; ++b) {
      const Half &half = storage_.half(b, 0);
      for (long long i = 0; i < p_.range; ++i)
        for (int l = 0; l < kLanes; ++l)
          half.lane[l][i] = initValue(b, i, l);
      storage_.refreshEnds(half, 0, p_.range);
      const Half &other = storage_.half(b, 1);
      for (int l = 0; l < kLanes; ++l)
        std::memset(other.lane[l] - Storage::kLeft, 0,
                    (Storage::kLeft + p_.range + Storage::kRight) *
                        sizeof(float));
    }
  }

  /// One evaluation per item with n = m from T (simple, traditional, and the
  /// component that bounds the hip step). Called by every thread of the
  /// parallel region; ends with a barrier.
  template <typename Comp> void evaluateKernel(Clock &clock) {
    int parity = clock.parity;
    int n = (int)clock.m;
    // Component 0 reads the others at T (back edge), the others read earlier
    // components at T + m: the half just written.
    HalfReader read;
    for (int b = 0; b < Scene::numBuffers; ++b)
      for (int l = 0; l < kLanes; ++l)
        read.lane[b][l] =
            storage_.half(b, Comp::index == 0 ? parity : parity ^ 1).lane[l];
    const Half &own = storage_.half(Comp::writes, parity);
    const Half &out = storage_.half(Comp::writes, parity ^ 1);
#pragma omp for schedule(static)
    for (long long g = 0; g < groups_; ++g) {
      auto [first, end] = groupItems(g);
      for (long long i0 = first; i0 < end; i0 += kChunk) {
        alignas(64) ChunkValues self, value;
        if constexpr (Comp::own)
          loadChunk(own, i0, self);
        evaluateChunk<Comp>(read, i0, self, n, p_, value);
        storeChunk(out, i0, (int)std::min<long long>(kChunk, end - i0), value);
      }
      storage_.refreshEnds(out, first, end);
    }
#pragma omp single nowait
    clock.evaluations[Comp::index] += p_.range;
  }

  /// Algorithm 2 of the paper for one component: sub-steps of the group's
  /// minimum num_steps inside the big step, the state in `scratch`, the
  /// target written once. With Cache, the window buffers' interpolated
  /// values of every sub-step are computed once for the group and its halo.
  template <typename Comp, bool Cache>
  void substepKernel(Clock &clock, Scratch &scratch) {
    long long T = clock.T, m = clock.m;
    int parity = clock.parity;
    InterpolatingReader global;
    for (int b = 0; b < Scene::numBuffers; ++b)
      for (int l = 0; l < kLanes; ++l) {
        global.source[b][l] = storage_.half(b, parity).lane[l];
        global.target[b][l] = storage_.half(b, parity ^ 1).lane[l];
      }
    const Half &own = storage_.half(Comp::writes, parity);
    const Half &out = storage_.half(Comp::writes, parity ^ 1);
    unsigned long long evaluations = 0;
#pragma omp for schedule(static)
    for (long long g = 0; g < groups_; ++g) {
      auto [first, end] = groupItems(g);
      long long items = end - first;
      auto stateOf = [&](long long i0) -> ChunkValues & {
        return *reinterpret_cast<ChunkValues *>(scratch.state.data() +
                                                kLanes * (i0 - first));
      };
      // The state, chunk by chunk: [lane][item] per chunk.
      for (long long i0 = first; i0 < end; i0 += kChunk) {
        if constexpr (Comp::own)
          loadChunk(own, i0, stateOf(i0));
        else
          std::memset(stateOf(i0), 0, sizeof(ChunkValues));
      }
      for (long long t = T; t < T + m;) {
        long long n = 1;
        if (m > 1) {
          long long left = T + m - t;
          n = left == 1
                  ? 1
                  : std::min<long long>(minSteps(Comp::index, first, end, t, p_,
                                                 /*floor=*/1),
                                        left);
        }
        global.setWeights(Weights((float)(t + n - T) / (float)m), p_.cubic,
                          Scene::numBuffers);
        if constexpr (Cache) {
          CachingReader<Comp> read{global, {}, first - kHalo};
          long long span = items + 2 * kHalo;
          for (int c = 0; c < Comp::numCached; ++c)
            for (int l = 0; l < kLanes; ++l) {
              float *slot =
                  scratch.cache.data() + (c * kLanes + l) * scratch.slice;
              read.cache[c][l] = slot;
              long long j0 = first - kHalo;
              auto fill = [&](auto view) {
#pragma omp simd
                for (long long s = 0; s < span; ++s)
                  slot[s] = view(j0 + s);
              };
              if (c == 0)
                fill(global.template view<Comp::a>(l));
              else if constexpr (Comp::numCached == 2)
                fill(global.template view<Comp::b>(l));
              // Items past the group (in its last chunk) read copies.
              for (long long s = span; s < scratch.slice; ++s)
                slot[s] = slot[span - 1];
            }
          for (long long i0 = first; i0 < end; i0 += kChunk)
            evaluateChunk<Comp>(read, i0, stateOf(i0), (int)n, p_, stateOf(i0));
        } else {
          for (long long i0 = first; i0 < end; i0 += kChunk)
            evaluateChunk<Comp>(global, i0, stateOf(i0), (int)n, p_,
                                stateOf(i0));
        }
        evaluations += items;
        t += n;
      }
      for (long long i0 = first; i0 < end; i0 += kChunk)
        storeChunk(out, i0, (int)std::min<long long>(kChunk, end - i0),
                   stateOf(i0));
      storage_.refreshEnds(out, first, end);
    }
#pragma omp atomic
    clock.evaluations[Comp::index] += evaluations;
#pragma omp barrier
  }

  Options options_;
  Params p_;
  Storage storage_;
  long long groups_ = 0;
  int parity_ = 0;
};

//===----------------------------------------------------------------------===//
// Command line, output
//===----------------------------------------------------------------------===//

const char *kOverview =
    "hand-written CPU code of the paper's scenes (sim's benchmark baseline)";

const char *kIntro =
    R"(Runs the gravity-like or PBD-like scene of examples/paper with one of the
five strategies (lts plans what hip plans for these scenes), written by hand in C++ (OpenMP threads over groups, SIMD
across the items of a group), and reports the same metrics as
`sim-run --json` (bench/run compares the two). It computes what sim's CPU
backend computes, bit for bit.
)";

const char *kFooter =
    R"(Kernel and wall time are the same here: the run's parallel region. Launches
counts the phases sim launches a kernel for (the step decision, the
estimate, one per component); there are no host syncs.

EXIT STATUS: 0 on success, 1 when the run fails, 2 on a usage error.
)";

Options parseOptions(int argc, char **argv) {
  Options o;
  sim::bench::BaselineCommandLine commandLine(
      "sim-baseline-cpu", kOverview, kIntro, kFooter, o,
      {1, 4096, 1,
       "items per group: the hip sub-step group, 1 to 4096\n"
       "(default 256)"});
  CLI::App &app = commandLine.app;
  app.add_option("--threads", o.threads,
                 "OpenMP threads, 1 to 1024 (default: OpenMP's,\n"
                 "every core unless OMP_NUM_THREADS says otherwise)")
      ->option_text("N")
      ->transform(simcli::integerIn(1, 1024, "an integer from 1 to 1024"));
  app.add_flag("--ftz", o.ftz,
               "flush subnormals to zero (FTZ and DAZ), as\n"
               "sim-run does for a bundle compiled with\n"
               "sim-translate --sim-ftz")
      ->disable_flag_override();
  app.add_flag("--fma-peak", o.fmaPeak,
               "instead of a scene, measure the f32 fused\n"
               "multiply-add peak of --threads threads (what\n"
               "bench/run's \"of peak\" column divides by) and\n"
               "print it (--json: as fma_peak_flops)")
      ->disable_flag_override();
  commandLine.parse(argc, argv);
  return o;
}

/// The instruction set the compiler targeted, as sim-run names ISA levels.
const char *isaName() {
#if defined(__AVX512F__) && defined(__AVX512BW__) && defined(__AVX512VL__)
  return "x86-64-v4";
#elif defined(__AVX2__) && defined(__FMA__)
  return "x86-64-v3";
#elif defined(__SSE4_2__)
  return "x86-64-v2";
#elif defined(__x86_64__)
  return "x86-64";
#else
  return "generic";
#endif
}

/// The f32 fused multiply-add peak of the threads OpenMP runs, in flop/s:
/// every thread runs independent chains of FMAs on the widest vectors the
/// compiler targets, enough of them to hide the FMA latency on both FMA
/// units and few enough to stay in registers; the best of a few trials.
/// x := x * a + b converges to 1 (no overflow, no subnormal).
double measureFmaPeak() {
#if defined(__AVX512F__)
  constexpr int kWidth = 16, kChains = 16; // 32 zmm registers
#elif defined(__AVX__)
  constexpr int kWidth = 8, kChains = 12; // 16 ymm registers
#else
  constexpr int kWidth = 4, kChains = 12; // 16 xmm registers
#endif
  typedef float Vector __attribute__((vector_size(kWidth * sizeof(float))));
  constexpr long long kIterations = 1 << 25;
  double best = 0;
  for (int trial = 0; trial < 3; ++trial) {
    double start = omp_get_wtime();
    float sink = 0;
#pragma omp parallel reduction(+ : sink)
    {
      Vector x[kChains], a, b;
      for (int lane = 0; lane < kWidth; ++lane) {
        a[lane] = 1.0f - 0x1p-20f;
        b[lane] = 0x1p-20f;
      }
      for (int c = 0; c < kChains; ++c)
        for (int lane = 0; lane < kWidth; ++lane)
          x[c][lane] = float(c + lane) * 0x1p-8f;
      for (long long i = 0; i < kIterations; ++i)
        for (int c = 0; c < kChains; ++c)
          x[c] = __builtin_elementwise_fma(x[c], a, b);
      for (int c = 0; c < kChains; ++c)
        for (int lane = 0; lane < kWidth; ++lane)
          sink += x[c][lane];
    }
    double seconds = omp_get_wtime() - start;
    if (!(sink > 0))
      std::fprintf(stderr, "warning: the FMA chains ended at %g\n", sink);
    double flops = 2.0 * kWidth * kChains * double(kIterations) *
                   double(omp_get_max_threads());
    best = std::max(best, flops / seconds);
  }
  return best;
}

int runFmaPeak(const Options &o) {
  if (o.threads > 0)
    omp_set_num_threads(o.threads);
  int threads = omp_get_max_threads();
  double peak = measureFmaPeak();
  std::printf("f32 FMA peak: %.1f GFLOP/s (%d %s, %s)\n", peak * 1e-9, threads,
              threads == 1 ? "thread" : "threads", isaName());
  if (!o.jsonPath.empty()) {
    nlohmann::ordered_json json = {
        {"fma_peak_flops", peak}, {"threads", threads}, {"isa", isaName()}};
    if (!sim::bench::writeJson(o.jsonPath, json))
      return 1;
  }
  return 0;
}

template <typename Scene> int runScene(const Options &o) {
  if (o.threads > 0)
    omp_set_num_threads(o.threads);
  int threads = omp_get_max_threads();
  std::string device = "CPU (" + std::to_string(threads) +
                       (threads == 1 ? " thread, " : " threads, ") + isaName() +
                       ")";
  Simulation<Scene> simulation(o);
  std::vector<double> times;
  RunMetrics last;
  int total = o.repeat > 1 ? o.repeat + 1 : 1;
  for (int r = 0; r < total; ++r) {
    RunMetrics metrics = simulation.run(o.steps);
    if (total > 1 && r == 0)
      continue; // warm-up
    times.push_back(metrics.seconds);
    last = metrics;
  }
  const Clock &clock = last.clock;

  std::printf("%s %s (hand-written, cpu): range %lld, group size %d, %lld "
              "base steps",
              Scene::name, strategyName(o.strategy), (long long)o.params.range,
              o.groupSize, o.steps);
  if (o.repeat > 1)
    std::printf(", median of %d runs after a warm-up", o.repeat);
  std::printf("\n  device           %s\n", device.c_str());
  std::printf("  time             %.3f ms\n", 1e3 * median(times));
  std::printf("  launches         %llu\n", last.launches);
  std::printf("  big steps        %llu\n  big-step sizes  ", clock.bigSteps);
  for (int m = 1; m <= kMaxSteps; ++m)
    std::printf(" %d: %llu", m, clock.histogram[m]);
  std::printf("\n  evaluations     ");
  for (int c = 0; c < numComponents<Scene>; ++c)
    std::printf(" C%d %llu", c, clock.evaluations[c]);
  std::printf("\n");

  if (!o.dumpDir.empty())
    writeNpy(o.dumpDir + "/B" + std::to_string(Scene::observed) + ".npy",
             simulation.observed(), o.params.range);
  if (!o.jsonPath.empty()) {
    sim::bench::RunRecord run =
        sim::bench::recordOf(o, Scene::name, strategyName(o.strategy));
    run.backend = "cpu";
    run.device = device;
    // Kernel and wall time are the same here: the run's parallel region.
    run.walls = run.kernels = times;
    run.wall = run.kernel = median(times);
    run.launches = last.launches;
    run.bigSteps = clock.bigSteps;
    nlohmann::ordered_json json = sim::bench::runJson(run);
    json["threads"] = threads;
    json["subnormals"] = o.ftz ? "flush-to-zero" : "ieee";
    sim::bench::addCounts(json, clock, kMaxSteps, numComponents<Scene>);
    if (!sim::bench::writeJson(o.jsonPath, json))
      return 1;
  }
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  Options options = parseOptions(argc, argv);
  if (options.fmaPeak)
    return runFmaPeak(options);
  if (options.scene == "gravity_like")
    return runScene<GravityLike>(options);
  return runScene<PbdLike>(options);
}
