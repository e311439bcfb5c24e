//===- decay.cu - hand-written CUDA kernels of the test scene "decay" -----===//
//
// The GPU twin of decay.c: the same scene and clock, and the same X and V
// bit for bit (no FMA contraction: -fmad=false), so that the CUDA backend
// can be tested on a machine with a GPU before the compiler makes bundles.
// The tests read the PTX committed next to this file, so no build needs
// nvcc. After a change, regenerate it with
//
//   for cap in 1:simple 4:hip; do
//     nvcc -ptx -arch=sm_90 -fmad=false -DSIM_CAP=${cap%%:*} decay.cu \
//          -o decay-${cap#*:}.ptx
//   done
//
// Parameters follow docs/Bundle.md: a memref is five (allocated pointer,
// aligned pointer, offset, size, stride).
//
//===----------------------------------------------------------------------===//

#ifndef SIM_CAP
#error "define SIM_CAP (the largest big step of the strategy)"
#endif

typedef long long i64;

#define MEMREF(type, name)                                                     \
  type *name##Allocated, type *name, i64 name##Offset, i64 name##Size,         \
      i64 name##Stride
#define KERNEL extern "C" __global__ void
#define FOR_ITEMS(i)                                                           \
  for (i64 i = i64(blockIdx.x) * blockDim.x + threadIdx.x; i < range;          \
       i += i64(gridDim.x) * blockDim.x)

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

constexpr i64 kNoEstimate = 0x7fffffffffffffffLL;

__device__ i64 numSteps(i64 t) { return 1 + (t / 5) % 4; }

KERNEL reset_clock(MEMREF(i64, clock)) {
  if (blockIdx.x != 0 || threadIdx.x != 0)
    return;
  for (i64 slot = 0; slot < clockSize; ++slot)
    clock[slot] = 0;
  clock[kEstimate] = kNoEstimate;
}

KERNEL init_X(MEMREF(double, x), i64 range) {
  FOR_ITEMS(i) { x[i] = 1.0 + 0.01 * double(i); }
}

KERNEL init_V(MEMREF(float, v), i64 range) {
  FOR_ITEMS(i) {
    v[4 * i + 0] = 0;
    v[4 * i + 1] = float(i);
    v[4 * i + 2] = 0;
    v[4 * i + 3] = 12345;
  }
}

KERNEL estimate_Decay(MEMREF(i64, clock), i64 range) {
  i64 next = clock[kBegin] + clock[kSize];
  if (next >= clock[kEnd])
    return;
  FOR_ITEMS(i) {
    atomicMin(&clock[kEstimate], numSteps(next));
    return; // every item estimates the same
  }
}

KERNEL advance(MEMREF(i64, clock)) {
  if (blockIdx.x != 0 || threadIdx.x != 0)
    return;
  i64 size = clock[kSize];
  i64 now = clock[kBegin] + size;
  i64 parity = size > 0 ? clock[kParity] ^ 1 : clock[kParity];
  i64 remaining = clock[kEnd] - now;
  i64 bound = SIM_CAP;
  if (clock[kEstimate] < bound)
    bound = clock[kEstimate];
  i64 next = remaining > 0 ? (bound < remaining ? bound : remaining) : 0;
  clock[kBigSteps] += size > 0;
  clock[kCuts] += remaining > 0 && remaining < bound;
  clock[kBegin] = now;
  clock[kSize] = next;
  clock[kParity] = parity;
  clock[kEstimate] = kNoEstimate;
  if (next > 0)
    clock[kHistogram + next] += 1;
}

KERNEL evaluate_Decay(MEMREF(i64, clock), MEMREF(double, x), double k,
                      int poison, i64 range, double dt) {
  i64 t = clock[kBegin], m = clock[kSize];
  if (m <= 0)
    return;
  i64 source = clock[kParity] * range, target = range - source;
  // m <= 4 multiplications, exactly as decay.c does them.
  double factor = 1;
  for (i64 s = 0; s < m; ++s)
    factor *= 1.0 - k * dt;
  unsigned long long count = 0;
  FOR_ITEMS(i) {
    double value = x[source + i] * factor;
    if (poison >= 0 && t >= poison && i == kPoisonItem)
      value = __longlong_as_double(0x7ff8000000000000LL);
    x[target + i] = value;
    ++count;
  }
  if (count)
    atomicAdd(reinterpret_cast<unsigned long long *>(&clock[kDecayEvaluations]),
              count);
}

KERNEL evaluate_Grow(MEMREF(i64, clock), MEMREF(float, v), i64 range) {
  i64 m = clock[kSize];
  if (m <= 0)
    return;
  i64 source = clock[kParity] * range, target = range - source;
  unsigned long long count = 0;
  FOR_ITEMS(i) {
    const float *from = &v[4 * (source + i)];
    float *to = &v[4 * (target + i)];
    to[0] = from[0] + float(m);
    to[1] = float(i);
    to[2] = from[2] + 1;
    to[3] = 12345;
    ++count;
  }
  if (count)
    atomicAdd(reinterpret_cast<unsigned long long *>(&clock[kGrowEvaluations]),
              count);
}

KERNEL exact_X(MEMREF(double, out), double k, i64 range, double time) {
  FOR_ITEMS(i) { out[i] = (1.0 + 0.01 * double(i)) * exp(-k * time); }
}
