#pragma once
// Where random grains may go: a rectangle or a simple polygon (convex or not). A grain is
// inside when it lies wholly in the region: every vertex strictly inside and no edge of
// the grain crossing or touching the outline (a non-convex region's corner can reach into
// a grain whose vertices are all inside).
#include "tridem/vec2.hpp"

#include <array>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace tridem::scene_detail {

class PlacementRegion {
 public:
  /// 2 points: the corners of a rectangle (max > min on both axes); 3 or more: a simple
  /// polygon in either orientation. `problem` says why the points make no region.
  static PlacementRegion make(const std::vector<Vec2d>& points,
                              std::optional<std::string>& problem);

  double area() const { return area_; }
  Vec2d lo() const { return lo_; }
  Vec2d hi() const { return hi_; }

  /// A point uniform over the region (a rectangle, or one of the polygon's triangles
  /// chosen by area): two draws.
  Vec2d sample(std::mt19937_64& rng) const;

  /// Whether the polygon `outline` (translated by `at`) lies wholly inside.
  bool holds(const std::vector<Vec2d>& outline, Vec2d at) const;

 private:
  bool rectangle_ = true;
  Vec2d lo_{}, hi_{};
  double area_ = 0;
  std::vector<Vec2d> outline_;                   // polygon only
  std::vector<std::array<Vec2d, 3>> triangles_;  // polygon only, for sampling
  std::vector<double> cumulative_area_;          // polygon only
};

}  // namespace tridem::scene_detail
