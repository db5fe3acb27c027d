// Random packing. Each triangle lives in its own cell of a square grid of pitch
// p = 2R(1+gap) and stays within a disk of radius R about a centre that is jittered by at
// most R·gap/2 per axis from the cell centre; that disk therefore never leaves the cell
// (margin R·gap/2), and triangles in different cells can't overlap whatever the draws.
//
// Irregular shapes: vertex k sits at polar angle θ0 + 2πk/3 + δk with |δk| <= irregularity·π/6,
// radius R·(1 − irregularity·uk/2) with uk in [0,1). Every angular gap between successive
// vertices is then in (π/3, π), so the centre is strictly inside and, with radii >= R/2, the
// area is at least ~0.2·R²: never degenerate. Increasing angles make the order CCW.
//
// Every triangle consumes exactly nine draws whatever the irregularity, so changing only the
// irregularity keeps positions and orientations and changes only shapes.
#include "tridem/generate.hpp"

#include "io/scene/generator_checks.hpp"
#include "io/scene/random_unit.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace tridem {
namespace {

double circumradius(const RandomPackingSpec& spec) { return spec.size / std::sqrt(3.0); }
double pitch(const RandomPackingSpec& spec) { return 2 * circumradius(spec) * (1 + spec.gap); }

void check_spec(const RandomPackingSpec& spec) {
  scene_detail::check_generator_common("random", spec.material, spec.region_min,
                                       spec.region_max, spec.size, spec.gap, spec.velocity);
  if (!(spec.irregularity >= 0 && spec.irregularity < 1))
    throw SceneError(fmt::format("random generator: irregularity must be in [0, 1), got {}",
                                 spec.irregularity));
}

struct Grid {
  double nx, ny;
};

Grid grid_of(const RandomPackingSpec& spec) {
  const double p = pitch(spec);
  return {scene_detail::tolerant_floor((spec.region_max.x - spec.region_min.x) / p),
          scene_detail::tolerant_floor((spec.region_max.y - spec.region_min.y) / p)};
}

}  // namespace

std::size_t count_random_cells(const RandomPackingSpec& spec) {
  check_spec(spec);
  const Grid g = grid_of(spec);
  return scene_detail::saturating_count(g.nx * g.ny);
}

std::vector<TriangleSpec> generate_random(const RandomPackingSpec& spec) {
  const std::size_t cells = count_random_cells(spec);
  if (spec.count > cells)
    throw SceneError(fmt::format(
        "random generator: count {} exceeds the {} cells the region holds at this size and gap",
        spec.count, cells));
  const std::size_t n = spec.count > 0 ? spec.count : cells;
  scene_detail::check_generated_count("random", n);

  const double R = circumradius(spec);
  const double p = pitch(spec);
  const double jitter = 0.5 * R * spec.gap;
  const double max_turn = spec.irregularity * std::numbers::pi / 6;
  const double max_shrink = 0.5 * spec.irregularity;
  const auto nx = static_cast<std::size_t>(grid_of(spec).nx);

  std::mt19937_64 rng(spec.seed);
  std::vector<TriangleSpec> out;
  out.reserve(n);
  TriangleSpec t;
  t.material = spec.material;
  t.velocity = spec.velocity;
  for (std::size_t i = 0; i < n; ++i) {
    const double cx = spec.region_min.x + (static_cast<double>(i % nx) + 0.5) * p;
    const double cy = spec.region_min.y + (static_cast<double>(i / nx) + 0.5) * p;
    const double jx = jitter * scene_detail::signed_unit_double(rng);
    const double jy = jitter * scene_detail::signed_unit_double(rng);
    const Vec2d centre{cx + jx, cy + jy};
    const double theta0 = 2 * std::numbers::pi * scene_detail::unit_double(rng);
    for (int k = 0; k < 3; ++k) {
      const double turn = max_turn * scene_detail::signed_unit_double(rng);
      const double radius = R * (1 - max_shrink * scene_detail::unit_double(rng));
      const double angle = theta0 + 2 * std::numbers::pi * k / 3 + turn;
      t.vertices[k] = centre + Vec2d{radius * std::cos(angle), radius * std::sin(angle)};
    }
    out.push_back(t);
  }
  return out;
}

}  // namespace tridem
