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
  /// Penetration depth: the largest φ reached by either boundary inside the other
  /// triangle, 0 at its edge and 1 at its centroid (the blow-up check reads it).
  Real depth = 0;
  bool touching = false;
};

/// The load of one contactor edge inside a target triangle.
template <class Real>
struct EdgeLoad {
  Real integral = 0;    ///< ∫ φ_T dΓ over the edge's pieces inside T, metres
  Vec2<Real> point{};   ///< its centroid (valid when integral > 0)
  Real stiffness = 0;   ///< Σ 3ℓ/h over the pieces: contact stiffness over p
  Real peak = 0;        ///< the largest φ_T on the pieces (φ is linear: at an end)
};

/// Signed areas of the contactor's vertices against the target's edges and against the
/// rays from the target's centroid to its vertices. Along a contactor edge every such area
/// is linear, so these nine plus nine numbers give every clipping value of the three edges;
/// the edge areas are also exactly what the separating-axis test looks at.
template <class Real>
struct RoleAreas {
  Real edge[3][3];  ///< [target edge k][contactor vertex i]: >= 0 on the inner side
  Real ray[3][3];   ///< [target ray k][contactor vertex i]
};

/// The edge areas: all the separating-axis test needs.
template <class Real>
TRIDEM_HD inline void edge_areas(const Triangle<Real>& contactor, const Triangle<Real>& target,
                                 RoleAreas<Real>& r) {
  for (int k = 0; k < 3; ++k) {
    const Vec2<Real> edge = target.v[(k + 1) % 3] - target.v[k];
    for (int i = 0; i < 3; ++i) r.edge[k][i] = cross(edge, contactor.v[i] - target.v[k]);
  }
}

/// The ray areas, needed only once the pair is known to overlap.
template <class Real>
TRIDEM_HD inline void ray_areas(const Triangle<Real>& contactor, const Triangle<Real>& target,
                                Vec2<Real> target_centroid, RoleAreas<Real>& r) {
  for (int k = 0; k < 3; ++k) {
    const Vec2<Real> ray = target.v[k] - target_centroid;
    for (int i = 0; i < 3; ++i) r.ray[k][i] = cross(ray, contactor.v[i] - target_centroid);
  }
}

template <class Real>
TRIDEM_HD inline RoleAreas<Real> role_areas(const Triangle<Real>& contactor,
                                            const Triangle<Real>& target,
                                            Vec2<Real> target_centroid) {
  RoleAreas<Real> r;
  edge_areas(contactor, target, r);
  ray_areas(contactor, target, target_centroid, r);
  return r;
}

/// True when an edge of the target has every contactor vertex on or outside it.
template <class Real>
TRIDEM_HD inline bool target_edge_separates(const RoleAreas<Real>& r) {
  for (int k = 0; k < 3; ++k)
    if (r.edge[k][0] <= Real(0) && r.edge[k][1] <= Real(0) && r.edge[k][2] <= Real(0))
      return true;
  return false;
}

/// Edge e of the contactor, p + t·d with t in [0, 1], is clipped to the target once; the
/// three centroid rays then split the inside part among the sub-triangles S_k = {ray_k >=
/// 0, ray_k+1 <= 0}. φ in S_k is the target-edge area f_k scaled by 3/(2A).
template <class Real>
TRIDEM_HD inline EdgeLoad<Real> edge_load(const RoleAreas<Real>& areas, int e,
                                          const Triangle<Real>& contactor,
                                          const Triangle<Real>& target, Real target_area) {
  EdgeLoad<Real> load;
  const int e1 = (e + 1) % 3;
  Real t_lo = Real(0), t_hi = Real(1);
  for (int k = 0; k < 3; ++k)
    if (!clip_to_half_plane(areas.edge[k][e], areas.edge[k][e1] - areas.edge[k][e], t_lo, t_hi))
      return load;
  const Vec2<Real> p = contactor.v[e];
  const Vec2<Real> d = contactor.v[e1] - p;
  const Real edge_length = norm(d);
  const Real to_phi = Real(3) / (Real(2) * target_area);
  Vec2<Real> moment{};
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    Real t0 = t_lo, t1 = t_hi;
    if (!clip_to_half_plane(areas.ray[k][e], areas.ray[k][e1] - areas.ray[k][e], t0, t1)) continue;
    if (!clip_to_half_plane(-areas.ray[next][e], areas.ray[next][e] - areas.ray[next][e1], t0, t1))
      continue;
    const Real f0 = areas.edge[k][e], fd = areas.edge[k][e1] - f0;
    const Vec2<Real> q0 = p + d * t0, q1 = p + d * t1;
    const Real phi0 = to_phi * (f0 + t0 * fd), phi1 = to_phi * (f0 + t1 * fd);
    const LinearLoad<Real> piece = linear_load(q0, q1, phi0, phi1);
    load.peak = phi0 > load.peak ? phi0 : load.peak;
    load.peak = phi1 > load.peak ? phi1 : load.peak;
    load.integral += piece.integral;
    moment += piece.point * piece.integral;
    // Piece of length ℓ in S_k of height h_k = 2A/|e_k|: stiffness 3pℓ/h_k.
    load.stiffness += edge_length * (t1 - t0) * to_phi * norm(target.v[next] - target.v[k]);
  }
  if (load.integral > Real(0)) load.point = moment / load.integral;
  return load;
}

/// The same for one edge on its own (tests and tools).
template <class Real>
TRIDEM_HD inline EdgeLoad<Real> edge_load(const Triangle<Real>& contactor, int e,
                                          const Triangle<Real>& target, Real target_area,
                                          Vec2<Real> target_centroid) {
  return edge_load(role_areas(contactor, target, target_centroid), e, contactor, target,
                   target_area);
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
  // The separating-axis test reads the same edge areas the clipping needs.
  RoleAreas<Real> areas[2];
  edge_areas(a.tri, b.tri, areas[0]);
  edge_areas(b.tri, a.tri, areas[1]);
  EdgeLoad<Real> loads[kEdgeContacts];
  Real total_integral = 0, total_stiffness = 0;
  if (!target_edge_separates(areas[0]) && !target_edge_separates(areas[1])) {
    ray_areas(a.tri, b.tri, b.c, areas[0]);
    ray_areas(b.tri, a.tri, a.c, areas[1]);
    for (int role = 0; role < 2; ++role) {
      const Body<Real>& c = role == 0 ? a : b;
      const Body<Real>& t = role == 0 ? b : a;
      for (int e = 0; e < 3; ++e) {
        loads[role * 3 + e] = edge_load(areas[role], e, c.tri, t.tri, t.area);
        total_integral += loads[role * 3 + e].integral;
        total_stiffness += loads[role * 3 + e].stiffness;
      }
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
      out.depth = load.peak > out.depth ? load.peak : out.depth;
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
