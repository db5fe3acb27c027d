#pragma once
// Scenes written once and used by tests, benchmarks and examples alike.
#include "tridem/scene.hpp"

#include <cstddef>
#include <vector>

namespace tridem {

/// A dense pile of about `n` triangles in a box under gravity: a triangular lattice of
/// equilateral grains (edge `size`) grown by 0.2% so that every lattice neighbour overlaps
/// slightly at the start; a floor and two side walls (fixed triangles); sand-like material
/// (ρ 2650 kg/m³, p 1e8 Pa, μ 0.5, ζ 0.3). The grains take up a region `aspect` times as
/// wide as it is high (about square by default; a wide layer for the paper's 1D
/// decomposition, whose strips must hold a whole column of the pile). The first steps
/// carry the contact load of a dense pile (about 6 touching pairs per triangle); the
/// pre-stressed pile then loosens from its free surface (at 10³ grains, about 2 touching
/// pairs per triangle after 200 steps), so benchmarks time early steps.
Scene dense_pile(std::size_t n, double size = 0.01, double aspect = 1.0);

/// dense_pile, and in `edges` (when not null) a bond for every two of its grains that share a
/// lattice edge, on the edge as the lattice made it (before the grains grew).
Scene dense_pile_with_edges(std::size_t n, double size, double aspect,
                            std::vector<BondSpec>* edges);

/// dense_pile(n, size) with every grain bonded to its lattice neighbours across their
/// shared edges (issue 14's benchmark: about 1.5 bonds per triangle): the same triangles,
/// overlaps and pair lists, the sand made bondable (E = its penalty; strengths its weight
/// never reaches). The pairs an intact bond holds add exact zeros; the bonds add their own
/// work, one per bond, in the same step.
Scene bonded_pile(std::size_t n, double size = 0.01);

/// dense_pile(n, size) with its grains grouped into rigid bodies (issue 13's benchmark: 10^6
/// triangles in 10^5 bodies against 10^6 free ones): in each lattice row, `members`
/// consecutive triangles, which share edges, make one body (a parallelogram or trapezoid
/// `members`/2 edges long; a row's last body may have fewer); the walls are bodies of one
/// member. The same triangles, overlaps and contacts as dense_pile, less the pairs inside a
/// body, which add exact zeros.
Scene body_pile(std::size_t n, double size = 0.01, int members = 10);

}  // namespace tridem
