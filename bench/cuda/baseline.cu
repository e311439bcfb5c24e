//===- baseline.cu - Hand-written CUDA of the paper's two scenes ----------===//
//
// What a user would write instead of sim: the gravity-like and PBD-like
// scenes of examples/paper, each with the four algorithms (simple,
// traditional, hip = the paper's HIP-NoCache, hip-cache = HIP), written by
// hand in CUDA for the benchmarks of bench/run. It computes the same numbers
// as the scenes compiled by sim (docs/Model.md is the contract; the bodies
// are those python/simscene generates), so bench/run can check the final
// state against sim's and compare times algorithm by algorithm.
//
// Like sim's runtime it keeps the clock (T, m, parity, the step estimate) in
// device memory, launches the step kernels in batches and reads the clock
// once per batch; --m-on-host reads it after every big step instead, as the
// paper's implementation does.
//
// The same source compiles for the host (cuda_compat.h), where CI checks it
// against sim-run --backend cpu bit for bit (test/Bench/baseline.test).
//
//===----------------------------------------------------------------------===//

#include "cuda_compat.h"

#include "../common/BaselineOptions.h"
#include "../common/Outputs.h"
#include "../common/RunJson.h"
#include "../common/Scenes.h"

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

//===----------------------------------------------------------------------===//
// The scenes
//===----------------------------------------------------------------------===//

/// Every buffer holds two halves of `range` elements; half `parity` of the
/// clock is the state at T.
struct Buffers {
  float4 *base[kMaxBuffers];
};

struct Clock {
  long long T, m, end;
  int parity;
  int estimate; // minimum num_steps for the next big step
  unsigned long long bigSteps;
  unsigned long long histogram[kMaxSteps + 1];
  unsigned long long evaluations[kMaxComponents];
};

__host__ __device__ __forceinline__ long long minOf(long long a, long long b) {
  return a < b ? a : b;
}

__host__ __device__ __forceinline__ uint64_t splitmix64(uint64_t z) {
  z = (z ^ (z >> 30)) * kMixMul1;
  z = (z ^ (z >> 27)) * kMixMul2;
  return z ^ (z >> 31);
}

/// The scenes' vector.fma: one rounding on every backend of sim
/// (--sim-fused-multiply-add lowers it to llvm.intr.fma), so fma.rn here
/// and libm's correctly rounded fmaf in the host build.
__device__ __forceinline__ float fmaLikeSim(float a, float b, float c) {
#ifdef __CUDACC__
  return __fmaf_rn(a, b, c);
#else
  return std::fma(a, b, c);
#endif
}
/// The init body of buffer `seed` at item i: four floats in [-1, 1).
__device__ __forceinline__ float4 initValue(int seed, long long i) {
  float lanes[4];
  for (int lane = 0; lane < 4; ++lane) {
    uint64_t x =
        (4ull * (uint64_t)i + lane) * kKeyMul ^ (uint64_t)(seed + 1) * kGolden;
    float u = (float)(splitmix64(x) >> 40);
    lanes[lane] = fmaLikeSim(u, 1.1920928955078125e-7f, -1.0f);
  }
  return make_float4(lanes[0], lanes[1], lanes[2], lanes[3]);
}

