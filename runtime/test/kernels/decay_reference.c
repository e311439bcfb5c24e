/*===- decay_reference.c - reference functions of the test scene "decay" --===
 *
 * What `sim-opt --sim-lower-to-reference` will produce for the decay scene
 * (kernels/decay.c), written by hand after the ABI of docs/Reference.md: one
 * plain per-item function per body; every view read goes through the
 * executor's `read` callback, every parameter through `param`. The model
 * text is decayReferenceModel() in TestBundle.cpp:
 *
 *   buffer 0 X, buffer 1 V; component 0 Decay (num_steps, writes X, reads
 *   X V), component 1 Grow (writes V, reads V); schedule Decay Grow.
 *
 * Decay's num_steps reads V, whose writer Grow comes later: that makes Decay
 * a bounding component under hip, as the hand-written hip plan treats it.
 *
 * With SIM_REFERENCE_WRONG defined, Decay adds 1e-6 to item 3 in every
 * evaluation: a reference that disagrees with the plan kernels, for the
 * failing case of `sim-run --check`, and an init of X that disagrees with
 * Decay evaluated with n = 0 (the init check).
 *
 * Grow's lane 2 counts evaluations, also one with n = 0: the init check
 * finds V's init inconsistent with Grow (at every item, lane 2).
 *
 * The model has no totals; tests that add "Mass" (the sum of X, total 0)
 * and "Steps" (the sum of V's lane 0, total 1) to it find their bodies
 * here.
 *
 *===----------------------------------------------------------------------===*/

#include <math.h>
#include <stdint.h>

#include "sim/Runtime/sim_reference.h"

enum { kX = 0, kV = 1, kParamK = 0, kParamPoison = 1, kPoisonItem = 7 };

#define EXPORT __attribute__((visibility("default")))

EXPORT void sim_ref_init_0(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx;
  *(double *)out = 1.0 + 0.01 * (double)item;
}

EXPORT void sim_ref_init_1(const sim_ref_context *ctx, int64_t item,
                           void *out) {
  (void)ctx;
  float *v = out;
  v[0] = 0;
  v[1] = (float)item;
  v[2] = 0;
}

EXPORT void sim_ref_exact_0(const sim_ref_context *ctx, int64_t item, double t,
                            void *out) {
  double k;
  ctx->param(ctx->executor, kParamK, &k);
  *(double *)out = (1.0 + 0.01 * (double)item) * exp(-k * t);
}

EXPORT int32_t sim_ref_num_steps_0(const sim_ref_context *ctx, int64_t item,
                                   int64_t t) {
  float v[3];
  ctx->read(ctx->executor, kV, item, v);
  return (int32_t)(1 + (t / 5) % 4);
}

EXPORT void sim_ref_evaluate_0(const sim_ref_context *ctx, int64_t item,
                               int64_t t, int32_t n, double dt,
                               void *const *outs) {
  double x, k;
  int32_t poison;
  ctx->read(ctx->executor, kX, item, &x);
  ctx->param(ctx->executor, kParamK, &k);
  ctx->param(ctx->executor, kParamPoison, &poison);
  /* n multiplications, exactly as decay.c does them. */
  double factor = 1;
  for (int32_t s = 0; s < n; ++s)
    factor *= 1.0 - k * dt;
  double value = x * factor;
  if (poison >= 0 && t >= poison && item == kPoisonItem)
    value = NAN;
#ifdef SIM_REFERENCE_WRONG
  if (item == 3)
    value += 1e-6;
#endif
  *(double *)outs[0] = value;
}

EXPORT void sim_ref_evaluate_1(const sim_ref_context *ctx, int64_t item,
                               int64_t t, int32_t n, double dt,
                               void *const *outs) {
  (void)t, (void)dt;
  float from[3];
  ctx->read(ctx->executor, kV, item, from);
  float *to = outs[0];
  to[0] = from[0] + (float)n;
  to[1] = (float)item;
  to[2] = from[2] + 1;
}

EXPORT void sim_ref_total_0(const sim_ref_context *ctx, int64_t item,
                            void *out) {
  double x;
  ctx->read(ctx->executor, kX, item, &x);
  *(double *)out = x;
}

EXPORT void sim_ref_total_1(const sim_ref_context *ctx, int64_t item,
                            void *out) {
  float v[3];
  ctx->read(ctx->executor, kV, item, v);
  *(double *)out = (double)v[0];
}
