#pragma once
// Where a pair-list build writes its rows, and how a row is completed once its partners
// are in place, for the fill kernels of every method (cell grid, decomposition): partners
// sorted, each pair's contact history carried over from the emitter's old row (both
// sorted by partner), the emitter and slot of each pair recorded.
#include "broadphase/row_sort.hpp"
#include "physics/contact_force.hpp"

namespace tridem::cuda {

template <class Real>
struct RowTargets {
  const int* offset;  ///< n + 1, from the counts
  int* partner;
  int* emitter;
  int* slot_id;
  physics::PairSlip<Real>* slip;
  const int* old_offset;
  const int* old_partner;
  const physics::PairSlip<Real>* old_slip;
};

/// Completes the row of emitter i, whose partners are written (in any order).
template <class Real>
__device__ inline void finish_row(const RowTargets<Real>& t, int i) {
  const int begin = t.offset[i], end = t.offset[i + 1];
  insertion_sort(t.partner, begin, end);
  int old = t.old_offset[i];
  const int old_end = t.old_offset[i + 1];
  for (int s = begin; s < end; ++s) {
    const int j = t.partner[s];
    while (old < old_end && t.old_partner[old] < j) ++old;
    physics::PairSlip<Real> h{};
    if (old < old_end && t.old_partner[old] == j) h = t.old_slip[old];
    t.slip[s] = h;
    t.emitter[s] = i;
    t.slot_id[s] = s;
  }
}

}  // namespace tridem::cuda
