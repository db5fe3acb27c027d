#pragma once
// Which GPU an MPI rank steps its particles on (GPU ranks, docs/scaling.md): the ranks of
// one node share its GPUs round-robin by their rank on the node, so that 2 ranks on a
// machine with one GPU both use it, and 8 ranks on 8 GPUs take one each.
#include <mpi.h>
#include <string>

namespace tridem::mpi {

/// The GPU of the rank numbered `local_rank` on its node, which has `devices` GPUs (> 0).
int device_for_rank(int local_rank, int devices);

/// This process's rank among the ranks of its node (MPI_Comm_split_type, shared memory).
/// Collective over `comm`.
int node_local_rank(MPI_Comm comm);

/// Why `rank` cannot run backend = "cuda" with `devices` usable GPUs (`why`: the CUDA
/// runtime's reason when there are none), or empty when it can.
std::string gpu_rank_refusal(const std::string& scene, int rank, int devices,
                             const std::string& why);

}  // namespace tridem::mpi
