#include "io/scene/triangle_shape.hpp"

#include "physics/geometry.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tridem::scene_detail {

std::optional<std::string> shape_problem(const std::array<Vec2d, 3>& v) {
  for (const Vec2d& p : v) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y))
      return fmt::format("vertex ({}, {}) is not finite", p.x, p.y);
  }
  double longest_sq = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec2d e = v[(i + 1) % 3] - v[i];
    longest_sq = std::max(longest_sq, dot(e, e));
  }
  const double area = 0.5 * std::abs(twice_signed_area(v));
  if (physics::is_degenerate(area, longest_sq))
    return fmt::format("triangle is degenerate (area {:g} <= {:g}*L^2 = {:g}, L = longest edge)",
                       area, physics::kDegenerateAreaFactor,
                       physics::kDegenerateAreaFactor * longest_sq);
  return std::nullopt;
}

}  // namespace tridem::scene_detail
