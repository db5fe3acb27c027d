// Motion programs and servo walls (physics/motion_program.hpp): a velocity table, a
// rotation about a point and an oscillation move their walls exactly as written (positions
// at given times against closed forms computed here, independently of the program's code,
// to rounding), a rotating body does not drift over 10^5 steps, and a servo lid on a static
// packing holds its target force within 1% once settled, on every backend and method.
#include "physics/motion_program.hpp"
#include "support/backend_test.hpp"
#include "support/body_scenes.hpp"
#include "support/lattice_scenes.hpp"
#include "support/program_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr double kDt = 1e-4;

/// A prescribed triangle of centroid c0 far from everything, with program k.
TriangleSpec programmed_wall(Vec2d c0, std::int32_t k) {
  TriangleSpec t = test::triangle(c0 + Vec2d{-0.1, -0.05}, c0 + Vec2d{0.1, -0.05},
                                  c0 + Vec2d{0.0, 0.1}, {}, Motion::Prescribed);
  t.program = k;
  return t;
}

Vec2d centroid_of(const TriangleSpec& t) {
  return (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
}

/// A gate closed until t = 0.5 s, then sliding right at up to 2 m/s, reached linearly at
/// 0.6 s and held; it turns at 1 rad/s between 0.6 s and 0.8 s only.
void add_gate_table(Scene& s) {
  MotionProgram p;
  p.kind = ProgramKind::Table;
  p.first_knot = static_cast<std::int32_t>(s.program_knots.size());
  p.knot_count = 4;
  s.program_knots.push_back({0.0, {0, 0}, 0});
  s.program_knots.push_back({0.5, {0, 0}, 0});
  s.program_knots.push_back({0.6, {2, 0}, 1});
  s.program_knots.push_back({0.8, {2, 0}, 1});
  s.programs.push_back(p);
}

/// The gate's displacement along x and angle at t, by hand: 0 before 0.5 s, the ramp's
/// parabola to 0.6 s, then 2 m/s; the angle ramps with the velocity and stops at 0.8 s:
/// the table's last entry is held, so the angular velocity stays 1 rad/s.
double gate_x(double t) {
  if (t <= 0.5) return 0;
  if (t <= 0.6) return 0.5 * 20.0 * (t - 0.5) * (t - 0.5);  // a = 2 / 0.1 s
  return 0.1 + 2.0 * (t - 0.6);
}
double gate_angle(double t) {
  if (t <= 0.5) return 0;
  if (t <= 0.6) return 0.5 * 10.0 * (t - 0.5) * (t - 0.5);
  return 0.05 + 1.0 * (t - 0.6);
}

/// Three walls far apart: the gate table, a rotation about (1, 2) at 3 rad/s and an
/// oscillation of 5 mm at 4 Hz along (3, 4)/5 with phase 0.3, plus one free grain far away.
Scene programmed_walls() {
  Scene s = test::empty_scene(1e7, 2000);
  s.simulation.dt = kDt;
  add_gate_table(s);
  s.triangles.push_back(programmed_wall({0, 0}, 0));
  MotionProgram rotation;
  rotation.kind = ProgramKind::Rotation;
  rotation.center = {1, 2};
  rotation.angular_velocity = 3;
  s.programs.push_back(rotation);
  s.triangles.push_back(programmed_wall({5, 0}, 1));
  MotionProgram oscillation;
  oscillation.kind = ProgramKind::Oscillation;
  oscillation.amplitude = 0.005;
  oscillation.frequency = 4;
  oscillation.direction = {0.6, 0.8};
  oscillation.phase = 0.3;
  s.programs.push_back(oscillation);
  s.triangles.push_back(programmed_wall({10, 0}, 2));
  s.triangles.push_back(test::triangle({20, 0}, {20.1, 0}, {20, 0.1}, {0.1, 0}));
  return s;
}

using MotionProgramTest = test::BackendTest;

TEST_P(MotionProgramTest, WallsFollowTheirProgramsExactly) {
  const Scene s = programmed_walls();
  const Vec2d gate0 = centroid_of(s.triangles[0]), rot0 = centroid_of(s.triangles[1]),
              osc0 = centroid_of(s.triangles[2]);
  auto solver = test::solver_for(s, GetParam());
  Snapshot snap;
  solver->snapshot(snap, false);
  EXPECT_EQ(snap.vx[0], 0);  // the table's velocity at t = 0
  std::int64_t done = 0;
  double worst = 0;
  for (const std::int64_t step : {2500, 5000, 5500, 6000, 7000, 8000, 10000}) {
    solver->advance(step - done);
    done = step;
    solver->snapshot(snap, false);
    const double t = static_cast<double>(step) * kDt;
    // The gate.
    const double e_gate = std::abs(snap.x[0] - (gate0.x + gate_x(t)));
    EXPECT_NEAR(snap.x[0], gate0.x + gate_x(t), 1e-12) << "t = " << t;
    EXPECT_EQ(snap.y[0], gate0.y);
    EXPECT_NEAR(snap.theta[0], gate_angle(t), 1e-12) << "t = " << t;
    const double v_gate = t <= 0.5 ? 0 : (t <= 0.6 ? 20 * (t - 0.5) : 2);
    EXPECT_NEAR(snap.vx[0], v_gate, 1e-10) << "t = " << t;
    // The rotation about (1, 2).
    const double a = 3 * t;
    const Vec2d r = rot0 - Vec2d{1, 2};
    const Vec2d expected{1 + std::cos(a) * r.x - std::sin(a) * r.y,
                         2 + std::sin(a) * r.x + std::cos(a) * r.y};
    const double e_rot = std::hypot(snap.x[1] - expected.x, snap.y[1] - expected.y);
    EXPECT_LE(e_rot, 1e-12) << "t = " << t;
    EXPECT_NEAR(snap.theta[1], a, 1e-12);
    EXPECT_NEAR(snap.vx[1], -3 * (expected.y - 2), 1e-11);
    EXPECT_NEAR(snap.vy[1], 3 * (expected.x - 1), 1e-11);
    EXPECT_EQ(snap.omega[1], 3);
    // The oscillation.
    const double u = 0.005 * (std::sin(2 * std::numbers::pi * 4 * t + 0.3) - std::sin(0.3));
    const double e_osc = std::hypot(snap.x[2] - (osc0.x + 0.6 * u), snap.y[2] - (osc0.y + 0.8 * u));
    EXPECT_LE(e_osc, 1e-12) << "t = " << t;
    EXPECT_EQ(snap.theta[2], 0);
    worst = std::max({worst, e_gate, e_rot, e_osc});
  }
  std::printf("largest position error against the closed forms: %.3g m\n", worst);
}

TEST_P(MotionProgramTest, ServoLidHoldsItsTargetForceOnAStaticPacking) {
  // A row of 8 lattice triangles between fixed ones at each end, on a fixed row below;
  // a wide lid whose flat bottom starts on the row's top, pressing down to 400 N/m.
  const double a = 0.1, h = a * std::sqrt(3.0) / 2;
  Scene s = test::empty_scene(1e7, 2000, 0.3, 0.3);
  s.simulation.local_damping = 0.5;
  for (int k = 0; k < 8; ++k) s.triangles.push_back(test::lattice_triangle(k, 0, a, 1));
  for (int k : {-2, -1, 8, 9})
    s.triangles.push_back(test::lattice_triangle(k, 0, a, 1, Motion::Fixed));
  for (int k = -3; k < 11; ++k)
    s.triangles.push_back(test::lattice_triangle(k, -1, a, 1, Motion::Fixed));
  MotionProgram servo;
  servo.kind = ProgramKind::Servo;
  servo.direction = {0, -1};
  servo.target_force = 400;
  servo.gain = 2e-6;
  servo.max_speed = 0.02;
  s.programs.push_back(servo);
  TriangleSpec lid = test::triangle({-0.1, h}, {0.6, h}, {0.25, h + 0.3}, {}, Motion::Prescribed);
  lid.program = 0;
  s.triangles.push_back(lid);
  const std::size_t top = s.triangles.size() - 1;
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Strips, 24);
  auto solver = test::solver_for(s, GetParam());
  const auto steps = static_cast<std::int64_t>(0.3 / solver->dt());
  Snapshot snap;
  solver->advance(steps);
  solver->snapshot(snap, false);
  // The grains push the lid up with the target force (its fy), and it has stopped.
  const double measured = snap.fy[top];
  std::printf("servo lid after %.2f s: force %.6g N/m (target 400), speed %.3g m/s, "
              "moved %.3g m\n",
              snap.time, measured, snap.vy[top], h + 0.1 - snap.y[top]);
  EXPECT_NEAR(measured, 400, 4);
  EXPECT_LT(std::abs(snap.vy[top]), 1e-3 * servo.max_speed);
  EXPECT_LT(snap.y[top], h + 0.1) << "it moved down into the packing";
}

