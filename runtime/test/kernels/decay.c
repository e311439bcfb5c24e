/*===- decay.c - hand-written CPU kernels of the test scene "decay" -------===
 *
 * What the compiler's CPU path will produce, written by hand after the ABI
 * of docs/Bundle.md and the clock of docs/Plan.md, so that the runtime can
 * be tested before a compiler-made bundle exists. Built twice: SIM_CAP = 1
 * for the simple plan, SIM_CAP = 4 (max_steps) for the hip plan. decay.cu
 * is the same for the GPU.
 *
 * The scene (TestBundle.cpp has its text):
 *   X : f64, x' = -k x, advanced per base step: x *= (1 - k dt) n times;
 *       exact solution x0 exp(-k t). Item 7 turns NaN from base step
 *       `poison` on (poison < 0: never).
 *   V : vector<3xf32> (stride 16): lane 0 counts base steps, lane 1 is the
 *       item, lane 2 counts evaluations; the padding lane holds 12345, so a
 *       runtime that does not strip it is caught.
 *   num_steps of Decay at T: 1 + (T / 5) % 4 for every item.
 *
 *===----------------------------------------------------------------------===*/

#include <math.h>
#include <stdint.h>

#ifndef SIM_CAP
#error "define SIM_CAP (the largest big step of the strategy)"
#endif

enum {
  kBegin = 0,
  kSize = 1,
  kParity = 2,
  kEnd = 3,
  kEstimate = 4,
  kBigSteps = 5,
  kCuts = 6,
  kDecayEvaluations = 8,
  kGrowEvaluations = 9,
  kHistogram = 10,
  kPoisonItem = 7,
};

#define EXPORT __attribute__((visibility("default")))

/* A memref argument is five parameters; the aligned pointer is the second. */
static void *memref(void **params, int at) { return *(void **)params[at + 1]; }
static int64_t memrefSize(void **params, int at) {
  return *(int64_t *)params[at + 3];
}
static int64_t i64(void **params, int at) { return *(int64_t *)params[at]; }
static int32_t i32(void **params, int at) { return *(int32_t *)params[at]; }
static double f64(void **params, int at) { return *(double *)params[at]; }

static int64_t load(int64_t *clock, int slot) {
  return __atomic_load_n(&clock[slot], __ATOMIC_RELAXED);
}

static void atomicMin(int64_t *slot, int64_t value) {
  int64_t old = __atomic_load_n(slot, __ATOMIC_RELAXED);
  while (value < old &&
         !__atomic_compare_exchange_n(slot, &old, value, 1, __ATOMIC_RELAXED,
                                      __ATOMIC_RELAXED)) {
  }
}

static int64_t numSteps(int64_t t) { return 1 + (t / 5) % 4; }

/* The items of groups [first, end) below `range`. */
#define FOR_ITEMS(i)                                                           \
  for (int64_t g = first; g < end; ++g)                                        \
    for (int64_t i = g * groupSize; i < (g + 1) * groupSize && i < range; ++i)

EXPORT void sim_cpu_reset_clock(void **params, int64_t first, int64_t end,
                                int64_t groupSize) {
  (void)first, (void)end, (void)groupSize;
  int64_t *clock = memref(params, 0);
  for (int64_t slot = 0; slot < memrefSize(params, 0); ++slot)
    clock[slot] = 0;
  clock[kEstimate] = INT64_MAX;
}

EXPORT void sim_cpu_init_X(void **params, int64_t first, int64_t end,
                           int64_t groupSize) {
  double *x = memref(params, 0);
  int64_t range = i64(params, 5);
  FOR_ITEMS(i) { x[i] = 1.0 + 0.01 * (double)i; }
}

EXPORT void sim_cpu_init_V(void **params, int64_t first, int64_t end,
                           int64_t groupSize) {
  float *v = memref(params, 0);
  int64_t range = i64(params, 5);
  FOR_ITEMS(i) {
    v[4 * i + 0] = 0;
    v[4 * i + 1] = (float)i;
    v[4 * i + 2] = 0;
    v[4 * i + 3] = 12345;
  }
}

