#include "io/scene/polygon_triangulation.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <fmt/format.h>

#include <cmath>
#include <set>
#include <utility>

namespace tridem::scene_detail {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_2;
using Polygon = CGAL::Polygon_2<Kernel>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel>;

}  // namespace

PolygonTriangulation triangulate_polygon(const std::vector<Vec2d>& outline) {
  PolygonTriangulation out;
  if (outline.size() < 3) {
    out.problem = fmt::format("a polygon needs at least 3 points, got {}", outline.size());
    return out;
  }
  std::set<std::pair<double, double>> seen;
  Polygon polygon;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    const Vec2d p = outline[k];
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
      out.problem = fmt::format("point {} ({}, {}) is not finite", k + 1, p.x, p.y);
      return out;
    }
    if (!seen.insert({p.x, p.y}).second) {
      out.problem = fmt::format("point {} ({}, {}) repeats an earlier point", k + 1, p.x, p.y);
      return out;
    }
    polygon.push_back(Point(p.x, p.y));
  }
  // Exact predicates: no rounding decides collinearity or simplicity. The points are
  // distinct, so the first two fix a line.
  bool collinear = true;
  for (std::size_t k = 2; k < polygon.size(); ++k)
    collinear = collinear && CGAL::collinear(polygon[0], polygon[1], polygon[k]);
  if (collinear) {
    out.problem = "the polygon is degenerate (all its points on one line)";
    return out;
  }
  if (!polygon.is_simple()) {
    out.problem = "the polygon intersects itself (its edges cross or touch)";
    return out;
  }
  Cdt cdt;
  cdt.insert_constraint(polygon.vertices_begin(), polygon.vertices_end(), true);
  // Every face lies wholly inside or wholly outside a simple outline that constrains all
  // of its edges; its centroid says which.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const Point& a = f->vertex(0)->point();
    const Point& b = f->vertex(1)->point();
    const Point& c = f->vertex(2)->point();
    if (polygon.bounded_side(CGAL::centroid(a, b, c)) != CGAL::ON_BOUNDED_SIDE) continue;
    // CGAL's faces are counter-clockwise.
    out.triangles.push_back({Vec2d{a.x(), a.y()}, Vec2d{b.x(), b.y()}, Vec2d{c.x(), c.y()}});
  }
  if (out.triangles.empty()) out.problem = "the polygon is degenerate (no area)";
  return out;
}

}  // namespace tridem::scene_detail
