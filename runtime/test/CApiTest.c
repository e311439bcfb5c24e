/*===- CApiTest.c - the C API, used from C --------------------------------===*\
|*                                                                            *|
|* Compiled as C99 to prove that sim_runtime.h is a C header and that a C    *|
|* program can open a bundle, read its metadata, run a session and read the  *|
|* results and metrics. CApiTest.cpp calls it from gtest.                    *|
|*                                                                            *|
\*===----------------------------------------------------------------------===*/

#include "sim/Runtime/sim_runtime.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CHECK(condition)                                                       \
  do {                                                                         \
    if (!(condition)) {                                                        \
      snprintf(message, capacity, "%s:%d: %s (last error: %s)", __FILE__,      \
               __LINE__, #condition, sim_last_error());                        \
      goto done;                                                               \
    }                                                                          \
  } while (0)

int sim_c_api_test(const char *path, char *message, size_t capacity) {
  int failed = 1;
  sim_bundle *bundle = NULL;
  sim_session *session = NULL;
  sim_session *reference = NULL;
  double *x = NULL;
  float *v = NULL;
  message[0] = '\0';

  /* Errors: a status and a message. */
  CHECK(sim_bundle_open("/nonexistent.simb", &bundle) == SIM_ERROR_IO);
  CHECK(bundle == NULL);
  CHECK(strstr(sim_last_error(), "cannot open bundle") != NULL);
  CHECK(sim_bundle_open_memory("SIMBNDL", 7, &bundle) == SIM_ERROR_BUNDLE);
  CHECK(strcmp(sim_status_name(SIM_ERROR_BUNDLE), "bad bundle") == 0);

  /* Metadata. */
  CHECK(sim_bundle_open(path, &bundle) == SIM_OK);
  CHECK(strcmp(sim_last_error(), "") == 0);
  CHECK(strcmp(sim_bundle_scene_name(bundle), "decay") == 0);
  CHECK(sim_bundle_range(bundle) == 100);
  CHECK(sim_bundle_dt(bundle) == 0.01);
  CHECK(strcmp(sim_bundle_dt_type(bundle), "f64") == 0);
  CHECK(sim_bundle_max_steps(bundle) == 4);
  CHECK(sim_bundle_has_strategy(bundle, SIM_STRATEGY_HIP));
  CHECK(!sim_bundle_has_strategy(bundle, SIM_STRATEGY_HIP_CACHE));
  CHECK(sim_bundle_has_cpu(bundle, SIM_STRATEGY_SIMPLE));
  CHECK(!sim_bundle_has_ptx(bundle, SIM_STRATEGY_SIMPLE));
  CHECK(sim_bundle_num_buffers(bundle) == 2);
  sim_buffer_info buffer;
  CHECK(sim_bundle_buffer(bundle, 1, &buffer) == SIM_OK);
  CHECK(strcmp(buffer.name, "V") == 0);
  CHECK(strcmp(buffer.element_type, "vector<3xf32>") == 0);
  CHECK(strcmp(buffer.scalar_type, "f32") == 0);
  CHECK(buffer.lanes == 3 && buffer.scalar_bytes == 4);
  CHECK(buffer.observed && !buffer.exact);
  CHECK(strcmp(buffer.interp, "none") == 0);
  CHECK(sim_bundle_buffer(bundle, 2, &buffer) == SIM_ERROR_INVALID_ARGUMENT);
  CHECK(sim_bundle_num_params(bundle) == 2);
  sim_param_info param;
  CHECK(sim_bundle_param(bundle, 0, &param) == SIM_OK);
  CHECK(strcmp(param.name, "k") == 0 && strcmp(param.type, "f64") == 0);
  CHECK(strcmp(param.default_value, "2") == 0);

  sim_strategy strategy;
  CHECK(sim_strategy_parse("hip-cache", &strategy) == SIM_OK);
  CHECK(strategy == SIM_STRATEGY_HIP_CACHE);
  CHECK(sim_strategy_parse("fast", &strategy) == SIM_ERROR_INVALID_ARGUMENT);
  sim_backend backend;
  CHECK(sim_backend_parse("cpu", &backend) == SIM_OK &&
        backend == SIM_BACKEND_CPU);
  CHECK(sim_backend_parse("reference", &backend) == SIM_OK &&
        backend == SIM_BACKEND_REFERENCE);
  CHECK(strcmp(sim_backend_name(SIM_BACKEND_REFERENCE), "reference") == 0);
  CHECK(sim_backend_parse("oracle", &backend) == SIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sim_last_error(), "(auto, cpu, cuda, reference)") != NULL);
  CHECK(sim_bundle_has_reference(bundle));
  CHECK(!sim_bundle_has_reference(NULL));

  /* A session. */
  sim_session_options options;
  sim_session_options_init(&options);
  CHECK(options.strategy == SIM_STRATEGY_HIP);
  CHECK(options.backend == SIM_BACKEND_AUTO);
  options.backend = SIM_BACKEND_CPU;
  options.cpu_threads = 2;
  CHECK(sim_session_create(bundle, &options, &session) == SIM_OK);
  /* Sessions keep what they need. */
  sim_bundle_close(bundle);
  bundle = NULL;
  CHECK(sim_session_backend(session) == SIM_BACKEND_CPU);
  CHECK(strncmp(sim_session_device(session), "CPU (2 threads, x86-64", 22) ==
        0);
  CHECK(sim_session_group_size(session) == 32);
  CHECK(sim_session_set(session, "k", "1") == SIM_OK);
  CHECK(sim_session_set(session, "q", "1") == SIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sim_last_error(), "'q' is not range, dt or a parameter") !=
        NULL);
  char value[32];
  CHECK(sim_session_get(session, "k", value, sizeof value) == SIM_OK);
  CHECK(strcmp(value, "1") == 0);
  CHECK(sim_session_get(session, "k", value, 1) == SIM_ERROR_INVALID_ARGUMENT);
  CHECK(sim_session_range(session) == 100);

  CHECK(sim_session_init(session) == SIM_OK);
  CHECK(sim_session_time(session) == 0);
  CHECK(sim_session_run(session, 30) == SIM_OK);
  CHECK(sim_session_time(session) == 30);

  size_t bytes = 0;
  CHECK(sim_session_buffer_bytes(session, "X", &bytes) == SIM_OK);
  CHECK(bytes == 100 * sizeof(double));
  x = malloc(bytes);
  CHECK(sim_session_get_buffer(session, "X", x, bytes) == SIM_OK);
  for (int i = 0; i < 100; ++i) {
    double expected = (1 + 0.01 * i) * pow(1 - 0.01, 30);
    CHECK(fabs(x[i] - expected) <= 1e-12 * expected);
  }
  CHECK(sim_session_get_buffer(session, "X", x, bytes - 8) ==
        SIM_ERROR_INVALID_ARGUMENT);
  CHECK(sim_session_buffer_bytes(session, "V", &bytes) == SIM_OK);
  CHECK(bytes == 100 * 3 * sizeof(float));
  v = malloc(bytes);
  CHECK(sim_session_get_buffer(session, "V", v, bytes) == SIM_OK);
  CHECK(v[3 * 99 + 0] == 30 && v[3 * 99 + 1] == 99);

  sim_metrics metrics;
  CHECK(sim_session_metrics(session, &metrics) == SIM_OK);
  CHECK(metrics.steps == 30 && metrics.begin == 0 && metrics.end == 30);
  CHECK(metrics.big_steps > 0 && metrics.launches > metrics.big_steps);
  CHECK(metrics.host_syncs >= 2);
  CHECK(sim_session_num_components(session) == 2);
  CHECK(strcmp(sim_session_component(session, 0), "Decay") == 0);
  CHECK(sim_session_component(session, 2) == NULL);
  /* The decay scene declares no totals. */
  CHECK(sim_session_num_totals(session) == 0);
  CHECK(sim_session_total_name(session, 0) == NULL);
  double total = 0;
  CHECK(sim_session_total(session, "Energy", &total) ==
        SIM_ERROR_INVALID_ARGUMENT);
  CHECK(strstr(sim_last_error(), "'Energy' is not a total of scene 'decay'") !=
        NULL);
  CHECK(sim_session_total(session, NULL, &total) == SIM_ERROR_INVALID_ARGUMENT);
  CHECK(sim_session_evaluations(session, 0) == metrics.big_steps * 100);
  int64_t steps = 0, bigSteps = 0;
  for (int64_t m = 1; m <= 4; ++m) {
    steps += m * sim_session_histogram(session, m);
    bigSteps += sim_session_histogram(session, m);
  }
  CHECK(steps == 30 && bigSteps == metrics.big_steps);

  CHECK(sim_session_has_exact(session, "X") &&
        !sim_session_has_exact(session, "V"));
  CHECK(sim_session_exact(session, "X", x, 100 * sizeof(double)) == SIM_OK);
  CHECK(fabs(x[0] - exp(-1.0 * 30 * 0.01)) < 1e-14);

  sim_nonfinite where;
  CHECK(sim_session_nonfinite(session, &where) == SIM_ERROR_INVALID_ARGUMENT);

  /* The init check, from C: V's lane 2 counts an evaluation with n = 0. */
  int32_t checked = 0;
  CHECK(sim_session_check_init(session, 0, 0, &checked) == SIM_OK);
  CHECK(checked == 2);
  sim_init_check init;
  CHECK(sim_session_init_check(session, 1, &init) == SIM_OK);
  CHECK(strcmp(init.buffer, "V") == 0 && strcmp(init.component, "Grow") == 0);
  CHECK(init.count == 100 && init.item == 0 && init.lane == 2);
  CHECK(sim_session_init_check(session, 0, &init) == SIM_OK);
  CHECK(strcmp(init.buffer, "X") == 0 && init.count == 0);
  CHECK(sim_session_time(session) == 30);

  /* The reference executor behind the same calls, with the same settings:
     the same work and the same values. */
  CHECK(sim_bundle_open(path, &bundle) == SIM_OK);
  options.backend = SIM_BACKEND_REFERENCE;
  CHECK(sim_session_create(bundle, &options, &reference) == SIM_OK);
  CHECK(sim_session_backend(reference) == SIM_BACKEND_REFERENCE);
  CHECK(strcmp(sim_session_device(reference),
               "reference executor (CPU, 1 thread)") == 0);
  CHECK(sim_session_group_size(reference) == 32);
  CHECK(sim_session_set(reference, "k", "1") == SIM_OK);
  CHECK(sim_session_run(reference, 30) == SIM_OK);
  sim_metrics referenceMetrics;
  CHECK(sim_session_metrics(reference, &referenceMetrics) == SIM_OK);
  CHECK(referenceMetrics.big_steps == metrics.big_steps);
  CHECK(referenceMetrics.launches == 0 && referenceMetrics.host_syncs == 0);
  CHECK(strcmp(sim_session_component(reference, 1), "Grow") == 0);
  CHECK(sim_session_evaluations(reference, 0) ==
        sim_session_evaluations(session, 0));
  for (int64_t m = 1; m <= 4; ++m)
    CHECK(sim_session_histogram(reference, m) ==
          sim_session_histogram(session, m));
  CHECK(sim_session_get_buffer(reference, "V", v, 100 * 3 * sizeof(float)) ==
        SIM_OK);
  CHECK(v[3 * 99 + 0] == 30 && v[3 * 99 + 1] == 99);
  failed = 0;

done:
  free(x);
  free(v);
  sim_session_destroy(session);
  sim_session_destroy(reference);
  sim_bundle_close(bundle);
  return failed;
}
