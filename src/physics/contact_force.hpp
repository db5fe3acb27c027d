#pragma once
// The potential contact force of one pair of rigid triangles, with friction and damping:
// the single definition every backend calls (docs/model.md, "The potential contact force").
//
// For each ordered role (contactor C, target T) — (a, b) then (b, a) — the potential of T
// along each edge of C is the minimum of three linear functions clipped at zero; its
// integral and first moment are exact between the breakpoints. The loads of one edge share
// its outward normal, so they add to one force −p·I·n at their centroid: the exact
// resultant and moment of the distributed force.
//
// Friction and damping act at ONE contact per pair: the normal is the direction of the
// pair's resultant potential force, the point the load-weighted centroid of all edges.
// The tangential history of a pair is a 2D elastic displacement that turns with the
// contact (PairSlip).
#include "physics/body.hpp"
#include "physics/damping.hpp"
#include "physics/potential.hpp"

namespace tridem::physics {

constexpr int kEdgeContacts = 6;  ///< 2 roles × 3 contactor edges carry the normal loads
constexpr int kHistoryValues = 2;  ///< the tangential displacement, x and y

/// Tangential history of a pair's contact, kept from step to step: u = √k_t·ξ with ξ the
/// elastic tangential displacement (world frame; units √(N/m)·m = √(J/m)). The spring
/// force on a is −√k_t·u and its energy ½|u|². Zero for a new contact.
template <class Real>
struct PairSlip {
  Real s[kHistoryValues];
};

/// What a pair does to its two bodies during one step.
template <class Real>
struct PairForce {
  Vec2<Real> force_a{};  ///< on a; b receives −force_a
  Real torque_a = 0;
  Real torque_b = 0;
  Vec2<Real> point{};    ///< where the normal loads act on average: the contact point
  /// Penetration depth: the largest φ reached by either boundary inside the other
  /// triangle, 0 at its edge and 1 at its centroid (the blow-up check reads it).
  Real depth = 0;
  /// Energy stored in the pair (J/m) at the configuration the force is computed for:
  /// the normal potential p·(∫_Ω φ_a dA + ∫_Ω φ_b dA) over the overlap Ω, plus the
  /// tangential spring's ½·|u|² (= ½·k_t·|ξ|²) with the history written back by this step.
  Real elastic_energy = 0;
  /// Energy removed by the normal and tangential dashpots over this step (J/m):
  /// c_n·v_n²·dt + the tangential dashpot's −f_d·v_t·dt. >= 0 except when the Coulomb cap
  /// trims a sticking force that the dashpot had raised.
  Real damping_dissipation = 0;
  /// Energy removed by Coulomb sliding over this step (J/m): μ·f_n times the slip, the
  /// part of the step's tangential displacement that the spring did not keep. >= 0.
  Real friction_dissipation = 0;
  /// The contact's unit normal N, from a into b (the force on a is −f_n·N + f_t·T, T = N
  /// turned +90°): what the contact network reports as its normal and tangential parts.
  Vec2<Real> normal{};
  bool touching = false;
  bool sliding = false;  ///< the Coulomb cap held the tangential force this step
};

/// The load of one contactor edge inside a target triangle.
template <class Real>
struct EdgeLoad {
  Real integral = 0;    ///< ∫ φ_T dΓ over the edge's part inside T, metres
  /// ∫ φ_T·x dΓ: the load's first moment, its centroid times the integral. Kept as a moment
  /// because every use (torques, the contact point, the stored energy) multiplies the
  /// centroid by the integral again: no division per piece or per edge.
  Vec2<Real> moment{};
  Real length = 0;      ///< |p1 − p0|, once the edge is known to enter T (else 0)
  Real stiffness = 0;   ///< Σ 3ℓ/h_k over the linear pieces: contact stiffness over p
  Real peak = 0;        ///< the largest φ_T on the edge (at a breakpoint or an end)
  /// Σ ℓ·∇φ_T over the pieces (|∇φ_T| = 3/h_k): the stiffness matrix of the edge's load
  /// is p·n ⊗ gradient, n the contactor edge's outward normal.
  Vec2<Real> gradient{};
  /// Σ ℓ·max(φ0, φ1) over the pieces: with the integral it gives the load exponent n_eff
  /// (a uniform load has 1, a triangular one 2).
  Real shape = 0;

