#include "core/solver_factory.hpp"

#include "backends/cpu/cpu_solver.hpp"
#include "backends/cuda/cuda_backend.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

namespace tridem {

Backend resolve_backend(Backend requested) {
  if (requested != Backend::Auto) return requested;
  if (cuda_available()) return Backend::Cuda;
  return omp_get_max_threads() > 1 ? Backend::OpenMP : Backend::Cpu;
}

namespace {

template <class Real>
std::unique_ptr<Solver> make_for_real(const Scene& scene, const ParticleModel& model,
                                      const TimeStep& ts, const SolverConfig& config,
                                      Backend backend) {
  switch (backend) {
    case Backend::Cpu:
      return std::make_unique<CpuSolver<Real>>(scene, model, ts, config, false);
    case Backend::OpenMP:
      return std::make_unique<CpuSolver<Real>>(scene, model, ts, config, true);
    case Backend::Cuda:
      return make_cuda_solver(scene, model, ts, config);
    case Backend::Auto:
      break;
  }
  throw RunError("internal error: unresolved backend");
}

/// The method settings again, with the config's method (a command line may have replaced
/// the scene's): a scene built in code has not been through the reader.
void check_method(const Scene& scene, Method method) {
  const std::string source = scene.source.empty() ? "scene built in code" : scene.source;
  const SimulationSettings& s = scene.simulation;
  if (auto why = method_settings_conflict(method, s.contact_test, s.bbox_prefilter))
    throw SceneError(source + ": [simulation] " + *why);
}

}  // namespace

std::unique_ptr<Solver> make_solver(const Scene& scene, const SolverConfig& config) {
  const ParticleModel model = build_particle_model(scene);
  return make_solver(scene, model, estimate_time_step(scene, model), config);
}

std::unique_ptr<Solver> make_solver(const Scene& scene, const ParticleModel& model,
                                    const TimeStep& ts, const SolverConfig& config) {
  check_method(scene, config.method);
  check_time_step(scene, ts, config.force);
  Backend backend = resolve_backend(config.backend);
  if (backend == Backend::Cuda && !model.bodies.empty()) {
    // Not yet on the GPU (issue 13): refused, never run as loose triangles.
    if (config.backend != Backend::Auto)
      throw RunError(
          "the cuda backend does not run bodies of several triangles ([[body]]) yet: use "
          "--backend cpu or openmp for this scene");
    backend = omp_get_max_threads() > 1 ? Backend::OpenMP : Backend::Cpu;
  }
  if (config.threads > 0 && backend != Backend::OpenMP)
    throw RunError(fmt::format(
        "--threads {} sets the OpenMP threads, but the backend is {}{}, which does not use "
        "them: give --backend openmp, or leave --threads out",
        config.threads, backend_name(backend),
        config.backend == Backend::Auto ? " (picked by backend = auto)" : ""));
  if (config.precision == Precision::Float)
    return make_for_real<float>(scene, model, ts, config, backend);
  return make_for_real<double>(scene, model, ts, config, backend);
}

}  // namespace tridem
