#pragma once
// How scattered in memory the neighbours of consecutive particles are: what the particles'
// order costs a solver's pair stage. A pair reads its partner's data at the partner's
// index; when the partners of a run of consecutive particles fall in few runs of
// consecutive indices (numbered by place, by rows, or along a curve and then sheared) the
// caches hold them, when they fall anywhere (numbered at random, or mixed by a flow) each
// is a miss. Positions only: a solver looks at its order mid-run without its pair list
// (core/place_numbered_solver).
#include "tridem/vec2.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

/// Particles read as one block (about a warp's, or a few cache lines' worth of columns).
inline constexpr std::size_t kNeighbourBlock = 32;
/// Consecutive particles looked at together.
inline constexpr std::size_t kNeighbourWindow = 1024;
/// Over this spread the neighbours are scattered: a solver numbers the particles by place
/// again. About 1.5-3 numbered by place or by rows (10^6 pile), 4 after a simple shear of
/// 100 of a curve's order, 190 at random (docs/performance.md, "The particles' order").
inline constexpr double kScatteredNeighbours = 16;

/// For windows of kNeighbourWindow consecutive free particles (up to 64 windows spread
/// over the order), the blocks of kNeighbourBlock consecutive indices that hold the free
/// particles within 1.5 `grain_size` of the window's particles (the window's own
/// included), over the blocks the window spans: the mean over the windows. `centroid[k]`
/// and `free[k]` are of the particle at index k. 0 with fewer than two windows' worth of
/// free particles or a grain size of 0.
double neighbour_block_spread(const std::vector<Vec2d>& centroid,
                              const std::vector<std::uint8_t>& free, double grain_size);

}  // namespace tridem
