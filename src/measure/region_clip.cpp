#include "measure/region_clip.hpp"

#include <cmath>
#include <cstddef>

namespace tridem::measure {

namespace {

// A triangle clipped by four half-planes has at most 3 + 4 vertices.
struct Polygon {
  std::array<Vec2d, 8> v{};
  std::size_t n = 0;
};

/// The part of `p` where coordinate `axis` (0: x, 1: y) times `side` is <= side·limit.
Polygon clip(const Polygon& p, int axis, double limit, double side) {
  Polygon out;
  const auto inside = [&](Vec2d q) { return side * ((axis == 0 ? q.x : q.y) - limit) <= 0; };
  for (std::size_t k = 0; k < p.n; ++k) {
    const Vec2d a = p.v[k], b = p.v[(k + 1) % p.n];
    const bool in_a = inside(a), in_b = inside(b);
    if (in_a) out.v[out.n++] = a;
    if (in_a != in_b) {
      const double ca = axis == 0 ? a.x : a.y, cb = axis == 0 ? b.x : b.y;
      const double t = (limit - ca) / (cb - ca);
      Vec2d q = a + (b - a) * t;
      (axis == 0 ? q.x : q.y) = limit;  // exactly on the line
      out.v[out.n++] = q;
    }
  }
  return out;
}

}  // namespace

double area_inside(const std::array<Vec2d, 3>& t, const MeasureRegion& region) {
  Polygon p;
  p.v[0] = t[0];
  p.v[1] = t[1];
  p.v[2] = t[2];
  p.n = 3;
  p = clip(p, 0, region.hi.x, 1);
  p = clip(p, 0, region.lo.x, -1);
  p = clip(p, 1, region.hi.y, 1);
  p = clip(p, 1, region.lo.y, -1);
  // About the first vertex, so that large coordinates cancel before the products.
  double twice = 0;
  for (std::size_t k = 0; k < p.n; ++k) {
    const Vec2d a = p.v[k] - p.v[0], b = p.v[(k + 1) % p.n] - p.v[0];
    twice += a.x * b.y - b.x * a.y;
  }
  return 0.5 * std::abs(twice);
}

}  // namespace tridem::measure
