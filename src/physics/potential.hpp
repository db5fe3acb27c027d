#pragma once
// Munjiza's triangle potential φ(P) = min_k 3A_k(P)/A: one at the centroid, zero on the
// boundary. In the sub-triangle S_k = (c, x_k, x_k+1) it is linear,
// φ = 3·cross(e_k, P − x_k) / (2A), so an edge clipped to S_k carries a linear load whose
// integral and centroid are exact (docs/model.md, "The potential contact force").
#include "physics/geometry.hpp"

namespace tridem::physics {

/// φ of the CCW triangle t (area `area`) at P, using the linear form of sub-triangle k.
template <class Real>
TRIDEM_HD inline Real potential_in_sub_triangle(const Triangle<Real>& t, Real area, int k,
                                                Vec2<Real> p) {
  const Vec2<Real> a = t.v[k];
  const Vec2<Real> b = t.v[(k + 1) % 3];
  return Real(3) * cross(b - a, p - a) / (Real(2) * area);
}

/// φ anywhere inside t: the minimum over the three linear forms (outside t it is < 0).
template <class Real>
TRIDEM_HD inline Real potential(const Triangle<Real>& t, Real area, Vec2<Real> p) {
  Real phi = potential_in_sub_triangle(t, area, 0, p);
  TRIDEM_UNROLL
  for (int k = 1; k < 3; ++k) {
    const Real pk = potential_in_sub_triangle(t, area, k, p);
    phi = pk < phi ? pk : phi;
  }
  return phi;
}

}  // namespace tridem::physics
