// [[body]] blocks: polygons triangulated (either orientation, convex or not), explicit
// members, ids in file order with [[triangle]]s, and the refusals of bad bodies.
#include "scene_refusal.hpp"

#include "io/scene/polygon_triangulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_refused;
using test::kSceneHead;

std::string with_body(std::string_view body) {
  return std::string(kSceneHead) + "[[body]]\nmaterial = \"m\"\n" + std::string(body);
}

double area_of(const std::array<Vec2d, 3>& v) { return 0.5 * cross(v[1] - v[0], v[2] - v[0]); }

double total_area(const std::vector<TriangleSpec>& t, std::size_t first, std::size_t count) {
  double a = 0;
  for (std::size_t i = first; i < first + count; ++i) a += area_of(t[i].vertices);
  return a;
}

TEST(SceneBodies, ConvexPolygonIsCutIntoCounterClockwiseMembers) {
  const Scene s = parse_scene(
      with_body("polygon = [[0, 0], [0.02, 0], [0.025, 0.01], [0.01, 0.02], [-0.005, 0.01]]\n"),
      "s.toml");
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].first, 0u);
  EXPECT_EQ(s.bodies[0].count, 3u);  // n - 2 triangles, no point added
  ASSERT_EQ(s.triangles.size(), 3u);
  for (const TriangleSpec& t : s.triangles) EXPECT_GT(area_of(t.vertices), 0);
  // Shoelace area of the pentagon.
  EXPECT_NEAR(total_area(s.triangles, 0, 3), 4e-4, 1e-18);
  EXPECT_TRUE(s.has_bodies());
}

TEST(SceneBodies, ClockwiseNonConvexPolygonKeepsOnlyItsInside) {
  // An L of area 3, written clockwise: its hull (area 4) must not be filled.
  const Scene s =
      parse_scene(with_body("polygon = [[0, 0], [0, 2], [1, 2], [1, 1], [2, 1], [2, 0]]\n"
                            "velocity = [1, 2]\nangular_velocity = 3\n"),
                  "s.toml");
  ASSERT_EQ(s.bodies.size(), 1u);
  EXPECT_EQ(s.bodies[0].count, 4u);
  EXPECT_DOUBLE_EQ(total_area(s.triangles, 0, 4), 3.0);
  EXPECT_EQ(s.bodies[0].velocity.x, 1);
  EXPECT_EQ(s.bodies[0].velocity.y, 2);
  EXPECT_EQ(s.bodies[0].angular_velocity, 3);
  EXPECT_EQ(s.bodies[0].motion, Motion::Free);
}

TEST(SceneBodies, ExplicitTrianglesAndIdsInFileOrder) {
  const std::string text = std::string(kSceneHead) +
                           "[[triangle]]\nmaterial = \"m\"\nvertices = [[5, 0], [6, 0], [5, 1]]\n"
                           "[[body]]\nmaterial = \"m\"\nmotion = \"prescribed\"\n"
                           "velocity = [0, -1]\n"
                           "triangles = [[[0, 0], [1, 0], [0, 1]], [[1, 0], [0, 1], [1, 1]]]\n"
                           "[[triangle]]\nmaterial = \"m\"\nvertices = [[8, 0], [9, 0], [8, 1]]\n"
                           "[[generate]]\nkind = \"lattice\"\nmaterial = \"m\"\n"
                           "region = [[20, 0], [24, 2]]\nsize = 1\n";
  const Scene s = parse_scene(text, "s.toml");
  ASSERT_GE(s.bodies.size(), 4u);
  EXPECT_EQ(s.bodies.size(), s.triangles.size() - 1);  // one body of two members
  EXPECT_EQ(s.bodies[0].first, 0u);
  EXPECT_EQ(s.bodies[0].count, 1u);
  EXPECT_EQ(s.triangles[0].vertices[0].x, 5);
  EXPECT_EQ(s.bodies[1].first, 1u);
  EXPECT_EQ(s.bodies[1].count, 2u);
  EXPECT_EQ(s.bodies[1].motion, Motion::Prescribed);
  EXPECT_EQ(s.bodies[1].velocity.y, -1);
  EXPECT_GT(area_of(s.triangles[2].vertices), 0);  // clockwise member made CCW
  EXPECT_EQ(s.bodies[2].first, 3u);
  EXPECT_EQ(s.triangles[3].vertices[0].x, 8);
  for (std::size_t b = 3; b < s.bodies.size(); ++b) {  // generated: one body each
    EXPECT_EQ(s.bodies[b].first, b + 1);
    EXPECT_EQ(s.bodies[b].count, 1u);
  }
}

