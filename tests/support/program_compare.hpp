#pragma once
// A run with motion programs and servo walls against the serial reference, step by step
// (the GPU parity tests of parity/gpu_program_parity_test.cpp, and their CPU checks in
// validation/unstable_parity_test.cpp, which give it wrong solvers to prove it fails).
//  - expect_runs_agree: pointwise, to the fixed tolerances of support/gpu_compare.hpp, for
//    a scene that keeps rounding at rounding size (a settled one).
//  - expect_runs_agree_within_rounding: for a pile whose contacts open and close, which
//    parts from any run of other rounding from its first contacts and then about tenfold
//    per 50-100 steps: each tolerance grows to kEnvelope times the spread of a rounding
//    twin that kicks positions too (support/rounding_twin.hpp), compared every `every`
//    steps so that the envelope is checked while it grows, not only once it has saturated.
#include "support/gpu_compare.hpp"
#include "support/rounding_twin.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>

namespace tridem::test {

/// How many times the twin's spread a run of other rounding may part from the reference
/// (the bond parity tests' kEnvelope, whose measured GPU/twin ratio was 4-12 in double).
constexpr double kProgramEnvelope = 50;

/// `tried` against `reference` every `every` steps up to `steps`, to the fixed tolerances.
inline void expect_runs_agree(Solver& reference, Solver& tried, std::int64_t steps,
                              std::int64_t every) {
  Snapshot a, b;
  for (std::int64_t s = every; s <= steps; s += every) {
    reference.advance(every);
    tried.advance(every);
    reference.snapshot(a, true);
    tried.snapshot(b, true);
    const std::string what = "step " + std::to_string(s);
    expect_agreement(a, b, what.c_str());
  }
}

/// The largest difference of the forces on the walls (particles not free), N/m.
inline double max_wall_force_difference(const Snapshot& a, const Snapshot& b) {
  double d = 0;
  for (std::size_t i = 0; i < a.size() && i < b.size(); ++i)
    if (a.motion[i] != Motion::Free)
      d = std::max({d, std::abs(a.fx[i] - b.fx[i]), std::abs(a.fy[i] - b.fy[i])});
  return d;
}

/// `tried` against `reference`, within kProgramEnvelope times `twin`'s spread where that is
/// larger than the fixed tolerances; `twin` is a twin of the reference at its step 0.
inline void expect_runs_agree_within_rounding(Solver& reference, Solver& tried, RoundingTwin& twin,
                                              std::int64_t steps, std::int64_t every) {
  Snapshot a, b;
  double twin_wall_force = 0;
  for (std::int64_t s = every; s <= steps; s += every) {
    reference.advance(every);
    tried.advance(every);
    twin.advance(every);
    reference.snapshot(a, true);
    tried.snapshot(b, true);
    ASSERT_EQ(a.size(), b.size());
    const Difference spread = twin.spread_from(a);
    twin_wall_force = std::max(twin_wall_force, max_wall_force_difference(a, twin.snapshot()));
    const Difference d = max_difference(a, b);
    const double dx = std::max(kPositionTolerance, kProgramEnvelope * spread.position);
    const double da = std::max(kAngleTolerance, kProgramEnvelope * spread.angle);
    const double dv = std::max(kVelocityTolerance, kProgramEnvelope * spread.velocity);
    const std::string what = "step " + std::to_string(s);
    std::printf("%s: max |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s, wall |dF| %.3g N/m; "
                "rounding twin |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s, wall |dF| %.3g "
                "N/m; contacts %zu/%zu\n",
                what.c_str(), d.position, d.angle, d.velocity, max_wall_force_difference(a, b),
                spread.position, spread.angle, spread.velocity, twin_wall_force, a.contacts.size(),
                b.contacts.size());
    EXPECT_LE(d.position, dx) << what;
    EXPECT_LE(d.angle, da) << what;
    EXPECT_LE(d.velocity, dv) << what;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a.motion[i] != Motion::Free) {
        const double df =
            std::max(1e-6 * (1 + std::hypot(a.fx[i], a.fy[i])), kProgramEnvelope * twin_wall_force);
        EXPECT_NEAR(a.fx[i], b.fx[i], df) << what << ": wall " << i;
        EXPECT_NEAR(a.fy[i], b.fy[i], df) << what << ": wall " << i;
      }
  }
}

}  // namespace tridem::test
