#pragma once
// The energy of one emitter's row of pairs over a step: what its dashpots and sliders
// dissipated and the work the moving walls among them did on the grains. Each pair is in
// exactly one row, so the per-particle sums add up to the whole without atomics; every
// backend adds them when it writes the step's state (a step stopped by a blow-up adds
// nothing).
#include "physics/contact_force.hpp"
#include "physics/integrate.hpp"
#include "tridem/energy_budget.hpp"

#include <cstdint>

namespace tridem {

struct RowEnergy {
  double damping = 0, friction = 0, wall_work = 0;
};

/// `wall_velocity(j, v, w)` is true only for a wall (non-free particle) that moves, and
/// then gives its velocity and angular velocity (double, as the state); a wall at rest
/// does no work. Work of a wall W over the step: −(F_W·v_W + τ_W·ω_W)·dt, F_W and τ_W the
/// contact force and torque on it. A pair of two walls is never listed, so the partner of
/// a wall is free.
/// `result` holds PairForce or physics::PairLoad records (the fields read are in both).
template <class Record, class Offset, class Index, class WallVelocity>
TRIDEM_HD inline RowEnergy row_energy(std::int64_t e, const Offset* offset, const Index* partner,
                                      const Record* result, WallVelocity&& wall_velocity,
                                      double dt) {
  RowEnergy sum;
  Vec2d v_e{};
  double w_e = 0;
  const bool e_moves = wall_velocity(e, v_e, w_e);
  for (auto s = offset[e]; s < offset[e + 1]; ++s) {
    const Record& r = result[s];
    sum.damping += static_cast<double>(r.damping_dissipation);
    sum.friction += static_cast<double>(r.friction_dissipation);
    const Vec2d f{static_cast<double>(r.force_a.x), static_cast<double>(r.force_a.y)};
    if (e_moves) {
      sum.wall_work -= (dot(f, v_e) + static_cast<double>(r.torque_a) * w_e) * dt;
    } else {
      Vec2d v_j{};
      double w_j = 0;
      if (wall_velocity(partner[s], v_j, w_j))
        sum.wall_work += (dot(f, v_j) - static_cast<double>(r.torque_b) * w_j) * dt;
    }
  }
  return sum;
}

/// What particle i's step adds to the budget's per-particle sums (`sums[k][i]`, k in
/// EnergyAccumulator order; host vectors or device pointers) when the backend writes it:
/// its own row of pairs (row_energy) and, if free, what local damping took from it over
/// the step from `before` to `after` under force f and torque m.
/// `row`: row_energy of particle i's row (the CUDA gather sums it from the loads it reads
/// anyway, so that the integration need not read the row again).
template <class Sums, class Real>
TRIDEM_HD inline void add_step_energy(Sums& sums, std::int64_t i, const RowEnergy& row, bool free,
                                      const physics::Pose<double>& before,
                                      const physics::Pose<double>& after, Vec2<Real> f, Real m,
                                      double inv_mass, double inv_inertia, Vec2d g, double alpha,
                                      double dt) {
  sums[kDissipatedDamping][i] += row.damping;
  sums[kDissipatedFriction][i] += row.friction;
  sums[kWallWork][i] += row.wall_work;
  if (free && alpha > 0)
    sums[kDissipatedLocal][i] += physics::local_damping_dissipation(
        before, after, Vec2d{static_cast<double>(f.x), static_cast<double>(f.y)},
        static_cast<double>(m), inv_mass, inv_inertia, g, alpha, dt);
}

template <class Sums, class Real, class Offset, class Index, class Record, class WallVelocity>
TRIDEM_HD inline void add_step_energy(Sums& sums, std::int64_t i, const Offset* offset,
                                      const Index* partner, const Record* result,
                                      WallVelocity&& wall_velocity, bool free,
                                      const physics::Pose<double>& before,
                                      const physics::Pose<double>& after, Vec2<Real> f, Real m,
                                      double inv_mass, double inv_inertia, Vec2d g, double alpha,
                                      double dt) {
  add_step_energy(sums, i, row_energy(i, offset, partner, result, wall_velocity, dt), free, before,
                  after, f, m, inv_mass, inv_inertia, g, alpha, dt);
}

}  // namespace tridem
