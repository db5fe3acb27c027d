#pragma once
// Pieces of a Snapshot that every solver fills the same way from its own layout.
#include "physics/contact_force.hpp"
#include "tridem/snapshot.hpp"

#include <cstddef>
#include <cstdint>

namespace tridem {

template <class Real>
inline void set_vertices(Snapshot& out, std::size_t i, const physics::Triangle<Real>& t) {
  out.x1[i] = t.v[0].x;
  out.y1[i] = t.v[0].y;
  out.x2[i] = t.v[1].x;
  out.y2[i] = t.v[1].y;
  out.x3[i] = t.v[2].x;
  out.y3[i] = t.v[2].y;
}

/// The touching pairs of a pair list (rows by emitter) as contact records, in slot order.
/// A pair's point is in its frame, relative to the emitter's centroid (cx, cy): placed
/// back in double here.
template <class Real, class Offset, class Partner>
inline void append_contacts(Snapshot& out, std::size_t n, const Offset* offset,
                            const Partner* partner, const physics::PairForce<Real>* result,
                            const double* cx, const double* cy) {
  for (std::size_t e = 0; e < n; ++e)
    for (auto s = offset[e]; s < offset[e + 1]; ++s) {
      const auto& r = result[s];
      if (!r.touching) continue;
      out.contacts.push_back({static_cast<std::int64_t>(e), static_cast<std::int64_t>(partner[s]),
                              r.force_a.x, r.force_a.y,
                              cx[e] + static_cast<double>(r.point.x),
                              cy[e] + static_cast<double>(r.point.y)});
    }
}

}  // namespace tridem
