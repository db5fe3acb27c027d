#pragma once
// The part of a triangle inside an axis-aligned rectangle, for packing fractions: a
// triangle cut by a region's edge counts with the area it has inside.
#include "tridem/scene.hpp"
#include "tridem/vec2.hpp"

#include <array>

namespace tridem::measure {

/// The area of triangle `t` (either orientation) inside `region`, exact up to rounding:
/// the triangle clipped by the rectangle's four half-planes in turn.
double area_inside(const std::array<Vec2d, 3>& t, const MeasureRegion& region);

}  // namespace tridem::measure
