#include "io/scene/placement_region.hpp"

#include "io/scene/polygon_triangulation.hpp"
#include "io/scene/random_unit.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tridem::scene_detail {
namespace {

double orient(Vec2d a, Vec2d b, Vec2d p) { return cross(b - a, p - a); }

// Segments pq and rs cross or touch (collinear overlaps included).
bool segments_meet(Vec2d p, Vec2d q, Vec2d r, Vec2d s) {
  const double d1 = orient(r, s, p), d2 = orient(r, s, q);
  const double d3 = orient(p, q, r), d4 = orient(p, q, s);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0)))
    return true;
  auto on = [](Vec2d a, Vec2d b, Vec2d c, double o) {
    return o == 0 && std::min(a.x, b.x) <= c.x && c.x <= std::max(a.x, b.x) &&
           std::min(a.y, b.y) <= c.y && c.y <= std::max(a.y, b.y);
  };
  return on(r, s, p, d1) || on(r, s, q, d2) || on(p, q, r, d3) || on(p, q, s, d4);
}

// Crossing number; a point on the outline counts as outside through the edge test of
// holds(), which runs after it.
bool point_in_polygon(const std::vector<Vec2d>& poly, Vec2d p) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2d a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

}  // namespace

PlacementRegion PlacementRegion::make(const std::vector<Vec2d>& points,
                                      std::optional<std::string>& problem) {
  PlacementRegion r;
  problem.reset();
  for (const Vec2d& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      problem = "its points must be finite";
      return r;
    }
  if (points.size() == 2) {
    r.lo_ = points[0];
    r.hi_ = points[1];
    if (!(r.hi_.x > r.lo_.x && r.hi_.y > r.lo_.y)) {
      problem = fmt::format("max corner ({}, {}) must exceed min corner ({}, {}) in x and y",
                            r.hi_.x, r.hi_.y, r.lo_.x, r.lo_.y);
      return r;
    }
    r.area_ = (r.hi_.x - r.lo_.x) * (r.hi_.y - r.lo_.y);
    return r;
  }
  if (points.size() < 2) {
    problem = fmt::format("expected 2 corners [[xmin, ymin], [xmax, ymax]] or a polygon of at "
                          "least 3 points, got {} point(s)",
                          points.size());
    return r;
  }
  PolygonTriangulation cut = triangulate_polygon(points);
  if (cut.problem) {
    problem = "as a polygon: " + *cut.problem;
    return r;
  }
  r.rectangle_ = false;
  r.outline_ = points;
  r.lo_ = r.hi_ = points[0];
  for (const Vec2d& p : points) {
    r.lo_ = {std::min(r.lo_.x, p.x), std::min(r.lo_.y, p.y)};
    r.hi_ = {std::max(r.hi_.x, p.x), std::max(r.hi_.y, p.y)};
  }
  r.triangles_ = std::move(cut.triangles);
  for (const auto& t : r.triangles_) {
    r.area_ += 0.5 * cross(t[1] - t[0], t[2] - t[0]);
    r.cumulative_area_.push_back(r.area_);
  }
  return r;
}

Vec2d PlacementRegion::sample(std::mt19937_64& rng) const {
  const double u = unit_double(rng), v = unit_double(rng);
  if (rectangle_) return {lo_.x + u * (hi_.x - lo_.x), lo_.y + v * (hi_.y - lo_.y)};
  // u picks a triangle by area and, rescaled within it, is reused as the first barycentric
  // draw: one draw does both without bias.
  const double target = u * area_;
  const auto it = std::upper_bound(cumulative_area_.begin(), cumulative_area_.end(), target);
  const std::size_t k =
      std::min(static_cast<std::size_t>(it - cumulative_area_.begin()), triangles_.size() - 1);
  const double before = k == 0 ? 0 : cumulative_area_[k - 1];
  const double a = std::clamp((target - before) / (cumulative_area_[k] - before), 0.0, 1.0);
  // Uniform in a triangle: fold the unit square's upper half back onto the lower one.
  double s = a, t = v;
  if (s + t > 1) {
    s = 1 - s;
    t = 1 - t;
  }
  const auto& tri = triangles_[k];
  return tri[0] + (tri[1] - tri[0]) * s + (tri[2] - tri[0]) * t;
}

bool PlacementRegion::holds(const std::vector<Vec2d>& outline, Vec2d at) const {
  if (rectangle_) {
    for (const Vec2d& p : outline) {
      const Vec2d q = p + at;
      if (!(q.x > lo_.x && q.x < hi_.x && q.y > lo_.y && q.y < hi_.y)) return false;
    }
    return true;
  }
  for (const Vec2d& p : outline)
    if (!point_in_polygon(outline_, p + at)) return false;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const Vec2d a = outline[i] + at, b = outline[(i + 1) % outline.size()] + at;
    for (std::size_t j = 0; j < outline_.size(); ++j)
      if (segments_meet(a, b, outline_[j], outline_[(j + 1) % outline_.size()])) return false;
  }
  return true;
}

}  // namespace tridem::scene_detail
