#pragma once
// The kernels of the cohesive bonds (docs/fracture.md), thin over the shared rules of
// physics/bond_step.hpp: each bond's force in the same step as the contacts (thread per
// bond, its result in its own slot: no atomics), which gather_kernel then adds to each
// particle after its pairs, its bonds ascending (CpuSolver's order); the step's damage
// written once the step is accepted (thread per bond); and each bond's elastic energy for
// energy(). Scenes without bonds never launch them.
#include "backends/cuda/device_views.cuh"
#include "physics/bond_step.hpp"
#include "physics/local_frame.hpp"

#include <climits>

namespace tridem::cuda {

/// Bond k's force of this step, in the frame of a's centroid as for a pair (CpuSolver's
/// compute_bond_forces); kPeriodic: b at its nearest image in `frame`.
template <class Real, bool kPeriodic = false>
__global__ void bond_forces_kernel(ParticleArrays<Real> p, physics::BondArrays<Real> v,
                                   physics::PeriodicFrame frame) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= v.count) return;
  const int a = v.a[k], b = v.b[k];
  const Vec2d origin{p.x[a], p.y[a]}, cb{p.x[b], p.y[b]};
  if constexpr (kPeriodic)
    v.result[k] = physics::step_bond(
        v, k, physics::image_offset<Real>(origin, cb, physics::nearest_image(frame, origin, cb)),
        p.theta[a], p.theta[b]);
  else
    v.result[k] =
        physics::step_bond(v, k, physics::offset_from<Real>(origin, cb), p.theta[a], p.theta[b]);
}

/// The step's damage, broken flags and released energy, unless the step was refused (a
/// runaway or a too-deep pair: the last good damage stays, as on the CPU).
template <class Real>
__global__ void commit_bonds_kernel(physics::BondArrays<Real> v, const StepStatus* status) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= v.count) return;
  if (status->failed()) return;
  physics::commit_bond(v, k);
}

/// Each bond's elastic energy of the last step, in double, for the host's ordered sum.
template <class Real>
__global__ void bond_elastic_kernel(physics::BondArrays<Real> v, double* out) {
  const std::int64_t k = static_cast<std::int64_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (k >= v.count) return;
  out[k] = static_cast<double>(v.result[k].elastic);
}

}  // namespace tridem::cuda