/// The num_steps body of component c, clamped to [1, max_steps].
__device__ __forceinline__ int numSteps(int c, long long i, long long t,
                                        const Params &p) {
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

__device__ __forceinline__ float4 add(float4 a, float4 b) {
  return make_float4(a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w);
}
__device__ __forceinline__ float4 sub(float4 a, float4 b) {
  return make_float4(a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w);
}
__device__ __forceinline__ float4 mul(float4 a, float4 b) {
  return make_float4(a.x * b.x, a.y * b.y, a.z * b.z, a.w * b.w);
}
__device__ __forceinline__ float4 scale(float s, float4 a) {
  return make_float4(s * a.x, s * a.y, s * a.z, s * a.w);
}
__device__ __forceinline__ float4 fma4(float s, float4 a, float4 c) {
  return make_float4(fmaLikeSim(s, a.x, c.x), fmaLikeSim(s, a.y, c.y),
                     fmaLikeSim(s, a.z, c.z), fmaLikeSim(s, a.w, c.w));
}

/// The load and the new value: L rounds of X := M X with M = rows / 4, the
/// sum of X's rows plus the bias, then tanh, relaxed towards from `self`
/// over n base steps when the component has a state.
template <bool Own>
__device__ __forceinline__ float4 loadAndUpdate(float4 r0, float4 r1, float4 r2,
                                                float4 r3, float4 bias,
                                                float4 self, int n,
                                                const Params &p) {
  float4 m0 = scale(0.25f, r0), m1 = scale(0.25f, r1);
  float4 m2 = scale(0.25f, r2), m3 = scale(0.25f, r3);
  float4 x0 = m0, x1 = m1, x2 = m2, x3 = m3;
  for (int round = 0; round < p.rounds; ++round) {
    float4 y0 = fma4(m0.w, x3, fma4(m0.z, x2, fma4(m0.y, x1, scale(m0.x, x0))));
    float4 y1 = fma4(m1.w, x3, fma4(m1.z, x2, fma4(m1.y, x1, scale(m1.x, x0))));
    float4 y2 = fma4(m2.w, x3, fma4(m2.z, x2, fma4(m2.y, x1, scale(m2.x, x0))));
    float4 y3 = fma4(m3.w, x3, fma4(m3.z, x2, fma4(m3.y, x1, scale(m3.x, x0))));
    x0 = y0;
    x1 = y1;
    x2 = y2;
    x3 = y3;
  }
  float4 force = add(add(add(add(x0, x1), x2), x3), bias);
  float4 target = make_float4(tanhf(force.x), tanhf(force.y), tanhf(force.z),
                              tanhf(force.w));
  if (!Own)
    return target;
  float h = (float)n * p.dt;
  h = h < 1.0f ? h : 1.0f;
  return fma4(h, sub(target, self), self);
}

__device__ __forceinline__ long long clampItem(long long j, long long range) {
  return j < 0 ? 0 : (j >= range ? range - 1 : j);
}

/// One evaluation of component `Comp` at item i. `read.template get<B>(j)`
/// is buffer B at item j as the component sees it (its value at T through
/// the back edge, or interpolated at the end of the sub-step).
template <typename Comp, typename Reader>
__device__ __forceinline__ float4 evaluate(const Reader &read, long long i,
                                           float4 self, int n,
                                           const Params &p) {
  constexpr int A = Comp::a, B = Comp::b;
  constexpr Pattern P = Comp::pattern;
  if constexpr (P == Pattern::PointOwn) {
    float4 point = read.template get<A>(i);
    float4 prod = mul(point, self);
    float4 halfDiff = scale(0.5f, sub(point, self));
    return loadAndUpdate<true>(point, self, prod, halfDiff, point, self, n, p);
  } else {
    const float ninth = 0.111111112f;
    float4 sumA = make_float4(0, 0, 0, 0), sumB = make_float4(0, 0, 0, 0);
    for (int k = -kHalo; k <= kHalo; ++k) {
      sumA = add(sumA, read.template get<A>(i + k));
      if constexpr (P == Pattern::TwoWindows || P == Pattern::TwoWindowsOwn)
        sumB = add(sumB, read.template get<B>(i + k));
    }
    float4 meanA = scale(ninth, sumA);
    if constexpr (P == Pattern::OneWindow) {
      return loadAndUpdate<false>(
          meanA, read.template get<A>(i), read.template get<A>(i - 1),
          read.template get<A>(i + 1), meanA, self, n, p);
    } else if constexpr (P == Pattern::TwoWindows ||
                         P == Pattern::TwoWindowsOwn) {
      float4 meanB = scale(ninth, sumB);
      return loadAndUpdate<Comp::own>(meanA, meanB, read.template get<A>(i),
                                      read.template get<B>(i), meanA, self, n,
                                      p);
    } else if constexpr (P == Pattern::WindowPoint) {
      return loadAndUpdate<false>(
          meanA, read.template get<A>(i), read.template get<B>(i),
          read.template get<A>(i - 1), meanA, self, n, p);
    } else {
      static_assert(P == Pattern::WindowOwn, "a pattern without rows");
      return loadAndUpdate<true>(meanA, read.template get<A>(i), self,
                                 read.template get<A>(i - 1), meanA, self, n,
                                 p);
    }
  }
}

//===----------------------------------------------------------------------===//
// Readers: where a read's value comes from
//===----------------------------------------------------------------------===//

/// One half of every buffer: the state at T (back edge) or at T + m.
struct HalfReader {
  const float4 *half[kMaxBuffers];
  long long range;
  template <int B> __device__ __forceinline__ float4 get(long long j) const {
    return half[B][clampItem(j, range)];
  }
};

/// The weights of the value at T and at T + m at fraction f of the big
/// step, as sim's interpolation attributes compute them.
struct Weights {
  float beginLinear, endLinear, beginCubic, endCubic;
  __device__ __forceinline__ explicit Weights(float f) {
    beginLinear = 1.0f - f;
    endLinear = f;
    float twoF = 2.0f * f;
    float s = (f * f) * (3.0f - twoF);
    beginCubic = 1.0f - s;
    endCubic = s;
  }
};

/// Interpolated between the halves (every buffer a later component reads
/// was written earlier in the step in these scenes).
struct InterpolatingReader {
  const float4 *source[kMaxBuffers];
  const float4 *target[kMaxBuffers];
  long long range;
  unsigned cubic;
  Weights weights;
  template <int B> __device__ __forceinline__ float4 get(long long j) const {
    long long item = clampItem(j, range);
    // A uniform select, not an indexed array, keeps the weights in registers.
    bool smooth = (cubic >> B) & 1;
    float begin = smooth ? weights.beginCubic : weights.beginLinear;
    float end = smooth ? weights.endCubic : weights.endLinear;
    return add(scale(begin, source[B][item]), scale(end, target[B][item]));
  }
};

/// hip-cache: the window buffers of the component come from shared memory,
/// filled once per sub-step for the group's items and the halo.
template <typename Comp> struct CachingReader {
  InterpolatingReader global;
  const float4 *cache; // numCached slices of (group + 2 * halo) elements
  long long first;     // the item in slot 0: the group's first minus the halo
  int slice;
  template <int B> __device__ __forceinline__ float4 get(long long j) const {
    if constexpr (B == Comp::a && Comp::numCached >= 1)
      return cache[j - first];
    else if constexpr (B == Comp::b && Comp::numCached == 2)
      return cache[slice + (j - first)];
    else
      return global.template get<B>(j);
  }
};

//===----------------------------------------------------------------------===//
// Kernels
//===----------------------------------------------------------------------===//

__device__ __forceinline__ const float4 *halfOf(const Buffers &buffers, int b,
                                                int half, long long range) {
  return buffers.base[b] + (half ? range : 0);
}

template <typename Scene>
__global__ void initKernel(Clock *clock, Buffers buffers, Params p) {
  long long i = (long long)blockIdx.x * blockDim.x + threadIdx.x;
  if (i == 0) {
    *clock = Clock{};
    clock->estimate = INT_MAX;
  }
  if (i >= p.range)
    return;
  for (int b = 0; b < Scene::numBuffers; ++b)
    buffers.base[b][i] = initValue(b, i);
}

/// Commits the big step that just ended and decides the next one.
__global__ void advanceKernel(Clock *clock, int cap) {
  if (clock->m > 0) {
    clock->T += clock->m;
    clock->parity ^= 1;
    clock->bigSteps += 1;
    clock->histogram[clock->m] += 1;
  }
  long long left = clock->end - clock->T;
  clock->m = left > 0 ? minOf(minOf(clock->estimate, cap), left) : 0;
  clock->estimate = INT_MAX;
}

/// The minimum of num_steps of components [First, Last) over every item,
/// at the start T + m of the next big step, into clock->estimate.
template <int First, int Last>
__global__ void estimateKernel(Clock *clock, Params p) {
  __shared__ int blockMin;
  long long next = clock->T + clock->m;
  if (next >= clock->end)
    return;
  if (threadIdx.x == 0)
    blockMin = INT_MAX;
  __syncthreads();
  long long i = (long long)blockIdx.x * blockDim.x + threadIdx.x;
  if (i < p.range) {
    int mine = INT_MAX;
    for (int c = First; c < Last; ++c)
      mine = (int)minOf(mine, numSteps(c, i, next, p));
    atomicMin(&blockMin, mine);
  }
  __syncthreads();
  if (threadIdx.x == 0)
    atomicMin(&clock->estimate, blockMin);
}

__device__ __forceinline__ int itemsInGroup(const Params &p) {
  long long first = (long long)blockIdx.x * blockDim.x;
  return (int)minOf(blockDim.x, p.range - first);
}

/// One evaluation per item with n = m from T (simple, traditional, and the
/// component that bounds the hip step).
template <typename Scene, typename Comp>
__global__ void evaluateKernel(Clock *clock, Buffers buffers, Params p) {
  long long m = clock->m;
  if (m == 0)
    return;
  int parity = clock->parity;
  long long i = (long long)blockIdx.x * blockDim.x + threadIdx.x;
  if (threadIdx.x == 0)
    atomicAdd(&clock->evaluations[Comp::index],
              (unsigned long long)itemsInGroup(p));
  if (i >= p.range)
    return;
  // Component 0 reads the others at T (back edge), the others read earlier
  // components at T + m: the half just written.
  HalfReader read;
  read.range = p.range;
  for (int b = 0; b < Scene::numBuffers; ++b)
    read.half[b] =
        halfOf(buffers, b, Comp::index == 0 ? parity : parity ^ 1, p.range);
  float4 self = Comp::own ? halfOf(buffers, Comp::writes, parity, p.range)[i]
                          : make_float4(0, 0, 0, 0);
  float4 value = evaluate<Comp>(read, i, self, (int)m, p);
  buffers.base[Comp::writes][(parity ^ 1 ? p.range : 0) + i] = value;
}

/// Algorithm 2 of the paper for one component: sub-steps of the group's
/// minimum num_steps inside the big step, the state in a register, the
/// target written once. With Cache, the window buffers' interpolated values
/// of every sub-step are staged in shared memory.
template <typename Scene, typename Comp, bool Cache>
__global__ void substepKernel(Clock *clock, Buffers buffers, Params p) {
  // Three slots, so one barrier per sub-step is enough: the slot of sub-step
  // k + 2 is reset after the barrier of sub-step k, when every thread has
  // read the slot of sub-step k - 1 (the same one).
  __shared__ int stepMin[3];
  SIM_DYNAMIC_SHARED(float4, cache);
  long long m = clock->m;
  if (m == 0)
    return;
  long long T = clock->T;
  int parity = clock->parity;
  long long first = (long long)blockIdx.x * blockDim.x;
  long long i = first + threadIdx.x;
  bool valid = i < p.range;

  InterpolatingReader global{{}, {}, p.range, p.cubic, Weights(1.0f)};
  for (int b = 0; b < Scene::numBuffers; ++b) {
    global.source[b] = halfOf(buffers, b, parity, p.range);
    global.target[b] = halfOf(buffers, b, parity ^ 1, p.range);
  }
  float4 state = Comp::own && valid ? global.source[Comp::writes][i]
                                    : make_float4(0, 0, 0, 0);
  if (threadIdx.x < 3)
    stepMin[threadIdx.x] = INT_MAX;
  __syncthreads();

  int slice = blockDim.x + 2 * kHalo;
  unsigned long long evaluations = 0;
  int group = itemsInGroup(p);
  long long t = T;
  for (int k = 0; t < T + m; ++k) {
    long long n = 1;
    if (m > 1) {
      if (valid)
        atomicMin(&stepMin[k % 3], numSteps(Comp::index, i, t, p));
      __syncthreads();
      n = minOf(stepMin[k % 3], T + m - t);
      if (threadIdx.x == 0)
        stepMin[(k + 2) % 3] = INT_MAX;
    }
    global.weights = Weights((float)(t + n - T) / (float)m);
    if constexpr (Cache) {
      // Every lane fills slots a group apart: the group and its halo.
      for (int s = threadIdx.x; s < slice; s += blockDim.x) {
        long long j = first - kHalo + s;
        cache[s] = global.template get<Comp::a>(j);
        if constexpr (Comp::numCached == 2)
          cache[slice + s] = global.template get<Comp::b>(j);
      }
      __syncthreads();
      CachingReader<Comp> read{global, cache, first - kHalo, slice};
      // The next sub-step's fill waits for its minimum's barrier, which
      // every lane reaches only after its reads of this one.
      if (valid)
        state = evaluate<Comp>(read, i, state, (int)n, p);
    } else {
      if (valid)
        state = evaluate<Comp>(global, i, state, (int)n, p);
    }
    evaluations += group;
    t += n;
  }
  if (valid)
    buffers.base[Comp::writes][(parity ^ 1 ? p.range : 0) + i] = state;
  if (threadIdx.x == 0)
    atomicAdd(&clock->evaluations[Comp::index], evaluations);
}

//===----------------------------------------------------------------------===//
// The host side
//===----------------------------------------------------------------------===//

// Lts: the scenes here read no buffer of their own at other items, so no
// component takes local time steps and lts plans what hip plans (docs/
// Model.md, "Local time stepping"): it runs as Hip.
using sim::bench::median;
using sim::bench::Strategy;
using sim::bench::strategyName;
using sim::bench::writeNpy;

struct Options : sim::bench::SceneOptions {
  /// Read the clock after every big step, as the paper's implementation.
  bool mOnHost = false;
};

struct RunMetrics {
  double wallSeconds = 0, kernelSeconds = 0;
  unsigned long long launches = 0, hostSyncs = 0;
  Clock clock{};
};

template <typename Scene> class Simulation {
public:
  Simulation(const Options &options) : options_(options), p_(options.params) {
    p_.cubic = options.interp == "cubic" ? (1u << Scene::numBuffers) - 1
                                         : Scene::cubicInScene;
    clock_ = compat::deviceAlloc<Clock>(1);
    for (int b = 0; b < kMaxBuffers; ++b)
      buffers_.base[b] = b < Scene::numBuffers
                             ? compat::deviceAlloc<float4>(2 * p_.range)
                             : nullptr;
    blocks_ =
        (unsigned)((p_.range + options.groupSize - 1) / options.groupSize);
  }
  ~Simulation() {
    compat::deviceFree(clock_);
    for (int b = 0; b < Scene::numBuffers; ++b)
      compat::deviceFree(buffers_.base[b]);
  }

  /// Runs `steps` base steps from the initial state.
  RunMetrics run(long long steps) {
    RunMetrics metrics;
    compat::launch(initKernel<Scene>, blocks_, threads(), 0, clock_, buffers_,
                   p_);
    // The run's end: the host writes it, like sim's runtime.
    Clock start{};
    compat::copyToHost(&start, clock_, 1);
    start.end = steps;
    compat::copyToDevice(clock_, &start, 1);

    auto wallStart = std::chrono::steady_clock::now();
    compat::Timer timer;
    timer.start();
    int cap = options_.strategy == Strategy::Simple ? 1 : p_.maxSteps;
    long long reached = 0;
    // Batches of step phases, sized by the big steps of the last batch, as
    // sim's runtime sizes them; one host synchronisation per batch.
    double meanStep = cap;
    while (reached < steps) {
      long long batch = (long long)std::ceil((steps - reached) / meanStep);
      batch = std::max(1ll, std::min(256ll, batch));
      if (options_.mOnHost)
        batch = 1;
      for (long long k = 0; k < batch; ++k)
        stepPhase(metrics, cap);
      Clock clock;
      compat::copyToHost(&clock, clock_, 1);
      metrics.hostSyncs += 1;
      if (clock.T + clock.m <= reached) {
        std::fprintf(stderr, "error: the clock made no progress at T = %lld\n",
                     clock.T);
        std::exit(1);
      }
      meanStep = std::clamp((double)(clock.T + clock.m - reached) / batch, 1.0,
                            (double)cap);
      reached = clock.T + clock.m;
    }
    compat::launch(advanceKernel, 1, 1, 0, clock_, cap);
    metrics.launches += 1;
    metrics.kernelSeconds = timer.stopSeconds();
    metrics.wallSeconds = std::chrono::duration<double>(
                              std::chrono::steady_clock::now() - wallStart)
                              .count();
    compat::copyToHost(&metrics.clock, clock_, 1);
    metrics.hostSyncs += 1;
    if (metrics.clock.T != steps || metrics.clock.m != 0) {
      std::fprintf(stderr,
                   "error: the run ended at T = %lld, m = %lld, not at "
                   "%lld\n",
                   metrics.clock.T, metrics.clock.m, steps);
      std::exit(1);
    }
    return metrics;
  }

  /// The observed buffer at the current T, `range` x 4 floats.
  std::vector<float> observed() {
    Clock clock;
    compat::copyToHost(&clock, clock_, 1);
    std::vector<float4> items(p_.range);
    compat::copyToHost(items.data(),
                       buffers_.base[Scene::observed] +
                           (clock.parity ? p_.range : 0),
                       p_.range);
    std::vector<float> values;
    values.reserve(4 * p_.range);
    for (const float4 &v : items)
      values.insert(values.end(), {v.x, v.y, v.z, v.w});
    return values;
  }

private:
  unsigned threads() const { return (unsigned)options_.groupSize; }

  template <typename F> static void forEachComponent(F &&f) {
    forEachComponentImpl(std::forward<F>(f),
                         std::make_index_sequence<numComponents<Scene>>{});
  }
  template <typename F, size_t... I>
  static void forEachComponentImpl(F &&f, std::index_sequence<I...>) {
    (f(std::tuple_element_t<I, typename Scene::Components>{}), ...);
  }

  void stepPhase(RunMetrics &metrics, int cap) {
    Strategy s = options_.strategy;
    if (s == Strategy::Traditional) {
      // One kernel estimates every component (sim launches one each).
      compat::launch(estimateKernel<0, numComponents<Scene>>, blocks_,
                     threads(), 0, clock_, p_);
      metrics.launches += 1;
    } else if (s != Strategy::Simple) {
      // Component 0 is the only one that reads through the back edge.
      compat::launch(estimateKernel<0, 1>, blocks_, threads(), 0, clock_, p_);
      metrics.launches += 1;
    }
    compat::launch(advanceKernel, 1, 1, 0, clock_, cap);
    metrics.launches += 1;
    forEachComponent([&](auto component) {
      using Comp = decltype(component);
      if constexpr (Comp::index == 0) {
        compat::launch(evaluateKernel<Scene, Comp>, blocks_, threads(), 0,
                       clock_, buffers_, p_);
      } else if (s == Strategy::Simple || s == Strategy::Traditional) {
        compat::launch(evaluateKernel<Scene, Comp>, blocks_, threads(), 0,
                       clock_, buffers_, p_);
      } else if (s == Strategy::Hip || s == Strategy::Lts) {
        compat::launch(substepKernel<Scene, Comp, false>, blocks_, threads(), 0,
                       clock_, buffers_, p_);
      } else {
        size_t shared = (size_t)Comp::numCached *
                        (options_.groupSize + 2 * kHalo) * sizeof(float4);
        compat::launch(substepKernel<Scene, Comp, true>, blocks_, threads(),
                       shared, clock_, buffers_, p_);
      }
      metrics.launches += 1;
    });
  }

  Options options_;
  Params p_;
  Clock *clock_ = nullptr;
  Buffers buffers_{};
  unsigned blocks_ = 0;
};

//===----------------------------------------------------------------------===//
// Command line, output
//===----------------------------------------------------------------------===//

const char *kOverview = "hand-written CUDA of the paper's scenes (sim's "
                        "benchmark baseline)";

const char *kIntro =
    R"(Runs the gravity-like or PBD-like scene of examples/paper with one of the
five strategies (lts plans what hip plans for these scenes), written by hand, and reports the same metrics as
`sim-run --json` (bench/run compares the two). sim-baseline-host runs the
same kernels emulated on the CPU, for checking.
)";