TEST(SceneBodies, SceneWithoutBodyBlocksHasNoBodyTable) {
  const Scene s = parse_scene(std::string(kSceneHead) + std::string(test::kGoodTriangle), "s.toml");
  EXPECT_TRUE(s.bodies.empty());
  EXPECT_FALSE(s.has_bodies());
}

TEST(SceneBodies, BadBodiesAreRefusedNamingTheBody) {
  expect_refused(with_body("polygon = [[0, 0], [1, 1], [1, 0], [0, 1]]\n"),
                 {"bad.toml:9:", "[[body]] #1 (body id 0)", "'polygon'", "intersects itself"});
  expect_refused(with_body("polygon = [[0, 0], [1, 0], [2, 0]]\n"),
                 {"[[body]] #1 (body id 0)", "'polygon'", "degenerate"});
  expect_refused(with_body("polygon = [[0, 0], [1, 0]]\n"), {"[[body]] #1", "at least 3 points"});
  expect_refused(with_body("polygon = [[0, 0], [1, 0], [1, 1], [1, 0]]\n"),
                 {"[[body]] #1", "repeats an earlier point"});
  expect_refused(with_body("polygon = [[0, 0], [1, 0], [1]]\n"), {"[[body]] #1", "'polygon'"});
  expect_refused(with_body("polygon = 3\n"), {"[[body]] #1", "'polygon'", "an integer"});
  expect_refused(with_body(""), {"[[body]] #1", "polygon", "triangles"});
  expect_refused(with_body("polygon = [[0, 0], [1, 0], [0, 1]]\n"
                           "triangles = [[[0, 0], [1, 0], [0, 1]]]\n"),
                 {"[[body]] #1", "not both"});
  expect_refused(with_body("triangles = []\n"), {"[[body]] #1", "'triangles'", "empty"});
  expect_refused(with_body("triangles = [[[0, 0], [1, 0]]]\n"), {"[[body]] #1", "'triangles'"});
  expect_refused(with_body("triangles = [[[0, 0], [1, 0], [2, 0]]]\n"),
                 {"[[body]] #1", "member triangle 1 of 1", "degenerate"});
  expect_refused(with_body("triangles = [[[0, 0], [1, 0], [0, 1]]]\nfixed = true\n"
                           "velocity = [1, 0]\n"),
                 {"[[body]] #1", "a fixed body can't have a velocity"});
  expect_refused(with_body("triangles = [[[0, 0], [1, 0], [0, 1]]]\nshape = 1\n"),
                 {"[[body]] #1", "unknown key 'shape'"});
  expect_refused(std::string(kSceneHead) + "[body]\nmaterial = \"m\"\n",
                 {"'body' must be an array of tables"});
}

TEST(SceneBodies, OverlappingMembersAreRefusedNamingTheBody) {
  expect_refused(with_body("triangles = [[[0, 0], [1, 0], [0, 1]], [[0.1, 0.1], [1, 0.1], "
                           "[0.1, 1]]]\n"),
                 {"body id 0, [[body]] #1", "overlap"});
}

TEST(PolygonTriangulation, SquareWithCollinearPointsKeepsItsArea) {
  const auto cut = scene_detail::triangulate_polygon({{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}});
  ASSERT_FALSE(cut.problem);
  double a = 0;
  for (const auto& t : cut.triangles) {
    EXPECT_GT(area_of(t), 0);
    a += area_of(t);
  }
  EXPECT_DOUBLE_EQ(a, 4.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
