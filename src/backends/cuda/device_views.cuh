#pragma once
// What kernels receive: plain structs of device pointers, passed by value. The particle
// data is a structure of arrays, so that the threads of a warp, handling consecutive
// particles, read consecutive addresses.
#include "physics/contact_laws.hpp"
#include "physics/motion_program.hpp"
#include "physics/pair_record.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/energy_budget.hpp"
#include "tridem/particle_fields.hpp"

#include <climits>
#include <cstdint>

namespace tridem::cuda {

/// Every field of the CUDA solver (tridem/particle_fields.hpp: the fields both backends
/// keep, then its own): `const Real* offset_x[3]`, `double* x`, `double* energy[4]`, ...
/// Model fields are const: no kernel writes them.
template <class Real>
struct ParticleArrays {
  int n;
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_DECLARE_POINTERS)

  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_COLUMN_ACCESSOR)
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
  physics::PairLoad<Real>* load;      ///< what every step reads of a pair's result
  physics::PairDetail<Real>* detail;  ///< the rest: written only when StepParams::details
  const int* reverse_offset;  ///< n + 1
  const int* reverse_slot;
};

/// What the host reads back after every step.
struct StepStatus {
  int rebuild;      ///< 1 when some particle has left its build box
  int bad;          ///< lowest particle whose step ran away, or INT_MAX
  int deep;         ///< lowest emitter of a pair deeper than max_depth, or INT_MAX
  int ghost_touch;  ///< 1 when a pair on a received particle touched (the split step's count)

  /// A step's status before any thread has written to it.
  __host__ __device__ static StepStatus fresh() { return {0, INT_MAX, INT_MAX, 0}; }
  /// The step ran away or overlapped too deep: its state is not written, the run stops.
  __host__ __device__ bool failed() const { return bad != INT_MAX || deep != INT_MAX; }
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
  /// The walls' motion programs (uploaded once) and the time the step reaches, set before
  /// each step from its index (physics::time_after_step).
  physics::ProgramTable programs;
  double time_new;
  /// This step's results will be read (the last step of an advance() call): the pairs
  /// write their PairDetail too. A pair deeper than max_depth always writes it.
  bool details;
  /// Periodic boundaries (physics/periodic_frame.hpp; read only by the kernels compiled
  /// for a periodic scene): the cell at the step's start, which the pairs see their
  /// partners' images in, and at its end, which the integration wraps into.
  physics::PeriodicFrame frame;
  physics::PeriodicFrame frame_new;
  /// Lees-Edwards only (else null): each emitter row's image_power of this step, booked
  /// as wall work when the step is written (CpuSolver's image_power_).
  double* image_power;
  /// The split step of MPI ranks (docs/scaling.md, "Overlap"; else null): a flag per
  /// particle whose State arrives from another rank (a touching pair on one sets
  /// StepStatus::ghost_touch), and which slots this launch of the pair kernel computes:
  /// kAllSlots, kOwnSlots (no received particle) or kGhostSlots.
  const std::uint8_t* received;
  int slots;
  /// Run-ahead (CudaSolver::advance_ahead; else null): the status of the step before this
  /// one, which the host had not read when it launched this one. If that step failed or
  /// asked for a new pair list, this one does nothing (held_back) and the host launches it
  /// again once it has read why.
  const StepStatus* gate;
  /// Run-ahead: the status the next step will write, reset by this step's gather. It is
  /// the status of the step two before this one (three take turns), whose last readers,
  /// its copy to the host and the gates of the step after it, came earlier on the stream.
  StepStatus* next_status;
};

constexpr int kAllSlots = 0, kOwnSlots = 1, kGhostSlots = 2;

}  // namespace tridem::cuda
