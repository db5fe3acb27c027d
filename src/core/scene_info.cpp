#include "backends/cuda/cuda_backend.hpp"
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "physics/contact_force.hpp"
#include "tridem/run.hpp"

#include <algorithm>
#include <limits>

namespace tridem {

namespace {

/// Bytes a run holds per particle, for real type Real: the CPU solver's arrays, plus the
/// host copies (scene, particle model, and the snapshot with its contact list on output
/// steps).
template <class Real>
std::size_t run_bytes(std::size_t n) {
  // Per particle: offsets and vertices (12), mass, area and size (3), forces (3), boxes
  // (4) reals; state (6) and inverse mass and inertia (2) in double in every precision;
  // material, motion, cell bookkeeping, the pair-row offsets and the energy budget's
  // four sums.
  const std::size_t per_particle = 22 * sizeof(Real) + 8 * 8 + sizeof(int) + 1 + 2 * 4 * 8 +
                                   8 + 4 + 8 + 3 * 8 + 2 * 8 + 4 * 8;
  // Per pair, two buffers of partner and slip, one of results and the reverse slot. A
  // dense packing has 6.6 candidate pairs per particle (bench/), and the lists keep 20%
  // headroom: 8 pairs per particle.
  const std::size_t per_pair = 2 * (4 + sizeof(physics::PairSlip<Real>)) +
                               sizeof(physics::PairForce<Real>) + 8;
  // Host copies: TriangleSpec, ParticleModel, Snapshot (17 doubles and two small ints),
  // and about six contact records of a dense packing.
  const std::size_t host = sizeof(TriangleSpec) + 136 + 17 * 8 + 8 + 6 * sizeof(ContactRecord);
  return n * (per_particle + 8 * per_pair + host);
}

}  // namespace

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
  info.memory_bytes = scene.simulation.precision == Precision::Float
                          ? run_bytes<float>(model.size())
                          : run_bytes<double>(model.size());
  info.gpu_memory_bytes = cuda_solver_bytes(
      model.size(), kCudaPairsPerParticle * model.size() + 1024, scene.simulation.precision);
  info.gpu = cuda_device_description();
  return info;
}

}  // namespace tridem
