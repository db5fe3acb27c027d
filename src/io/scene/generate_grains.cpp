// Random grains by random sequential addition: every grain's size and shape is drawn
// first (one stream of draws), then the grains are placed largest first, each at uniform
// random positions of the region (a second stream) until one is inside the region and
// overlaps no grain placed before, or max_attempts positions have failed. The overlap
// test is the solvers' exact one (physics::triangles_overlap) on the grains' member
// triangles, after a disk test on their reach, over the grains of the 3 × 3 cells about
// the candidate.
#include "core/space_filling_order.hpp"
#include "io/scene/generator_checks.hpp"
#include "io/scene/grain_shape.hpp"
#include "io/scene/placement_grid.hpp"
#include "io/scene/placement_region.hpp"
#include "io/scene/polygon_triangulation.hpp"
#include "io/scene/size_distribution.hpp"
#include "io/scene/triangle_shape.hpp"
#include "physics/geometry.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace tridem {
namespace {

constexpr int kMaxSides = 64;

[[noreturn]] void refuse(const std::string& what) {
  throw SceneError(fmt::format("grain generator: {}", what));
}

bool finite(double x) { return std::isfinite(x); }

void check_sizes(const SizeDistribution& d) {
  if (d.classes.empty()) {
    if (!(finite(d.min_size) && finite(d.max_size) && d.min_size > 0 && d.max_size >= d.min_size))
      refuse(fmt::format("sizes must be finite with 0 < min <= max, got [{}, {}]", d.min_size,
                         d.max_size));
    return;
  }
  double sum = 0;
  for (std::size_t k = 0; k < d.classes.size(); ++k) {
    const SizeClass& c = d.classes[k];
    if (!(finite(c.size) && c.size > 0))
      refuse(fmt::format("size {} of the table must be finite and > 0, got {}", k + 1, c.size));
    if (!(finite(c.mass_fraction) && c.mass_fraction > 0))
      refuse(fmt::format("mass fraction {} of the table must be finite and > 0, got {}", k + 1,
                         c.mass_fraction));
    sum += c.mass_fraction;
  }
  if (std::abs(sum - 1) > 1e-6)
    refuse(fmt::format("the mass fractions must sum to 1, they sum to {}", sum));
}

scene_detail::PlacementRegion region_of(const GrainSpec& spec) {
  std::optional<std::string> problem;
  scene_detail::PlacementRegion region = scene_detail::PlacementRegion::make(spec.region, problem);
  if (problem) refuse("region: " + *problem);
  return region;
}

void check_spec(const GrainSpec& spec) {
  if (spec.material < 0) refuse(fmt::format("material index {} is negative", spec.material));
  if (!(spec.min_sides >= 3 && spec.min_sides <= spec.max_sides && spec.max_sides <= kMaxSides))
    refuse(fmt::format("sides must satisfy 3 <= min <= max <= {}, got [{}, {}]", kMaxSides,
                       spec.min_sides, spec.max_sides));
  if (!(finite(spec.max_aspect) && spec.min_aspect >= 1 && spec.max_aspect >= spec.min_aspect))
    refuse(fmt::format("aspect ratios must be finite with 1 <= min <= max, got [{}, {}]",
                       spec.min_aspect, spec.max_aspect));
  if (!(spec.angularity >= 0 && spec.angularity < 1))
    refuse(fmt::format("angularity must be in [0, 1), got {}", spec.angularity));
  check_sizes(spec.sizes);
  if (spec.count == 0 && !(spec.packing_fraction > 0 && spec.packing_fraction < 1))
    refuse(fmt::format("give a count > 0 or a packing fraction in (0, 1), got {}",
                       spec.packing_fraction));
  if (spec.count > 0 && spec.packing_fraction != 0)
    refuse("give a count or a packing fraction, not both");
  if (spec.max_attempts == 0) refuse("max_attempts must be >= 1");
  if (!finite(spec.velocity.x) || !finite(spec.velocity.y)) refuse("velocity must be finite");
}

// Most grains the amount can take: the count, or the packing fraction's area over the
// smallest grain's (plus the last one, which may overshoot).
std::size_t max_grains(const GrainSpec& spec, double region_area) {
  if (spec.count > 0) return spec.count;
  const double d = scene_detail::smallest_size(spec.sizes);
  return scene_detail::saturating_count(
      std::ceil(spec.packing_fraction * region_area / (std::numbers::pi * d * d / 4)) + 1);
}

struct Grain {
  double size = 0;
  double reach = 0;
  std::vector<Vec2d> outline;                      // about its centroid
  std::vector<physics::Triangle<double>> members;  // about its centroid, counter-clockwise
};

Grain make_grain(std::mt19937_64& rng, const GrainSpec& spec, double size) {
  const scene_detail::GrainShapeRange range{spec.min_sides, spec.max_sides, spec.min_aspect,
                                            spec.max_aspect, spec.angularity};
  Grain g;
  g.size = size;
  g.outline = scene_detail::random_convex_outline(rng, range, size);
  g.reach = scene_detail::reach(g.outline);
  std::vector<std::array<Vec2d, 3>> cut;
  if (g.outline.size() == 3) {
    cut.push_back({g.outline[0], g.outline[1], g.outline[2]});
  } else {
    scene_detail::PolygonTriangulation t = scene_detail::triangulate_polygon(g.outline);
    if (t.problem) refuse("a drawn grain could not be triangulated: " + *t.problem);
    cut = std::move(t.triangles);
  }
  for (const auto& v : cut) {
    if (auto problem = scene_detail::shape_problem(v))
      refuse(fmt::format("a drawn grain of {} sides has a degenerate member ({}): lower the "
                         "angularity or the aspect ratio",
                         g.outline.size(), *problem));
    g.members.push_back({{v[0], v[1], v[2]}});
  }
  return g;
}

physics::Triangle<double> moved(const physics::Triangle<double>& t, Vec2d by) {
  return {{t.v[0] + by, t.v[1] + by, t.v[2] + by}};
}

bool grains_overlap(const Grain& a, Vec2d at_a, const Grain& b, Vec2d at_b) {
  const Vec2d d = at_b - at_a;
  if (dot(d, d) >= (a.reach + b.reach) * (a.reach + b.reach)) return false;
  for (const auto& ta : a.members) {
    const physics::Triangle<double> pa = moved(ta, at_a);
    for (const auto& tb : b.members)
      if (physics::triangles_overlap(pa, moved(tb, at_b))) return true;
  }
  return false;
}

}  // namespace

