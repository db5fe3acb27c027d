// Vertex k of an n-gon sits at parametric angle φk = 2πk/n + δk, δk uniform in
// [−a·π/n, a·π/n] (a: angularity), on the ellipse (√λ cos φ, sin φ / √λ) of aspect ratio
// λ, turned by a uniform orientation. Points of an ellipse in angular order are in convex
// position, and successive angles differ by at least 2π(1 − a)/n > 0, so the outline is
// convex and counter-clockwise; it is then scaled to its area and centred on its centroid.
#include "io/scene/grain_shape.hpp"

#include "io/scene/random_unit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tridem::scene_detail {
namespace {

double polygon_area(const std::vector<Vec2d>& p) {
  double twice = 0;
  for (std::size_t k = 0; k < p.size(); ++k) twice += cross(p[k], p[(k + 1) % p.size()]);
  return 0.5 * twice;
}

Vec2d polygon_centroid(const std::vector<Vec2d>& p, double area) {
  Vec2d c{};
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2d a = p[k], b = p[(k + 1) % p.size()];
    c += (a + b) * cross(a, b);
  }
  return c / (6 * area);
}

}  // namespace

std::vector<Vec2d> random_convex_outline(std::mt19937_64& rng, const GrainShapeRange& range,
                                         double size) {
  const int span = range.max_sides - range.min_sides + 1;
  const int n =
      std::min(range.max_sides, range.min_sides + static_cast<int>(unit_double(rng) * span));
  const double aspect = range.min_aspect + (range.max_aspect - range.min_aspect) * unit_double(rng);
  const double turn = 2 * std::numbers::pi * unit_double(rng);
  const double sx = std::sqrt(aspect), sy = 1 / sx;
  const double c = std::cos(turn), s = std::sin(turn);
  std::vector<Vec2d> outline(static_cast<std::size_t>(n));
  for (int k = 0; k < range.max_sides; ++k) {
    const double spread = range.angularity * std::numbers::pi / n * signed_unit_double(rng);
    if (k >= n) continue;  // the draw is still taken: a fixed number per grain
    const double phi = 2 * std::numbers::pi * k / n + spread;
    const double ex = sx * std::cos(phi), ey = sy * std::sin(phi);
    outline[static_cast<std::size_t>(k)] = {c * ex - s * ey, s * ex + c * ey};
  }
  const double area = polygon_area(outline);
  const Vec2d centre = polygon_centroid(outline, area);
  const double scale = std::sqrt(std::numbers::pi * size * size / 4 / area);
  for (Vec2d& p : outline) p = (p - centre) * scale;
  return outline;
}

double reach(const std::vector<Vec2d>& outline) {
  double r = 0;
  for (const Vec2d& p : outline) r = std::max(r, norm(p));
  return r;
}

}  // namespace tridem::scene_detail
