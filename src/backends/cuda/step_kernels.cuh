#pragma once
// The kernels of one time step after the broad phase: pair forces (one thread per
// candidate pair), the per-particle sum of those forces with the runaway check (one
// thread per particle, in the CPU's fixed order, so that results do not depend on
// scheduling), and the integration fused with the geometry of the new state.
#include "backends/cuda/device_views.cuh"
#include "broadphase/pair_sums.hpp"
#include "broadphase/row_energy.hpp"
#include "physics/bond_step.hpp"
#include "physics/contact_force.hpp"
#include "physics/integrate.hpp"
#include "physics/local_frame.hpp"
#include "physics/rigid_body.hpp"

#include <climits>

namespace tridem::cuda {

/// Body i in the frame whose origin is at `origin` (the pair's emitter's centroid): the
/// CPU's gather, physics/local_frame.hpp.
template <class Real>
__device__ inline physics::Body<Real> load_body(const ParticleArrays<Real>& p, int i,
                                                Vec2d origin) {
  Vec2<Real> rel[3];
  physics::load_vertices(p.rel_x, p.rel_y, i, rel);
  return physics::body_at(physics::offset_from<Real>(origin, Vec2d{p.x[i], p.y[i]}), rel,
                          Vec2d{p.vx[i], p.vy[i]}, p.w[i], p.area[i], p.mass[i]);
}

/// Body i as its nearest periodic image `im` is seen from `origin` (CpuSolver::image_body).
template <class Real>
__device__ inline physics::Body<Real> load_image_body(const ParticleArrays<Real>& p, int i,
                                                      Vec2d origin,
                                                      const physics::PeriodicImage& im) {
  const Vec2d c{p.x[i], p.y[i]};
  Vec2<Real> rel[3];
  physics::load_vertices(p.rel_x, p.rel_y, i, rel);
  return physics::body_at(physics::image_offset<Real>(origin, c, im), rel,
                          Vec2d{p.vx[i] + im.dvx, p.vy[i]}, p.w[i], p.area[i], p.mass[i]);
}

/// Launch shape of the pair-force kernel: 128-thread blocks with a register cap, measured
/// best on an H100 (bench/results/cuda_tuning_2026-11-23_nvidia-h100-80gb-hbm3.md): the
/// double kernel needs 226 registers uncapped, so 4 blocks per SM (128 registers, a few
/// spills) beat 8 warps without spills.
/// TRIDEM_PAIR_BLOCKS_DOUBLE and _FLOAT override min_blocks for a tuning build
/// (bench/compare_builds.sh); releases use the defaults.
#ifndef TRIDEM_PAIR_BLOCKS_DOUBLE
#define TRIDEM_PAIR_BLOCKS_DOUBLE 4
#endif
#ifndef TRIDEM_PAIR_BLOCKS_FLOAT
#define TRIDEM_PAIR_BLOCKS_FLOAT 6
#endif
template <class Real>
struct PairKernelShape;
template <>
struct PairKernelShape<double> {
  static constexpr int threads = 128, min_blocks = TRIDEM_PAIR_BLOCKS_DOUBLE;
};
template <>
struct PairKernelShape<float> {
  static constexpr int threads = 128, min_blocks = TRIDEM_PAIR_BLOCKS_FLOAT;
};

/// Run-ahead (StepParams::gate): this step was launched behind one that has failed or
/// asked for a new pair list, so it does nothing; the host launches it again.
template <class Real>
__device__ inline bool held_back(const StepParams<Real>& sp) {
  if (sp.gate == nullptr) return false;
  const StepStatus before = *sp.gate;
  return before.rebuild != 0 || before.failed();
}

/// kBodies: a scene with bodies of several triangles, whose members of one body
/// (`member_body`) add exact zeros and keep no history (physics::same_body, as on the CPU);
/// kBonds: a bonded scene, whose pairs an intact bond holds (`bonds`, physics::
/// intact_bond_between: the bond carries them) add exact zeros and keep no history too. A
/// scene without them compiles the kernel without the filter. kPeriodic: a periodic scene,
/// whose partners are seen through their nearest image (StepParams::frame), as on the CPU.
/// kDetails: the step writes every pair's PairDetail (StepParams::details, the last step of
/// an advance), stored energy included; the other steps compute no energy (pair_force's
/// kEnergy), and a pair deeper than max_depth writes its detail without it.
template <class Real, bool kDetails, bool kBodies = false, bool kBonds = false,
          bool kPeriodic = false>
__global__ void __launch_bounds__(PairKernelShape<Real>::threads, PairKernelShape<Real>::min_blocks)
    pair_forces_kernel(ParticleArrays<Real> p, PairArrays<Real> q, StepParams<Real> sp,
                       StepStatus* status, const std::int32_t* member_body,
                       physics::BondArrays<Real> bonds) {
  const int s = blockIdx.x * blockDim.x + threadIdx.x;
  if (s >= q.count || held_back(sp)) return;
  const int e = q.emitter[s], j = q.partner[s];
  // The split step's passes: the slots of no received particle, then the others.
  const bool on_ghost = sp.received != nullptr && (sp.received[e] | sp.received[j]) != 0;
  if (sp.slots != kAllSlots && on_ghost != (sp.slots == kGhostSlots)) return;
  if constexpr (kBodies || kBonds) {
    if ((kBodies && physics::same_body(member_body, e, j)) ||
        (kBonds && physics::intact_bond_between(bonds, e, j))) {
      q.load[s] = physics::PairLoad<Real>{};
      if constexpr (kDetails) q.detail[s] = physics::PairDetail<Real>{};
      q.slip[s] = physics::PairSlip<Real>{};
      return;
    }
  }
  physics::PairSlip<Real> slip = q.slip[s];
  const physics::LawParameters<Real> law = sp.laws[p.material[e] * sp.n_materials + p.material[j]];
  const Vec2d origin{p.x[e], p.y[e]};
  const physics::PairForce<Real> result = [&] {
    if constexpr (kPeriodic) {
      const physics::PeriodicImage im =
          physics::nearest_image(sp.frame, origin, Vec2d{p.x[j], p.y[j]});
      return physics::SceneContactLaw::force<kDetails>(load_body(p, e, origin),
                                                       load_image_body(p, j, origin, im), law,
                                                       static_cast<Real>(sp.dt), slip);
    } else {
      return physics::SceneContactLaw::force<kDetails>(
          load_body(p, e, origin), load_body(p, j, origin), law, static_cast<Real>(sp.dt), slip);
    }
  }();
  q.load[s] = physics::load_of(result);
  q.slip[s] = slip;
  const bool deep = result.depth > sp.max_depth;
  if (kDetails || deep) q.detail[s] = physics::detail_of(result);
  // The lowest emitter, as the CPU reports it, whatever order the threads run in.
  if (deep) atomicMin(&status->deep, e);
  if (on_ghost && result.touching) status->ghost_touch = 1;
}

/// Lees-Edwards: the image_power of each emitter row (physics::image_power of each pair's
/// force through its partner's image, partners ascending: CpuSolver::compute_pair_forces'
/// sum), after the pair forces and before anything moves. A pair the filters zeroed, or one
/// the skin keeps in the list without touching, adds an exact zero. Thread per particle.
template <class Real>
__global__ void row_image_power_kernel(ParticleArrays<Real> p, PairArrays<Real> q,
                                       StepParams<Real> sp) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= p.n) return;
  const Vec2d origin{p.x[i], p.y[i]};
  double sum = 0;
  for (int s = q.offset[i]; s < q.offset[i + 1]; ++s) {
    const int j = q.partner[s];
    const physics::PeriodicImage im =
        physics::nearest_image(sp.frame, origin, Vec2d{p.x[j], p.y[j]});
    sum += physics::image_power(im, static_cast<double>(q.load[s].force_a.x));
  }
  sp.image_power[i] = sum;
}

