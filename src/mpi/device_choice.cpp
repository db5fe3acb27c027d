#include "mpi/device_choice.hpp"

#include <fmt/format.h>

namespace tridem::mpi {

int device_for_rank(int local_rank, int devices) {
  return devices > 0 && local_rank >= 0 ? local_rank % devices : 0;
}

int node_local_rank(MPI_Comm comm) {
  MPI_Comm node = MPI_COMM_NULL;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int rank = 0;
  MPI_Comm_rank(node, &rank);
  MPI_Comm_free(&node);
  return rank;
}

std::string gpu_rank_refusal(const std::string& scene, int rank, int devices,
                             const std::string& why) {
  if (devices > 0) return {};
  return fmt::format("{}: backend = \"cuda\" on MPI ranks needs a GPU for every rank, and "
                     "rank {} has none ({}); use backend = \"cpu\" on the ranks, or run one "
                     "rank per GPU on a machine with GPUs",
                     scene.empty() ? std::string("scene") : scene, rank,
                     why.empty() ? std::string("no usable GPU") : why);
}

}  // namespace tridem::mpi
