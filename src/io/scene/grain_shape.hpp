#pragma once
// The outline of one random convex grain (docs/scene-format.md, kind = "polygons"): its
// vertices lie on an ellipse, at polar angles spread about those of the regular polygon.
#include "tridem/vec2.hpp"

#include <random>
#include <vector>

namespace tridem::scene_detail {

struct GrainShapeRange {
  int min_sides = 3, max_sides = 3;
  double min_aspect = 1, max_aspect = 1;
  double angularity = 0;
};

/// A counter-clockwise convex outline of area π·size²/4 (size: the equal-area diameter)
/// with its centroid at the origin. Draws, in order: the number of sides, the aspect
/// ratio, the orientation, then one angle per vertex; always 3 + max_sides draws, so that
/// the grains after it do not depend on how many sides this one got.
std::vector<Vec2d> random_convex_outline(std::mt19937_64& rng, const GrainShapeRange& range,
                                         double size);

/// Radius of the smallest disk about the origin that holds the outline.
double reach(const std::vector<Vec2d>& outline);

}  // namespace tridem::scene_detail
