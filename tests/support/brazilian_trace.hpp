#pragma once
// Diagnosis of the Brazilian disc (docs/fracture.md, "Why the first disc was low"): where
// the bonds are damaged and broken (near the poles, in the central band, elsewhere), the
// platen's travel against the disc's own shortening (the contact's share of the
// compliance), printed along the run.
#include "tridem/snapshot.hpp"

#include <cmath>
#include <cstdio>

namespace tridem::test {

struct BondMap {
  int damaged_pole = 0, damaged_centre = 0, damaged_other = 0;
  int broken_pole = 0, broken_centre = 0, broken_other = 0;
};

/// Bonds by where their edge's midpoint lies in a disc of radius r about the origin: the
/// poles are |y| > 0.7 r, the central band |x| < 0.15 r (the loaded diameter, away from
/// the poles), the rest elsewhere.
inline BondMap bond_map(const Snapshot& s, double r) {
  BondMap m;
  for (std::size_t k = 0; k < s.bond_a.size(); ++k) {
    if (s.bond_damage[k] <= 0) continue;
    const double x = 0.5 * (s.bond_x0[k] + s.bond_x1[k]), y = 0.5 * (s.bond_y0[k] + s.bond_y1[k]);
    const bool pole = std::abs(y) > 0.7 * r, centre = !pole && std::abs(x) < 0.15 * r;
    const bool broken = s.bond_broken[k] != 0;
    (pole ? m.damaged_pole : centre ? m.damaged_centre : m.damaged_other)++;
    if (broken) (pole ? m.broken_pole : centre ? m.broken_centre : m.broken_other)++;
  }
  return m;
}

/// The mean vertical displacement of the triangles whose centroid started above y0 (top)
/// or below -y0 (bottom), the two platens (ids 0, 1) left out.
inline double pole_shortening(const Snapshot& s, const Snapshot& start, double y0) {
  double top = 0, bottom = 0;
  int nt = 0, nb = 0;
  for (std::size_t i = 2; i < s.size(); ++i) {
    if (start.y[i] > y0) top += s.y[i] - start.y[i], ++nt;
    if (start.y[i] < -y0) bottom += s.y[i] - start.y[i], ++nb;
  }
  return (nb > 0 ? bottom / nb : 0) - (nt > 0 ? top / nt : 0);
}

inline void print_trace(const Snapshot& s, const Snapshot& start, double r, double force,
                        double platen_travel) {
  const BondMap m = bond_map(s, r);
  std::printf("t %.4g s travel %.3g um F %.4g N/m sigma %.3g MPa | shortening r>0.9: %.3g um "
              "r>0.5: %.3g um | damaged pole/centre/other %d/%d/%d broken %d/%d/%d\n",
              s.time, platen_travel * 1e6, force, 2 * force / (M_PI * 2 * r) * 1e-6,
              pole_shortening(s, start, 0.9 * r) * 1e6, pole_shortening(s, start, 0.5 * r) * 1e6,
              m.damaged_pole, m.damaged_centre, m.damaged_other, m.broken_pole, m.broken_centre,
              m.broken_other);
  std::fflush(stdout);
}

}  // namespace tridem::test