const char *kFooter =
    R"(EXIT STATUS: 0 on success, 1 when the run fails, 2 on a usage error.
)";

Options parseOptions(int argc, char **argv) {
  Options o;
  sim::bench::BaselineCommandLine commandLine(
      compat::programName(), kOverview, kIntro, kFooter, o,
      {32, 1024, 32,
       "threads per group: the hip sub-step group, a\n"
       "multiple of 32 from 32 to 1024 (default 256)"});
  commandLine.app
      .add_flag("--m-on-host", o.mOnHost,
                "read the clock after every big step (the paper's\n"
                "implementation) instead of once per batch")
      ->disable_flag_override();
  commandLine.parse(argc, argv);
  return o;
}

template <typename Scene> int runScene(const Options &o) {
  std::string device = compat::deviceName();
  Simulation<Scene> simulation(o);
  std::vector<double> walls, kernels;
  RunMetrics last;
  int total = o.repeat > 1 ? o.repeat + 1 : 1;
  for (int r = 0; r < total; ++r) {
    RunMetrics metrics = simulation.run(o.steps);
    if (total > 1 && r == 0)
      continue; // warm-up
    walls.push_back(metrics.wallSeconds);
    kernels.push_back(metrics.kernelSeconds);
    last = metrics;
  }
  const Clock &clock = last.clock;

  std::printf("%s %s (hand-written, %s%s): range %lld, group size %d, %lld "
              "base steps",
              Scene::name, strategyName(o.strategy), compat::backendName(),
              o.mOnHost ? ", m on host" : "", (long long)o.params.range,
              o.groupSize, o.steps);
  if (o.repeat > 1)
    std::printf(", median of %d runs after a warm-up", o.repeat);
  std::printf("\n  device           %s\n", device.c_str());
  std::printf("  kernel time      %.3f ms\n", 1e3 * median(kernels));
  std::printf("  wall time        %.3f ms\n", 1e3 * median(walls));
  std::printf("  launches         %llu\n", last.launches);
  std::printf("  host syncs       %llu\n", last.hostSyncs);
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
    run.backend = compat::backendName();
    run.device = device;
    run.mOnHost = o.mOnHost;
    run.walls = walls;
    run.kernels = kernels;
    run.wall = median(walls);
    run.kernel = median(kernels);
    run.launches = last.launches;
    run.hostSyncs = last.hostSyncs;
    run.bigSteps = clock.bigSteps;
    nlohmann::ordered_json json = sim::bench::runJson(run);
    sim::bench::addCounts(json, clock, kMaxSteps, numComponents<Scene>);
    if (!sim::bench::writeJson(o.jsonPath, json))
      return 1;
  }
  return 0;
}

} // namespace

int main(int argc, char **argv) {
  Options options = parseOptions(argc, argv);
  if (options.scene == "gravity_like")
    return runScene<GravityLike>(options);
  return runScene<PbdLike>(options);
}
