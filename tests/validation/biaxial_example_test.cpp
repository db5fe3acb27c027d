// examples/biaxial.toml: a biaxial test of angular grains (bodies of triangles) at constant
// confining stress: two servo side walls, a top wall moving down at constant speed, a fixed
// bottom, frictionless walls. Checked on the example itself, run to 4 % of axial strain
// instead of its 15 % (docs/experiments.md has the whole curve): the servos hold their
// stress over the sample's current height, and the mobilised friction angle sin(phi) = (s1 - s3) /
// (s1 + s3), from the walls' loads over the box's current size (walls.csv's forces and positions),
// is that of a frictional granular material, 15 to 45 degrees.
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// walls.csv: step,time,id,fx,fy,torque,x,y,vx,vy (docs/output-format.md).
struct WallRow {
  double fx, fy, x, y;
};

TEST(BiaxialExample, ServosHoldTheConfiningStressAndTheFrictionAngleIsPlausible) {
  Scene s = read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/biaxial.toml");
  ASSERT_TRUE(s.has_bodies());
  ASSERT_GT(s.bodies.size(), 100u) << "about 150 angular grains";
  // The walls are the scene's first four triangles: left, right, bottom, top
  // (scripts/tridem_experiments.py, box_walls); the sides are servos.
  constexpr std::size_t kLeft = 0, kRight = 1, kBottom = 2, kTop = 3;
  // Each side wall holds its stress over the sample's current height: the gap between
  // the bottom and top walls (length_between).
  double stress[2] = {};
  for (std::size_t w : {kLeft, kRight}) {
    const std::int32_t p = s.triangles[w].program;
    ASSERT_GE(p, 0) << "side wall " << w << " follows a program";
    const MotionProgram& servo = s.programs[static_cast<std::size_t>(p)];
    ASSERT_EQ(servo.kind, ProgramKind::Servo);
    ASSERT_EQ(servo.length_walls[0], static_cast<std::int32_t>(kBottom));
    ASSERT_EQ(servo.length_walls[1], static_cast<std::int32_t>(kTop));
    stress[w] = servo.stress;
  }
  ASSERT_GT(stress[kLeft], 0);
  ASSERT_EQ(stress[kLeft], stress[kRight]);
  ASSERT_EQ(s.triangles[kTop].motion, Motion::Prescribed);
  ASSERT_LT(s.triangles[kTop].velocity.y, 0) << "the top wall moves down";
  ASSERT_EQ(s.triangles[kBottom].motion, Motion::Fixed);
  // Each wall's face is one of its edges: the distance from its centroid to the face (a
  // third of its thickness) turns walls.csv's centroids into the box's size.
  const auto centroid = [&](std::size_t w) {
    const auto& v = s.triangles[w].vertices;
    return (v[0] + v[1] + v[2]) * (1.0 / 3);
  };
  const auto extreme = [&](std::size_t w, double Vec2d::*axis, bool largest) {
    const auto& v = s.triangles[w].vertices;
    double e = v[0].*axis;
    for (const Vec2d& p : v) e = largest ? std::max(e, p.*axis) : std::min(e, p.*axis);
    return e;
  };
  const double face_offset[4] = {extreme(kLeft, &Vec2d::x, true) - centroid(kLeft).x,
                                 centroid(kRight).x - extreme(kRight, &Vec2d::x, false),
                                 extreme(kBottom, &Vec2d::y, true) - centroid(kBottom).y,
                                 centroid(kTop).y - extreme(kTop, &Vec2d::y, false)};
  const double height0 = extreme(kTop, &Vec2d::y, false) - extreme(kBottom, &Vec2d::y, true);
  ASSERT_GT(height0, 0);

  // 4 % of axial strain at the top wall's speed.
  const double duration = 0.04 * height0 / -s.triangles[kTop].velocity.y;
  const double dt = describe_scene(s).dt_chosen;
  test::TempDir dir;
  s.simulation.backend = Backend::Cpu;
  s.simulation.duration = 0;
  s.simulation.steps = static_cast<std::int64_t>(std::ceil(duration / dt));
  s.output.dir = dir.path().string();
  s.output.every = 0;
  s.output.energy_every = s.simulation.steps / 40;
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  run_scene(s, o);

  std::map<double, std::map<int, WallRow>> rows;  // time -> wall id -> row
  const auto lines = test::read_lines(dir.path() / "walls.csv");
  ASSERT_EQ(lines[0], "step,time,id,fx,fy,torque,x,y,vx,vy");
  for (std::size_t k = 1; k < lines.size(); ++k) {
    const auto r = test::numbers(lines[k]);
    ASSERT_EQ(r.size(), 10u);
    rows[r[1]][static_cast<int>(r[2])] = WallRow{r[3], r[4], r[6], r[7]};
  }
  ASSERT_GE(rows.size(), 40u);
  // From 1 % of axial strain on (the servos have closed the gaps the scene starts with),
  // each side wall's load is its stress times the current height within 10 % at every
  // logged step.
  double phi_end = 0, worst = 0;
  bool loaded = false;
  for (const auto& [time, walls] : rows) {
    ASSERT_EQ(walls.size(), 4u);
    const double width =
        (walls.at(kRight).x - face_offset[kRight]) - (walls.at(kLeft).x + face_offset[kLeft]);
    const double height =
        (walls.at(kTop).y - face_offset[kTop]) - (walls.at(kBottom).y + face_offset[kBottom]);
    const double strain = 1 - height / height0;
    if (strain < 0.01) continue;
    const double target[2] = {stress[kLeft] * height, stress[kRight] * height};
    EXPECT_NEAR(-walls.at(kLeft).fx, target[kLeft], 0.1 * target[kLeft]) << "t = " << time;
    EXPECT_NEAR(walls.at(kRight).fx, target[kRight], 0.1 * target[kRight]) << "t = " << time;
    worst = std::max({worst, std::abs(-walls.at(kLeft).fx / target[kLeft] - 1),
                      std::abs(walls.at(kRight).fx / target[kRight] - 1)});
    const double s3 = 0.5 * (-walls.at(kLeft).fx + walls.at(kRight).fx) / height;
    const double s1 = 0.5 * (-walls.at(kBottom).fy + walls.at(kTop).fy) / width;
    const double phi = std::asin((s1 - s3) / (s1 + s3)) * 180 / std::numbers::pi;
    loaded = true;
    phi_end = phi;
  }
  ASSERT_TRUE(loaded) << "the top wall never reached 1 % of axial strain";
  std::printf("side walls' load off stress x current height by at most %.2f %%; phi at 4 %% "
              "axial strain %.1f deg\n",
              100 * worst, phi_end);
  EXPECT_GT(phi_end, 15.0);
  EXPECT_LT(phi_end, 45.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