  /// The load's centroid (where the distributed normal load acts): tests and tools.
  TRIDEM_HD Vec2<Real> centroid() const {
    return integral > Real(0) ? moment / integral : Vec2<Real>{};
  }
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

/// Vertex k of t for a run-time k.
template <class Real>
TRIDEM_HD inline Vec2<Real> vertex(const Triangle<Real>& t, int k) {
  return k == 0 ? t.v[0] : (k == 1 ? t.v[1] : t.v[2]);
}

/// What edge_load needs of the target, computed once per role.
template <class Real>
struct TargetShape {
  Triangle<Real> tri;
  Vec2<Real> centroid;
  Real to_phi;          ///< 3/(2A): φ in sub-triangle k is to_phi times edge area k
  Real edge_length[3];  ///< |v_k+1 − v_k|
  Vec2<Real> edge[3];   ///< v_k+1 − v_k, once per target rather than once per loaded piece
};

template <class Real>
TRIDEM_HD inline TargetShape<Real> target_shape(const Triangle<Real>& t, Real area,
                                                Vec2<Real> centroid) {
  TargetShape<Real> s{t, centroid, Real(3) / (Real(2) * area), {}, {}};
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    s.edge[k] = t.v[(k + 1) % 3] - t.v[k];
    s.edge_length[k] = norm(s.edge[k]);
  }
  return s;
}

/// The contactor edge p0 + t·(p1 − p0), t in [0, 1]. Along it φ_T(t) = max(0, min_k g_k(t))
/// with g_k = to_phi·(edge area k), linear in t (inside T the minimum is Munjiza's φ,
/// outside it is negative). The part where the minimum is positive is [t_lo, t_hi] (three
/// half-plane clips). Line k is the minimum on the part of it where g_k <= g_j for both
/// other lines j: two more clips, at the crossings of k with each of them. Each of the three
/// crossings is divided once and clips both of its lines, so the lines' parts meet without
/// a gap or an overlap; each part is integrated with its own line, known at compile time
/// (no run-time line index: on the GPU the three parts are the same instructions for every
/// thread of a warp). Two equal lines (an edge lying on a centroid ray) give their common
/// part to the one of lower index only, so it is counted once.
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
  const Vec2<Real> d = p1 - p0;
  const Real edge_length = norm(d);
  load.length = edge_length;
  Real lo[3] = {t_lo, t_lo, t_lo}, hi[3] = {t_hi, t_hi, t_hi};
  TRIDEM_UNROLL
  for (int j = 0; j < 2; ++j) {
    TRIDEM_UNROLL
    for (int k = j + 1; k < 3; ++k) {
      const Real rise = fd[k] - fd[j];  // the slope of g_k − g_j
      if (rise == Real(0)) {
        // Parallel: the lower line throughout; of two equal ones, j.
        if (f0[k] - f0[j] >= Real(0))
          hi[k] = t_lo;
        else
          hi[j] = t_lo;
        continue;
      }
      const Real crossing = math::divide(f0[j] - f0[k], rise);  // where g_k = g_j
      // Compares written so that a crossing that is not a number clips nothing.
      if (rise > Real(0)) {  // g_k is the lower before the crossing, g_j after it
        hi[k] = math::min(crossing, hi[k]);
        lo[j] = math::max(crossing, lo[j]);
      } else {
        hi[j] = math::min(crossing, hi[j]);
        lo[k] = math::max(crossing, lo[k]);
      }
    }
  }
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    if (!(hi[k] > lo[k])) continue;
    const Real t0 = lo[k], t1 = hi[k];
    Real phi0 = target.to_phi * (f0[k] + t0 * fd[k]);
    Real phi1 = target.to_phi * (f0[k] + t1 * fd[k]);
    phi0 = math::max(phi0, Real(0));  // zero at t_lo and t_hi up to rounding
    phi1 = math::max(phi1, Real(0));
    const Real length = edge_length * (t1 - t0);
    const Vec2<Real> q0 = p0 + d * t0, q1 = p0 + d * t1;
    // A linear load φ0 → φ1 over [q0, q1]: ∫ φ = ℓ(φ0 + φ1)/2 and ∫ φ·x = q0·∫ φ +
    // (q1 − q0)·ℓ(φ0 + 2φ1)/6 (the trapezoid's centroid times its integral).
    const Real integral = length * (phi0 + phi1) * Real(0.5);
    const Real high = math::max(phi0, phi1);
    load.peak = math::max(high, load.peak);
    load.integral += integral;
    load.moment += q0 * integral + (q1 - q0) * (length * (phi0 + Real(2) * phi1) / Real(6));
    // A piece of length ℓ in S_k, of height h_k = 2A/|e_k|: stiffness 3pℓ/h_k, and
    // ∇φ = to_phi·perp(e_k) (|∇φ| = 3/h_k).
    load.stiffness += length * target.to_phi * target.edge_length[k];
    const Vec2<Real> e_k = target.edge[k];
    load.gradient += Vec2<Real>{-e_k.y, e_k.x} * (length * target.to_phi);
    load.shape += length * high;
  }
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

