#pragma once
// A run with motion programs and servo walls against the serial reference, step by step
// (the GPU parity tests of parity/gpu_program_parity_test.cpp, and their CPU checks in
// validation/unstable_parity_test.cpp, which give it wrong solvers to prove it fails).
//  - expect_runs_agree: pointwise, to the fixed tolerances of support/gpu_compare.hpp, for
//    a scene that keeps rounding at rounding size (a settled one).
//  - expect_servo_box_runs_agree: the servo box of support/program_scenes.hpp, whose pile of loose
//    triangles parts from any run of other rounding from its first contacts (step ~382) and then
//    about tenfold per 50-100 steps, until it is another pile: runs of the serial solver moved by
//    an offset (support/shifted_run.hpp) leave even fifty times a rounding twin's spread at step
//    1000 or 1100, depending on the offset (by velocity: 2 of 8 offsets with one rounding of the
//    pair force, 4 of 8 with another). So the pile is compared pointwise, within kProgramEnvelope
//    times the twin's spread (support/rounding_twin.hpp), only for `pointwise_steps`; over the
//    whole run each solver must follow the servo law exactly on its own state (the velocity it
//    gives the wall is the law's for the target of its own floor-lid gap and the force of its own
//    contacts: rounding size, where a servo of 1 % other gain is off by 1 % of its speed), the
//    walls that programs of time move agree pointwise, and the servo wall stays within
//    kServoWallSpread of the reference's.
#include "physics/motion_program.hpp"
#include "support/gpu_compare.hpp"
#include "support/program_scenes.hpp"
#include "support/rounding_twin.hpp"
#include "tridem/scene.hpp"
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

/// How far a servo's wall velocity may be from its law on the solver's own state, m/s: the
/// law's rounding (2.4e-16 m/s measured at speeds up to the servo box's 0.1 m/s); a servo
/// of 1 % other gain is 3e-4 to 8e-4 m/s off once the pile holds it.
constexpr double kServoLawTolerance = 1e-12;

/// How far the servo box's servo wall may be from the reference's, m: a twentieth of its
/// grains' side. The piles of runs of other rounding push it 0.2-0.9 mm apart (8 offsets
/// over 3000 steps, main's rounding).
constexpr double kServoWallSpread = 5e-3;

/// How long the servo box is compared pointwise in a run of `steps`: its pile of single
/// triangles up to its first contacts (step ~382); its pile of two-triangle bodies over the
/// whole run, since it keeps to its rounding twin (at most twice the twin's spread after
/// step 200, 8 offsets, 3000 steps).
inline std::int64_t servo_box_pointwise_steps(bool bodies, std::int64_t steps) {
  return bodies ? steps : 300;
}

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

/// `b` against `a` within kProgramEnvelope times the spread of `twin` (a twin of the run of
/// `a`, at the same step) where that is larger than the fixed tolerances; `twin_wall_force`
/// is the running maximum of the twin's wall force difference.
inline void expect_within_rounding(const Snapshot& a, const Snapshot& b, RoundingTwin& twin,
                                   double& twin_wall_force, const std::string& what) {
  ASSERT_EQ(a.size(), b.size());
  const Difference spread = twin.spread_from(a);
  twin_wall_force = std::max(twin_wall_force, max_wall_force_difference(a, twin.snapshot()));
  const Difference d = max_difference(a, b);
  const double dx = std::max(kPositionTolerance, kProgramEnvelope * spread.position);
  const double da = std::max(kAngleTolerance, kProgramEnvelope * spread.angle);
  const double dv = std::max(kVelocityTolerance, kProgramEnvelope * spread.velocity);
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

/// How far the servo wall's velocity at `after` is from the servo law of `scene` (its
/// program 0, the servo box's side servo) for the run's own state: the target of the
/// floor-lid gap at the step's start (`before`, one step earlier) and the contact force the
/// step put on the wall. The law is physics::servo_velocity, which the solvers call too:
/// what this checks is that a solver feeds it its own gap and force and moves the wall by it
/// (the law itself: validation/servo_length_test.cpp, unit/physics/motion_program_test.cpp).
inline double servo_box_law_residual(const Scene& scene, const Snapshot& before,
                                     const Snapshot& after) {
  const MotionProgram& servo = scene.programs[0];
  const auto centroid_y = [&](std::size_t k) {
    const auto& v = scene.triangles[k].vertices;
    return (v[0].y + v[1].y + v[2].y) / 3;
  };
  // The part of the floor-lid centroid distance that the two walls fill.
  const double filled =
      centroid_y(ServoBox::kLid) - centroid_y(ServoBox::kFloor) - ServoBox::kHeight0;
  const double gap = before.y[ServoBox::kLid] - before.y[ServoBox::kFloor] - filled;
  const std::size_t w = ServoBox::kRight;
  const Vec2d law = physics::servo_velocity(servo, physics::servo_target_of_length(servo, gap),
                                            Vec2d{after.fx[w], after.fy[w]});
  return std::hypot(after.vx[w] - law.x, after.vy[w] - law.y);
}

/// The servo box `scene` run by `tried` against `reference`, checked every `every` steps up
/// to `steps`: pointwise within the rounding `twin`'s envelope (a twin of the reference at
/// its step 0) up to `pointwise_steps`, the servo law, the programmed walls and the servo
/// wall's spread throughout (see the top of this file).
inline void expect_servo_box_runs_agree(const Scene& scene, Solver& reference, Solver& tried,
                                        RoundingTwin& twin, std::int64_t steps, std::int64_t every,
                                        std::int64_t pointwise_steps) {
  Snapshot a0, b0, a, b;
  double twin_wall_force = 0;
  for (std::int64_t s = every; s <= steps; s += every) {
    reference.advance(every - 1);
    tried.advance(every - 1);
    reference.snapshot(a0, false);
    tried.snapshot(b0, false);
    reference.advance(1);
    tried.advance(1);
    const bool pointwise = s <= pointwise_steps;  // only its printout counts the contacts
    reference.snapshot(a, pointwise);
    tried.snapshot(b, pointwise);
    ASSERT_EQ(a.size(), b.size());
    const std::string what = "step " + std::to_string(s);
    if (pointwise) {
      twin.advance(every);
      expect_within_rounding(a, b, twin, twin_wall_force, what);
    }
    EXPECT_LE(servo_box_law_residual(scene, a0, a), kServoLawTolerance) << what << ": reference";
    EXPECT_LE(servo_box_law_residual(scene, b0, b), kServoLawTolerance) << what << ": servo law";
    for (const std::size_t wall : {ServoBox::kFloor, ServoBox::kLeft, ServoBox::kLid}) {
      EXPECT_NEAR(a.x[wall], b.x[wall], kPositionTolerance) << what << ": wall " << wall;
      EXPECT_NEAR(a.y[wall], b.y[wall], kPositionTolerance) << what << ": wall " << wall;
    }
    const std::size_t servo_wall = ServoBox::kRight;
    EXPECT_NEAR(a.x[servo_wall], b.x[servo_wall], kServoWallSpread) << what << ": servo wall";
  }
}

}  // namespace tridem::test
