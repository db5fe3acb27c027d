#pragma once
// What kernels receive: plain structs of device pointers, passed by value. The particle
// data is a structure of arrays, so that the threads of a warp, handling consecutive
// particles, read consecutive addresses.
#include "physics/contact_laws.hpp"
#include "tridem/energy_budget.hpp"

#include <cstdint>

namespace tridem::cuda {

template <class Real>
struct ParticleArrays {
  int n;
  // Fixed per particle.
  const Real* offset_x[3];
  const Real* offset_y[3];
  const double* inv_mass;     ///< the integration is double in every precision
  const double* inv_inertia;
  const Real* mass;  ///< 0 for bodies moved by prescription
  const Real* area;
  const Real* half_size;
  const int* material;
  const std::uint8_t* free;   ///< 1 for bodies moved by forces
  // State: double in every precision (docs/model.md, "Precision").
  double *x, *y, *theta, *vx, *vy, *w;
  Real *fx, *fy, *torque;
  // Geometry of the current state: vertices relative to the centroid, bounding box.
  Real* rel_x[3];
  Real* rel_y[3];
  Real *lo_x, *lo_y, *hi_x, *hi_y;
  // The boxes of the last pair-list build, grown by the skin: while every current box lies
  // inside its build box, the list holds every pair whose boxes overlap.
  Real *build_lo_x, *build_lo_y, *build_hi_x, *build_hi_y;
  // The energy budget's cumulative sums, per particle (EnergyAccumulator order), in double
  // whatever Real is: they add small amounts to a growing total for the whole run.
  double* energy[kEnergyAccumulators];
};

/// Candidate pairs in compressed rows by emitter (partners ascending), as on the CPU
/// (broadphase/pair_list.hpp), plus the emitter of each slot for one-thread-per-pair work
/// and the reverse index (the slots where a particle is the partner, ascending).
template <class Real>
struct PairArrays {
  int count;
  const int* offset;  ///< n + 1
  const int* partner;
  const int* emitter;
  physics::PairSlip<Real>* slip;
  physics::PairForce<Real>* result;
  const int* reverse_offset;  ///< n + 1
  const int* reverse_slot;
};

template <class Real>
struct StepParams {
  double dt;              ///< the integration's; pairs take it rounded to Real
  Vec2d gravity;
  double local_damping;
  const physics::LawParameters<Real>* laws;  ///< row-major by material pair
  int n_materials;
  Real max_depth;  ///< deepest PairForce::depth accepted ([simulation] max_penetration)
  bool walls_move;  ///< some fixed or prescribed particle has a velocity (does work)
};

/// What the host reads back after every step.
struct StepStatus {
  int rebuild;  ///< 1 when some particle has left its build box
  int bad;      ///< lowest particle whose step ran away, or INT_MAX
  int deep;     ///< lowest emitter of a pair deeper than max_depth, or INT_MAX
};

}  // namespace tridem::cuda
