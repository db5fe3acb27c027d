#include "mpi/collectives.hpp"

#include "mpi/agreement.hpp"
#include "tridem/error.hpp"

#include <algorithm>
#include <climits>
#include <fmt/format.h>
#include <optional>

namespace tridem::mpi {

std::vector<double> collect(MPI_Comm comm, const std::vector<double>& mine, bool all) {
  int ranks = 1, rank = 0;
  MPI_Comm_size(comm, &ranks);
  MPI_Comm_rank(comm, &rank);
  const int count = static_cast<int>(mine.size());
  std::vector<int> counts(static_cast<std::size_t>(ranks)), displs(static_cast<std::size_t>(ranks));
  if (all)
    MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  else
    MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, comm);
  long long total = 0;
  for (int r = 0; r < ranks; ++r) {
    displs[static_cast<std::size_t>(r)] = static_cast<int>(total);
    total += counts[static_cast<std::size_t>(r)];
  }
  std::vector<double> out(all || rank == 0 ? static_cast<std::size_t>(total) : 0);
  if (all)
    MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, out.data(), counts.data(), displs.data(),
                   MPI_DOUBLE, comm);
  else
    MPI_Gatherv(mine.data(), count, MPI_DOUBLE, out.data(), counts.data(), displs.data(),
                MPI_DOUBLE, 0, comm);
  return out;
}

std::vector<double> send_each(MPI_Comm comm, const std::vector<std::vector<double>>& to) {
  const std::size_t ranks = to.size();
  std::vector<long long> sizes(ranks), got(ranks);
  for (std::size_t r = 0; r < ranks; ++r) sizes[r] = static_cast<long long>(to[r].size());
  MPI_Alltoall(sizes.data(), 1, MPI_LONG_LONG, got.data(), 1, MPI_LONG_LONG, comm);
  long long sent = 0, received = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    sent += sizes[r];
    received += got[r];
  }
  std::optional<std::string> problem;
  if (std::max(sent, received) > INT_MAX)
    problem = fmt::format("a rank's share of {} values exceeds what one MPI exchange counts "
                          "({}): run on more ranks",
                          std::max(sent, received), INT_MAX);
  if (auto message = agree(comm, problem)) throw RunError(*message);
  std::vector<int> send_counts(ranks), send_displs(ranks), recv_counts(ranks), recv_displs(ranks);
  std::vector<double> out, in(static_cast<std::size_t>(received));
  out.reserve(static_cast<std::size_t>(sent));
  int at = 0, from = 0;
  for (std::size_t r = 0; r < ranks; ++r) {
    send_counts[r] = static_cast<int>(sizes[r]);
    send_displs[r] = at;
    at += send_counts[r];
    out.insert(out.end(), to[r].begin(), to[r].end());
    recv_counts[r] = static_cast<int>(got[r]);
    recv_displs[r] = from;
    from += recv_counts[r];
  }
  MPI_Alltoallv(out.data(), send_counts.data(), send_displs.data(), MPI_DOUBLE, in.data(),
                recv_counts.data(), recv_displs.data(), MPI_DOUBLE, comm);
  return in;
}

}  // namespace tridem::mpi
