#pragma once
// Which edges of a body's triangles are inside the body (shared by two of its members), so
// that the renderer draws a body as one outlined polygon rather than as its triangulation.
#include "tridem/snapshot.hpp"

#include <cstdint>
#include <vector>

namespace tridem::io {

/// Per triangle, bit e set when its edge from vertex e to vertex e+1 (mod 3) is also an
/// edge of another member of its body (the same two end points, to 1e-7 of the edge's
/// length: members are placed on their body one by one, so shared vertices agree only to
/// rounding). All zero for a snapshot without bodies of several triangles.
std::vector<std::uint8_t> inner_edges(const Snapshot&);

}  // namespace tridem::io