template <class Real>
__device__ inline physics::Pose<double> pose(const ParticleArrays<Real>& p, int i) {
  return {{p.x[i], p.y[i]}, p.theta[i], {p.vx[i], p.vy[i]}, p.w[i]};
}

template <class Real>
__device__ inline physics::Pose<double> advanced_pose(const ParticleArrays<Real>& p,
                                                      const StepParams<Real>& sp, int i) {
  return physics::stepped_or_programmed_pose(sp.programs, p.program[i], sp.time_new, pose(p, i),
                                             p.free[i] != 0, Vec2<Real>{p.fx[i], p.fy[i]},
                                             p.torque[i], p.inv_mass[i], p.inv_inertia[i],
                                             sp.gravity, sp.local_damping, sp.dt);
}

/// `wall_velocity(j, v, w)` of row_energy (broadphase/row_energy.hpp): a moving wall's
/// velocity at the step's start.
template <class Real>
__device__ inline auto wall_velocity_of(const ParticleArrays<Real>& p, const StepParams<Real>& sp) {
  return [&p, &sp](std::int64_t j, Vec2d& v, double& w) {
    if (!sp.walls_move || p.free[j] != 0) return false;
    v = {p.vx[j], p.vy[j]};
    w = p.w[j];
    return true;
  };
}

