#pragma once
// The CUDA backend as the rest of tridem sees it: plain C++, no CUDA types, so that the
// solver factory, `tridem info` and the tests compile with or without nvcc. Without CUDA
// (cuda_backend_absent.cpp) every entry point says so instead of failing obscurely.
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

#include <cstddef>
#include <memory>
#include <string>

namespace tridem {

/// True when this build has the CUDA backend and a usable GPU is present; otherwise
/// false, with the reason (no nvcc at build time, no device, driver too old...).
bool cuda_available(std::string* reason = nullptr);

/// The GPU the CUDA backend uses, e.g. "NVIDIA H100 80GB HBM3 (sm_90, 132 SMs, 79 GiB)";
/// empty when none is usable.
std::string cuda_device_description();

/// The solver running the whole time loop on the GPU. Throws RunError when no GPU is
/// usable or the scene does not fit in its memory.
std::unique_ptr<Solver> make_cuda_solver(const Scene& scene, const ParticleModel& model,
                                         const TimeStep& ts, const SolverConfig& config);

/// Bytes of GPU memory the CUDA solver allocates at start for n particles
/// (core/memory_estimate.hpp); 0 in a build without CUDA.
std::size_t cuda_solver_bytes(std::size_t n, Precision precision);

}  // namespace tridem
