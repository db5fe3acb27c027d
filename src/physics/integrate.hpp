#pragma once
// Symplectic Euler, the paper's Eqs. (5)–(7): velocities first, then positions with the
// new velocities. Optional Cundall local damping removes a fraction α of the unbalanced
// force against each velocity component, for quasi-static runs.
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

namespace tridem::physics {

/// A velocity component this many times smaller than the change the step's force makes
/// in it counts as at rest for local damping.
inline constexpr double kDampingRestRatio = 1e-9;

/// Cundall's damping of one component: the force less α|F| along the velocity's sign.
/// `response` is the component's velocity change per unit force in one step (inv_mass·dt,
/// or inv_inertia·dt). A velocity below kDampingRestRatio of the step's change counts as
/// at rest (no damping), as v = 0 does: a grain that starts from rest carries velocities of
/// rounding noise (1e-13 m/s against the 0.4 m/s a platen's first contact gives it), whose
/// sign would otherwise decide ±α of that force, and differ between backends that round
/// differently (docs/model.md, "Local damping").
template <class Real>
TRIDEM_HD inline Real local_damping(Real force, Real velocity, Real alpha, Real response) {
  const Real magnitude = force < Real(0) ? -force : force;
  const Real speed = velocity < Real(0) ? -velocity : velocity;
  if (!(speed > static_cast<Real>(kDampingRestRatio) * magnitude * response)) return force;
  return force - alpha * magnitude * (velocity > Real(0) ? Real(1) : Real(-1));
}

template <class Real>
struct Pose {
  Vec2<Real> c;
  Real theta;
  Vec2<Real> v;
  Real w;
};

/// Advances a free body by one step under contact force f, torque m and gravity g.
template <class Real>
TRIDEM_HD inline void integrate_free(Pose<Real>& p, Vec2<Real> f, Real m, Real inv_mass,
                                     Real inv_inertia, Vec2<Real> g, Real alpha, Real dt) {
  const Real mass = Real(1) / inv_mass;
  Vec2<Real> total = f + g * mass;
  if (alpha > Real(0)) {
    const Real linear = inv_mass * dt, angular = inv_inertia * dt;
    total = {local_damping(total.x, p.v.x, alpha, linear),
             local_damping(total.y, p.v.y, alpha, linear)};
    m = local_damping(m, p.w, alpha, angular);
  }
  p.v += total * (inv_mass * dt);
  p.w += m * inv_inertia * dt;
  p.c += p.v * dt;
  p.theta += p.w * dt;
}

/// Energy that Cundall's local damping removed from a free body over the step that took
/// it from `before` to `after` (energy.csv). Each damped component loses α|F|·sign(v) with
/// F the undamped force (contact plus gravity), and symplectic Euler changes the kinetic
/// energy by exactly F·(v_before + v_after)/2·dt, so that velocity is the one used here.
template <class Real>
TRIDEM_HD inline Real local_damping_dissipation(const Pose<Real>& before, const Pose<Real>& after,
                                                Vec2<Real> f, Real m, Real inv_mass,
                                                Real inv_inertia, Vec2<Real> g, Real alpha,
                                                Real dt) {
  if (!(alpha > Real(0))) return Real(0);
  const Vec2<Real> total = f + g * (Real(1) / inv_mass);
  const Real linear = inv_mass * dt, angular = inv_inertia * dt;
  const Real fx = total.x - local_damping(total.x, before.v.x, alpha, linear);
  const Real fy = total.y - local_damping(total.y, before.v.y, alpha, linear);
  const Real mz = m - local_damping(m, before.w, alpha, angular);
  const Real half_dt = Real(0.5) * dt;
  return (fx * (before.v.x + after.v.x) + fy * (before.v.y + after.v.y) +
          mz * (before.w + after.w)) * half_dt;
}

/// A fixed or prescribed body keeps its velocity and moves with it.
template <class Real>
TRIDEM_HD inline void integrate_prescribed(Pose<Real>& p, Real dt) {
  p.c += p.v * dt;
  p.theta += p.w * dt;
}

/// The step every backend takes for one body: free bodies by their forces, the others by
/// prescription.
template <class Real>
TRIDEM_HD inline void advance_body(Pose<Real>& p, bool free, Vec2<Real> f, Real m,
                                   Real inv_mass, Real inv_inertia, Vec2<Real> g, Real alpha,
                                   Real dt) {
  if (free) integrate_free(p, f, m, inv_mass, inv_inertia, g, alpha, dt);
  else integrate_prescribed(p, dt);
}

/// A body's pose after one step, as every backend advances it: the contact force and
/// torque come in the pair precision Real; the integration is double in every precision.
template <class Real>
TRIDEM_HD inline Pose<double> stepped_pose(Pose<double> p, bool free, Vec2<Real> f, Real torque,
                                           double inv_mass, double inv_inertia, Vec2d g,
                                           double alpha, double dt) {
  advance_body(p, free, Vec2d{static_cast<double>(f.x), static_cast<double>(f.y)},
               static_cast<double>(torque), inv_mass, inv_inertia, g, alpha, dt);
  return p;
}

/// True when the advanced pose of a free body is non-finite or has moved more than half
/// the body's size in one step: the contact forces are then no longer resolved in time.
template <class Real>
TRIDEM_HD inline bool runaway_step(const Pose<Real>& p, Real half_size, Real dt) {
  const bool finite = isfinite(p.c.x) && isfinite(p.c.y) && isfinite(p.theta) &&
                      isfinite(p.v.x) && isfinite(p.v.y) && isfinite(p.w);
  return !finite || norm(p.v) * dt > half_size;
}

}  // namespace tridem::physics