/// Force, torques and new tangential history of the pair (a, b) over a step dt. `slip`
/// holds the history of the previous step on entry (zeros for a new contact) and the new
/// one on exit; a pair that has opened gets zeros.
///
/// Edge contacts are numbered i = 3·role + e (role 0: a's edges in b, role 1: b's in a);
/// only those that may carry a load are visited, in that order, so that the threads of a
/// GPU warp each spend their time on their own few edges rather than on all six.
///
/// kEnergy = false leaves elastic_energy at zero and everything else bit for bit as with
/// true: the stored energy needs the overlap polygon (a clipping with divisions, on the GPU
/// an array in local memory), and only the steps whose results are read (the last of an
/// advance) need it. The forces never read it.
template <bool kEnergy = true, class Real>
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
  // Sums over the loaded edges of both roles.
  Real total_integral = 0, total_stiffness = 0, total_shape = 0;
  Real phi_moment = 0;                      // for the stored energy (see elastic_energy)
  Real kxx = 0, kxy = 0, kyx = 0, kyy = 0;  // Σ n ⊗ gradient: the normal stiffness over p
  Vec2<Real> point_moment{};
  TRIDEM_UNROLL
  for (int role = 0; role < 2; ++role) {
    if (((active >> (3 * role)) & 7u) == 0) continue;
    const Body<Real>& c = role == 0 ? a : b;
    const Body<Real>& t = role == 0 ? b : a;
    const TargetShape<Real> target = target_shape(t.tri, t.area, t.c);
    for (unsigned left = (active >> (3 * role)) & 7u; left != 0; left &= left - 1) {
      const int e = lowest_bit(left);
      const Vec2<Real> p0 = vertex(c.tri, e), p1 = vertex(c.tri, (e + 1) % 3);
      const EdgeLoad<Real> load = edge_load(p0, p1, target);
      out.depth = math::max(load.peak, out.depth);
      if (!(load.integral > Real(0))) continue;
      const Vec2<Real> d = p1 - p0;
      const Real per_length = math::divide(Real(1), load.length);
      const Vec2<Real> normal{d.y * per_length, -d.x * per_length};  // outward, CCW contactor
      const Vec2<Real> f_on_c = normal * (-law.penalty * load.integral);
      const Vec2<Real> f_on_a = role == 0 ? f_on_c : -f_on_c;
      out.force_a += f_on_a;
      // The load acts at its centroid M/I: cross(M/I − c, −p·I·n) = −p·cross(M − I·c, n).
      const Real towards_a = role == 0 ? -law.penalty : law.penalty;  // f_on_a = towards_a·I·n
      out.torque_a += towards_a * cross(load.moment - a.c * load.integral, normal);
      out.torque_b -= towards_a * cross(load.moment - b.c * load.integral, normal);
      point_moment += load.moment;
      total_integral += load.integral;
      total_stiffness += load.stiffness;
      total_shape += load.shape;
      kxx += normal.x * load.gradient.x;
      kxy += normal.x * load.gradient.y;
      kyx += normal.y * load.gradient.x;
      kyy += normal.y * load.gradient.y;
      // ∫_Ω φ_T dA = (1/3)[Σ I·n·(point − c_T) + |Ω|] (divergence of φ·(x − c_T), which is
      // 3φ − 1 inside T): the pieces of T's own edges, where φ_T = 0, add nothing.
      if constexpr (kEnergy) phi_moment += dot(normal, load.moment - t.c * load.integral);
    }
  }
  if (!(total_integral > Real(0))) {
    TRIDEM_UNROLL
    for (int i = 0; i < kHistoryValues; ++i) slip.s[i] = Real(0);
    out.force_a = {};
    out.torque_a = out.torque_b = Real(0);
    return out;
  }
  out.touching = true;
  const Vec2<Real> r = point_moment * (Real(1) / total_integral);
  out.point = r;

  // The contact: normal N from a into b along the resultant potential force (the force on
  // a is −|F|·N), tangent perpendicular to it.
  const Real f_potential = norm(out.force_a);
  Vec2<Real> n_ab = b.c - a.c;
  if (f_potential > Real(0))
    n_ab = out.force_a * (Real(-1) / f_potential);
  else n_ab = n_ab / norm(n_ab);
  out.normal = n_ab;
  // Stiffnesses: along N, N·K·N of the loads' stiffness matrix K = p·Σ n ⊗ ∇φ·ℓ (what a
  // normal approach meets); tangential k_t = p_t·Σ 3ℓ/h (= (p_t/p)·k_n with k_n the bound
  // p·Σ 3ℓ/h of any direction's stiffness).
  const Real k_along = n_ab.x * (kxx * n_ab.x + kxy * n_ab.y) + n_ab.y * (kyx * n_ab.x + kyy * n_ab.y);
  const Real k_normal = law.penalty * (k_along > Real(0) ? k_along : Real(0));
  const Real k_tangent = law.tangential_penalty * total_stiffness;
  // Load exponent n_eff = k·δ/F of the loads' shapes: 1 for a face, 2 for a vertex.
  const Real zeta = damping_ratio(law, total_shape / total_integral);
  const Real m_eff = effective_mass(a.mass, b.mass);
  const Real c_normal = Real(2) * zeta * math::sqrt(m_eff * k_normal);
  const Real c_tangent = Real(2) * zeta * math::sqrt(m_eff * k_tangent);

  const Vec2<Real> v_rel = velocity_at(a, r) - velocity_at(b, r);
  const Real v_n = dot(v_rel, n_ab);  // > 0 approaching
  const Vec2<Real> v_t = v_rel - n_ab * v_n;
  const Real f_normal = f_potential + c_normal * v_n;
  Vec2<Real> extra = n_ab * (-c_normal * v_n);  // on a, at r: normal dashpot ...
  out.damping_dissipation = c_normal * v_n * v_n * dt;

  // ... and friction. The history u = √k_t·ξ (ξ the elastic tangential displacement) turns
  // with the contact: projected onto the new tangent, keeping its length; then it grows by
  // √k_t times the step's tangential motion. The spring force is −√k_t·u and its energy
  // ½|u|²: a change of k_t (the contact growing or shrinking) scales the force and leaves
  // the stored energy alone, so the energy budget closes (docs/model.md, "Friction").
  const Real root_k = math::sqrt(k_tangent);
  Vec2<Real> u{slip.s[0], slip.s[1]};
  const Real u_length = norm(u);
  u = u - n_ab * dot(u, n_ab);
  const Real u_projected = norm(u);
  u = u_projected > Real(0) ? u * (u_length / u_projected) : Vec2<Real>{};
  u += v_t * (dt * root_k);
  const Vec2<Real> f_spring = u * (-root_k);
  const Real spring = norm(f_spring);
  const Real cap = law.friction * (f_normal > Real(0) ? f_normal : Real(0));
  Vec2<Real> f_tangent;
  if (spring > cap) {
    // Sliding: the force is the cap; the spring keeps what the cap allows, the rest of
    // the displacement, (|u| − |u_kept|)/√k_t, is slip.
    f_tangent = spring > Real(0) ? f_spring * (cap / spring) : Vec2<Real>{};
    const Vec2<Real> kept = root_k > Real(0) ? f_tangent / (-root_k) : Vec2<Real>{};
    if (root_k > Real(0)) out.friction_dissipation = cap * (norm(u) - norm(kept)) / root_k;
    u = kept;
    out.sliding = true;
  } else {
    // Sticking: spring and dashpot, together no more than the cap.
    f_tangent = f_spring - v_t * c_tangent;
    const Real total = norm(f_tangent);
    if (total > cap) f_tangent = f_tangent * (cap / total);
    out.damping_dissipation -= dot(f_tangent - f_spring, v_t) * dt;
  }
  extra += f_tangent;
  slip.s[0] = u.x;
  slip.s[1] = u.y;

  out.force_a += extra;
  out.torque_a += cross(r - a.c, extra);
  out.torque_b -= cross(r - b.c, extra);
  // Both roles' integrals: (1/3)[Σ I·n·(point − c_T) over both + 2|Ω|]. |Ω| from the
  // triangles themselves, not from the loaded pieces: a piece along the other's edge (the
  // collinear sides of lattice neighbours) has no load, and a sum of the loaded pieces'
  // cross products left it out, so that the area depended on the origin (a pair sharing a
  // vertex stored -96 J/m where the same pair turned the other way stored 0.0004 J/m).
  if constexpr (kEnergy) {
    const Real twice_area = Real(2) * overlap_area(a.tri, b.tri, a.c);
    out.elastic_energy = law.penalty * (phi_moment + twice_area) / Real(3) + Real(0.5) * dot(u, u);
  }
  return out;
}

}  // namespace tridem::physics