/// Sums the forces of free particles and flags the lowest one whose step would run away
/// (the state is not written yet). A free particle's row energy is summed here too, from
/// the loads just read (`row_step_energy`), so that the integration does not read the
/// row again. With `prescribed`, sums those of the other particles
/// instead: only output needs them (wall forces), and walls can touch thousands of grains.
/// kBodies: the particles are members of bodies, whose runaway test is their body's
/// (body_kernels.cuh), so none is made here. With bonds (bonds.count > 0), each particle adds
/// its bonds' loads after its pairs' (bond_kernels.cuh computed them), as the CPU does.
template <class Real, bool kBodies = false>
__global__ void gather_kernel(ParticleArrays<Real> p, PairArrays<Real> q, StepParams<Real> sp,
                              StepStatus* status, bool prescribed,
                              physics::BondArrays<Real> bonds) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (sp.next_status != nullptr && i == 0) *sp.next_status = StepStatus::fresh();
  if (i >= p.n || (p.free[i] != 0) == prescribed || held_back(sp)) return;
  Vec2<Real> f;
  Real t;
  sum_pair_forces(i, q.offset, q.reverse_offset, q.reverse_slot, q.load, f, t);
  if (bonds.count > 0) physics::add_bond_loads(bonds, i, f, t);
  p.fx[i] = f.x;
  p.fy[i] = f.y;
  p.torque[i] = t;
  if (prescribed || kBodies) return;
  const RowEnergy row = row_energy(i, q.offset, q.partner, q.load, wall_velocity_of(p, sp), sp.dt);
  p.row_step_energy[0][i] = row.damping;
  p.row_step_energy[1][i] = row.friction;
  p.row_step_energy[2][i] = row.wall_work;
  if (physics::runaway_step(advanced_pose(p, sp, i), static_cast<double>(p.half_size[i]), sp.dt))
    atomicMin(&status->bad, i);
}

/// Vertices (about the centroid) and box of particle i at its current pose, by the CPU's
/// rules (physics/local_frame.hpp); flags a rebuild of the pair list when the box has left
/// its build box.
template <class Real>
__device__ inline void update_geometry(const ParticleArrays<Real>& p, int i,
                                       StepStatus* status) {
  Vec2<Real> body_frame[3];
  physics::load_vertices(p.offset_x, p.offset_y, i, body_frame);
  const physics::PlacedBody<Real> placed =
      physics::place_body(Vec2d{p.x[i], p.y[i]}, p.theta[i], body_frame, p.half_size[i]);
  const physics::Aabb<Real>& box = placed.box;
  physics::store_vertices(p.rel_x, p.rel_y, i, placed.rel);
  p.lo_x[i] = box.lo.x;
  p.lo_y[i] = box.lo.y;
  p.hi_x[i] = box.hi.x;
  p.hi_y[i] = box.hi.y;
  const bool inside = box.lo.x >= p.build_lo_x[i] && box.lo.y >= p.build_lo_y[i] &&
                      box.hi.x <= p.build_hi_x[i] && box.hi.y <= p.build_hi_y[i];
  if (!inside) atomicOr(&status->rebuild, 1);
}

/// The energy of particle i's step as the CPU adds it (CpuSolver::add_step_energy): its
/// own row of pairs and, if `is_free`, what local damping took from it (a body's member
/// passes false: its body books the damping once). `gathered`: the gather summed the row
/// (row_step_energy: a free particle without bodies), else it is summed here.
template <class Real>
__device__ inline void add_step_energy(const ParticleArrays<Real>& p, const PairArrays<Real>& q,
                                       const StepParams<Real>& sp, int i, bool is_free,
                                       const physics::Pose<double>& before,
                                       const physics::Pose<double>& after, bool gathered = false) {
  const RowEnergy row =
      gathered
          ? RowEnergy{p.row_step_energy[0][i], p.row_step_energy[1][i], p.row_step_energy[2][i]}
          : row_energy(i, q.offset, q.partner, q.load, wall_velocity_of(p, sp), sp.dt);
  double* const* sums = p.energy;
  tridem::add_step_energy(sums, i, row, is_free, before, after, Vec2<Real>{p.fx[i], p.fy[i]},
                          p.torque[i], p.inv_mass[i], p.inv_inertia[i], sp.gravity,
                          sp.local_damping, sp.dt);
}