TRIDEM_INSTANTIATE_SOLVERS(MotionProgramTest);

// A drum of 12 triangles as one body, rotating about a point off its centroid, does not
// drift over 10^5 steps: its pose is a closed form of the time. (An angle summed step by
// step would be off by ~1e-10 rad, its rounding random-walking to ~6e-13 at best: both
// beyond the 1e-13 bound. 10^6 steps gave 5.9e-17 m but took minutes of a loaded CI core.)
TEST(MotionProgram, RotatingBodyDoesNotDriftOverAHundredThousandSteps) {
  Scene s = test::empty_scene(1e7, 2000);
  s.simulation.dt = 1e-5;
  test::add_polygon(s, {0.3, 0.1}, 0.2, 12, 0.0, {}, 0);
  s.bodies.back().motion = Motion::Prescribed;
  for (TriangleSpec& t : s.triangles) t.motion = Motion::Prescribed;
  MotionProgram rotation;
  rotation.kind = ProgramKind::Rotation;
  rotation.center = {0, 0};
  rotation.angular_velocity = 2.5;
  s.programs.push_back(rotation);
  s.bodies.back().program = 0;
  // A second body, a lone free triangle, so that the scene has bodies of one and several.
  s.triangles.push_back(test::triangle({5, 5}, {5.1, 5}, {5, 5.1}));
  test::add_body(s, s.triangles.size() - 1);
  auto solver = test::solver_for(s, Backend::Cpu);
  Snapshot start, snap;
  solver->snapshot(start, false);
  const std::int64_t steps = 100000;
  solver->advance(steps);
  solver->snapshot(snap, false);
  const double t = static_cast<double>(steps) * 1e-5, a = 2.5 * t;
  const Vec2d expected{std::cos(a) * 0.3 - std::sin(a) * 0.1,
                       std::sin(a) * 0.3 + std::cos(a) * 0.1};
  const double error = std::hypot(snap.body_x[0] - expected.x, snap.body_y[0] - expected.y);
  std::printf("after 10^5 steps (%.0f turns): centroid off the closed form by %.3g m\n",
              a / (2 * std::numbers::pi), error);
  EXPECT_LE(error, 1e-13);
  EXPECT_NEAR(snap.body_theta[0], a, 1e-13);
  // The members follow, at their distance from the body's centroid.
  EXPECT_NEAR(std::hypot(snap.x[0] - snap.body_x[0], snap.y[0] - snap.body_y[0]),
              std::hypot(start.x[0] - start.body_x[0], start.y[0] - start.body_y[0]), 1e-12);
}

// Serial and OpenMP agree bit for bit with programs and a servo, every CPU method.
TEST(MotionProgram, OpenMPReproducesSerialBitForBit) {
  const Scene s = test::programmed_pile();
  for (const Method m : {Method::Grid, Method::SingleDomain, Method::Decomposition}) {
    const Scene scene = m == Method::Decomposition
                            ? test::with_decomposition(s, DecompositionLayout::Strips, 16)
                            : s;
    const Snapshot serial = test::run_to(scene, Backend::Cpu, 400, Precision::Double, m);
    const Snapshot parallel = test::run_to(scene, Backend::OpenMP, 400, Precision::Double, m);
    test::expect_identical(serial, parallel);
    EXPECT_NE(serial.x[2], centroid_of(s.triangles[2]).x) << "the servo moved";
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
