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

std::optional<std::string> triangle_problem(const TriangleSpec& t, std::size_t materials) {
  if (t.material < 0 || static_cast<std::size_t>(t.material) >= materials)
    return fmt::format("material index {} out of range (scene has {} materials)", t.material,
                       materials);
  if (auto problem = shape_problem(t.vertices)) return problem;
  if (!std::isfinite(t.velocity.x) || !std::isfinite(t.velocity.y) ||
      !std::isfinite(t.angular_velocity))
    return "velocity and angular_velocity must be finite";
  switch (t.motion) {
    case Motion::Free:
    case Motion::Prescribed: return std::nullopt;
    case Motion::Fixed:
      if (t.velocity.x != 0 || t.velocity.y != 0 || t.angular_velocity != 0)
        return "a fixed triangle must have zero velocity and angular_velocity";
      return std::nullopt;
  }
  return fmt::format("invalid motion value {}", static_cast<int>(t.motion));
}

}  // namespace tridem::scene_detail
