#pragma once
// A [[body]]'s polygon cut into the triangles that become its members: CGAL's constrained
// Delaunay triangulation of the outline, keeping the faces inside it. The member vertices
// are the outline's own points (a constrained triangulation adds none), so a body read
// from a polygon is exactly the shape written in the file.
#include "tridem/vec2.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace tridem::scene_detail {

struct PolygonTriangulation {
  std::vector<std::array<Vec2d, 3>> triangles;  ///< counter-clockwise
  std::optional<std::string> problem;           ///< why the outline was refused
};

/// Triangulates a simple polygon given in either orientation. Refused (problem set):
/// fewer than 3 points, non-finite or repeated points, a self-intersecting outline, zero
/// area.
PolygonTriangulation triangulate_polygon(const std::vector<Vec2d>& outline);

}  // namespace tridem::scene_detail
