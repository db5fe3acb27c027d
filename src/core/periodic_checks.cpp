#include "core/periodic_checks.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace tridem {

namespace {

/// The farthest vertex of any triangle from its centroid, and the triangle.
std::pair<double, std::size_t> farthest_reach(const ParticleModel& model) {
  double reach = 0;
  std::size_t widest = 0;
  for (std::size_t i = 0; i < model.size(); ++i)
    for (const Vec2d& v : model.offsets[i])
      if (std::hypot(v.x, v.y) > reach) {
        reach = std::hypot(v.x, v.y);
        widest = i;
      }
  return {reach, widest};
}

}  // namespace

double gpu_exact_periodic_length(const Scene& scene, const ParticleModel& model) {
  if (!scene.simulation.periodic.any()) return 0;
  const double grid_cell = classify_for_grid(model.longest_edge, model.motion).cell;
  return 8 * farthest_reach(model).first + 2 * scene.simulation.skin * grid_cell;
}

GpuPeriodicLimit gpu_periodic_limit(const Scene& scene, const ParticleModel& model) {
  if (!scene.simulation.periodic.any() || gpu_lists_periodic_cell_exactly(scene, model)) return {};
  const std::string label = scene_label(scene);
  const std::string cpu_backends = fmt::format(
      "backend = \"{}\", \"{}\" or \"{}\" (auto runs it on the CPU)", backend_name(Backend::OpenMP),
      backend_name(Backend::Cpu), backend_name(Backend::Auto));
  const double shortest = gpu_exact_periodic_length(scene, model);
  return {fmt::format("{}: the periodic cell is too short for backend '{}': its pair list can "
                      "miss a pair in cells shorter than {} (8 x the farthest vertex from a "
                      "centroid, plus twice the skin); make periodic_x / periodic_y longer "
                      "than that, or use {}",
                      label, backend_name(Backend::Cuda), shortest, cpu_backends),
          fmt::format("its cell is shorter than {}, under which the GPU's pair list could miss "
                      "a pair",
                      shortest)};
}

bool gpu_lists_periodic_cell_exactly(const Scene& scene, const ParticleModel& model) {
  const PeriodicCell& cell = scene.simulation.periodic;
  const double shortest = gpu_exact_periodic_length(scene, model);
  for (const auto& range : {cell.x, cell.y})
    if (range && !(range->length() > shortest)) return false;
  return true;
}

void check_periodic_cell(const Scene& scene, const ParticleModel& model) {
  const PeriodicCell& cell = scene.simulation.periodic;
  if (!cell.any()) return;
  const std::string label = scene_label(scene);
  // The farthest vertex of any triangle from its centroid: two touching triangles are at
  // most twice that apart, and the nearest image is the only one they can touch through
  // when that is under half a period.
  const auto [reach, widest] = farthest_reach(model);
  const double grid_cell = classify_for_grid(model.longest_edge, model.motion).cell;
  for (const auto& [key, range] :
       {std::pair{"periodic_x", cell.x}, std::pair{"periodic_y", cell.y}}) {
    if (!range) continue;
    const double length = range->length();
    if (length < 2 * grid_cell)
      throw SceneError(fmt::format(
          "{}: [simulation] {} = [{}, {}] is {} long, shorter than 2 cells of the pair grid "
          "(2 x {}, the longest edge of the free triangles): make the cell at least {} long",
          label, key, range->lo, range->hi, length, grid_cell, 2 * grid_cell));
    if (!(length > 4 * reach))
      throw SceneError(fmt::format(
          "{}: [simulation] {} = [{}, {}] is {} long, not longer than 4 x {} (particle id {}: "
          "its farthest vertex from its centroid), so two touching triangles could meet "
          "through two images of the cell: make the cell longer than {}, or build long walls "
          "from shorter triangles",
          label, key, range->lo, range->hi, length, reach, widest, 4 * reach));
  }
}

}  // namespace tridem
