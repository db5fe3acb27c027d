#pragma once
// Scenes written once and used by tests, benchmarks and examples alike.
#include "tridem/scene.hpp"

#include <cstddef>

namespace tridem {

/// A dense pile of about `n` triangles in a box under gravity: a triangular lattice of
/// equilateral grains (edge `size`) whose neighbours all overlap by about 0.1% of the size
/// from the first step, so that every step carries the contact load of a settled pile;
/// a floor and two side walls (fixed triangles); sand-like material (ρ 2650 kg/m³,
/// p 1e8 Pa, μ 0.5, ζ 0.3). The grains take up a region about as wide as it is high.
Scene dense_pile(std::size_t n, double size = 0.01);

}  // namespace tridem
