#pragma once
// Provisional home of the decomposition settings until the settings plumbing of issue 4
// (scene.hpp, [simulation.decomposition]) is merged; the names are the ones it uses.
namespace tridem {

/// 1D strips along x, or 2D rows along y each split into columns.
enum class DecompositionLayout { Strips, Grid };

struct DecompositionSettings {
  DecompositionLayout layout = DecompositionLayout::Strips;
  int rows = 0;         ///< 2D: bands along y; 0 = chosen from the particle count
  int columns = 0;      ///< sub-domains per row at the start; 0 = as few as capacity allows
  int capacity = 256;   ///< particles a sub-domain holds, overlap band included
};

}  // namespace tridem
