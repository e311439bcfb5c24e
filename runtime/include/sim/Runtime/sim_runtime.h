//===- sim_runtime.h - the C API of the sim runtime ---------------*- C -*-===//
//
// The one public header of the runtime that reads scene bundles
// (docs/Bundle.md) and runs them on the CUDA or the CPU backend. It is plain
// C99, for C programs and Python's ctypes: handles are opaque, every call
// that can fail returns a sim_status, and sim_last_error() says what went
// wrong. docs/Runtime.md describes the API and the sim-run tool.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_SIM_RUNTIME_H
#define SIM_RUNTIME_SIM_RUNTIME_H

#include <stddef.h>
#include <stdint.h>

#if defined(SIM_RUNTIME_BUILDING)
#define SIM_API __attribute__((visibility("default")))
#else
#define SIM_API
#endif

/// The enumerations below are int-sized in C. C++ gives them the same fixed
/// type, so that any int a C caller (or Python's ctypes) passes is a value
/// of the type and the functions can refuse the unknown ones: without a
/// fixed type, reading a value outside the enumerators' range is undefined
/// in C++.
#ifdef __cplusplus
#define SIM_ENUM_TYPE : int32_t
#else
#define SIM_ENUM_TYPE
#endif

#ifdef __cplusplus
extern "C" {
#endif

//===----------------------------------------------------------------------===//
// Status and errors
//===----------------------------------------------------------------------===//

typedef enum sim_status SIM_ENUM_TYPE {
  SIM_OK = 0,
  /// A null handle, an unknown name, a value that does not parse, a host
  /// array of the wrong size.
  SIM_ERROR_INVALID_ARGUMENT = 1,
  /// The file cannot be read.
  SIM_ERROR_IO = 2,
  /// The bundle is malformed or lacks what the request needs.
  SIM_ERROR_BUNDLE = 3,
  /// libcuda.so.1 cannot be loaded (or is the stub library).
  SIM_ERROR_NO_DRIVER = 4,
  /// The driver loaded but there is no usable CUDA device.
  SIM_ERROR_NO_DEVICE = 5,
  /// A backend call failed (a driver call, dlopen, a missing kernel).
  SIM_ERROR_BACKEND = 6,
  /// A run stopped at the first NaN or infinity (check_finite).
  SIM_ERROR_NONFINITE = 7,
  /// The kernels broke the clock contract of docs/Plan.md.
  SIM_ERROR_CLOCK = 8,
  /// A run stopped early because sim_session_interrupt() asked it to; the
  /// state is the one at the big-step boundary it reached.
  SIM_ERROR_INTERRUPTED = 9,
  /// The session would need more memory than its limit allows
  /// (sim_session_options.max_memory).
  SIM_ERROR_MEMORY_LIMIT = 10,
  /// A checkpoint that is damaged, truncated or not a checkpoint, or that
  /// belongs to another bundle, scene, strategy, group size, range, dt or
  /// parameter value than the session's; or a session whose state is not on
  /// a big-step boundary (its last run failed inside one).
  SIM_ERROR_CHECKPOINT = 11,
  /// A distributed session's communication failed, or its ranks disagree
  /// (another bundle, strategy, range, ...) or are too many for the range.
  SIM_ERROR_DISTRIBUTED = 12,
} sim_status;

/// The message of the last failed call on this thread (never null; empty
/// after a call that returned SIM_OK).
SIM_API const char *sim_last_error(void);

/// A short name of a status code ("ok", "invalid argument", ...).
SIM_API const char *sim_status_name(sim_status status);

//===----------------------------------------------------------------------===//
// Strategies and backends
//===----------------------------------------------------------------------===//

/// The values are those of the bundle's section table.
typedef enum sim_strategy SIM_ENUM_TYPE {
  SIM_STRATEGY_SIMPLE = 0,
  SIM_STRATEGY_TRADITIONAL = 1,
  SIM_STRATEGY_HIP = 2,
  SIM_STRATEGY_HIP_CACHE = 3,
  /// hip with local time steps (docs/Model.md, "Local time stepping").
  SIM_STRATEGY_LTS = 4,
} sim_strategy;

typedef enum sim_backend SIM_ENUM_TYPE {
  /// CUDA when a driver, a device and the strategy's PTX are there, else
  /// the CPU.
  SIM_BACKEND_AUTO = 0,
  SIM_BACKEND_CPU = 1,
  SIM_BACKEND_CUDA = 2,
  /// The reference executor (docs/Reference.md): the bundle's per-body
  /// reference functions run item by item on the host, with big steps and
  /// sub-steps decided by plain C++. The oracle for the other backends;
  /// `auto` never chooses it.
  SIM_BACKEND_REFERENCE = 3,
} sim_backend;

/// "simple", "traditional", "hip", "hip-cache", "lts".
SIM_API const char *sim_strategy_name(sim_strategy strategy);
SIM_API sim_status sim_strategy_parse(const char *name, sim_strategy *out);
/// "auto", "cpu", "cuda", "reference".
SIM_API const char *sim_backend_name(sim_backend backend);
SIM_API sim_status sim_backend_parse(const char *name, sim_backend *out);
/// The CUDA devices of this machine; SIM_ERROR_NO_DRIVER or
/// SIM_ERROR_NO_DEVICE where there are none to use.
SIM_API sim_status sim_cuda_device_count(int32_t *out);

//===----------------------------------------------------------------------===//
// Bundles and scene metadata
//===----------------------------------------------------------------------===//

typedef struct sim_bundle sim_bundle;

/// Reads and validates a bundle file.
SIM_API sim_status sim_bundle_open(const char *path, sim_bundle **out);
/// Validates a bundle held in memory (the bytes are copied).
SIM_API sim_status sim_bundle_open_memory(const void *data, size_t size,
                                          sim_bundle **out);
/// Sessions keep what they need: a bundle may be closed before them.
SIM_API void sim_bundle_close(sim_bundle *bundle);

SIM_API const char *sim_bundle_scene_name(const sim_bundle *bundle);
/// The scene's default range (items).
SIM_API int64_t sim_bundle_range(const sim_bundle *bundle);
/// The scene's default dt and whether it is "f32" or "f64".
SIM_API double sim_bundle_dt(const sim_bundle *bundle);
SIM_API const char *sim_bundle_dt_type(const sim_bundle *bundle);
SIM_API int64_t sim_bundle_max_steps(const sim_bundle *bundle);

/// Whether the bundle holds a plan for the strategy, and its kernels.
SIM_API int sim_bundle_has_strategy(const sim_bundle *bundle,
                                    sim_strategy strategy);
SIM_API int sim_bundle_has_ptx(const sim_bundle *bundle, sim_strategy strategy);
SIM_API int sim_bundle_has_cpu(const sim_bundle *bundle, sim_strategy strategy);
/// Whether the bundle holds the reference model and functions (sections 5
/// and 6) that SIM_BACKEND_REFERENCE runs.
SIM_API int sim_bundle_has_reference(const sim_bundle *bundle);
/// Whether the bundle's code runs with subnormal values flushed to zero on
/// every backend (compiled with sim-translate --sim-ftz); 0: IEEE.
SIM_API int sim_bundle_flushes_subnormals(const sim_bundle *bundle);

typedef struct sim_buffer_info {
  const char *name;
  /// "f32", "f64", "vector<3xf32>", ...
  const char *element_type;
  /// "f32" or "f64".
  const char *scalar_type;
  /// Bytes of one scalar (4 or 8) and scalars per element (1 for a scalar
  /// type). A host array of a buffer holds `lanes` packed scalars per item.
  int32_t scalar_bytes;
  int32_t lanes;
  /// "linear", "cubic", "hermite:<derivative>", "none" or "flux".
  const char *interp;
  /// "clamp", "wrap" or "zero".
  const char *boundary;
  int32_t observed;
  /// The scene declares its exact solution.
  int32_t exact;
  /// Bytes of the narrowest float its values derive from (4 or 8): 4 for an
  /// f64 buffer computed from f32 data. sim-run --check's default tolerance
  /// follows it.
  int32_t precision_bytes;
} sim_buffer_info;

SIM_API int32_t sim_bundle_num_buffers(const sim_bundle *bundle);
/// Strings stay valid as long as the bundle.
SIM_API sim_status sim_bundle_buffer(const sim_bundle *bundle, int32_t index,
                                     sim_buffer_info *out);
/// Bytes of the narrowest float the values of total `name` derive from (4
/// or 8, as sim_buffer_info.precision_bytes); 0 for no such total.
SIM_API int32_t sim_bundle_total_precision_bytes(const sim_bundle *bundle,
                                                 const char *name);

typedef struct sim_param_info {
  const char *name;
  /// "i32", "i64", "index", "f32" or "f64".
  const char *type;
  /// The default value as written in the bundle.
  const char *default_value;
} sim_param_info;

SIM_API int32_t sim_bundle_num_params(const sim_bundle *bundle);
SIM_API sim_status sim_bundle_param(const sim_bundle *bundle, int32_t index,
                                    sim_param_info *out);

//===----------------------------------------------------------------------===//
// Sessions: one strategy of one bundle on one backend
//===----------------------------------------------------------------------===//

typedef struct sim_session sim_session;

/// The processes of a distributed session (docs/Distributed.md): the
/// runtime splits the range into one block of whole groups per rank and
/// calls these functions, collectively, in the same order on every rank;
/// it never calls MPI itself (runtime/mpi/ implements them with MPI for
/// sim-run --distributed). Every function returns 0 on success and
/// non-zero on failure (then the session fails with
/// SIM_ERROR_DISTRIBUTED). Zero the struct before filling it in
/// (`sim_communicator comm = {0};`): optional functions left null are not
/// called.
typedef struct sim_communicator {
  void *user;
  /// This process's rank and the number of ranks.
  int32_t rank, size;
  /// Replaces each of `count` values by its minimum (`sum`: its sum) over
  /// all ranks.
  int (*allreduce_min_i64)(void *user, int64_t *values, int32_t count);
  int (*allreduce_sum_i64)(void *user, int64_t *values, int32_t count);
  /// Point to point: sends `send_bytes[r]` bytes from `send[r]` to every
  /// rank r with a non-zero count and receives `recv_bytes[r]` into
  /// `recv[r]` (arrays of `size` entries; a rank's own entries are 0).
  int (*exchange)(void *user, const void *const *send, const size_t *send_bytes,
                  void *const *recv, const size_t *recv_bytes);
  /// Every rank's `bytes[rank]` bytes from `data`, concatenated in rank
  /// order into `out` on every rank (`bytes` has `size` entries).
  int (*allgather)(void *user, const void *data, const size_t *bytes,
                   void *out);
  /// Optional (both or neither): `exchange` in two halves, so that the
  /// runtime computes the items that need no ghost items while they
  /// travel. `exchange_begin` starts it (the arrays stay valid until
  /// `exchange_end`, which waits for it); at most one is under way.
  int (*exchange_begin)(void *user, const void *const *send,
                        const size_t *send_bytes, void *const *recv,
                        const size_t *recv_bytes);
  int (*exchange_end)(void *user);
} sim_communicator;

typedef struct sim_session_options {
  sim_strategy strategy;
  sim_backend backend;
  /// Threads per group; 0: the plan's group_size. A multiple of 32 on
  /// CUDA. The reference executor sub-steps groups of this size.
  int64_t group_size;
  /// CPU worker threads, 1 to 1024; 0: one per hardware thread. A
  /// negative value or one above 1024 is refused with
  /// SIM_ERROR_INVALID_ARGUMENT on every backend.
  int32_t cpu_threads;
  /// CUDA device ordinal.
  int32_t cuda_device;
  /// Replay the step phase as a CUDA graph instead of launching its
  /// kernels one by one.
  int32_t cuda_graph;
  /// Run the step phase launch by launch and stop at the first NaN or
  /// infinity in the buffers a component writes (SIM_ERROR_NONFINITE).
  int32_t check_finite;
  /// The most bytes the session may allocate on its device (the host for
  /// the CPU and reference backends); a range whose buffers would need more
  /// is refused with SIM_ERROR_MEMORY_LIMIT before anything is allocated.
  /// 0: three quarters of the device's memory. A distributed session's
  /// limit, and sim_session_memory_bytes, are per rank (its block and
  /// ghosts).
  int64_t max_memory;
  /// Distributed sessions: the ranks to split the range over (NULL: one
  /// process). Needs a bundle compiled with sim-translate
  /// --sim-distributed and the CPU backend; the communicator must outlive
  /// the session.
  const sim_communicator *communicator;
} sim_session_options;

/// Fills in the defaults: hip, auto, the plan's group size, all threads,
/// device 0, no graph, no check, the default memory limit.
SIM_API void sim_session_options_init(sim_session_options *options);

SIM_API sim_status sim_session_create(const sim_bundle *bundle,
                                      const sim_session_options *options,
                                      sim_session **out);
SIM_API void sim_session_destroy(sim_session *session);

/// The backend that runs the session (never SIM_BACKEND_AUTO).
SIM_API sim_backend sim_session_backend(const sim_session *session);
/// The device, e.g. "NVIDIA H100 (sm_90)", "CPU (8 threads)" or
/// "reference executor (CPU, 1 thread)".
SIM_API const char *sim_session_device(const sim_session *session);
/// Why `auto` chose the CPU (empty when it did not).
SIM_API const char *sim_session_backend_note(const sim_session *session);
SIM_API int64_t sim_session_group_size(const sim_session *session);

/// Sets `range`, `dt` or a parameter from its text, like `--set`. A new
/// range discards the state (the next call that needs it runs init). A
/// `dt` that is not a positive, finite, normal number of the scene's type
/// (NaN, 0, subnormal) is SIM_ERROR_INVALID_ARGUMENT. `max_steps` is
/// fixed when the scene is compiled: any value but the bundle's is
/// SIM_ERROR_INVALID_ARGUMENT.
SIM_API sim_status sim_session_set(sim_session *session, const char *name,
                                   const char *value);
/// The bytes the session's state takes on its device at the current range
/// (allocated or not), and the most it may take (its max_memory, or the
/// default limit).
SIM_API int64_t sim_session_memory_bytes(const sim_session *session);
SIM_API int64_t sim_session_memory_limit(const sim_session *session);
/// The current value of `range`, `dt`, `max_steps` or a parameter as text.
SIM_API sim_status sim_session_get(const sim_session *session, const char *name,
                                   char *value, size_t capacity);
SIM_API int64_t sim_session_range(const sim_session *session);

/// Allocates the clock and the buffers (zeroed) and runs the init phase:
/// the state at base step 0. Calls that need a state do it when needed.
SIM_API sim_status sim_session_init(sim_session *session);

/// The current base step T.
SIM_API int64_t sim_session_time(const sim_session *session);

/// The bytes of a host array of a buffer: range * lanes * scalar_bytes.
SIM_API sim_status sim_session_buffer_bytes(const sim_session *session,
                                            const char *buffer, size_t *out);
/// Copies a buffer's current state (item-major, lanes packed) from or to a
/// host array of exactly sim_session_buffer_bytes bytes.
SIM_API sim_status sim_session_get_buffer(sim_session *session,
                                          const char *buffer, void *data,
                                          size_t bytes);
SIM_API sim_status sim_session_set_buffer(sim_session *session,
                                          const char *buffer, const void *data,
                                          size_t bytes);

/// Whether the scene has an exact solution for the buffer.
SIM_API int sim_session_has_exact(const sim_session *session,
                                  const char *buffer);
/// The exact solution of a buffer at the current time (T * dt) into a host
/// array like sim_session_get_buffer's.
SIM_API sim_status sim_session_exact(sim_session *session, const char *buffer,
                                     void *data, size_t bytes);

/// The totals the scene declares (`sim.total`: sums over all items it
/// observes), in declaration order.
SIM_API int32_t sim_session_num_totals(const sim_session *session);
SIM_API const char *sim_session_total_name(const sim_session *session,
                                           int32_t index);
/// The value of total `name` at the current time: the device computes the
/// value of every item, the host adds them in item order in double.
SIM_API sim_status sim_session_total(sim_session *session, const char *name,
                                     double *out);

/// Whether the value of total `name` on the exact solution exists: every
/// buffer its body reads has an exact solution (the bundle's reference
/// model says which it reads).
SIM_API int sim_session_has_exact_total(const sim_session *session,
                                        const char *name);
/// The value of total `name` on the exact solution at the current time
/// (T * dt): its body (the bundle's reference function) summed over the
/// items as sim_session_total does, each read seeing the exact solution of
/// the buffer. The session's state is not touched.
SIM_API sim_status sim_session_exact_total(sim_session *session,
                                           const char *name, double *out);

//===----------------------------------------------------------------------===//
// The init check: initial states against their writers
//===----------------------------------------------------------------------===//

/// What sim_session_check_init found for one buffer.
typedef struct sim_init_check {
  /// The buffer and the component that writes it.
  const char *buffer;
  const char *component;
  /// Items evaluated (all of the range, or max_items of it).
  int64_t items;
  /// The largest |evaluate - init| over the finite values of those items,
  /// its item (-1: none) and lane, and the init and evaluate values there.
  double max_abs;
  int64_t item;
  int32_t lane;
  double initial;
  double evaluated;
  /// The largest |value| of the buffer (init and evaluate) over the items,
  /// the relative tolerance, and how many values differ by more than
  /// tolerance * scale: the buffer's init disagrees with its writer when
  /// this is not 0.
  double scale;
  double tolerance;
  int64_t count;
  /// Values where init or evaluate is NaN or infinite (and they are not the
  /// same infinity): evaluate cannot run with n = 0, or the init is not
  /// finite; the first such item (-1: none).
  int64_t non_finite;
  int64_t non_finite_item;
  /// A component later in the schedule reads the buffer, so hip and
  /// hip-cache interpolate its readers' values from the init in the first
  /// big step.
  int32_t interpolated;
} sim_init_check;

/// Checks the scene's init bodies against its components with the
/// bundle's reference functions (docs/Runtime.md, "Warnings"): for
/// every item, every component's evaluate body at t = 0 with n = 0, every
/// read seeing the initial state, against the initial state of each buffer
/// it writes. A model whose init is consistent gets its state back
/// unchanged (n base steps of nothing). `tolerance` is relative to the
/// buffer's largest value (0: 1e-5 for buffers whose values derive from
/// f32 data, precision_bytes 4, 1e-12 for the others);
/// `max_items` bounds the items evaluated (0: 65536; above it, the first
/// and the last half of them). The session's range, dt and parameters
/// apply; its state is not touched. `*count` gets the number of buffers
/// checked, whose results sim_session_init_check returns until the next
/// check. SIM_ERROR_BUNDLE when the bundle has no reference functions;
/// SIM_ERROR_INTERRUPTED when sim_session_interrupt stops it (it evaluates
/// every item on the host, which takes a while on a large scene).
SIM_API sim_status sim_session_check_init(sim_session *session,
                                          double tolerance, int64_t max_items,
                                          int32_t *count);
/// Result `index` of the last sim_session_check_init; the strings live
/// until the next check or the session's end.
SIM_API sim_status sim_session_init_check(const sim_session *session,
                                          int32_t index, sim_init_check *out);

/// Called after each host synchronisation of a run with the base steps done
/// so far and the run's total. The callback may read the session (buffers,
/// totals, time, metrics) and call sim_session_interrupt; a call that would
/// change it (sim_session_set, _set_buffer, _init, _run, _run_pausing,
/// _checkpoint, _checkpoint_fd, _restart) returns
/// SIM_ERROR_INVALID_ARGUMENT and changes nothing. sim_session_destroy
/// there stops the run: sim_session_run returns SIM_ERROR_INTERRUPTED and
/// the session is gone.
typedef void (*sim_progress_fn)(void *user, int64_t done, int64_t total);
SIM_API void sim_session_set_progress(sim_session *session,
                                      sim_progress_fn progress, void *user);

/// What the last run measured.
typedef struct sim_metrics {
  /// Base steps run; the clock's T before and after the run.
  int64_t steps;
  int64_t begin;
  int64_t end;
  /// Host time of the run; time spent in kernels (CUDA events around the
  /// run on CUDA, the sum of kernel calls on the CPU).
  double wall_seconds;
  double kernel_seconds;
  /// Kernel launches (a graph replay counts its kernels), graph replays,
  /// and host synchronisations (waits for the device).
  int64_t launches;
  int64_t graph_launches;
  int64_t host_syncs;
  /// Big steps taken (clock slot 5).
  int64_t big_steps;
  /// Distributed sessions (0 otherwise), this rank's: ghost refreshes of a
  /// buffer or snapshot after a launch (one per plan `exchange` entry),
  /// the bytes this rank sent for them, and all-reduce calls (the same
  /// on every rank).
  int64_t halo_exchanges;
  int64_t exchanged_bytes;
  int64_t allreduces;
} sim_metrics;

/// Runs `steps` base steps from the current state (initialising first if
/// needed). The run ends exactly at T + steps, or fails. An interrupted run
/// returns SIM_ERROR_INTERRUPTED with the state at the big-step boundary it
/// reached (sim_session_time) and metrics of the base steps it did.
SIM_API sim_status sim_session_run(sim_session *session, int64_t steps);
/// Runs towards T + steps like sim_session_run, but returns early, with
/// SIM_OK, at the first big-step boundary at or after T + pause that a host
/// synchronisation sees (the reference executor sees every one). No big
/// step is cut there: a later run towards the same end (steps less the base
/// steps done, sim_session_time) takes the big steps, and gives the values,
/// of one run. For checkpoints that must not change a run. `pause >= steps`
/// is sim_session_run; a pause below 1 is SIM_ERROR_INVALID_ARGUMENT.
SIM_API sim_status sim_session_run_pausing(sim_session *session, int64_t steps,
                                           int64_t pause);
/// Asks the session's current and later runs to stop at their next host
/// synchronisation (SIM_ERROR_INTERRUPTED). Safe to call from another thread
/// or a signal handler; the request stays until sim_session_resume().
SIM_API void sim_session_interrupt(sim_session *session);
SIM_API void sim_session_resume(sim_session *session);
SIM_API sim_status sim_session_metrics(const sim_session *session,
                                       sim_metrics *out);

/// One kernel of the plan during the last run (sim-run --profile).
typedef struct sim_kernel_profile {
  /// The plan's name of the kernel ("substep_C1", "local_step_Heat").
  const char *name;
  /// Launches of it in the run (a graph replay counts each of its kernels).
  int64_t launches;
  /// Their kernel time where the backend times every launch (the CPU
  /// backend; the sum over kernels is the metrics' kernel_seconds), or -1
  /// where it times only the whole run (CUDA: use Nsight Systems or
  /// Nsight Compute for the kernels' times there).
  double seconds;
} sim_kernel_profile;

/// The kernels of the session's plan: 0 for SIM_BACKEND_REFERENCE, which
/// runs no kernels.
SIM_API int32_t sim_session_num_kernels(const sim_session *session);
/// Kernel `index`'s launches and time in the last run; the name stays valid
/// while the session lives. SIM_ERROR_INVALID_ARGUMENT for an index out of
/// range.
SIM_API sim_status sim_session_kernel_profile(const sim_session *session,
                                              int32_t index,
                                              sim_kernel_profile *out);

/// The components of the plan (of the reference model for
/// SIM_BACKEND_REFERENCE: the same names), for the counters below.
SIM_API int32_t sim_session_num_components(const sim_session *session);
SIM_API const char *sim_session_component(const sim_session *session,
                                          int32_t index);
/// Item evaluations of a component during the last run.
SIM_API int64_t sim_session_evaluations(const sim_session *session,
                                        int32_t component);
/// Big steps of `size` base steps (1 .. max_steps) during the last run.
SIM_API int64_t sim_session_histogram(const sim_session *session, int64_t size);
/// Big steps of the last run that its end cut short: the end, not the
/// estimates or the strategy's cap, decided their size (clock slot Cuts,
/// docs/Plan.md). At most one per run, its last, except under lts: it
/// rounds big steps down to powers of two, so the base steps the end leaves
/// go in power-of-two pieces, each a cut (docs/Model.md); 0 under simple.
SIM_API int64_t sim_session_cut_big_steps(const sim_session *session);

/// Checkpoints (docs/Runtime.md, "Checkpoints"): the session's state on
/// the big-step boundary it stands on, with the whole clock (T, parity, big
/// steps, cuts, evaluation counters, histogram, ...) and what identifies
/// the run (the bundle's CRC-32, scene, strategy, group size, range, dt and
/// every parameter). A restarted session continues bit for bit as the
/// session that wrote it would have. Initialises a session without a state.
///
/// Writes the checkpoint to `path`: a new file in its folder, fsync'ed and
/// renamed over `path`, so a reader finds the old checkpoint or the whole
/// new one.
SIM_API sim_status sim_session_checkpoint(sim_session *session,
                                          const char *path);
/// The same into an open, seekable file descriptor from its current offset
/// (the caller syncs, closes and names the file).
SIM_API sim_status sim_session_checkpoint_fd(sim_session *session, int fd);
/// Continues from the checkpoint at `path`: its T, clock and buffers become
/// the session's. Refused (SIM_ERROR_CHECKPOINT, the session unchanged)
/// when the file is damaged or belongs to another bundle, strategy, group
/// size or settings; a checkpoint of the plan executor also restarts the
/// reference executor (T and the buffers), not the reverse.
SIM_API sim_status sim_session_restart(sim_session *session, const char *path);

/// Where the last run found a non-finite value (SIM_ERROR_NONFINITE).
typedef struct sim_nonfinite {
  /// The clock's T when the launch ran.
  int64_t base_step;
  const char *component;
  const char *buffer;
  const char *kernel;
  int64_t item;
  int32_t lane;
  double value;
} sim_nonfinite;
SIM_API sim_status sim_session_nonfinite(const sim_session *session,
                                         sim_nonfinite *out);

#ifdef __cplusplus
}
#endif

#endif // SIM_RUNTIME_SIM_RUNTIME_H
