// Builds without nvcc: the CUDA backend is absent and says so when asked for.
#include "backends/cuda/cuda_backend.hpp"
#include "tridem/error.hpp"

namespace tridem {

namespace {
constexpr const char* kAbsent =
    "this tridem was built without CUDA (no nvcc found, or -DTRIDEM_ENABLE_CUDA=OFF)";
}

bool cuda_available(std::string* reason) {
  if (reason) *reason = kAbsent;
  return false;
}

int cuda_device_count() { return 0; }

std::string cuda_device_description(int) { return {}; }

std::size_t cuda_stream_pool_peak(int, bool) { return 0; }

std::unique_ptr<Solver> make_cuda_solver(const Scene&, const ParticleModel&, const TimeStep&,
                                         const SolverConfig&) {
  throw RunError(kAbsent);  // make_solver asks cuda_available() first, and says why
}

template <class Real>
std::unique_ptr<RankSolver<Real>> make_cuda_rank(const Scene&, const ParticleModel&,
                                                 const TimeStep&, const SolverConfig&) {
  throw RunError(kAbsent);  // the MPI ranks ask cuda_available() first, and say why
}
template std::unique_ptr<RankSolver<float>> make_cuda_rank(const Scene&, const ParticleModel&,
                                                           const TimeStep&, const SolverConfig&);
template std::unique_ptr<RankSolver<double>> make_cuda_rank(const Scene&, const ParticleModel&,
                                                            const TimeStep&, const SolverConfig&);

std::size_t cuda_solver_bytes(std::size_t, std::size_t, Precision, std::size_t) { return 0; }

}  // namespace tridem
