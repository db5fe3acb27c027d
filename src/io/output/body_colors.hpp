#pragma once
// Colours of bodies for the renderer: neighbouring bodies get different colours of the
// categorical palette, so that each grain of a packing stands out from those it touches.
#include "tridem/snapshot.hpp"

#include <cstddef>
#include <vector>

namespace tridem::io {

/// Two free triangles of different bodies are neighbours when their bounding boxes, grown
/// by `reach` on each side, overlap; two bodies are neighbours when some of their triangles
/// are. A greedy colouring in body-id order gives each free body a colour index in
/// [0, palette) that none of its coloured neighbours has, when one is left (a body with
/// `palette` or more differently coloured neighbours takes the one fewest of them use).
/// Deterministic. Bodies of walls (no free member) get -1. One entry per body_count().
std::vector<int> body_colors(const Snapshot&, double reach, int palette);

}  // namespace tridem::io
