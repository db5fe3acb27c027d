// The checks every backend's load_state makes before touching its state, so that a bad
// state (a checkpoint of another scene, a bug in a backend) is refused with one message
// instead of indexing out of range.
#include "tridem/solver_state.hpp"

#include "tridem/error.hpp"

#include <cmath>
#include <fmt/format.h>

namespace tridem {

namespace {

void check_size(std::size_t got, std::size_t expected, const char* what,
                const std::string& source) {
  if (got != expected)
    throw Error(fmt::format("{}: state has {} values of {} for {} particles", source, got,
                            what, expected));
}

void check_finite(const std::vector<double>& v, const char* what, const std::string& source) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw Error(fmt::format("{}: {} of particle {} is not finite ({})", source, what, i, v[i]));
}

}  // namespace

void validate_solver_state(const SolverState& s, std::size_t particles, std::size_t bodies,
                           const std::string& source) {
  if (s.step < 0) throw Error(fmt::format("{}: negative step {}", source, s.step));
  if (!std::isfinite(s.time) || s.time < 0)
    throw Error(fmt::format("{}: time {} is not a finite time >= 0", source, s.time));
  SolverState::for_each_field([&](auto field) {
    using Field = decltype(field);
    for_each_array(s.column(field), [&](const std::vector<double>& v, int k) {
      if (Field::role == FieldRole::Sum && v.empty()) return;  // zeros
      const std::string what = Field::label(k);
      check_size(v.size(), particles, what.c_str(), source);
      check_finite(v, what.c_str(), source);
    });
  });
  SolverState::for_each_body_column([&](auto field) {
    const std::vector<double>& v = s.column(field);
    const std::string what = std::string("body ") + decltype(field)::name;
    if (v.size() != bodies)
      throw Error(fmt::format("{}: state has {} values of {} for {} bodies of several "
                              "triangles (a checkpoint of another scene?)",
                              source, v.size(), what, bodies));
    for (std::size_t b = 0; b < v.size(); ++b)
      if (!std::isfinite(v[b]))
        throw Error(fmt::format("{}: {} of body {} is not finite ({})", source, what, b, v[b]));
  });
  // An order names every particle (and body) or none; the solver that takes it up checks
  // that it is one it could have (core/place_numbered_solver).
  const bool ordered = !s.particle_order.empty() || !s.body_order.empty();
  if (ordered && s.particle_order.size() != particles)
    throw Error(fmt::format("{}: state has a particle order of {} entries for {} particles (a "
                            "checkpoint of another scene?)",
                            source, s.particle_order.size(), particles));
  if (ordered && s.body_order.size() != bodies)
    throw Error(fmt::format("{}: state has a bodies' order of {} entries for {} bodies of "
                            "several triangles (a checkpoint of another scene?)",
                            source, s.body_order.size(), bodies));
  const std::size_t m = s.pair_emitter.size();
  for_each_pair_history_field([&](auto field) {
    if (s.column(field).size() != m)
      throw Error(fmt::format("{}: contact history arrays differ in length ({} emitters, {} "
                              "{})",
                              source, m, s.column(field).size(), decltype(field)::name));
  });
  const auto n = static_cast<std::int64_t>(particles);
  for (std::size_t k = 0; k < m; ++k) {
    const std::int64_t e = s.pair_emitter[k], p = s.pair_partner[k];
    if (e < 0 || e >= n || p < 0 || p >= n || e == p)
      throw Error(fmt::format("{}: contact history pair {} ({}, {}) is not a pair of two "
                              "particles among 0..{}",
                              source, k, e, p, n - 1));
    if (k > 0) {
      const std::int64_t pe = s.pair_emitter[k - 1], pp = s.pair_partner[k - 1];
      if (e < pe || (e == pe && p <= pp))
        throw Error(fmt::format("{}: contact history pair {} ({}, {}) is out of order after "
                                "({}, {}): pairs must be sorted by emitter, then partner, "
                                "without repeats",
                                source, k, e, p, pe, pp));
    }
    for (double slip : s.pair_slip[k])
      if (!std::isfinite(slip))
        throw Error(fmt::format("{}: contact history pair {} ({}, {}) has a non-finite slip",
                                source, k, e, p));
  }
}

void validate_bond_state(const SolverState& s, std::size_t bonds, const std::string& source) {
  if (s.bond_dissipated.size() != bonds ||
      s.bond_damage.size() != bonds * SolverState::kBondStatePoints)
    throw Error(fmt::format("{}: state has {} bonds' energies and {} damage values for a scene "
                            "of {} cohesive bonds (a checkpoint of another scene, or one "
                            "written before bonds were checkpointed?)",
                            source, s.bond_dissipated.size(), s.bond_damage.size(), bonds));
  for (std::size_t k = 0; k < s.bond_damage.size(); ++k)
    if (!(s.bond_damage[k] >= 0 && s.bond_damage[k] <= 1))
      throw Error(fmt::format("{}: damage {} of bond {} is not in [0, 1]", source, s.bond_damage[k],
                              k / SolverState::kBondStatePoints));
  for (std::size_t k = 0; k < bonds; ++k)
    if (!(std::isfinite(s.bond_dissipated[k]) && s.bond_dissipated[k] >= 0))
      throw Error(fmt::format("{}: dissipated energy {} of bond {} is not finite and >= 0", source,
                              s.bond_dissipated[k], k));
}

}  // namespace tridem
