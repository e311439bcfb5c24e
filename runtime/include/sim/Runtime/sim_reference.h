/*===- sim_reference.h - the ABI of a bundle's reference functions -*- C -*-===//
//
// The functions of a bundle's reference object (docs/Reference.md) take a
// sim_ref_context, through which their view reads and parameter reads call
// back into the reference executor. The compiler generates them
// (lib/Conversion/SimToReference); hand-written ones (the runtime's tests)
// include this header, so that caller and callee agree on one type, also
// for -fsanitize=function. Plain C99.
//
//===----------------------------------------------------------------------===*/

#ifndef SIM_RUNTIME_SIM_REFERENCE_H
#define SIM_RUNTIME_SIM_REFERENCE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct sim_ref_context {
  void *executor;
  /* The element of buffer `buffer` at item `item` (any int64: the executor
     applies the boundary rule), as the running body sees it, written to
     `out` with its lanes packed (vector<3xf32>: 12 bytes). */
  void (*read)(void *executor, int32_t buffer, int64_t item, void *out);
  /* The value of parameter `param` (an index into the model's `params`, or
     -1 range, -2 dt, -3 max_steps) written to `out`: i32 as int32_t, i64 and
     index as int64_t (range too), f32 as float, f64 as double (dt in the
     scene's dt type), max_steps as int32_t. */
  void (*param)(void *executor, int32_t param, void *out);
} sim_ref_context;

/* sim_ref_init_<b>: the initial element of `item` of buffer b. */
typedef void (*sim_ref_init_fn)(const sim_ref_context *ctx, int64_t item,
                                void *out);
/* sim_ref_exact_<b>: the exact solution of buffer b at time t (time units). */
typedef void (*sim_ref_exact_fn)(const sim_ref_context *ctx, int64_t item,
                                 double t, void *out);
/* sim_ref_num_steps_<c>: num_steps of component c at local time t. */
typedef int32_t (*sim_ref_num_steps_fn)(const sim_ref_context *ctx,
                                        int64_t item, int64_t t);
/* sim_ref_evaluate_<c>: n base steps of dt from local time t; the k-th value
   (the k-th buffer of `writes`) goes to outs[k]. dt is passed as a double;
   an f32 scene's dt converts to double and back exactly. */
typedef void (*sim_ref_evaluate_fn)(const sim_ref_context *ctx, int64_t item,
                                    int64_t t, int32_t n, double dt,
                                    void *const *outs);
/* sim_ref_total_<k>: the value (its declared f32 or f64) of total k at
   `item`, at T. */
typedef void (*sim_ref_total_fn)(const sim_ref_context *ctx, int64_t item,
                                 void *out);

#ifdef __cplusplus
}
#endif

#endif /* SIM_RUNTIME_SIM_REFERENCE_H */
