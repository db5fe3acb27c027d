#pragma once
// The kernels of bodies of several triangles, after the members' own gather (gather_kernel
// of step_kernels.cuh, without its per-particle runaway test): the per-body sum of the
// members' loads with the runaway test of each body (thread per body, members in
// ascending order: CpuSolver::gather_bodies' order), the members' energy rows (thread per
// triangle) and the body's step (thread per body: CpuSolver::integrate_bodies), then every
// member placed on its body with the geometry of the new state (thread per triangle:
// place_members, fused with the Geometry stage as integrate_kernel is). Scenes without bodies never
// launch them.
#include "backends/cuda/body_buffers.cuh"
#include "backends/cuda/step_kernels.cuh"
#include "physics/rigid_body.hpp"

#include <climits>

namespace tridem::cuda {

__device__ inline physics::Pose<double> body_pose(const BodyArrays& b, int k) {
  return {{b.body_x[k], b.body_y[k]}, b.body_theta[k], {b.body_vx[k], b.body_vy[k]}, b.body_w[k]};
}

template <class Real>
__device__ inline physics::Pose<double> advanced_body_pose(const BodyArrays& b,
                                                           const StepParams<Real>& sp, int k) {
  return physics::stepped_or_programmed_pose(
      sp.programs, b.body_program[k], sp.time_new, body_pose(b, k),
      b.body_motion[k] == Motion::Free, Vec2d{b.body_fx[k], b.body_fy[k]}, b.body_torque[k],
      b.body_inv_mass[k], b.body_inv_inertia[k], sp.gravity, sp.local_damping, sp.dt);
}

/// Sums the members' loads of each free body and flags the lowest body whose step would
/// run away (nothing is written yet). With `prescribed`, sums those of the other bodies
/// instead: only output needs them, as gather_kernel's walls.
template <class Real>
__global__ void body_gather_kernel(ParticleArrays<Real> p, BodyArrays b, StepParams<Real> sp,
                                   StepStatus* status, bool prescribed) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= b.n || (b.body_motion[k] == Motion::Free) == prescribed) return;
  Vec2d f{};
  double t = 0;
  for (std::int64_t i = b.body_first[k]; i < b.body_last[k]; ++i)
    physics::add_member_load(f, t, Vec2<Real>{p.fx[i], p.fy[i]}, p.torque[i],
                             Vec2d{p.x[i] - b.body_x[k], p.y[i] - b.body_y[k]});
  b.body_fx[k] = f.x;
  b.body_fy[k] = f.y;
  b.body_torque[k] = t;
  if (prescribed) return;
  if (physics::runaway_step(advanced_body_pose(b, sp, k), b.body_half_size[k], sp.dt))
    atomicMin(&status->bad, k);
}

/// The energy rows of every member (unless the step was refused): thread per triangle, as
/// CpuSolver::integrate_bodies adds them (free = false: a member's row only; its body's
/// local damping goes to another sum, in body_integrate_kernel), before any member moves,
/// so the walls' member velocities read are those of the step.
/// kPeriodic: with the boundary's work through the member's row (Lees-Edwards).
template <class Real, bool kPeriodic = false>
__global__ void member_energy_kernel(ParticleArrays<Real> p, PairArrays<Real> q,
                                     StepParams<Real> sp, const StepStatus* status) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= p.n) return;
  if (status->failed()) return;
  const physics::Pose<double> unused{};  // read only for a free particle's local damping
  add_step_energy(p, q, sp, i, false, unused, unused);
  if constexpr (kPeriodic) add_image_work(p, sp, i);
}

/// The step of each body (unless some body ran away or some pair overlaps too deep: then
/// the last good state stays, as on the CPU), with the body's local damping, booked on its
/// first member. kPeriodic: a free body is put back into the cell (StepParams::frame_new)
/// after its step's energy, what that gave it booked on its first member, as
/// CpuSolver::integrate_bodies does; its members follow it (place_members_kernel).
template <class Real, bool kPeriodic = false>
__global__ void body_integrate_kernel(ParticleArrays<Real> p, BodyArrays b, StepParams<Real> sp,
                                      const StepStatus* status) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= b.n) return;
  if (status->failed()) return;
  const physics::Pose<double> before = body_pose(b, k);
  physics::Pose<double> after = advanced_body_pose(b, sp, k);
  const bool free = b.body_motion[k] == Motion::Free;
  if (free && sp.local_damping > 0)
    p.energy[kDissipatedLocal][b.body_first[k]] += physics::local_damping_dissipation(
        before, after, Vec2d{b.body_fx[k], b.body_fy[k]}, b.body_torque[k], b.body_inv_mass[k],
        b.body_inv_inertia[k], sp.gravity, sp.local_damping, sp.dt);
  if constexpr (kPeriodic) {
    if (free)
      p.energy[kWallWork][b.body_first[k]] +=
          physics::wrap_with_work(sp.frame_new, after, b.body_inv_mass[k], sp.gravity);
  }
  b.body_x[k] = after.c.x;
  b.body_y[k] = after.c.y;
  b.body_theta[k] = after.theta;
  if (!free && b.body_program[k] < 0) return;
  b.body_vx[k] = after.v.x;
  b.body_vy[k] = after.v.y;
  b.body_w[k] = after.w;
}

/// Every member at its body's pose (unless the step was refused), then the geometry of
/// the state it leaves, with the rebuild flag (integrate_kernel's update_geometry).
template <class Real>
__global__ void place_members_kernel(ParticleArrays<Real> p, BodyArrays b, StepStatus* status) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= p.n) return;
  if (status->failed()) return;
  const physics::Pose<double> m =
      physics::member_pose(body_pose(b, b.member_body[i]), Vec2d{b.member_dx[i], b.member_dy[i]});
  p.x[i] = m.c.x;
  p.y[i] = m.c.y;
  p.theta[i] = m.theta;
  p.vx[i] = m.v.x;
  p.vy[i] = m.v.y;
  p.w[i] = m.w;
  update_geometry(p, i, status);
}

}  // namespace tridem::cuda
