// examples/angular_drum.toml: angular grains (bodies of triangles) in a drum that is one
// prescribed body turned about its centre by a rotation program. Checked on the example
// itself, run for its first 10 000 steps, 0.08 s (the whole example takes about 150 s of
// one core): the drum turns at its angular velocity about a centre that stays put, the
// grains stay inside it, and the run writes every body's row in bodies.csv.
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(AngularDrumExample, DrumTurnsAndHoldsItsGrains) {
  Scene s = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/angular_drum.toml");
  ASSERT_TRUE(s.has_bodies());
  ASSERT_GT(s.bodies.size(), 100u);
  const BodySpec& drum = s.bodies[0];
  ASSERT_EQ(drum.motion, Motion::Prescribed) << "the drum is the first body";
  ASSERT_GT(drum.count, 100u);
  // It turns by a rotation program about the origin (docs/scene-format.md).
  ASSERT_GE(drum.program, 0) << "the drum follows a motion program";
  const MotionProgram& rotation = s.programs[static_cast<std::size_t>(drum.program)];
  ASSERT_EQ(rotation.kind, ProgramKind::Rotation);
  EXPECT_EQ(rotation.center.x, 0);
  EXPECT_EQ(rotation.center.y, 0);
  const double omega = rotation.angular_velocity;
  ASSERT_GT(omega, 0);
  // The drum's inner radius: the nearest vertex of its members to the centre (the origin).
  // Its centroid (the members' area-weighted centroids), the centre it turns about.
  double inner = INFINITY, area = 0;
  Vec2d centre{};
  for (std::size_t k = drum.first; k < drum.first + drum.count; ++k) {
    const auto& v = s.triangles[k].vertices;
    for (const Vec2d& p : v) inner = std::min(inner, std::hypot(p.x, p.y));
    const double a = 0.5 * std::abs(cross(v[1] - v[0], v[2] - v[0]));
    centre += (v[0] + v[1] + v[2]) * (a / 3);
    area += a;
  }
  centre = centre * (1 / area);
  ASSERT_LT(std::hypot(centre.x, centre.y), 1e-6) << "the drum is centred on the origin";

  test::TempDir dir;
  s.simulation.backend = Backend::Cpu;
  s.simulation.duration = 0;  // 10 000 steps instead of the example's 2.1 s
  s.simulation.steps = 10000;
  s.output.dir = dir.path().string();
  s.output.every = 0;
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  run_scene(s, o);  // without --force: the example's automatic step is below dt_crit

  const auto rows = test::read_lines(dir.path() / "bodies.csv");
  ASSERT_EQ(rows.size(), 1 + s.bodies.size());
  const double t = 10000 * describe_scene(s).dt_chosen;
  const auto d = test::numbers(rows[1]);  // id,x,y,theta,vx,vy,omega,mass,inertia,members
  EXPECT_NEAR(d[1], centre.x, 1e-12);
  EXPECT_NEAR(d[2], centre.y, 1e-12);
  EXPECT_NEAR(d[3], omega * t, 1e-12);  // the program's closed form, no accumulated angle
  EXPECT_EQ(d[6], omega);
  EXPECT_EQ(d[7], 0) << "a prescribed body's mass is 0";
  EXPECT_EQ(d[9], static_cast<double>(drum.count));
  // Every grain's centroid stays inside the drum, and the grains have started to move.
  double fastest = 0;
  for (std::size_t b = 2; b < rows.size(); ++b) {
    const auto g = test::numbers(rows[b]);
    EXPECT_LT(std::hypot(g[1], g[2]), inner) << "body " << g[0];
    EXPECT_GT(g[7], 0) << "a free grain has a mass";
    fastest = std::max(fastest, std::hypot(g[4], g[5]));
  }
  EXPECT_GT(fastest, 0.01);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