std::size_t max_grain_triangles(const GrainSpec& spec) {
  check_spec(spec);
  const double area = region_of(spec).area();
  return scene_detail::saturating_count(static_cast<double>(max_grains(spec, area)) *
                                        (spec.max_sides - 2));
}

GeneratedGrains generate_grains(const GrainSpec& spec) {
  scene_detail::check_generated_count("grain", max_grain_triangles(spec));
  const scene_detail::PlacementRegion region = region_of(spec);

  std::mt19937_64 shapes(spec.seed);
  const std::vector<double> sizes = scene_detail::draw_sizes(shapes, spec.sizes, spec.count,
                                                             spec.packing_fraction * region.area(),
                                                             max_grains(spec, region.area()));
  std::vector<Grain> grains;
  grains.reserve(sizes.size());
  double widest = 0;
  for (double size : sizes) {
    grains.push_back(make_grain(shapes, spec, size));
    widest = std::max(widest, grains.back().reach);
  }
  // Largest first: they are the hardest to fit once the region fills up.
  std::vector<std::size_t> order(grains.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return grains[a].size > grains[b].size; });

  std::mt19937_64 positions(spec.seed ^ 0x9e3779b97f4a7c15ULL);
  scene_detail::PlacementGrid grid(region.lo(), region.hi(), 2 * widest, grains.size());
  std::vector<Vec2d> at;
  at.reserve(grains.size());
  double placed_area = 0;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const Grain& g = grains[order[n]];
    bool placed = false;
    for (std::size_t attempt = 0; attempt < spec.max_attempts && !placed; ++attempt) {
      const Vec2d c = region.sample(positions);
      if (!region.holds(g.outline, c)) continue;
      placed = !grid.any_near(
          c, [&](std::size_t k) { return grains_overlap(g, c, grains[order[k]], at[k]); });
      if (placed) {
        grid.insert(n, c);
        at.push_back(c);
      }
    }
    if (!placed)
      refuse(fmt::format(
          "placed {} of {} grains (packing fraction {:.3f} of the region{}) when grain {} "
          "(size {} m) found no free place in {} random positions (max_attempts): enlarge the "
          "region, ask for fewer or smaller grains, or raise max_attempts",
          n, grains.size(), placed_area / region.area(),
          spec.count > 0 ? "" : fmt::format(", {} asked for", spec.packing_fraction), n + 1, g.size,
          spec.max_attempts));
    placed_area += std::numbers::pi * g.size * g.size / 4;
  }

  GeneratedGrains out;
  std::size_t triangles = 0;
  for (const Grain& g : grains) triangles += g.members.size();
  out.triangles.reserve(triangles);
  out.bodies.reserve(grains.size());
  TriangleSpec t;
  t.material = spec.material;
  t.velocity = spec.velocity;
  std::vector<std::size_t> numbering(order.size());
  if (spec.numbering == GrainNumbering::Space)
    numbering = space_filling_order(at);
  else
    std::iota(numbering.begin(), numbering.end(), std::size_t{0});
  for (const std::size_t n : numbering) {
    const Grain& g = grains[order[n]];
    out.bodies.push_back({out.triangles.size(), g.members.size(), spec.velocity, 0, Motion::Free});
    for (const auto& m : g.members) {
      for (int k = 0; k < 3; ++k) t.vertices[k] = m.v[k] + at[n];
      out.triangles.push_back(t);
    }
  }
  return out;
}

}  // namespace tridem
