#pragma once
// The local solver of one MPI rank (src/mpi/, docs/scaling.md): a Solver stepping the
// particles of its strip, their ghosts and the walls, and what the decomposition needs of
// it besides: the step split at its Check (the ranks agree there that every rank's step
// is good before any rank writes it), the ghosts' states packed and written in bulk, the
// drift test, and the last step's pairs and energies by local index. CPU ranks
// (mpi/cpu_rank.hpp) and GPU ranks (backends/cuda/cuda_rank.cu) implement it. Plain C++:
// no MPI and no CUDA types, so that either side compiles without the other.
#include "core/ghost_overlap.hpp"
#include "physics/contact_force.hpp"
#include "tridem/body_fields.hpp"
#include "tridem/particle_fields.hpp"
#include "tridem/solver.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace tridem {

/// Doubles a particle's State fields take in an exchange buffer (x, y, theta, vx, vy, w).
inline int state_array_count() {
  int count = 0;
  for_each_particle_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State) count += decltype(field)::count;
  });
  return count;
}

template <class Real>
class RankSolver {
 public:
  virtual ~RankSolver() = default;

  virtual Solver& solver() = 0;
  virtual const Solver& solver() const = 0;

  /// Called after every step's Check, before anything is written; it may throw RunError.
  virtual void set_check_hook(std::function<void()> hook) = 0;

  /// A plan's exchange: the local particles whose State leaves this rank at each exchange
  /// and those whose State arrives (each in buffer order), and those this rank owns (the
  /// drift test starts from their centroids now).
  virtual void set_plan(const std::vector<std::int32_t>& send,
                        const std::vector<std::int32_t>& receive,
                        const std::vector<std::int32_t>& own) = 0;
  /// Host buffers of the exchange, state_array_count() doubles per particle: its State
  /// arrays in the order of particle_fields.hpp.
  virtual double* send_buffer() = 0;
  virtual double* receive_buffer() = 0;
  /// The sent particles' State into send_buffer() (complete on return).
  virtual void pack() = 0;
  /// receive_buffer() into the received particles' State, and what follows from it (a GPU
  /// rank's geometry of the new state).
  virtual void unpack() = 0;
  /// Bodies of several triangles: the
  /// local bodies whose State leaves this rank at each exchange and those whose State
  /// arrives, in buffer order, and their buffers, kBodyStateArrays doubles per body; pack
  /// and unpack carry them with the particles'.
  static constexpr int kBodyStateArrays = 0 TRIDEM_BODY_STATE_FIELDS(TRIDEM_PLUS_COUNT);
  virtual void set_body_plan(const std::vector<std::int32_t>& send,
                             const std::vector<std::int32_t>& receive) = 0;
  virtual double* body_send_buffer() = 0;
  virtual double* body_receive_buffer() = 0;
  /// Whether an owned particle has moved more than `limit` since set_plan, or is not finite.
  virtual bool drifted(double limit) const = 0;

  /// Local particle i's energy accumulator k at out[i * kEnergyAccumulators + k].
  virtual void energy_sums(std::vector<double>& out) const = 0;
  using PairVisitor = std::function<void(std::int32_t emitter, std::int32_t partner,
                                         const physics::PairForce<Real>&)>;
  /// f for each pair of the last completed step, by local index, in slot order (none before
  /// the first step).
  virtual void for_each_last_pair(const PairVisitor& f) const = 0;
  /// From the check hook: f for each pair of the step in progress, its forces computed, by
  /// local index in slot order (GPU ranks visit only the pairs with a servo wall, all
  /// that the servos' sums read).
  virtual void for_each_step_pair(const PairVisitor& f) const = 0;
  /// From the check hook: local particle i's force and torque for the rest of the step
  /// (a servo wall's load summed across ranks, which its program reads).
  virtual void set_load(std::int32_t i, Vec2<Real> force, Real torque) = 0;
  /// Cohesive bonds: f(local bond, its elastic energy of the last step (0
  /// before the first), the energy it has released) for each local bond, in order.
  virtual void bond_terms(const std::function<void(std::size_t, double, double)>& f) const = 0;
  /// The elastic energy in the terms the backend's energy() adds: f(emitter, partner, value)
  /// per pair (the CPU adds pair by pair), or f(emitter, -1, sum) per row (CUDA adds each
  /// row's sum). Added in ascending (emitter, partner) order they give that total.
  virtual void elastic_terms(
      const std::function<void(std::int32_t emitter, std::int32_t partner, double)>& f) const = 0;

  /// The exchange overlapped with the step (docs/scaling.md, "Overlap"): whether this rank's
  /// solver takes the ghosts' states in the middle of its steps, after the pairs of its own
  /// particles, by calling `take` (which completes the exchange started after the last step
  /// and runs unpack()), and `poll` now and then before; false (the default): the exchange
  /// completes between steps. Called after set_plan.
  virtual bool take_ghosts_mid_step(const std::function<void()>& take,
                                    const std::function<void()>& poll) {
    (void)take;
    (void)poll;
    return false;
  }
  /// What the overlap did on this rank since its plan (zeros without).
  virtual GhostOverlapCounts overlap_counts() const { return {}; }

  /// How the ghosts reach MPI, for the start line ("host memory", "pinned host memory,
  /// packed on the GPU").
  virtual std::string transport() const = 0;
};

}  // namespace tridem
