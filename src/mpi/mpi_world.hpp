#pragma once
// MPI for the whole process: initialised only when a launcher (mpirun, srun) started
// this process, so that tridem run alone needs no MPI runtime at all.
#include <mpi.h>

namespace tridem::mpi {

class World {
 public:
  /// MPI_Init when the environment names a launcher's job (Open MPI's
  /// OMPI_COMM_WORLD_SIZE, PMI's PMI_SIZE, PMIx's PMIX_RANK); otherwise nothing.
  World(int& argc, char**& argv);
  ~World();  ///< MPI_Finalize when it initialised
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  bool active() const { return active_; }
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
};

}  // namespace tridem::mpi
