#pragma once
// Cohesive bonds between rigid triangles that share an edge (issue 14; docs/fracture.md).
// Rigid triangles cannot deform, so a bonded specimen's whole compliance sits in its
// bonds: each bond is a layer of normal and shear springs along the shared edge, sampled at
// kBondPoints Gauss points. A point's traction follows a mixed-mode damage law: elastic up
// to the quadratic interaction of the tensile strength f_t and the Mohr-Coulomb shear
// strength c + sigma_c tan(phi), then linear softening in an effective opening whose end
// is set by the fracture energies G_I and G_II (the linear energy criterion); damage never
// heals, and a bond whose points are all fully damaged is broken for good. Every backend
// calls these functions; the backends only load, store and loop.
#include "physics/local_frame.hpp"
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

#include <cstdint>
#include <math.h>

namespace tridem::physics {

/// Points along the shared edge: two Gauss points integrate exactly the elastic energy of
/// the gap between two rigid triangles, which varies linearly along the edge.
constexpr int kBondPoints = 2;

/// Where the Gauss points sit along the edge (0 at its first end, 1 at its second), and
/// the share of the edge's length each one carries.
TRIDEM_HD inline double bond_point_position(int k) {
  return k == 0 ? 0.5 - 0.28867513459481287 : 0.5 + 0.28867513459481287;  // 1/(2 sqrt 3)
}
constexpr double kBondPointWeight = 0.5;

/// The strengths of a bonded material (per unit area of the crack face, per unit
/// thickness: Pa and J/m^2). The stiffness is per bond (BondGeometry::stiffness).
template <class Real>
struct BondStrength {
  Real tensile;       ///< f_t, Pa
  Real cohesion;      ///< c, Pa: the shear strength without normal stress
  Real tan_friction;  ///< tan(phi) of the Mohr-Coulomb shear strength under compression
  Real mode1_energy;  ///< G_I, J/m^2
  Real mode2_energy;  ///< G_II, J/m^2
};

template <class To, class From>
inline BondStrength<To> bond_strength_cast(const BondStrength<From>& s) {
  return {static_cast<To>(s.tensile), static_cast<To>(s.cohesion), static_cast<To>(s.tan_friction),
          static_cast<To>(s.mode1_energy), static_cast<To>(s.mode2_energy)};
}

/// What one point of a bond does this step: its tractions (per unit length of the edge,
/// on b, along the bond's normal and tangent), its damage after the step, the elastic
/// energy it stores and the energy its new damage dissipated (both per unit length).
template <class Real>
struct BondPointResponse {
  Real normal = 0;      ///< sigma: > 0 pulls b towards a (tension), Pa
  Real shear = 0;       ///< tau: opposes the sliding of b along the tangent, Pa
  Real damage = 0;      ///< D in [0, 1]; 1 = this point carries nothing any more
  Real elastic = 0;     ///< J/m^2
  Real dissipated = 0;  ///< J/m^2 released by this step's growth of D
};

/// The traction-separation law of one point: opening `dn` (> 0 opens, < 0 presses the
/// faces into each other), sliding `ds`, spring stiffness `k` (Pa/m, normal and shear
/// alike: docs/fracture.md, "Stiffness"), and the point's damage before the step.
///
/// Effective opening u = sqrt(un^2 + us^2), un = <dn>/dn0, us = |ds|/ds0, with
/// dn0 = f_t/k and ds0 = s/k, s = c + tan(phi) * k * <-dn> the shear strength under
/// compression: damage starts at u = 1, where (sigma/f_t)^2 + (tau/s)^2 = 1. Along a path of
/// fixed mixity (cos^2 a = un^2/u^2) linear softening in u ends at
///   u_f = 1 / (f_t^2 cos^2 a / (2 k G_I) + s^2 sin^2 a / (2 k G_II)),
/// the opening at which the energy released in each mode, G_n and G_s, meets
/// G_n/G_I + G_s/G_II = 1; the damage of that softening is D = u_f (u - 1) / (u (u_f - 1)).
/// A brittle point (u_f <= 1: the elastic energy at the peak already exceeds the fracture
/// energy, a mesh too coarse for the material) breaks at its peak.
template <class Real>
TRIDEM_HD inline BondPointResponse<Real> bond_point_response(Real dn, Real ds, Real k,
                                                             const BondStrength<Real>& m,
                                                             Real damage_before) {
  BondPointResponse<Real> r;
  r.damage = damage_before;
  if (damage_before >= Real(1)) return r;  // broken: nothing at all, the contact takes over
  const Real open = dn > Real(0) ? dn : Real(0);
  const Real pressed = dn < Real(0) ? -dn : Real(0);
  const Real shear_strength = m.cohesion + m.tan_friction * k * pressed;
  const Real un = open * k / m.tensile;
  const Real us = (ds < Real(0) ? -ds : ds) * k / shear_strength;
  const Real u2 = un * un + us * us;
  // Y, the energy a growth of D releases per unit of D: the undamaged springs' energy of
  // the opening and the sliding (pressing is never damaged).
  const Real released = Real(0.5) * k * (open * open + ds * ds);
  if (u2 > Real(1)) {
    const Real u = math::sqrt(u2);
    const Real cos2 = un * un / u2, sin2 = us * us / u2;
    const Real inv_uf = m.tensile * m.tensile * cos2 / (Real(2) * k * m.mode1_energy) +
                        shear_strength * shear_strength * sin2 / (Real(2) * k * m.mode2_energy);
    if (inv_uf < Real(1)) {
      const Real uf = Real(1) / inv_uf;
      const Real d = u >= uf ? Real(1) : uf * (u - Real(1)) / (u * (uf - Real(1)));
      if (d > r.damage) {
        // The energy released from damage D_old to D is W(u) - W(u_old), with
        // W(u) = Y1 u_f (u - 1) / (u_f - 1) the integral of Y dD along the softening
        // (Y = Y1 u^2) and u_old the opening at which the law gives D_old: exact whatever
        // the step, so a mode I crack releases G_I per unit length to rounding.
        const Real u_old = uf / (uf - r.damage * (uf - Real(1)));
        const Real u_new = u < uf ? u : uf;
        const Real w = released / u2 * uf / (uf - Real(1)) * (u_new - u_old);
        r.dissipated = w > Real(0) ? w : Real(0);
        r.damage = d;
      }
    } else if (r.damage < Real(1)) {  // brittle: all the stored energy goes at once
      r.dissipated = (Real(1) - r.damage) * released;
      r.damage = Real(1);
    }
  }
  const Real kept = Real(1) - r.damage;
  r.normal = -k * (kept * open - pressed);  // tension pulls b back: negative along n
  r.shear = -k * kept * ds;
  r.elastic = kept * released + Real(0.5) * k * pressed * pressed;
  return r;
}

/// A bond as the solvers keep it: its two triangles, where its points sit on each (in the
/// body frame of each triangle at theta = 0, about its centroid), its normal at theta = 0
/// (from a to b), the edge's length and the springs' stiffness.
template <class Real>
struct BondGeometry {
  Vec2<Real> on_a[kBondPoints];
  Vec2<Real> on_b[kBondPoints];
  Vec2<Real> normal;  ///< unit, at theta = 0, pointing out of a into b
  Real length;        ///< m
  Real stiffness;     ///< k, Pa/m
};

/// What one bond does to its two triangles during one step, in the frame of a's centroid.
template <class Real>
struct BondForce {
  Vec2<Real> force_a{};  ///< on a; b receives -force_a
  Real torque_a = 0;     ///< about a's centroid
  Real torque_b = 0;     ///< about b's centroid
  Real damage[kBondPoints] = {};
  Real elastic = 0;     ///< J/m stored in the bond
  Real dissipated = 0;  ///< J/m released by this step's damage
  bool broken = false;  ///< every point fully damaged
};

/// A pose as a bond sees it: the centroid in the frame of a's centroid and the angle.
template <class Real>
struct BondSide {
  Vec2<Real> c;
  double theta;
};

/// The bond's force between a and b, both given in one frame (the solvers put its origin
/// at a's centroid, as for a pair: physics/local_frame.hpp). The normal turns with the mean of the
/// two angles, so that the law treats a and b alike; the gap at each point is the distance between
/// the point as carried by b and as carried by a.
template <class Real>
TRIDEM_HD inline BondForce<Real> bond_force(const BondSide<Real>& a, const BondSide<Real>& b,
                                            const BondGeometry<Real>& g,
                                            const BondStrength<Real>& m,
                                            const Real damage_before[kBondPoints]) {
  BondForce<Real> f;
  const Real ca = static_cast<Real>(::cos(a.theta)), sa = static_cast<Real>(::sin(a.theta));
  const Real cb = static_cast<Real>(::cos(b.theta)), sb = static_cast<Real>(::sin(b.theta));
  const double mean = 0.5 * (a.theta + b.theta);
  const Vec2<Real> n =
      rotate(g.normal, static_cast<Real>(::cos(mean)), static_cast<Real>(::sin(mean)));
  const Vec2<Real> t = perp(n);
  const Real share = static_cast<Real>(kBondPointWeight) * g.length;
  bool all_broken = true;
  TRIDEM_UNROLL
  for (int k = 0; k < kBondPoints; ++k) {
    const Vec2<Real> ra = rotate(g.on_a[k], ca, sa), rb = rotate(g.on_b[k], cb, sb);
    const Vec2<Real> gap = (b.c + rb) - (a.c + ra);
    const BondPointResponse<Real> r =
        bond_point_response(dot(gap, n), dot(gap, t), g.stiffness, m, damage_before[k]);
    const Vec2<Real> on_b = (n * r.normal + t * r.shear) * share;
    f.force_a -= on_b;
    f.torque_a -= cross(ra, on_b);
    f.torque_b += cross(rb, on_b);
    f.damage[k] = r.damage;
    f.elastic += r.elastic * share;
    f.dissipated += r.dissipated * share;
    all_broken = all_broken && r.damage >= Real(1);
  }
  f.broken = all_broken;
  return f;
}

/// True when triangles i and j hold an intact bond: such a pair gets no contact force
/// (the bond carries their interaction). Bonds of particle i are bond_of[first[i] ..
/// first[i + 1]) with partners partner[...] (a particle has at most three).
TRIDEM_HD inline bool intact_bond_between(const std::int32_t* first, const std::int32_t* partner,
                                          const std::int32_t* bond_of, const std::uint8_t* broken,
                                          std::int64_t i, std::int64_t j) {
  if (first == nullptr) return false;
  for (std::int32_t s = first[i]; s < first[i + 1]; ++s)
    if (partner[s] == j) return broken[bond_of[s]] == 0;
  return false;
}

}  // namespace tridem::physics