/* Minimum of num_steps over all items at the start of the next big step. */
EXPORT void sim_cpu_estimate_Decay(void **params, int64_t first, int64_t end,
                                   int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  int64_t range = i64(params, 5);
  int64_t next = load(clock, kBegin) + load(clock, kSize);
  if (next >= load(clock, kEnd))
    return;
  int64_t least = INT64_MAX;
  FOR_ITEMS(i) {
    (void)i;
    int64_t n = numSteps(next);
    least = n < least ? n : least;
  }
  atomicMin(&clock[kEstimate], least);
}

/* Commits the big step that ended and decides the next (docs/Plan.md). */
EXPORT void sim_cpu_advance(void **params, int64_t first, int64_t end,
                            int64_t groupSize) {
  (void)first, (void)end, (void)groupSize;
  int64_t *clock = memref(params, 0);
  int64_t size = clock[kSize];
  int64_t now = clock[kBegin] + size;
  int64_t parity = size > 0 ? clock[kParity] ^ 1 : clock[kParity];
  int64_t remaining = clock[kEnd] - now;
  int64_t bound = SIM_CAP;
  if (clock[kEstimate] < bound)
    bound = clock[kEstimate];
  int64_t next = remaining > 0 ? (bound < remaining ? bound : remaining) : 0;
  clock[kBigSteps] += size > 0;
  clock[kCuts] += remaining > 0 && remaining < bound;
  clock[kBegin] = now;
  clock[kSize] = next;
  clock[kParity] = parity;
  clock[kEstimate] = INT64_MAX;
  if (next > 0)
    clock[kHistogram + next] += 1;
}

EXPORT void sim_cpu_evaluate_Decay(void **params, int64_t first, int64_t end,
                                   int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  double *x = memref(params, 5);
  double k = f64(params, 10);
  int32_t poison = i32(params, 11);
  int64_t range = i64(params, 12);
  double dt = f64(params, 13);
  int64_t t = load(clock, kBegin), m = load(clock, kSize);
  if (m <= 0)
    return;
  int64_t source = load(clock, kParity) * range, target = range - source;
  /* m <= 4 multiplications, exactly as decay.cu does them. */
  double factor = 1;
  for (int64_t s = 0; s < m; ++s)
    factor *= 1.0 - k * dt;
  int64_t count = 0;
  FOR_ITEMS(i) {
    double value = x[source + i] * factor;
    if (poison >= 0 && t >= poison && i == kPoisonItem)
      value = NAN;
    x[target + i] = value;
    ++count;
  }
  __atomic_fetch_add(&clock[kDecayEvaluations], count, __ATOMIC_RELAXED);
}

EXPORT void sim_cpu_evaluate_Grow(void **params, int64_t first, int64_t end,
                                  int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  float *v = memref(params, 5);
  int64_t range = i64(params, 10);
  int64_t m = load(clock, kSize);
  if (m <= 0)
    return;
  int64_t source = load(clock, kParity) * range, target = range - source;
  int64_t count = 0;
  FOR_ITEMS(i) {
    const float *from = &v[4 * (source + i)];
    float *to = &v[4 * (target + i)];
    to[0] = from[0] + (float)m;
    to[1] = (float)i;
    to[2] = from[2] + 1;
    to[3] = 12345;
    ++count;
  }
  __atomic_fetch_add(&clock[kGrowEvaluations], count, __ATOMIC_RELAXED);
}

EXPORT void sim_cpu_exact_X(void **params, int64_t first, int64_t end,
                            int64_t groupSize) {
  double *out = memref(params, 0);
  double k = f64(params, 5);
  int64_t range = i64(params, 6);
  double time = f64(params, 7);
  FOR_ITEMS(i) { out[i] = (1.0 + 0.01 * (double)i) * exp(-k * time); }
}
