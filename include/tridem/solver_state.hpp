#pragma once
// Everything a solver needs to continue a run exactly: the state a checkpoint stores.
//
// The contract every backend keeps (save_state / load_state in solver.hpp):
//  - Values are the solver's own, stored in double: the state (positions, angles,
//    velocities) is double in every precision (mixed precision, docs/model.md), and the
//    slips are the solver's Real (float -> double -> float is exact), so a float run
//    restarted from its state is bit-identical too.
//  - Per-particle arrays (x, y, theta, vx, vy, omega) have one entry per particle, in id
//    order. Forces are not state: each step recomputes them before integrating.
//  - The contact history is the tangential spring state u = √k_t·ξ of the pairs of the
//    last completed step (physics::PairSlip), as three parallel arrays in emitter-major,
//    partner-ascending order (strictly increasing (emitter, partner)); the emitter of a
//    pair is the one that computes it (see ARCHITECTURE.md). Only pairs with a history
//    other than +0.0 need to be listed: a pair that is absent starts from zero, exactly as
//    a new contact does.
//  - The energy budget's cumulative sums (dissipations, wall work) are kept per particle,
//    as the solver accumulates them, so that a restarted run sums them in the same order
//    and writes the same energy.csv: energy[k] has one entry per particle, or is empty
//    for zeros (k indexes EnergyAccumulator).
//  - Bodies of several triangles (tridem/body_fields.hpp): the pose and velocities of each
//    body (body_x, ..., body_omega), one entry per body in Scene::bodies order, all empty
//    when the scene has no body of several triangles. The members' per-particle state is
//    stored as well (it is what the body's pose places them at, bit for bit).
//  - Cohesive bonds (docs/fracture.md), in Scene::bonds order, both empty without bonds:
//    bond_damage, the damage of each bond's points (kBondStatePoints per bond, bond-major;
//    a bond whose points are all 1 is broken), and bond_dissipated, the energy each bond's
//    damage released so far (J/m).
//  - The order the solver keeps its particles in, when it renumbered them by place
//    (core/place_numbered_solver): particle_order[k] is the scene id of its particle k,
//    body_order[k] that of its body k (bodies of several triangles). Both empty for the
//    scene's order or the one the solver picks from the scene alone. Everything else stays
//    in the scene's ids whatever the order; a solver that cannot use an order ignores it.
//  - load_state(save_state()) followed by advance(n) gives, bit for bit, what advance(n)
//    would have given without the round trip.
#include "tridem/body_fields.hpp"
#include "tridem/particle_fields.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace tridem {

/// The checkpointed fields of tridem/particle_fields.hpp (State, then Sum) under their
/// public names (x, y, theta, vx, vy, omega, energy), and the contact history.
struct SolverState {
  std::int64_t step = 0;
  double time = 0;
  /// x, y, theta, vx, vy, omega, energy; column(field), for_each_field(f) in checkpoint
  /// order, kArraysPerParticle.
  TRIDEM_PUBLIC_COLUMNS(TRIDEM_CHECKPOINTED_FIELDS)
  /// body_x, body_y, body_theta, body_vx, body_vy, body_omega: one entry per body, or
  /// empty without bodies of several triangles; column(body_field), for_each_body_column(f).
  TRIDEM_BODY_PUBLIC_COLUMNS(TRIDEM_BODY_CHECKPOINTED_FIELDS)
  TRIDEM_PAIR_HISTORY_FIELDS(TRIDEM_DECLARE_PAIR_COLUMN)
  TRIDEM_PAIR_HISTORY_FIELDS(TRIDEM_PAIR_COLUMN_ACCESSOR)

  std::vector<double> bond_damage;
  std::vector<double> bond_dissipated;

  std::vector<std::int32_t> particle_order;
  std::vector<std::int32_t> body_order;

  std::size_t size() const { return x.size(); }
  std::size_t bonds() const { return bond_dissipated.size(); }
  /// The points of a bond whose damage is kept (physics::kBondPoints).
  static constexpr std::size_t kBondStatePoints = 2;
  std::size_t bodies() const { return body_x.size(); }
  /// Arrays per body.
  static constexpr int kArraysPerBody = 0 TRIDEM_BODY_CHECKPOINTED_FIELDS(TRIDEM_PLUS_COUNT);
  std::size_t pairs() const { return pair_emitter.size(); }
  /// Bytes of one pair's history.
  static constexpr std::size_t kBytesPerPair = 0 TRIDEM_PAIR_HISTORY_FIELDS(TRIDEM_PAIR_BYTES);
};

/// Checks `state` against a solver of `particles` particles and `bodies` bodies of several
/// triangles (0 without): array sizes, pair indices in range and distinct, pairs strictly
/// sorted, values finite. Throws tridem::Error naming the first problem, prefixed by
/// `source` (a file name, or the solver's name).
void validate_solver_state(const SolverState& state, std::size_t particles, std::size_t bodies,
                           const std::string& source);

/// Checks the bonds' part of `state` against a solver of `bonds` bonds: sizes, damage in
/// [0, 1], dissipated energy finite and >= 0. Throws tridem::Error prefixed by `source`.
void validate_bond_state(const SolverState& state, std::size_t bonds, const std::string& source);

}  // namespace tridem
