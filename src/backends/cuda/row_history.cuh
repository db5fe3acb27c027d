#pragma once
// The last step of every pair-list build, whatever found the pairs: each emitter's new row
// (partners ascending) gets its slots' emitter and id, and the contact history of the
// same pairs from the emitter's old row.
#include "backends/cuda/device_views.cuh"
#include "broadphase/history_carry.hpp"

namespace tridem::cuda {

/// Where a build writes its rows, and the list it replaces.
template <class Real>
struct RowHistory {
  const int* offset;  ///< n + 1, the new rows
  int* partner;
  int* emitter;
  int* slot_id;       ///< s at slot s: the values the reverse-index sort carries
  physics::PairSlip<Real>* slip;
  const int* old_offset;
  const int* old_partner;
  const physics::PairSlip<Real>* old_slip;
};

/// Emitter i's row, already filled and sorted: each pair takes the slip stored for it in
/// i's old row (broadphase/history_carry.hpp), or zero if it is new.
template <class Real>
__device__ inline void carry_history(int i, const RowHistory<Real>& h) {
  OldRow<int, physics::PairSlip<Real>> old{h.old_partner, h.old_slip, h.old_offset[i],
                                           h.old_offset[i + 1]};
  for (int s = h.offset[i]; s < h.offset[i + 1]; ++s) {
    h.slip[s] = old.history_of(h.partner[s]);
    h.emitter[s] = i;
    h.slot_id[s] = s;
  }
}

}  // namespace tridem::cuda
