#pragma once
// A fixed hash of everything a run ends with, so that a test can pin a backend's results
// to one constant (regression/state_hash_test.cpp): any change of any bit shows.
//
// The hash is FNV-1a, 64 bits (offset basis 0xcbf29ce484222325, prime 0x100000001b3),
// over a byte stream that does not depend on the machine: every value is written as its
// IEEE-754 or two's-complement bit pattern, little-endian, at its own width (double and
// int64 8 bytes, int32 4, Motion 1), and every array is preceded by its length (8 bytes).
// The stream, in this order:
//   step, time;
//   the snapshot's per-particle arrays x, y, theta, vx, vy, omega, fx, fy, torque,
//   x1, y1, x2, y2, x3, y3, mass, inertia, material, motion;
//   the contact records, each i, j, fx, fy, px, py, in the snapshot's order;
//   the saved state's contact history, each pair emitter, partner, slip[0], slip[1];
//   the four per-particle energy accumulators (EnergyAccumulator order);
//   the energy budget elastic, dissipated_damping, dissipated_friction,
//   dissipated_local, wall_work.
// Changing the stream changes every recorded constant: do it only with all of them.
#include "tridem/energy_budget.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <bit>
#include <cstdint>
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

namespace tridem::test {

class Fnv1a64 {
 public:
  static constexpr std::uint64_t kOffsetBasis = 0xcbf29ce484222325ULL;
  static constexpr std::uint64_t kPrime = 0x100000001b3ULL;

  /// One value's bit pattern, little-endian, sizeof(T) bytes.
  template <class T>
  void add(T value) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) <= 8);
    std::uint64_t bits = 0;
    if constexpr (std::is_enum_v<T>)
      bits = static_cast<std::uint64_t>(static_cast<std::underlying_type_t<T>>(value));
    else if constexpr (std::is_floating_point_v<T>)
      bits = std::bit_cast<std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>>(value);
    else
      bits = static_cast<std::uint64_t>(static_cast<std::make_unsigned_t<T>>(value));
    for (std::size_t k = 0; k < sizeof(T); ++k) byte(static_cast<unsigned char>(bits >> (8 * k)));
  }

  /// The array's length, then its values in index order.
  template <class T>
  void add_array(const std::vector<T>& values) {
    add(static_cast<std::uint64_t>(values.size()));
    for (const T& v : values) add(v);
  }

  std::uint64_t value() const { return hash_; }

 private:
  void byte(unsigned char b) {
    hash_ ^= b;
    hash_ *= kPrime;
  }

  std::uint64_t hash_ = kOffsetBasis;
};

/// The hash of a run's end, by the stream documented above. `snapshot` must be taken
/// with contacts.
inline std::uint64_t state_hash(const Snapshot& snapshot, const SolverState& state,
                                const EnergyBudget& energy) {
  Fnv1a64 h;
  h.add(snapshot.step);
  h.add(snapshot.time);
  for (const auto* a : {&snapshot.x, &snapshot.y, &snapshot.theta, &snapshot.vx, &snapshot.vy,
                        &snapshot.omega, &snapshot.fx, &snapshot.fy, &snapshot.torque,
                        &snapshot.x1, &snapshot.y1, &snapshot.x2, &snapshot.y2, &snapshot.x3,
                        &snapshot.y3, &snapshot.mass, &snapshot.inertia})
    h.add_array(*a);
  h.add_array(snapshot.material);
  h.add_array(snapshot.motion);
  h.add(static_cast<std::uint64_t>(snapshot.contacts.size()));
  for (const ContactRecord& c : snapshot.contacts) {
    h.add(c.i);
    h.add(c.j);
    h.add(c.fx);
    h.add(c.fy);
    h.add(c.px);
    h.add(c.py);
  }
  h.add(static_cast<std::uint64_t>(state.pairs()));
  for (std::size_t k = 0; k < state.pairs(); ++k) {
    h.add(state.pair_emitter[k]);
    h.add(state.pair_partner[k]);
    for (double s : state.pair_slip[k]) h.add(s);
  }
  for (const auto& sums : state.energy) h.add_array(sums);
  for (double e : {energy.elastic, energy.dissipated_damping, energy.dissipated_friction,
                   energy.dissipated_local, energy.wall_work})
    h.add(e);
  return h.value();
}

/// The hash of the solver's current state (snapshot with contacts, saved state, energy).
inline std::uint64_t state_hash(const Solver& solver) {
  Snapshot snapshot;
  solver.snapshot(snapshot, true);
  SolverState state;
  solver.save_state(state);
  return state_hash(snapshot, state, solver.energy());
}

/// "0x0123456789abcdef": how a hash is printed and written in a test's table.
inline std::string hash_text(std::uint64_t hash) {
  char text[19];
  std::snprintf(text, sizeof text, "0x%016llx", static_cast<unsigned long long>(hash));
  return text;
}

}  // namespace tridem::test
