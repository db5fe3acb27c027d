#pragma once
// Which particle of a pair computes it (its emitter): the rule every pair finder of every
// backend follows, the cell grid, all-pairs, single-domain and decomposition alike, so
// that they build the same rows and the pairs are computed in the same frame.
#include "tridem/hd.hpp"

namespace tridem {

/// A pair needs one free particle; two small particles are emitted by the lower index, a
/// small and a large one (a wall) by the small one; a large particle emits nothing. All-pairs
/// has no size classes: it asks with both particles small (the lower index emits). Following
/// it, the paper's methods build exactly the grid's rows (minus the pairs that fail their
/// contact test), so that with the exact test they reproduce the grid bit for bit.
TRIDEM_HD inline bool emits_pair(int i, int j, bool small_i, bool small_j, bool free_i,
                                 bool free_j) {
  if (!small_i || !(free_i || free_j)) return false;
  return !small_j || j > i;
}

}  // namespace tridem
