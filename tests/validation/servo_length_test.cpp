// A servo whose length follows the sample (length_between, physics/motion_program.hpp):
// as a lid comes down and the sample's height shrinks by 16 %, the side servo holds its
// stress over the current height, F/H, where a servo of the starting length holds F and so
// a stress that drifts with the height. Triangles and bodies; the refusals of the model.
#include "core/particle_model.hpp"
#include "support/backend_test.hpp"
#include "support/program_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::ServoBox;

struct SideLoad {
  double force = 0;   ///< the grains' push on the side servo, N/m
  double height = 0;  ///< the gap between floor and lid, m
  double speed = 0;   ///< the servo's speed, m/s
};

/// The side servo's load and the sample's height at the end of the run, 0.6 s after the
/// lid stopped; `bodies`: the scene of bodies, read through their fields.
SideLoad side_load_after_settling(const Scene& s, bool bodies) {
  auto solver = test::solver_for(s, Backend::Cpu);
  solver->advance(static_cast<std::int64_t>(1.4 / solver->dt()));
  Snapshot snap;
  solver->snapshot(snap, false);
  const std::size_t right = ServoBox::kRight, lid = ServoBox::kLid;
  SideLoad out;
  out.force = bodies ? snap.body_fx[right] : snap.fx[right];
  out.height = (bodies ? snap.body_y[lid] : snap.y[lid]) - ServoBox::kLidCentroid;
  out.speed = bodies ? snap.body_vx[right] : snap.vx[right];
  return out;
}

void expect_stress_follows_height(bool bodies) {
  const double sigma = ServoBox::kStress;
  const SideLoad follow = side_load_after_settling(
      bodies ? test::servo_box_of_bodies(true) : test::servo_box(true), bodies);
  const SideLoad fixed = side_load_after_settling(
      bodies ? test::servo_box_of_bodies(false) : test::servo_box(false), bodies);
  std::printf("%s: height %.4f m (from %.2f); length_between: F/H = %.1f Pa (speed %.2g m/s); "
              "fixed length: F = %.1f N/m (target %.1f), F/H = %.1f Pa\n",
              bodies ? "bodies" : "triangles", follow.height, ServoBox::kHeight0,
              follow.force / follow.height, follow.speed, fixed.force, sigma * ServoBox::kHeight0,
              fixed.force / fixed.height);
  // The lid came down as programmed, so the height is what the table gives.
  EXPECT_NEAR(follow.height, ServoBox::kHeight0 - ServoBox::kLidTravel, 1e-9);
  EXPECT_NEAR(follow.force / follow.height, sigma, 0.01 * sigma);
  // The fixed-length servo holds its force, so its stress is off by H0/H = 1.18.
  EXPECT_NEAR(fixed.force, sigma * ServoBox::kHeight0, 0.01 * sigma * ServoBox::kHeight0);
  EXPECT_GT(fixed.force / fixed.height, 1.1 * sigma);
}

TEST(ServoLength, HoldsItsStressOverTheCurrentHeightAsTheLidComesDown) {
  expect_stress_follows_height(false);
}

TEST(ServoLength, HoldsItsStressOverTheCurrentHeightWithBodies) {
  expect_stress_follows_height(true);
}

// Serial and OpenMP agree bit for bit: the targets are computed once, before any thread
// writes a wall's pose.
TEST(ServoLength, OpenMPReproducesSerialBitForBit) {
  for (const Scene& s : {test::servo_box(true), test::servo_box_of_bodies(true)}) {
    const Snapshot serial = test::run_to(s, Backend::Cpu, 600);
    const Snapshot parallel = test::run_to(s, Backend::OpenMP, 600);
    test::expect_identical(serial, parallel);
  }
}

/// The scene's model refused, with every fragment in its message.
void expect_model_refused(const Scene& s, std::initializer_list<std::string> fragments) {
  try {
    (void)build_particle_model(s);
    ADD_FAILURE() << "accepted";
  } catch (const SceneError& e) {
    for (const std::string& f : fragments)
      EXPECT_NE(std::string(e.what()).find(f), std::string::npos)
          << "'" << f << "' not in: " << e.what();
  }
}

TEST(ServoLength, RefusesWallsItCannotMeasureBetween) {
  Scene s = test::servo_box(true);
  s.programs[0].length_walls[1] = 99;
  expect_model_refused(
      s, {"length_between = [0, 99]", "99 is no wall of this scene", "59 particle ids"});
  s.programs[0].length_walls[1] = 5;  // a grain
  expect_model_refused(s, {"particle id 5 is free", "name walls"});
  s.programs[0].length_walls[1] = static_cast<std::int32_t>(ServoBox::kRight);
  expect_model_refused(s, {"particle id 2 is the servo's own wall"});
  // The left wall is beside the floor, not across the servo's direction from it.
  s.programs[0].length_walls[1] = static_cast<std::int32_t>(ServoBox::kLeft);
  expect_model_refused(s, {"gap across the servo's direction", "not > 0"});
  // A turning wall: the gap is measured from centroids.
  s = test::servo_box(true);
  s.program_knots[1].angular_velocity = 0.5;
  expect_model_refused(s, {"particle id 3 turns", "only translate"});
  // The same with bodies, in body ids.
  s = test::servo_box_of_bodies(true);
  s.programs[0].length_walls[0] = 40;
  expect_model_refused(s, {"40 is no wall of this scene", "32 body ids"});
  s.programs[0].length_walls[0] = 4;
  expect_model_refused(s, {"body id 4 is free"});
}

TEST(ServoLength, StartsAtItsTargetOverTheStartingGap) {
  // At t = 0 the servo's velocity is the law's with no force: gain x stress x gap, capped.
  Scene s = test::servo_box(true);
  s.programs[0].gain = 1e-5;  // 1e-5 x 5000 x 0.45 = 0.0225 m/s, under max_speed 0.05
  const ParticleModel m = build_particle_model(s);
  EXPECT_NEAR(m.velocity[ServoBox::kRight].x, -1e-5 * ServoBox::kStress * ServoBox::kHeight0,
              1e-15);
  EXPECT_EQ(m.programs[0].length_axis.x, 0);
  EXPECT_EQ(m.programs[0].length_axis.y, 1);  // from the floor up to the lid
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
