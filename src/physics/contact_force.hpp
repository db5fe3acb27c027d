#pragma once
// The potential contact force of one pair of rigid triangles, with friction and normal
// damping: the single definition every backend calls (contact-model.md).
//
// For each ordered role (contactor C, target T) — (a, b) then (b, a) — every edge of C is
// clipped to the three sub-triangles of T, where φ_T is linear. The pieces of one edge
// share its outward normal n, so their loads p∫φ_T dΓ add to one force −p·I·n acting at
// the load-weighted centroid of the pieces: this gives the exact resultant and moment of
// the distributed force. Friction and damping act per such edge contact at that point:
// the edge contact is what carries the stored tangential slip, so the slip of a pair is
// six numbers (2 roles × 3 edges).
#include "physics/body.hpp"
#include "physics/potential.hpp"

namespace tridem::physics {

constexpr int kEdgeContacts = 6;  ///< 2 roles × 3 contactor edges

/// Tangential slip of each edge contact of a pair, kept from step to step.
template <class Real>
struct PairSlip {
  Real s[kEdgeContacts];
};

/// What a pair does to its two bodies during one step.
template <class Real>
struct PairForce {
  Vec2<Real> force_a{};  ///< on a; b receives −force_a
  Real torque_a = 0;
  Real torque_b = 0;
  Vec2<Real> point{};    ///< where the normal loads act on average (for output)
  bool touching = false;
};

/// The load of one contactor edge inside a target triangle.
template <class Real>
struct EdgeLoad {
  Real integral = 0;    ///< ∫ φ_T dΓ over the edge's pieces inside T, metres
  Vec2<Real> point{};   ///< its centroid (valid when integral > 0)
  Real stiffness = 0;   ///< Σ 3ℓ/h over the pieces: contact stiffness over p
};

/// Narrows [t0, t1] to where f0 + t·fd >= 0; false when nothing of positive length is left.
template <class Real>
TRIDEM_HD inline bool clip_to_half_plane(Real f0, Real fd, Real& t0, Real& t1) {
  if (fd == Real(0)) return f0 >= Real(0) && t1 > t0;
  const Real t = -f0 / fd;
  if (fd > Real(0)) t0 = t > t0 ? t : t0;
  else t1 = t < t1 ? t : t1;
  return t1 > t0;
}

/// The edge p + t·d, t in [0, 1], is clipped to the target once; the three lines from the
/// target's centroid to its vertices then split the inside part among the sub-triangles.
/// Along the edge every signed area is linear in t, f(t) = f0 + t·fd, and φ in S_k is the
/// target-edge area f_k scaled by 3/(2A), so each value is computed once.
template <class Real>
TRIDEM_HD inline EdgeLoad<Real> edge_load(const Triangle<Real>& contactor, int e,
                                          const Triangle<Real>& target, Real target_area,
                                          Vec2<Real> target_centroid) {
  EdgeLoad<Real> load;
  const Vec2<Real> p = contactor.v[e];
  const Vec2<Real> d = contactor.v[(e + 1) % 3] - p;
  Real f0[3], fd[3];
  Real t_lo = Real(0), t_hi = Real(1);
  for (int k = 0; k < 3; ++k) {
    const Vec2<Real> edge = target.v[(k + 1) % 3] - target.v[k];
    f0[k] = cross(edge, p - target.v[k]);
    fd[k] = cross(edge, d);
    if (!clip_to_half_plane(f0[k], fd[k], t_lo, t_hi)) return load;
  }
  // g_k >= 0 on the side of the line c → x_k where S_k lies; S_k = {g_k >= 0, g_k+1 <= 0}.
  Real g0[3], gd[3];
  for (int k = 0; k < 3; ++k) {
    const Vec2<Real> ray = target.v[k] - target_centroid;
    g0[k] = cross(ray, p - target_centroid);
    gd[k] = cross(ray, d);
  }
  const Real edge_length = norm(d);
  const Real to_phi = Real(3) / (Real(2) * target_area);
  Vec2<Real> moment{};
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    Real t0 = t_lo, t1 = t_hi;
    if (!clip_to_half_plane(g0[k], gd[k], t0, t1)) continue;
    if (!clip_to_half_plane(-g0[next], -gd[next], t0, t1)) continue;
    const Vec2<Real> q0 = p + d * t0, q1 = p + d * t1;
    const Real phi0 = to_phi * (f0[k] + t0 * fd[k]);
    const Real phi1 = to_phi * (f0[k] + t1 * fd[k]);
    const LinearLoad<Real> piece = linear_load(q0, q1, phi0, phi1);
    load.integral += piece.integral;
    moment += piece.point * piece.integral;
    // Piece of length ℓ in S_k of height h_k = 2A/|e_k|: stiffness 3pℓ/h_k.
    load.stiffness += edge_length * (t1 - t0) * to_phi *
                      norm(target.v[next] - target.v[k]);
  }
  if (load.integral > Real(0)) load.point = moment / load.integral;
  return load;
}

