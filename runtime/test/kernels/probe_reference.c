/*===- probe_reference.c - reference functions of the test scene "probe" --===
 *
 * A tiny scene that makes the reference executor's rules visible: what a
 * body reads at interior sub-steps through each interpolation, across each
 * boundary rule, and initial states computed on demand (probeReferenceModel()
 * in TestBundle.cpp has the model):
 *
 *   buffers 0 D, 1 A (linear, clamp), 2 C (cubic, wrap), 3 H (hermite:D,
 *   zero), 4 N (none), 5 L, all f64; 6 RA, 7 RC, 8 RH (vector<4xf64>),
 *   9 E (vector<6xf64>).
 *   component 0 Source writes D A C H N: A, C, H = 2 + i + 2 time,
 *     D = 1 + time / 2 (the derivative of H over base steps of dt 0.5).
 *   component 1 Sink (num_steps 1) writes RA RC RH: lane t % 4 of each is A,
 *     C or H as read at its sub-step from t to t + 1; with parameter
 *     read_none it reads N as well.
 *   component 2 Edge writes E L: E holds A, C and H at items i - 1 and
 *     i + 1; L = 1 + time / 2.
 *
 * The init body of D reads A, declared after it; with parameter `cycle`,
 * the init bodies of A and C read each other.
 *
 *===----------------------------------------------------------------------===*/

#include <stdint.h>

#include "sim/Runtime/sim_reference.h"

enum { kD, kA, kC, kH, kN, kL, kRA, kRC, kRH, kE };
enum { kParamCycle = 0, kParamReadNone = 1 };

#define EXPORT __attribute__((visibility("default")))

static double read1(const sim_ref_context *ctx, int32_t buffer, int64_t item) {
  double value;
  ctx->read(ctx->executor, buffer, item, &value);
  return value;
}

static int32_t param(const sim_ref_context *ctx, int32_t index) {
  int32_t value;
  ctx->param(ctx->executor, index, &value);
  return value;
}

static double line(int64_t item, double time) {
  return 2.0 + (double)item + 2.0 * time;
}

EXPORT void sim_ref_init_0(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  *(double *)out = read1(ctx, kA, item) - 1.0 - (double)item;
}

EXPORT void sim_ref_init_1(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  if (param(ctx, kParamCycle))
    (void)read1(ctx, kC, item);
  *(double *)out = line(item, 0);
}

EXPORT void sim_ref_init_2(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  if (param(ctx, kParamCycle))
    (void)read1(ctx, kA, item);
  *(double *)out = line(item, 0);
}

EXPORT void sim_ref_init_3(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx;
  *(double *)out = line(item, 0);
}

EXPORT void sim_ref_init_4(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  *(double *)out = 0;
}

EXPORT void sim_ref_init_5(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  *(double *)out = 1;
}

static void zeros(double *out, int lanes) {
  for (int lane = 0; lane < lanes; ++lane)
    out[lane] = 0;
}

EXPORT void sim_ref_init_6(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  zeros(out, 4);
}

EXPORT void sim_ref_init_7(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  zeros(out, 4);
}

EXPORT void sim_ref_init_8(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  zeros(out, 4);
}

EXPORT void sim_ref_init_9(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx, (void)item;
  zeros(out, 6);
}

EXPORT void sim_ref_evaluate_0(const sim_ref_context *ctx, int64_t item,
                               int64_t t, int32_t n, double dt,
                               void *const *outs) {
  (void)ctx, (void)dt;
  double time = (double)(t + n);
  *(double *)outs[0] = 1.0 + time / 2;
  *(double *)outs[1] = line(item, time);
  *(double *)outs[2] = line(item, time);
  *(double *)outs[3] = line(item, time);
  *(double *)outs[4] = time;
}

EXPORT int32_t sim_ref_num_steps_1(const sim_ref_context *ctx, int64_t item,
                                   int64_t t) {
  (void)ctx, (void)item, (void)t;
  return 1;
}

EXPORT void sim_ref_evaluate_1(const sim_ref_context *ctx, int64_t item,
                               int64_t t, int32_t n, double dt,
                               void *const *outs) {
  (void)n, (void)dt;
  const int32_t sources[3] = {kA, kC, kH};
  const int32_t owns[3] = {kRA, kRC, kRH};
  for (int k = 0; k < 3; ++k) {
    double *out = outs[k];
    ctx->read(ctx->executor, owns[k], item, out);
    out[t % 4] = read1(ctx, sources[k], item);
  }
  if (param(ctx, kParamReadNone))
    (void)read1(ctx, kN, item);
}

EXPORT void sim_ref_evaluate_2(const sim_ref_context *ctx, int64_t item,
                               int64_t t, int32_t n, double dt,
                               void *const *outs) {
  (void)dt;
  const int32_t sources[3] = {kA, kC, kH};
  double *e = outs[0];
  for (int k = 0; k < 3; ++k) {
    e[2 * k] = read1(ctx, sources[k], item - 1);
    e[2 * k + 1] = read1(ctx, sources[k], item + 1);
  }
  *(double *)outs[1] = 1.0 + (double)(t + n) / 2;
}
