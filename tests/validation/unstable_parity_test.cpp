// The comparisons of the GPU parity tests of unstable runs, checked on the CPU, where a run
// of other rounding is the serial solver of the scene moved by an offset
// (support/shifted_run.hpp): each comparison must let that run pass, and must fail a
// solver that is wrong by a little (a servo of 1 % other gain, bonds 5 % weaker), so that the GPU
// tests built on them still catch a bug.
//  - The servo box (support/program_scenes.hpp): its pile parts from any run of other
//    rounding from its first contacts, tenfold per 50-100 steps (H200), so it is compared
//    pointwise within a rounding twin's envelope only so long, and by the servo's law on
//    each run's own state throughout (support/program_compare.hpp).
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
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Not a power of two, so that every coordinate rounds otherwise.
constexpr Vec2d kOffset{0.0123456789, 0.00987654321};

std::unique_ptr<Solver> moved(const Scene& s, const test::SolverChoice& choice = Backend::Cpu) {
  return std::make_unique<test::ShiftedSolver>(
      test::solver_for(test::shifted_scene(s, kOffset), choice), kOffset);
}

/// How many failures `compare` reports (it must report some for a wrong solver).
template <class Compare>
std::size_t failures_of(Compare&& compare) {
  ::testing::TestPartResultArray failures;
  {
    const ::testing::ScopedFakeTestPartResultReporter intercept(
        ::testing::ScopedFakeTestPartResultReporter::INTERCEPT_ONLY_CURRENT_THREAD, &failures);
    compare();
  }
  return static_cast<std::size_t>(failures.size());
}

/// The servo box with its side servo's gain off by 1 %.
Scene other_gain(Scene s) {
  s.programs[0].gain *= 1.01;
  return s;
}

constexpr std::int64_t kServoSteps = 3000;

TEST(UnstableParity, ServoBoxPileComparisonPassesOtherRoundingAndFailsAWrongServo) {
  for (const bool bodies : {false, true}) {
    const Scene s = bodies ? test::servo_box_of_bodies(true) : test::servo_box(true);
    // A servo of another gain, and one that holds the force of the starting length instead
    // of following the lid (the pointwise comparison alone, which the single triangles' pile
    // leaves at its first contacts, caught neither there).
    const Scene wrong[] = {other_gain(s),
                           bodies ? test::servo_box_of_bodies(false) : test::servo_box(false)};
    for (int k = -1; k < 2; ++k) {
      auto reference = make_solver(s, {});
      auto tried = k < 0 ? moved(s) : make_solver(wrong[k], {});
      test::RoundingTwin twin(make_solver(s, {}), 0x1p-53,
                              test::RoundingTwin::Kicks::VelocitiesAndPositions);
      const auto compare = [&] {
        test::expect_servo_box_runs_agree(s, *reference, *tried, twin, kServoSteps, 100,
                                          test::servo_box_pointwise_steps(bodies, kServoSteps));
      };
      if (k < 0)
        compare();
      else
        EXPECT_GT(failures_of(compare), 0u) << (k == 0 ? "other gain" : "fixed length");
    }
  }
}

TEST(UnstableParity, FloatBondComparisonPassesOtherRoundingAndFailsWeakerBonds) {
  bool skip = false;
  const Scene s = test::loaded_bonded_disc_or_skip(skip);
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
    EXPECT_GT(failures_of([&] {
                test::expect_bonds_agree(s, serial, *tried, test::kLoadedDiscSteps, 100);
              }),
              0u);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
