#pragma once
// Shape rules for one triangle, shared by the file reader, validate_scene and the tests;
// "degenerate" is physics::is_degenerate, the rule the particle model applies too.
#include "tridem/vec2.hpp"

#include <array>
#include <optional>
#include <string>
#include <utility>

namespace tridem::scene_detail {

/// Twice the signed area: > 0 for counter-clockwise vertices.
inline double twice_signed_area(const std::array<Vec2d, 3>& v) {
  return cross(v[1] - v[0], v[2] - v[0]);
}

/// Why these vertices can't be a grain (non-finite, degenerate), or nullopt if they can.
std::optional<std::string> shape_problem(const std::array<Vec2d, 3>& v);

/// Swaps two vertices of a clockwise triangle so that it becomes counter-clockwise.
inline void make_counter_clockwise(std::array<Vec2d, 3>& v) {
  if (twice_signed_area(v) < 0) std::swap(v[1], v[2]);
}

}  // namespace tridem::scene_detail
