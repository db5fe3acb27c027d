#pragma once
// Rules for one triangle, shared by the file reader, validate_scene, the particle model
// and the tests so that "degenerate" (physics::is_degenerate) and every other refusal of a
// triangle mean the same thing everywhere.
#include "tridem/scene.hpp"
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

/// Why `t` can't be a particle of a scene with `materials` materials (material index out
/// of range, a shape_problem, a non-finite velocity, a fixed triangle that moves), or
/// nullopt if it can. validate_scene and build_particle_model both refuse by this.
std::optional<std::string> triangle_problem(const TriangleSpec& t, std::size_t materials);

/// Swaps two vertices of a clockwise triangle so that it becomes counter-clockwise.
inline void make_counter_clockwise(std::array<Vec2d, 3>& v) {
  if (twice_signed_area(v) < 0) std::swap(v[1], v[2]);
}

}  // namespace tridem::scene_detail
