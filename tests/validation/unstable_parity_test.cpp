// The comparisons of the GPU parity tests of unstable runs, checked on the CPU, where a run
// of other rounding is the serial solver of the scene moved by an offset
// (support/shifted_run.hpp): each comparison must let that run pass, and must fail a
// solver that is wrong by a little (a servo of another gain, one that ignores the length
// it follows, bonds 5 % weaker), so that the GPU tests built on them still catch a bug.
//  - The servo box (support/program_scenes.hpp): its pile of 5 rows parts from any run of
//    other rounding from its first contacts, tenfold per 50-100 steps (H200); the settled
//    box of kSettledServoRows rows keeps rounding at rounding size, so it is compared
//    pointwise (support/program_compare.hpp).
//  - The loaded bonded disc in float (support/bond_compare.hpp): pointwise over
//    kFloatPointwiseSteps, then by the fracture's statistics.
#include "support/bond_compare.hpp"
#include "support/bonded_disc.hpp"
#include "support/program_compare.hpp"
#include "support/program_scenes.hpp"
#include "support/rounding_twin.hpp"
#include "support/shifted_run.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

namespace tridem {
namespace {

/// Not a power of two, so that every coordinate rounds otherwise.
constexpr Vec2d kOffset{0.0123456789, 0.00987654321};

std::unique_ptr<Solver> moved(const Scene& s, const test::SolverChoice& choice = Backend::Cpu) {
  return std::make_unique<test::ShiftedSolver>(
      test::solver_for(test::shifted_scene(s, kOffset), choice), kOffset);
}

/// The servo box with its side servo's gain off by 1 %.
Scene other_gain(Scene s) {
  s.programs[0].gain *= 1.01;
  return s;
}

constexpr std::int64_t kServoSteps = 3000;

TEST(UnstableParity, SettledServoBoxKeepsRoundingAtRoundingSize) {
  for (const Scene& s : {test::settled_servo_box(false), test::settled_servo_box(true)}) {
    auto reference = make_solver(s, {});
    test::RoundingTwin twin(make_solver(s, {}), 0x1p-53,
                            test::RoundingTwin::Kicks::VelocitiesAndPositions);
    reference->advance(kServoSteps);
    twin.advance(kServoSteps);
    Snapshot a;
    reference->snapshot(a, true);
    const test::Difference d = twin.spread_from(a);
    std::printf("settled servo box%s: rounding twin |dx| %.3g m, |dv| %.3g m/s at step %lld\n",
                s.bodies.empty() ? "" : " of bodies", d.position, d.velocity,
                static_cast<long long>(kServoSteps));
    EXPECT_LT(d.position, test::kPositionTolerance / 100);
    EXPECT_LT(d.angle, test::kAngleTolerance / 100);
    EXPECT_LT(d.velocity, test::kVelocityTolerance / 100);
  }
}

TEST(UnstableParity, SettledServoBoxComparisonPassesOtherRoundingAndFailsAWrongServo) {
  for (const bool bodies : {false, true}) {
    const Scene s = test::settled_servo_box(bodies);
    {
      auto reference = make_solver(s, {});
      auto tried = moved(s);
      test::expect_runs_agree(*reference, *tried, kServoSteps, 1000);
    }
    {
      auto reference = make_solver(s, {});
      auto tried = make_solver(other_gain(s), {});
      EXPECT_NONFATAL_FAILURE(test::expect_runs_agree(*reference, *tried, kServoSteps, 1000),
                              "step");
    }
    {
      // The same box whose servo holds the force of the starting length.
      auto reference = make_solver(s, {});
      auto tried = make_solver(test::settled_servo_box(bodies, false), {});
      EXPECT_NONFATAL_FAILURE(test::expect_runs_agree(*reference, *tried, kServoSteps, 1000),
                              "step");
    }
  }
}

TEST(UnstableParity, ServoBoxPileComparisonPassesOtherRoundingAndFailsAWrongServo) {
  for (const Scene& s : {test::servo_box(true), test::servo_box_of_bodies(true)}) {
    {
      auto reference = make_solver(s, {});
      auto tried = moved(s);
      test::RoundingTwin twin(make_solver(s, {}), 0x1p-53,
                              test::RoundingTwin::Kicks::VelocitiesAndPositions);
      test::expect_runs_agree_within_rounding(*reference, *tried, twin, kServoSteps, 100);
    }
    {
      auto reference = make_solver(s, {});
      auto tried = make_solver(other_gain(s), {});
      test::RoundingTwin twin(make_solver(s, {}), 0x1p-53,
                              test::RoundingTwin::Kicks::VelocitiesAndPositions);
      EXPECT_NONFATAL_FAILURE(
          test::expect_runs_agree_within_rounding(*reference, *tried, twin, kServoSteps, 100),
          "step");
    }
  }
}

Scene disc_or_skip(bool& skip) {
  try {
    return test::loaded_bonded_disc();
  } catch (const SceneError&) {
    skip = true;  // a build without Gmsh
    return {};
  }
}

TEST(UnstableParity, FloatBondComparisonPassesOtherRoundingAndFailsWeakerBonds) {
  bool skip = false;
  const Scene s = disc_or_skip(skip);
  if (skip) GTEST_SKIP() << "no Gmsh";
  const test::SolverChoice serial(Backend::Cpu, Method::Grid, Precision::Float);
  {
    auto tried = moved(s, serial);
    test::expect_bonds_agree(s, serial, *tried, test::kLoadedDiscSteps, 100);
  }
  {
    Scene weaker = s;
    for (Material& m : weaker.materials) m.tensile_strength *= 0.95;
    auto tried = test::solver_for(weaker, serial);
    EXPECT_NONFATAL_FAILURE(test::expect_bonds_agree(s, serial, *tried, test::kLoadedDiscSteps, 100),
                            "step");
  }
}

}  // namespace
}  // namespace tridem
