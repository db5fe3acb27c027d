#pragma once
// The stability limit of symplectic Euler for the contact springs and dashpots of a
// particle (docs/model.md, "The time step"). core/time_step builds the worst case a scene
// allows from these pieces and the contact law's EdgeStiffness (physics/potential_law.hpp);
// they are TRIDEM_HD so that a run-time check can reuse them.
#include "physics/body.hpp"
#include "physics/damping.hpp"

namespace tridem::physics {

/// A symmetric 3×3 matrix over a body's (x, y, θ).
template <class Real>
struct Sym3 {
  Real xx = 0, yy = 0, tt = 0, xy = 0, xt = 0, yt = 0;
};

/// Adds springs along unit direction u with Σk = k, Σk·λ = k_lever and Σk·λ² = k_lever2
/// over their lever arms λ = r × u.
template <class Real>
TRIDEM_HD inline void add_springs(Sym3<Real>& m, Vec2<Real> u, Real k, Real k_lever,
                                  Real k_lever2) {
  m.xx += k * u.x * u.x;
  m.yy += k * u.y * u.y;
  m.xy += k * u.x * u.y;
  m.xt += k_lever * u.x;
  m.yt += k_lever * u.y;
  m.tt += k_lever2;
}

/// Adds the springs of a load spread along the body edge r0 → r1 (offsets from the
/// centroid, CCW body): normal springs of `normal` per metre along the edge's outward
/// normal, tangential ones of `tangential` per metre along it. A spring of stiffness k
/// along unit u at point r adds k·g·gᵀ with g = (u, r × u); integrated exactly along the
/// edge (the lever arm r × n is linear in the arc length, r × t constant).
template <class Real>
TRIDEM_HD inline void add_edge_springs(Sym3<Real>& m, Vec2<Real> r0, Vec2<Real> r1,
                                       Real normal, Real tangential) {
  const Vec2<Real> d = r1 - r0;
  const Real length = norm(d);
  const Vec2<Real> t = d / length;
  const Vec2<Real> n{t.y, -t.x};
  // Normal lever arm λ(s) = r0 × n − s for s in [0, L].
  const Real l0 = cross(r0, n), l1 = l0 - length;
  const Real int_l = Real(0.5) * (l0 + l1) * length;
  const Real int_l2 = (l0 * l0 + l0 * l1 + l1 * l1) * length / Real(3);
  add_springs(m, n, normal * length, normal * int_l, normal * int_l2);
  const Real a = cross(r0, t), kt = tangential * length;
  add_springs(m, t, kt, kt * a, kt * a * a);
}

/// The largest eigenvalue of M^(−1/2)·S·M^(−1/2), M = diag(m, m, I): the largest ω² of
/// the body held by these springs (closed form for a symmetric 3×3).
template <class Real>
TRIDEM_HD inline Real largest_mode(const Sym3<Real>& s, Real mass, Real inertia) {
  const Real rm = Real(1) / mass, rmi = Real(1) / math::sqrt(mass * inertia);
  const Real a = s.xx * rm, b = s.yy * rm, c = s.tt / inertia;
  const Real d = s.xy * rm, e = s.xt * rmi, f = s.yt * rmi;
  const Real q = (a + b + c) / Real(3);
  const Real off = d * d + e * e + f * f;
  const Real p2 = (a - q) * (a - q) + (b - q) * (b - q) + (c - q) * (c - q) + Real(2) * off;
  if (!(p2 > Real(0))) return q;
  const Real p = math::sqrt(p2 / Real(6));
  const Real ap = (a - q) / p, bp = (b - q) / p, cp = (c - q) / p;
  const Real dp = d / p, ep = e / p, fp = f / p;
  Real r = Real(0.5) * (ap * (bp * cp - fp * fp) - dp * (dp * cp - fp * ep) +
                        ep * (dp * fp - bp * ep));
  r = r < Real(-1) ? Real(-1) : (r > Real(1) ? Real(1) : r);
  return q + Real(2) * p * ::cos(::acos(r) / Real(3));
}

/// The largest dt for which symplectic Euler (kick with the forces of the old state, then
/// drift) is stable on a linear system whose mass-normalised stiffness and damping have
/// Rayleigh quotients at most lambda_k and lambda_c: dt²·λ_K + 2·dt·λ_C < 4, i.e.
/// (2/ω)(√(1 + ζ²) − ζ) for one oscillator. Infinite without springs.
template <class Real>
TRIDEM_HD inline Real symplectic_euler_limit(Real lambda_k, Real lambda_c) {
  const Real root = lambda_c + math::sqrt(lambda_c * lambda_c + Real(4) * lambda_k);
  return root > Real(0) ? Real(4) / root : Real(1) / Real(0);
}

}  // namespace tridem::physics
