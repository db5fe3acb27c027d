#include "mpi/agreement.hpp"

namespace tridem::mpi {

std::optional<std::string> agree(MPI_Comm comm, const std::optional<std::string>& problem) {
  int rank = 0, ranks = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &ranks);
  // The lowest failing rank wins: the maximum of ranks - rank over those that failed.
  const int mine = problem ? ranks - rank : 0;
  int top = 0;
  MPI_Allreduce(&mine, &top, 1, MPI_INT, MPI_MAX, comm);
  if (top == 0) return std::nullopt;
  std::string text = problem ? *problem : std::string();
  broadcast(comm, text, ranks - top);
  return text;
}

void broadcast(MPI_Comm comm, std::string& text, int root) {
  long long length = static_cast<long long>(text.size());
  MPI_Bcast(&length, 1, MPI_LONG_LONG, root, comm);
  text.resize(static_cast<std::size_t>(length));
  MPI_Bcast(text.data(), static_cast<int>(length), MPI_CHAR, root, comm);
}

}  // namespace tridem::mpi
