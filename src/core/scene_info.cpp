#include "backends/cuda/cuda_backend.hpp"
#include "core/memory_estimate.hpp"
#include "core/numbering_note.hpp"
#include "core/particle_model.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/time_step.hpp"
#include "tridem/run.hpp"

#include <algorithm>
#include <limits>

namespace tridem {

SceneInfo describe_scene(const Scene& scene) {
  const ParticleModel model = build_particle_model(scene);
  const TimeStep ts = estimate_time_step(scene, model);
  SceneInfo info;
  info.triangles = model.size();
  info.box_lo = {std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  info.box_hi = {std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
  for (std::size_t i = 0; i < model.size(); ++i) {
    switch (model.motion[i]) {
      case Motion::Free: ++info.free; break;
      case Motion::Fixed: ++info.fixed; break;
      case Motion::Prescribed: ++info.prescribed; break;
    }
    for (const Vec2d& r : model.offsets[i]) {
      const Vec2d v = model.centroid[i] + r;
      info.box_lo = {std::min(info.box_lo.x, v.x), std::min(info.box_lo.y, v.y)};
      info.box_hi = {std::max(info.box_hi.x, v.x), std::max(info.box_hi.y, v.y)};
    }
    if (model.motion[i] == Motion::Free)
      info.longest_edge = std::max(info.longest_edge, model.longest_edge[i]);
  }
  info.dt_critical = ts.critical;
  info.dt_limit = ts.limit.describe();
  info.dt_chosen = ts.chosen;
  info.dt_automatic = ts.automatic;
  info.steps = steps_to_reach(scene.simulation, ts.chosen);
  const std::size_t n = model.size();
  const std::size_t pairs = first_list_pairs(scene, model);
  info.first_list_pairs = pairs;
  info.memory_bytes = cpu_run_bytes(n, pairs, scene.simulation.precision, scene.bonds.size());
  info.gpu_memory_bytes =
      cuda_solver_bytes(n, pairs, scene.simulation.precision, scene.bonds.size());
  info.gpu = cuda_device_description();
  info.numbering_distance = consecutive_id_distance(model);
  info.numbering_spread = numbering_spread(model);
  info.numbered_by_place = numbers_by_place(scene, model, ParticleOrder::Auto);
  return info;
}

}  // namespace tridem
