#pragma once
// The CUDA backend as the rest of tridem sees it: plain C++, no CUDA types, so that the
// solver factory, `tridem info` and the tests compile with or without nvcc. Without CUDA
// (cuda_backend_absent.cpp) every entry point says so instead of failing obscurely.
#include "core/particle_model.hpp"
#include "core/rank_solver.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace tridem {

/// True when this build has the CUDA backend and a usable GPU is present; otherwise
/// false, with the reason (no nvcc at build time, no device, driver too old...).
bool cuda_available(std::string* reason = nullptr);

/// How many GPUs the CUDA backend can choose from (SolverConfig::device is an index below
/// it); 0 when none is usable or the build has no CUDA.
int cuda_device_count();

/// GPU `device`, e.g. "NVIDIA H100 80GB HBM3 (sm_90, 132 SMs, 79 GiB)"; empty when there is
/// no such usable device.
std::string cuda_device_description(int device = 0);

/// The most bytes taken at once from GPU `device`'s stream-ordered pool (cudaMallocAsync:
/// the scratch of a frame's contact network, backends/cuda/touching_pairs.cuh) since the
/// last reset, and with `reset` the count starts again from what is in use now; 0 without
/// CUDA or such a device.
std::size_t cuda_stream_pool_peak(int device = 0, bool reset = false);

/// The solver running the whole time loop on the GPU. Throws RunError when no GPU is
/// usable or the scene does not fit in its memory (make_solver first refuses a build or
/// machine without one, with the way out).
std::unique_ptr<Solver> make_cuda_solver(const Scene& scene, const ParticleModel& model,
                                         const TimeStep& ts, const SolverConfig& config);

/// An MPI rank's local solver on GPU `config.device` (core/rank_solver.hpp, src/mpi/): the
/// CUDA solver, its ghosts packed on the GPU and staged through pinned host memory. Throws
/// RunError as make_cuda_solver does.
template <class Real>
std::unique_ptr<RankSolver<Real>> make_cuda_rank(const Scene& scene, const ParticleModel& model,
                                                 const TimeStep& ts, const SolverConfig& config);

/// Bytes of GPU memory the CUDA solver holds for n particles, a first list of `pairs` pairs
/// (its slots: pair_slots_for) and `bonds` cohesive bonds (core/memory_estimate.hpp); 0 in a
/// build without CUDA.
std::size_t cuda_solver_bytes(std::size_t n, std::size_t pairs, Precision precision,
                              std::size_t bonds = 0);

}  // namespace tridem
