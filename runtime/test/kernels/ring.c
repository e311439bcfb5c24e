/*===- ring.c - hand-written CPU kernels of the distributed test scene ----===
 *
 * A distributed plan (plan.distributed, halo 2) written by hand, so that the
 * runtime's ranks, ghosts and all-reduces are tested before the compiler
 * makes such bundles. Kernels take First and Extent and address item i at
 * element i - First + HALO.
 *
 * The scene "ring" (TestBundle.cpp): X : f64, boundary(wrap), read at
 * i-2 .. i+2: x' = x + m dt (x[i-1] - 2 x[i] + x[i+1])
 * + 1e-3 (x[i-2] - x[i+2]); num_steps at T is 1 + (T / 5) % 4, but 1 for
 * the last item when (T / 3) is odd, so only the rank holding it sees the
 * smaller estimate (the all-reduce of the estimate slot must spread it).
 * A total sums x.
 *
 *===----------------------------------------------------------------------===*/

#include <stdint.h>

enum {
  kBegin = 0,
  kSize = 1,
  kParity = 2,
  kEnd = 3,
  kEstimate = 4,
  kBigSteps = 5,
  kCuts = 6,
  kEvaluations = 8,
  kHistogram = 10,
  kCap = 4,
  kHalo = 2,
};

#define EXPORT __attribute__((visibility("default")))

static void *memref(void **params, int at) { return *(void **)params[at + 1]; }
static int64_t memrefSize(void **params, int at) {
  return *(int64_t *)params[at + 3];
}
static int64_t i64(void **params, int at) { return *(int64_t *)params[at]; }
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

static int64_t numSteps(int64_t item, int64_t range, int64_t t) {
  if (item == range - 1 && (t / 3) % 2 == 1)
    return 1;
  return 1 + (t / 5) % 4;
}

/* The block's items of groups [first, end): local l, global i. */
#define FOR_ITEMS(l, i)                                                        \
  for (int64_t g = first; g < end; ++g)                                        \
    for (int64_t l = g * groupSize, i = l + base;                              \
         l < (g + 1) * groupSize && l < count; ++l, ++i)

EXPORT void sim_cpu_reset_clock(void **params, int64_t first, int64_t end,
                                int64_t groupSize) {
  (void)first, (void)end, (void)groupSize;
  int64_t *clock = memref(params, 0);
  for (int64_t slot = 0; slot < memrefSize(params, 0); ++slot)
    clock[slot] = 0;
  clock[kEstimate] = INT64_MAX;
}

/* (X, First, Extent, Range) */
EXPORT void sim_cpu_init_X(void **params, int64_t first, int64_t end,
                           int64_t groupSize) {
  double *x = memref(params, 0);
  int64_t base = i64(params, 5), extent = i64(params, 6);
  int64_t count = extent - 2 * kHalo;
  FOR_ITEMS(l, i) {
    double value = 1.0 + 0.01 * (double)i + (i % 3 == 0 ? 0.5 : 0.0);
    x[kHalo + l] = value;
    x[extent + kHalo + l] = value;
  }
}

/* (Clock, First, Extent, Range) */
EXPORT void sim_cpu_estimate(void **params, int64_t first, int64_t end,
                             int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  int64_t base = i64(params, 5), extent = i64(params, 6);
  int64_t range = i64(params, 7), count = extent - 2 * kHalo;
  int64_t next = load(clock, kBegin) + load(clock, kSize);
  if (next >= load(clock, kEnd))
    return;
  int64_t least = INT64_MAX;
  FOR_ITEMS(l, i) {
    (void)l;
    int64_t n = numSteps(i, range, next);
    least = n < least ? n : least;
  }
  atomicMin(&clock[kEstimate], least);
}

