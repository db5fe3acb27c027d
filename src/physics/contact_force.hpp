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
  // The pair's share of the energy budget (energy.csv). A minimal version, isolated in
  // OverlapSums below and a few marked lines of pair_force: normal energy p∫_Ω(φ_a + φ_b)dA at the positions of this step plus
  // the tangential springs' ½p_t·s² at the new slips; dashpots and sliding over this step.
  Real elastic_energy = 0;        ///< J/m stored in the pair
  Real damping_dissipation = 0;   ///< J/m removed by the dashpots over this step (>= 0)
  Real friction_dissipation = 0;  ///< J/m removed by Coulomb sliding over this step (>= 0)
};

/// The load of one contactor edge inside a target triangle.
template <class Real>
struct EdgeLoad {
  Real integral = 0;    ///< ∫ φ_T dΓ over the edge's pieces inside T, metres
  Vec2<Real> point{};   ///< its centroid (valid when integral > 0)
  Real stiffness = 0;   ///< Σ 3ℓ/h over the pieces: contact stiffness over p
  Real peak = 0;        ///< the largest φ_T on the pieces (φ is linear: at an end)
  Real inside = 0;      ///< fraction of the edge inside the target (for the overlap area)
};

/// Signed areas of the contactor's vertices against the target's edges: >= 0 on the
/// inner side. Along a contactor edge each is linear, and they are exactly what the
/// separating-axis test looks at.
template <class Real>
struct EdgeAreas {
  Real a[3][3];  ///< [target edge k][contactor vertex i]
};

template <class Real>
TRIDEM_HD inline Real edge_area(const Triangle<Real>& target, int k, Vec2<Real> p) {
  return cross(target.v[(k + 1) % 3] - target.v[k], p - target.v[k]);
}

template <class Real>
TRIDEM_HD inline EdgeAreas<Real> edge_areas(const Triangle<Real>& contactor,
                                            const Triangle<Real>& target) {
  EdgeAreas<Real> r;
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    TRIDEM_UNROLL
    for (int i = 0; i < 3; ++i) r.a[k][i] = edge_area(target, k, contactor.v[i]);
  }
  return r;
}

/// True when an edge of the target has every contactor vertex on or outside it.
template <class Real>
TRIDEM_HD inline bool target_edge_separates(const EdgeAreas<Real>& r) {
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k)
    if (r.a[k][0] <= Real(0) && r.a[k][1] <= Real(0) && r.a[k][2] <= Real(0)) return true;
  return false;
}

/// False only when contactor edge e certainly misses the target: both ends strictly
/// outside one target edge, where edge_load's clipping would find nothing whatever the
/// rounding. Costs no division, so a pair spends its clipping on the edges that matter.
template <class Real>
TRIDEM_HD inline bool edge_may_enter(const EdgeAreas<Real>& r, int e) {
  const int e1 = (e + 1) % 3;
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k)
    if (r.a[k][e] < Real(0) && r.a[k][e1] < Real(0)) return false;
  return true;
}

/// What edge_load needs of the target, computed once per role.
template <class Real>
struct TargetShape {
  Triangle<Real> tri;
  Vec2<Real> centroid;
  Real to_phi;          ///< 3/(2A): φ in sub-triangle k is to_phi times edge area k
  Real edge_length[3];  ///< |v_k+1 − v_k|
};

template <class Real>
TRIDEM_HD inline TargetShape<Real> target_shape(const Triangle<Real>& t, Real area,
                                                Vec2<Real> centroid) {
  TargetShape<Real> s{t, centroid, Real(3) / (Real(2) * area), {}};
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) s.edge_length[k] = norm(t.v[(k + 1) % 3] - t.v[k]);
  return s;
}

