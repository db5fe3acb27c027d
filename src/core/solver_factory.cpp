#include "core/solver_factory.hpp"

#include "backends/cpu/cpu_solver.hpp"
#include "backends/cuda/cuda_backend.hpp"
#include "core/numbering_note.hpp"
#include "core/periodic_checks.hpp"
#include "core/place_numbered_solver.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"

#include <fmt/format.h>
#include <omp.h>

namespace tridem {

namespace {
/// What backend = auto picks when no GPU is usable.
Backend fastest_cpu_backend() { return omp_get_max_threads() > 1 ? Backend::OpenMP : Backend::Cpu; }
}  // namespace

Backend resolve_backend(Backend requested) {
  if (requested != Backend::Auto) return requested;
  if (cuda_available()) return Backend::Cuda;
  return fastest_cpu_backend();
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

/// The method settings again: a scene built in code has not been through the reader.
void check_method(const Scene& scene) {
  const SimulationSettings& s = scene.simulation;
  if (auto why = method_settings_conflict(s.method, s.contact_test, s.bbox_prefilter))
    throw SceneError(scene_label(scene) + ": [simulation] " + *why);
}

/// The GPU the caller chose, refused with the way out where it is not one of this machine.
void check_device(int device, Backend backend, Backend requested) {
  if (backend != Backend::Cuda) {
    if (device != 0)
      throw RunError(fmt::format(
          "--device {} picks a GPU, but the backend is {}{}, which runs on the CPU: give "
          "--backend {}, or leave --device out",
          device, backend_name(backend),
          requested == Backend::Auto ? " (picked by backend = auto)" : "",
          backend_name(Backend::Cuda)));
    return;
  }
  if (std::string why; !cuda_available(&why))
    throw RunError(fmt::format("backend '{}' is not available: {}; use backend = \"{}\", "
                               "\"{}\" or \"{}\"",
                               backend_name(backend), why, backend_name(Backend::Cpu),
                               backend_name(Backend::OpenMP), backend_name(Backend::Auto)));
  const int count = cuda_device_count();
  if (device < 0 || device >= count)
    throw RunError(fmt::format(
        "--device {} is not a GPU of this machine, which has {} usable GPU{} ({}): give one "
        "of those, or leave --device out for device 0",
        device, count, count == 1 ? "" : "s",
        count == 1 ? std::string("device 0") : fmt::format("devices 0 to {}", count - 1)));
}

}  // namespace

std::unique_ptr<Solver> make_solver(const Scene& scene, const SolverConfig& config) {
  const ParticleModel model = build_particle_model(scene);
  return make_solver(scene, model, estimate_time_step(scene, model), config);
}

MakeInnerSolver scene_order_maker(const TimeStep& ts, SolverConfig config) {
  config.particle_order = ParticleOrder::Scene;
  return [ts, config](const Scene& scene, const ParticleModel& model) {
    return make_solver(scene, model, ts, config);
  };
}

std::unique_ptr<Solver> make_solver(const Scene& scene, const ParticleModel& model,
                                    const TimeStep& ts, const SolverConfig& config) {
  check_method(scene);
  check_time_step(scene, ts, config.force);
  const Backend requested = scene.simulation.backend;
  // Bonded and periodic scenes too: the GPU computes bonds and periodic cells.
  Backend backend = resolve_backend(requested);
  check_periodic_cell(scene, model);
  // A periodic cell too short for the GPU's pair list runs on the CPU under auto, never
  // risking a missed pair.
  if (backend == Backend::Cuda) {
    const GpuPeriodicLimit limit = gpu_periodic_limit(scene, model);
    if (!limit.refusal.empty()) {
      if (requested != Backend::Auto) throw SceneError(limit.refusal);
      backend = fastest_cpu_backend();
      fmt::print(stderr, "note: backend = auto runs this periodic scene on {}: {}\n",
                 backend_name(backend), limit.reason);
    }
  }
  if (config.threads > 0 && backend != Backend::OpenMP)
    throw RunError(fmt::format(
        "--threads {} sets the OpenMP threads, but the backend is {}{}, which does not use "
        "them: give --backend {}, or leave --threads out",
        config.threads, backend_name(backend),
        requested == Backend::Auto ? " (picked by backend = auto)" : "",
        backend_name(Backend::OpenMP)));
  check_device(config.device, backend, requested);
  // By value: a solver that numbers its particles by place again mid-run makes its inner
  // solver again with them.
  MakeInnerSolver make = [ts, config, backend](const Scene& s, const ParticleModel& m) {
    return s.simulation.precision == Precision::Float
               ? make_for_real<float>(s, m, ts, config, backend)
               : make_for_real<double>(s, m, ts, config, backend);
  };
  const bool by_place = numbers_by_place(scene, model, config.particle_order);
  // A large scene in its own order gets the wrapper too, which looks at the order as the
  // run goes and keeps it as it is until the grains have mixed.
  const bool may_renumber = config.particle_order != ParticleOrder::Scene &&
                            config.order_check_steps > 0 && model.size() >= kLargeNumbering &&
                            model.size() <= static_cast<std::size_t>(INT32_MAX);
  if (!by_place && !may_renumber) return make(scene, model);
  return make_renumbering_solver(scene, model, by_place ? place_order(model) : scene_order(model),
                                 make, may_renumber ? config.order_check_steps : 0);
}

}  // namespace tridem
