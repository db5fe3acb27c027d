// Bodies of several triangles: mass and moment of inertia against the closed forms.
#include "core/particle_model.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <numbers>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::string scene_with(const std::string& body) {
  return "[simulation]\nsteps = 1\n[[material]]\nname = \"m\"\ndensity = 2500\n"
         "penalty = 1e9\n[[body]]\nmaterial = \"m\"\n" +
         body;
}

TEST(BodyModel, SquareOfTwoTriangles) {
  const double a = 0.3;  // side; rho a^2 and M a^2 / 6 about the centre
  const Scene s = parse_scene(
      scene_with("triangles = [[[1, 2], [1.3, 2], [1.3, 2.3]], [[1, 2], [1.3, 2.3], [1, 2.3]]]\n"),
      "s.toml");
  const ParticleModel m = build_particle_model(s);
  ASSERT_EQ(m.bodies.size(), 1u);
  const double mass = 2500 * a * a;
  EXPECT_NEAR(m.bodies.mass[0], mass, 1e-12 * mass);
  EXPECT_NEAR(m.bodies.inertia[0], mass * a * a / 6, 1e-12 * mass * a * a);
  EXPECT_NEAR(m.bodies.centroid[0].x, 1.15, 1e-14);
  EXPECT_NEAR(m.bodies.centroid[0].y, 2.15, 1e-14);
  EXPECT_EQ(m.bodies.first, (std::vector<std::int64_t>{0, 2}));
  EXPECT_EQ(m.bodies.body, (std::vector<std::int32_t>{0, 0}));
}

TEST(BodyModel, RegularPolygonFromItsOutline) {
  // A regular n-gon of circumradius R: area n/2 R^2 sin(2 pi / n),
  // polar moment M R^2 (2 + cos(2 pi / n)) / 6 about its centre.
  for (int n : {5, 12, 31}) {
    const double radius = 0.01;
    std::string outline = "polygon = [";
    for (int k = 0; k < n; ++k) {
      const double t = 2 * std::numbers::pi * k / n;
      outline += fmt::format("{}[{:.17g}, {:.17g}]", k ? ", " : "", 3 + radius * std::cos(t),
                             -1 + radius * std::sin(t));
    }
    const Scene s = parse_scene(scene_with(outline + "]\n"), "s.toml");
    const ParticleModel m = build_particle_model(s);
    ASSERT_EQ(m.bodies.size(), 1u);
    EXPECT_EQ(m.size(), static_cast<std::size_t>(n - 2));
    const double area = 0.5 * n * radius * radius * std::sin(2 * std::numbers::pi / n);
    const double mass = 2500 * area;
    const double inertia = mass * radius * radius * (2 + std::cos(2 * std::numbers::pi / n)) / 6;
    EXPECT_NEAR(m.bodies.mass[0], mass, 1e-12 * mass) << n;
    EXPECT_NEAR(m.bodies.inertia[0], inertia, 1e-11 * inertia) << n;
    EXPECT_NEAR(m.bodies.centroid[0].x, 3, 1e-15) << n;
    EXPECT_NEAR(m.bodies.centroid[0].y, -1, 1e-15) << n;
  }
}

TEST(BodyModel, LoneTriangleIsItsOwnBodyBitForBit) {
  const Scene s = parse_scene(
      scene_with("triangles = [[[0, 0], [1, 0], [0, 1]], [[1, 0], [1, 1], [0, 1]]]\n") +
          "[[triangle]]\nmaterial = \"m\"\nvertices = [[5, 0], [6.1, 0.3], [5.2, 1.7]]\n"
          "velocity = [0.5, 1]\nangular_velocity = 2\n",
      "s.toml");
  const ParticleModel m = build_particle_model(s);
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_EQ(m.bodies.centroid[1].x, m.centroid[2].x);
  EXPECT_EQ(m.bodies.centroid[1].y, m.centroid[2].y);
  EXPECT_EQ(m.bodies.mass[1], m.mass[2]);
  EXPECT_EQ(m.bodies.inertia[1], m.inertia[2]);
  EXPECT_EQ(m.bodies.member_offset[2].x, 0.0);
  EXPECT_EQ(m.velocity[2].x, 0.5);
  EXPECT_EQ(m.angular_velocity[2], 2.0);
}

TEST(BodyModel, MembersStartWithTheRigidMotion) {
  const Scene s =
      parse_scene(scene_with("triangles = [[[0, 0], [1, 0], [0, 1]], [[1, 0], [1, 1], [0, 1]]]\n"
                             "velocity = [1, 0]\nangular_velocity = 2\nmotion = \"prescribed\"\n"),
                  "s.toml");
  const ParticleModel m = build_particle_model(s);
  for (std::size_t i = 0; i < 2; ++i) {
    const Vec2d r = m.centroid[i] - m.bodies.centroid[0];
    EXPECT_NEAR(m.velocity[i].x, 1 - 2 * r.y, 1e-15);
    EXPECT_NEAR(m.velocity[i].y, 2 * r.x, 1e-15);
    EXPECT_EQ(m.angular_velocity[i], 2.0);
    EXPECT_EQ(m.motion[i], Motion::Prescribed);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