/// The contactor edge p0 + t·(p1 − p0), t in [0, 1], is clipped to the target once; the
/// three centroid rays then split the inside part among the sub-triangles S_k = {ray_k >=
/// 0, ray_k+1 <= 0}, where φ is linear. Every clipping value is a signed area, linear
/// along the edge, so the areas at the two ends give them all.
template <class Real>
TRIDEM_HD inline EdgeLoad<Real> edge_load(Vec2<Real> p0, Vec2<Real> p1,
                                          const TargetShape<Real>& target) {
  EdgeLoad<Real> load;
  Real f0[3], fd[3];
  Real t_lo = Real(0), t_hi = Real(1);
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    f0[k] = edge_area(target.tri, k, p0);
    fd[k] = edge_area(target.tri, k, p1) - f0[k];
    if (!clip_to_half_plane(f0[k], fd[k], t_lo, t_hi)) return load;
  }
  load.inside = t_hi - t_lo;
  // Where the edge crosses each ray: each ray bounds two sub-triangles.
  Real r0[3], rd[3], crossing[3];
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    const Vec2<Real> ray = target.tri.v[k] - target.centroid;
    r0[k] = cross(ray, p0 - target.centroid);
    rd[k] = cross(ray, p1 - target.centroid) - r0[k];
    crossing[k] = rd[k] != Real(0) ? -r0[k] / rd[k] : Real(0);
  }
  const Vec2<Real> d = p1 - p0;
  const Real edge_length = norm(d);
  Vec2<Real> moment{};
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    const int next = (k + 1) % 3;
    Real t0 = t_lo, t1 = t_hi;
    // ray_k >= 0 ...
    if (!clip_at_crossing(r0[k], rd[k], crossing[k], t0, t1)) continue;
    // ... and ray_k+1 <= 0.
    if (!clip_at_crossing(-r0[next], -rd[next], crossing[next], t0, t1)) continue;
    const Real phi0 = target.to_phi * (f0[k] + t0 * fd[k]);
    const Real phi1 = target.to_phi * (f0[k] + t1 * fd[k]);
    const Real length = edge_length * (t1 - t0);
    const Vec2<Real> q0 = p0 + d * t0, q1 = p0 + d * t1;
    const LinearLoad<Real> piece = linear_load(q0, q1, length, phi0, phi1);
    load.peak = phi0 > load.peak ? phi0 : load.peak;
    load.peak = phi1 > load.peak ? phi1 : load.peak;
    load.integral += piece.integral;
    moment += piece.point * piece.integral;
    // Piece of length ℓ in S_k of height h_k = 2A/|e_k|: stiffness 3pℓ/h_k.
    load.stiffness += length * target.to_phi * target.edge_length[k];
  }
  if (load.integral > Real(0)) load.point = moment / load.integral;
  return load;
}

/// The same for edge e of a whole contactor (tests and tools).
template <class Real>
TRIDEM_HD inline EdgeLoad<Real> edge_load(const Triangle<Real>& contactor, int e,
                                          const Triangle<Real>& target, Real target_area,
                                          Vec2<Real> target_centroid) {
  return edge_load(contactor.v[e], contactor.v[(e + 1) % 3],
                   target_shape(target, target_area, target_centroid));
}

/// Mass that sets the damping of a pair: the reduced mass, or the free body's mass when
/// the other is moved by prescription (mass 0).
template <class Real>
TRIDEM_HD inline Real effective_mass(Real ma, Real mb) {
  return (ma > Real(0) && mb > Real(0)) ? ma * mb / (ma + mb) : ma + mb;
}

/// Element i of a small array with a run-time index, without forcing the array out of
/// registers on the device (the loop unrolls to predicated moves).
template <class T, int N>
TRIDEM_HD inline T pick(const T (&array)[N], int i) {
  T v = array[0];
  TRIDEM_UNROLL
  for (int k = 1; k < N; ++k)
    if (k == i) v = array[k];
  return v;
}

template <class T, int N>
TRIDEM_HD inline void put(T (&array)[N], int i, const T& v) {
  TRIDEM_UNROLL
  for (int k = 0; k < N; ++k)
    if (k == i) array[k] = v;
}

/// Vertex k of t for a run-time k.
template <class Real>
TRIDEM_HD inline Vec2<Real> vertex(const Triangle<Real>& t, int k) {
  return k == 0 ? t.v[0] : (k == 1 ? t.v[1] : t.v[2]);
}

/// The overlap Ω of a pair, gathered edge contact by edge contact, for the elastic energy
/// p∫_Ω(φ_a + φ_b)dA. In each sub-triangle φ_T = 1 + ∇φ·(P − c_T), so div(φ_T(P − c_T)) =
/// 3φ_T − 1 and, φ_T being 0 on ∂T, ∫_Ω φ_T dA = (1/3)[Σ I·n·(point − c_T) + |Ω|] over the
/// contactor edges in T (I their load integral, n their outward normal, point their load
/// centroid). |Ω| = ½∮cross(P − R, dP) over the clipped edges of both roles; a clipped
/// piece of edge (p0, d) gives cross(p0 − R, d)·inside.
template <class Real>
struct OverlapSums {
  Real moment = 0;      ///< Σ I·n·(point − c_T)
  Real twice_area = 0;  ///< 2|Ω|

  TRIDEM_HD void add(const EdgeLoad<Real>& load, Vec2<Real> p0, Vec2<Real> d, Vec2<Real> normal,
                     Vec2<Real> target_centroid, Vec2<Real> reference) {
    moment += load.integral * dot(normal, load.point - target_centroid);
    twice_area += cross(p0 - reference, d) * load.inside;
  }
  /// p∫_Ω(φ_a + φ_b)dA = (p/3)(Σ + 2|Ω|); never negative (rounding aside).
  TRIDEM_HD Real normal_energy(Real penalty) const {
    const Real e = penalty * (moment + twice_area) / Real(3);
    return e > Real(0) ? e : Real(0);
  }
};

