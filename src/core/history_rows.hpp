#pragma once
// The contact history between a backend's pair rows (by emitter, partners ascending, one
// PairSlip per slot) and a SolverState's three arrays. Both backends keep their rows in
// this shape, so save_state and load_state differ only in where the rows live.
#include "physics/contact_force.hpp"
#include "tridem/solver_state.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

namespace tridem {

static_assert(kSlipsPerPair == physics::kHistoryValues);

/// +0.0 is the slip of a pair without history; anything else, -0.0 included, must be kept
/// for the restarted run to be bit-identical.
template <class Real>
bool has_history(const physics::PairSlip<Real>& slip) {
  for (Real s : slip.s)
    if (s != Real(0) || std::signbit(s)) return true;
  return false;
}

/// Appends the pairs of rows 0..n that carry history to `out` (already in the contract's
/// emitter-major, partner-ascending order).
template <class Offset, class Real>
void append_history(SolverState& out, std::size_t n, const Offset* offset,
                    const std::int32_t* partner, const physics::PairSlip<Real>* slip) {
  out.pair_emitter.clear();
  out.pair_partner.clear();
  out.pair_slip.clear();
  for (std::size_t e = 0; e < n; ++e)
    for (Offset s = offset[e]; s < offset[e + 1]; ++s) {
      if (!has_history(slip[s])) continue;
      std::array<double, kSlipsPerPair> values{};
      for (int k = 0; k < kSlipsPerPair; ++k) values[k] = static_cast<double>(slip[s].s[k]);
      out.pair_emitter.push_back(static_cast<std::int32_t>(e));
      out.pair_partner.push_back(partner[s]);
      out.pair_slip.push_back(values);
    }
}

/// The rows of a validated state's history: offset has n + 1 entries, partner and slip one
/// per pair.
template <class Offset, class Real>
void history_rows(const SolverState& in, std::size_t n, std::vector<Offset>& offset,
                  std::vector<std::int32_t>& partner, std::vector<physics::PairSlip<Real>>& slip) {
  const std::size_t m = in.pairs();
  offset.assign(n + 1, 0);
  for (std::int32_t e : in.pair_emitter) ++offset[static_cast<std::size_t>(e) + 1];
  for (std::size_t i = 0; i < n; ++i) offset[i + 1] += offset[i];
  partner.assign(in.pair_partner.begin(), in.pair_partner.end());
  slip.resize(m);
  for (std::size_t s = 0; s < m; ++s)
    for (int k = 0; k < kSlipsPerPair; ++k) slip[s].s[k] = static_cast<Real>(in.pair_slip[s][k]);
}

}  // namespace tridem
