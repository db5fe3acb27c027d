#pragma once
// Independent overlap test for the generator tests: written from first principles (vertex
// containment, proper edge crossings, centroid containment) rather than with the solver's
// contact geometry, so a bug there can't hide a bug in the generators.
#include "tridem/scene.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace tridem::test {

using Tri = std::array<Vec2d, 3>;

/// Signed distance of p from the line a→b, positive on its left.
inline double side(Vec2d a, Vec2d b, Vec2d p) { return cross(b - a, p - a) / norm(b - a); }

/// p strictly inside the CCW triangle t, deeper than tol from every edge.
inline bool strictly_inside(const Tri& t, Vec2d p, double tol) {
  for (int i = 0; i < 3; ++i)
    if (side(t[i], t[(i + 1) % 3], p) <= tol) return false;
  return true;
}

/// Segments cross at a point interior to both, by more than tol on each side.
inline bool properly_cross(Vec2d p1, Vec2d p2, Vec2d q1, Vec2d q2, double tol) {
  const double a = side(p1, p2, q1), b = side(p1, p2, q2);
  const double c = side(q1, q2, p1), d = side(q1, q2, p2);
  return ((a > tol && b < -tol) || (a < -tol && b > tol)) &&
         ((c > tol && d < -tol) || (c < -tol && d > tol));
}

/// Whether two CCW triangles share interior area (touching within tol does not count).
inline bool overlap(const Tri& s, const Tri& t, double tol) {
  const Vec2d cs = (s[0] + s[1] + s[2]) / 3.0, ct = (t[0] + t[1] + t[2]) / 3.0;
  if (strictly_inside(t, cs, tol) || strictly_inside(s, ct, tol)) return true;
  for (int i = 0; i < 3; ++i) {
    if (strictly_inside(t, s[i], tol) || strictly_inside(s, t[i], tol)) return true;
    for (int j = 0; j < 3; ++j)
      if (properly_cross(s[i], s[(i + 1) % 3], t[j], t[(j + 1) % 3], tol)) return true;
  }
  return false;
}

inline double point_segment_distance(Vec2d p, Vec2d a, Vec2d b) {
  const Vec2d ab = b - a;
  const double u = std::clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
  return norm(p - (a + ab * u));
}

/// Distance between two non-overlapping triangles.
inline double distance(const Tri& s, const Tri& t) {
  double d = INFINITY;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      d = std::min(d, point_segment_distance(s[i], t[j], t[(j + 1) % 3]));
      d = std::min(d, point_segment_distance(t[i], s[j], s[(j + 1) % 3]));
    }
  return d;
}

/// First overlapping pair, by brute force over all pairs (fine for a few thousand).
inline std::optional<std::pair<std::size_t, std::size_t>> find_overlap(
    const std::vector<TriangleSpec>& ts, double tol) {
  for (std::size_t i = 0; i < ts.size(); ++i)
    for (std::size_t j = i + 1; j < ts.size(); ++j)
      if (overlap(ts[i].vertices, ts[j].vertices, tol)) return std::pair{i, j};
  return std::nullopt;
}

/// Smallest distance between any two triangles.
inline double min_separation(const std::vector<TriangleSpec>& ts) {
  double d = INFINITY;
  for (std::size_t i = 0; i < ts.size(); ++i)
    for (std::size_t j = i + 1; j < ts.size(); ++j)
      d = std::min(d, distance(ts[i].vertices, ts[j].vertices));
  return d;
}

inline double twice_area(const Tri& t) { return cross(t[1] - t[0], t[2] - t[0]); }

}  // namespace tridem::test
