#pragma once
// How ranks agree that something failed: every rank says whether it failed, and all of
// them learn the message of the lowest failing rank, so that one message is printed (by
// rank 0) and no rank waits for one that has given up.
#include <mpi.h>
#include <optional>
#include <string>

namespace tridem::mpi {

/// Collective over `comm`: `problem` is this rank's failure (empty when it is fine).
/// Returns the message of the lowest rank that failed, or nothing when none did.
std::optional<std::string> agree(MPI_Comm comm, const std::optional<std::string>& problem);

/// Collective: `text` as rank `root` has it, on every rank.
void broadcast(MPI_Comm comm, std::string& text, int root);

}  // namespace tridem::mpi
