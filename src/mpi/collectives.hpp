#pragma once
// The MPI collectives the ranks' gathers and the parallel checkpoint share: records of
// doubles (ids travel as doubles, exact below 2^53) gathered in rank order, or sent each
// to the rank that takes it.
#include <cstdint>
#include <mpi.h>
#include <vector>

namespace tridem::mpi {

/// Every rank's `mine`, one after the other in rank order: on every rank (`all`) or on
/// rank 0 only (others get nothing).
std::vector<double> collect(MPI_Comm comm, const std::vector<double>& mine, bool all);

/// Collective: `to[r]` goes to rank r; returns what every rank sent this one, in rank
/// order. Throws RunError (on every rank) when a rank's share exceeds an MPI count.
std::vector<double> send_each(MPI_Comm comm, const std::vector<std::vector<double>>& to);

/// An id that travelled as a double.
inline std::int32_t as_id(double v) { return static_cast<std::int32_t>(v); }

}  // namespace tridem::mpi