/// Lees-Edwards: the boundary's work through particle i's row of pairs this step, added to
/// its wall work after its row's energy (CpuSolver::add_step_energy).
template <class Real>
__device__ inline void add_image_work(const ParticleArrays<Real>& p, const StepParams<Real>& sp,
                                      int i) {
  if (sp.image_power) p.energy[kWallWork][i] += sp.image_power[i] * sp.dt;
}

/// Writes the advanced state (unless some particle ran away or some pair overlaps too
/// deep: then the last good state stays, as on the CPU), adds the step's energy and
/// computes the geometry of the state it leaves. `q` is read only when advancing.
/// kPeriodic: a periodic scene, whose rows book the boundary's work and whose free
/// particles are put back into the cell (StepParams::frame_new) as CpuSolver::integrate
/// does. A free particle's row energy is read from row_step_energy, which only
/// gather_kernel<Real, false> writes: so this kernel is for scenes without bodies (their
/// members step in body_kernels.cuh), launched after that gather in the same step.
template <class Real, bool kPeriodic = false>
__global__ void integrate_kernel(ParticleArrays<Real> p, PairArrays<Real> q, StepParams<Real> sp,
                                 StepStatus* status, bool advance) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= p.n || held_back(sp)) return;
  if (advance) {
    if (status->failed()) return;
    const physics::Pose<double> before = pose(p, i);
    physics::Pose<double> pose = advanced_pose(p, sp, i);
    const bool is_free = p.free[i] != 0;
    add_step_energy(p, q, sp, i, is_free, before, pose, is_free);
    if constexpr (kPeriodic) {
      add_image_work(p, sp, i);
      if (p.free[i] != 0)
        p.energy[kWallWork][i] +=
            physics::wrap_with_work(sp.frame_new, pose, p.inv_mass[i], sp.gravity);
    }
    p.x[i] = pose.c.x;
    p.y[i] = pose.c.y;
    p.theta[i] = pose.theta;
    // A wall's velocity is read by add_step_energy from other threads: a programmed wall's
    // is written by program_velocity_kernel, after this one.
    if (p.free[i] != 0) {
      p.vx[i] = pose.v.x;
      p.vy[i] = pose.v.y;
      p.w[i] = pose.w;
    }
  }
  update_geometry(p, i, status);
}

/// The programmed walls' new velocities (unless the step was refused), once every row's
/// energy has read the old ones: CpuSolver::write_program_velocities. Launched only when
/// some wall has a program.
template <class Real>
__global__ void program_velocity_kernel(ParticleArrays<Real> p, StepParams<Real> sp,
                                        const StepStatus* status) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= p.n || p.program[i] < 0) return;
  if (status->failed()) return;
  Vec2d v;
  double w = 0;
  physics::program_velocity(sp.programs, p.program[i], sp.time_new,
                            Vec2d{static_cast<double>(p.fx[i]), static_cast<double>(p.fy[i])}, v,
                            w);
  p.vx[i] = v.x;
  p.vy[i] = v.y;
  p.w[i] = w;
}

/// The targets of the servos that follow a length (CpuSolver::update_servo_targets): thread
/// per program, from the walls' centroids (x, y: the particles', or the bodies' in a scene
/// with bodies) at the step's start, before the runaway test and the integration read them.
/// Launched only when some servo follows a length.
template <class Real>
__global__ void servo_target_kernel(StepParams<Real> sp, int n_programs, const double* x,
                                    const double* y, double* targets) {
  const int k = blockIdx.x * blockDim.x + threadIdx.x;
  if (k >= n_programs) return;
  const MotionProgram& program = sp.programs.programs[k];
  if (physics::follows_length(program)) targets[k] = physics::servo_target_at(program, x, y);
}

/// The elastic energy of particle i's own row of pairs (the last step's), for energy().
template <class Real>
__global__ void row_elastic_kernel(int n, PairArrays<Real> q, double* out) {
  const int i = blockIdx.x * blockDim.x + threadIdx.x;
  if (i >= n) return;
  double sum = 0;
  for (int s = q.offset[i]; s < q.offset[i + 1]; ++s)
    sum += static_cast<double>(q.detail[s].elastic_energy);
  out[i] = sum;
}

}  // namespace tridem::cuda