/* (Clock) */
EXPORT void sim_cpu_advance(void **params, int64_t first, int64_t end,
                            int64_t groupSize) {
  (void)first, (void)end, (void)groupSize;
  int64_t *clock = memref(params, 0);
  int64_t size = clock[kSize];
  int64_t now = clock[kBegin] + size;
  int64_t parity = size > 0 ? clock[kParity] ^ 1 : clock[kParity];
  int64_t remaining = clock[kEnd] - now;
  int64_t bound = kCap;
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

/* (Clock, X, First, Extent, Range, Dt) */
EXPORT void sim_cpu_evaluate(void **params, int64_t first, int64_t end,
                             int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  double *x = memref(params, 5);
  int64_t base = i64(params, 10), extent = i64(params, 11);
  double dt = f64(params, 13);
  int64_t count = extent - 2 * kHalo;
  int64_t m = load(clock, kSize);
  if (m <= 0)
    return;
  int64_t source = load(clock, kParity) * extent, target = extent - source;
  int64_t evaluated = 0;
  FOR_ITEMS(l, i) {
    (void)i;
    const double *s = &x[source + kHalo + l];
    x[target + kHalo + l] = s[0] + (double)m * dt * (s[-1] - 2 * s[0] + s[1]) +
                            1e-3 * (s[-2] - s[2]);
    ++evaluated;
  }
  __atomic_fetch_add(&clock[kEvaluations], evaluated, __ATOMIC_RELAXED);
}

/* (Total, Clock, X, First, Extent, Range) */
EXPORT void sim_cpu_total_X(void **params, int64_t first, int64_t end,
                            int64_t groupSize) {
  double *out = memref(params, 0);
  int64_t *clock = memref(params, 5);
  double *x = memref(params, 10);
  int64_t base = i64(params, 15), extent = i64(params, 16);
  int64_t count = extent - 2 * kHalo;
  int64_t half = load(clock, kParity) * extent;
  FOR_ITEMS(l, i) {
    (void)i;
    out[kHalo + l] = x[half + kHalo + l] * (1.0 + 1e-7 * (double)i);
  }
}

/* The gather variant (ringContents(boundary, true)): a second buffer Y,
 * replicated (every rank holds all `range` items, item i at element i of
 * each half), that every item reads at all items: y' = y + m dt 0.1
 * (mean_j w(i, j) y[j] - y[i]), w(i, j) = 1 + 1e-3 ((i + j) % 5), summed
 * in item order. Its writers write only their block. A memref of the
 * wrong size (not 2 range elements) makes the values NaN. */

/* (Y, First, Extent, Range) */
EXPORT void sim_cpu_init_Y(void **params, int64_t first, int64_t end,
                           int64_t groupSize) {
  double *y = memref(params, 0);
  int64_t base = i64(params, 5), extent = i64(params, 6);
  int64_t range = i64(params, 7), count = extent - 2 * kHalo;
  FOR_ITEMS(l, i) {
    (void)l;
    y[i] = y[range + i] = 1.0 + 0.02 * (double)i + (i % 4 == 1 ? 0.25 : 0.0);
  }
}

/* (Clock, Y, First, Extent, Range, Dt) */
EXPORT void sim_cpu_pull(void **params, int64_t first, int64_t end,
                         int64_t groupSize) {
  int64_t *clock = memref(params, 0);
  double *y = memref(params, 5);
  int64_t base = i64(params, 10), extent = i64(params, 11);
  int64_t range = i64(params, 12), count = extent - 2 * kHalo;
  double dt = f64(params, 13);
  int64_t m = load(clock, kSize);
  if (m <= 0)
    return;
  double wrong = memrefSize(params, 5) == 2 * range ? 0.0 : __builtin_nan("");
  int64_t source = load(clock, kParity) * range, target = range - source;
  int64_t evaluated = 0;
  FOR_ITEMS(l, i) {
    (void)l;
    double sum = 0;
    for (int64_t j = 0; j < range; ++j)
      sum += (1.0 + 1e-3 * (double)((i + j) % 5)) * y[source + j];
    double s = y[source + i];
    y[target + i] =
        s + (double)m * dt * 0.1 * (sum / (double)range - s) + wrong;
    ++evaluated;
  }
  __atomic_fetch_add(&clock[kEvaluations + 1], evaluated, __ATOMIC_RELAXED);
}

/* (Exact, First, Extent, Range, Time) */
EXPORT void sim_cpu_exact_Y(void **params, int64_t first, int64_t end,
                            int64_t groupSize) {
  double *e = memref(params, 0);
  int64_t base = i64(params, 5), extent = i64(params, 6);
  int64_t range = i64(params, 7), count = extent - 2 * kHalo;
  double time = f64(params, 8);
  double wrong = memrefSize(params, 0) == range ? 0.0 : __builtin_nan("");
  FOR_ITEMS(l, i) {
    (void)l;
    e[i] = (double)i + 2.0 * time + wrong;
  }
}
