#pragma once
// An order of points along a Hilbert curve through their bounding box, so that points
// near each other in space get near positions in the order (docs/performance.md, "The
// particles' order": a GPU run of grains numbered at random took 0.45 of the time-step
// rate of the same grains numbered row by row).
#include "tridem/scene.hpp"
#include "tridem/vec2.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tridem {

/// Position of cell (x, y) of a 2^16 x 2^16 grid along the Hilbert curve that starts at
/// cell (0, 0) and ends at (2^16 - 1, 0).
std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y);

/// The indices of `points` in the order of their cells (2^16 to a side of their bounding
/// box) along the Hilbert curve; points of one cell keep their order.
std::vector<std::size_t> space_filling_order(const std::vector<Vec2d>& points);

/// The first `count` of `triangles` (lone ones: no body or bond refers to them) put in the
/// space_filling_order of their centroids; the rest stay where they are.
void number_by_place(std::vector<TriangleSpec>& triangles, std::size_t count);

}  // namespace tridem