/// Mass that sets the damping of a pair: the reduced mass, or the free body's mass when
/// the other is moved by prescription (mass 0).
template <class Real>
TRIDEM_HD inline Real effective_mass(Real ma, Real mb) {
  return (ma > Real(0) && mb > Real(0)) ? ma * mb / (ma + mb) : ma + mb;
}

/// Force, torques and new slips of the pair (a, b) over a step dt. `slip` holds the
/// slips of the previous step on entry (zeros for a new contact) and the new ones on exit;
/// an edge contact that has opened gets slip 0.
template <class Real>
TRIDEM_HD inline PairForce<Real> pair_force(const Body<Real>& a, const Body<Real>& b,
                                            const ContactLaw<Real>& law, Real dt,
                                            PairSlip<Real>& slip) {
  PairForce<Real> out;
  EdgeLoad<Real> loads[kEdgeContacts];
  Real total_integral = 0, total_stiffness = 0;
  for (int role = 0; role < 2; ++role) {
    const Body<Real>& c = role == 0 ? a : b;
    const Body<Real>& t = role == 0 ? b : a;
    for (int e = 0; e < 3; ++e) {
      loads[role * 3 + e] = edge_load(c.tri, e, t.tri, t.area, t.c);
      total_integral += loads[role * 3 + e].integral;
      total_stiffness += loads[role * 3 + e].stiffness;
    }
  }
  if (!(total_integral > Real(0))) {
    for (int i = 0; i < kEdgeContacts; ++i) slip.s[i] = Real(0);
    return out;
  }
  out.touching = true;
  // One dashpot for the whole pair, c = 2ζ√(m k), shared among the edge contacts in
  // proportion to their stiffness: a face-to-face impact is then a linear spring-dashpot
  // with restitution exp(−πζ/√(1−ζ²)) (docs/model.md).
  const Real k_total = law.penalty * total_stiffness;
  const Real c_total = Real(2) * law.damping * math::sqrt(effective_mass(a.mass, b.mass) * k_total);
  Vec2<Real> point_moment{};
  for (int role = 0; role < 2; ++role) {
    const Body<Real>& c = role == 0 ? a : b;
    const Body<Real>& t = role == 0 ? b : a;
    for (int e = 0; e < 3; ++e) {
      const int i = role * 3 + e;
      const EdgeLoad<Real>& load = loads[i];
      if (!(load.integral > Real(0))) {
        slip.s[i] = Real(0);
        continue;
      }
      const Vec2<Real> d = c.tri.v[(e + 1) % 3] - c.tri.v[e];
      const Vec2<Real> tangent = d / norm(d);
      const Vec2<Real> normal{tangent.y, -tangent.x};  // outward for a CCW contactor
      const Vec2<Real> r = load.point;
      const Vec2<Real> v_rel = velocity_at(c, r) - velocity_at(t, r);
      const Real damping = c_total * load.stiffness / total_stiffness;
      const Real f_normal = law.penalty * load.integral + damping * dot(v_rel, normal);
      // Elastic–perfectly-plastic tangential spring (Coulomb friction, contact-model.md).
      Real s = slip.s[i] + dot(v_rel, tangent) * dt;
      Real f_tangent = -law.tangential_penalty * s;
      const Real cap = law.friction * (f_normal > Real(0) ? f_normal : Real(0));
      if (f_tangent > cap || f_tangent < -cap) {
        f_tangent = f_tangent > Real(0) ? cap : -cap;
        s = -f_tangent / law.tangential_penalty;
      }
      slip.s[i] = s;
      const Vec2<Real> f_on_c = normal * (-f_normal) + tangent * f_tangent;
      const Vec2<Real> f_on_a = role == 0 ? f_on_c : -f_on_c;
      out.force_a += f_on_a;
      out.torque_a += cross(r - a.c, f_on_a);
      out.torque_b -= cross(r - b.c, f_on_a);
      point_moment += r * load.integral;
    }
  }
  out.point = point_moment / total_integral;
  return out;
}

}  // namespace tridem::physics