/// Force, torques and new slips of the pair (a, b) over a step dt. `slip` holds the
/// slips of the previous step on entry (zeros for a new contact) and the new ones on exit;
/// an edge contact that has opened gets slip 0.
///
/// Edge contacts are numbered i = 3·role + e (role 0: a's edges in b, role 1: b's in a);
/// only those that may carry a load are visited, in that order, so that the threads of a
/// GPU warp each spend their time on their own few edges rather than on all six.
template <class Real>
TRIDEM_HD inline PairForce<Real> pair_force(const Body<Real>& a, const Body<Real>& b,
                                            const ContactLaw<Real>& law, Real dt,
                                            PairSlip<Real>& slip) {
  PairForce<Real> out;
  // The separating-axis test reads the same edge areas that tell which edges may enter.
  const EdgeAreas<Real> areas[2] = {edge_areas(a.tri, b.tri), edge_areas(b.tri, a.tri)};
  unsigned active = 0;
  if (!target_edge_separates(areas[0]) && !target_edge_separates(areas[1])) {
    TRIDEM_UNROLL
    for (int i = 0; i < kEdgeContacts; ++i)
      if (edge_may_enter(areas[i / 3], i % 3)) active |= 1u << i;
  }
  EdgeLoad<Real> loads[kEdgeContacts];
  Real total_integral = 0, total_stiffness = 0;
  if (active != 0) {
    const TargetShape<Real> b_shape = target_shape(b.tri, b.area, b.c);
    const TargetShape<Real> a_shape = target_shape(a.tri, a.area, a.c);
    TRIDEM_UNROLL
    for (int role = 0; role < 2; ++role) {
      const Triangle<Real>& contactor = role == 0 ? a.tri : b.tri;
      const TargetShape<Real>& target = role == 0 ? b_shape : a_shape;
      for (unsigned left = (active >> (3 * role)) & 7u; left != 0; left &= left - 1) {
        const int e = lowest_bit(left);
        const EdgeLoad<Real> load =
            edge_load(vertex(contactor, e), vertex(contactor, (e + 1) % 3), target);
        put(loads, 3 * role + e, load);
        total_integral += load.integral;
        total_stiffness += load.stiffness;
      }
    }
  }
  if (!(total_integral > Real(0))) {
    TRIDEM_UNROLL
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
  OverlapSums<Real> overlap;
  Real new_slip[kEdgeContacts] = {};
  TRIDEM_UNROLL
  for (int role = 0; role < 2; ++role) {
    const Body<Real>& c = role == 0 ? a : b;
    const Body<Real>& t = role == 0 ? b : a;
    for (unsigned left = (active >> (3 * role)) & 7u; left != 0; left &= left - 1) {
      const int e = lowest_bit(left);
      const int i = 3 * role + e;
      const EdgeLoad<Real> load = pick(loads, i);
      out.depth = load.peak > out.depth ? load.peak : out.depth;
      const Vec2<Real> d = vertex(c.tri, (e + 1) % 3) - vertex(c.tri, e);
      const Vec2<Real> tangent = d / norm(d);
      const Vec2<Real> normal{tangent.y, -tangent.x};  // outward for a CCW contactor
      overlap.add(load, vertex(c.tri, e), d, normal, t.c, a.c);
      if (!(load.integral > Real(0))) continue;
      const Vec2<Real> r = load.point;
      const Vec2<Real> v_rel = velocity_at(c, r) - velocity_at(t, r);
      const Real damping = c_total * load.stiffness / total_stiffness;
      const Real v_normal = dot(v_rel, normal);
      const Real f_normal = law.penalty * load.integral + damping * v_normal;
      out.damping_dissipation += damping * v_normal * v_normal * dt;
      // Elastic–perfectly-plastic tangential spring (Coulomb friction, contact-model.md).
      Real s = pick(slip.s, i) + dot(v_rel, tangent) * dt;
      Real f_tangent = -law.tangential_penalty * s;
      const Real cap = law.friction * (f_normal > Real(0) ? f_normal : Real(0));
      if (f_tangent > cap || f_tangent < -cap) {
        f_tangent = f_tangent > Real(0) ? cap : -cap;
        const Real s_capped = -f_tangent / law.tangential_penalty;
        // The slider's work: the capped force over the slip it let go.
        out.friction_dissipation += cap * (s > s_capped ? s - s_capped : s_capped - s);
        s = s_capped;
      }
      out.elastic_energy += Real(0.5) * law.tangential_penalty * s * s;
      put(new_slip, i, s);
      const Vec2<Real> f_on_c = normal * (-f_normal) + tangent * f_tangent;
      const Vec2<Real> f_on_a = role == 0 ? f_on_c : -f_on_c;
      out.force_a += f_on_a;
      out.torque_a += cross(r - a.c, f_on_a);
      out.torque_b -= cross(r - b.c, f_on_a);
      point_moment += r * load.integral;
    }
  }
  // Edge contacts without a load (opened or never closed) forget their slip.
  TRIDEM_UNROLL
  for (int i = 0; i < kEdgeContacts; ++i) slip.s[i] = new_slip[i];
  out.point = point_moment / total_integral;
  out.elastic_energy += overlap.normal_energy(law.penalty);
  return out;
}

}  // namespace tridem::physics
