//===- MpiCommunicator.h - a sim_communicator over MPI ------------*- C++
//-*-===//
//
// The runtime never calls MPI (libsim_runtime links no MPI); sim-run
// --distributed fills a sim_communicator with these MPI_COMM_WORLD calls
// and hands it to its sessions. Built only when CMake finds MPI, as a
// plugin (libsim_mpi.so) that sim-run opens only for --distributed, so
// that sim-run itself starts on machines without MPI's libraries.
//
//===----------------------------------------------------------------------===//

#ifndef SIM_RUNTIME_MPI_MPICOMMUNICATOR_H
#define SIM_RUNTIME_MPI_MPICOMMUNICATOR_H

#include "sim/Runtime/sim_runtime.h"

namespace sim::mpi {

/// MPI_Init_thread (funneled: the sessions' worker threads never call
/// MPI) unless MPI is initialised already; MPI_Finalize at the end of its
/// life unless MPI was initialised before it.
class World {
public:
  World(int *argc, char ***argv);
  ~World();
  World(const World &) = delete;
  World &operator=(const World &) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// The rank among the ranks on this machine (0 when MPI cannot tell).
  int localRank() const { return localRank_; }
  /// The communicator of MPI_COMM_WORLD (valid while this object lives).
  const sim_communicator *communicator() const { return &comm; }

  /// Ends every rank with `status` (MPI_Abort), so that none waits for a
  /// rank that failed.
  [[noreturn]] static void abort(int status);

private:
  int rank_ = 0, size_ = 1, localRank_ = 0;
  bool owns = false;
  sim_communicator comm{};
};

} // namespace sim::mpi

extern "C" {
/// The plugin's entry points, which sim-run looks up with dlsym.
typedef struct sim_mpi_world_info {
  const sim_communicator *communicator;
  int rank, size, local_rank;
} sim_mpi_world_info;

/// Starts MPI (a sim::mpi::World) and describes it in `info`; the handle
/// goes to sim_mpi_close.
typedef void *(*sim_mpi_open_fn)(int *argc, char ***argv,
                                 sim_mpi_world_info *info);
typedef void (*sim_mpi_close_fn)(void *world);
/// sim::mpi::World::abort.
typedef void (*sim_mpi_abort_fn)(int status);
}

#endif // SIM_RUNTIME_MPI_MPICOMMUNICATOR_H
