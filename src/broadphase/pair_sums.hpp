#pragma once
// The total pair force and torque on one particle: its own pairs (as emitter), then those
// where it is the partner, each in ascending slot order. Every backend sums in exactly this
// order, which is why OpenMP equals serial bit for bit and CUDA agrees to rounding.
#include "physics/contact_force.hpp"

#include <cstdint>

namespace tridem {

// `result` holds PairForce or physics::PairLoad records (the fields read are in both).
template <class Real, class Offset, class Slot, class Record>
TRIDEM_HD inline void sum_pair_forces(std::int64_t i, const Offset* offset,
                                      const Offset* reverse_offset, const Slot* reverse_slot,
                                      const Record* result, Vec2<Real>& f, Real& t) {
  f = Vec2<Real>{};
  t = Real(0);
  for (auto s = offset[i]; s < offset[i + 1]; ++s) {
    f += result[s].force_a;
    t += result[s].torque_a;
  }
  for (auto r = reverse_offset[i]; r < reverse_offset[i + 1]; ++r) {
    const Record& res = result[reverse_slot[r]];
    f -= res.force_a;
    t += res.torque_b;
  }
}

}  // namespace tridem
