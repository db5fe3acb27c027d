// The case the paper's direct area test misses: two triangles that overlap with no vertex
// of either inside the other (a star of David, pulled a little apart so that the overlap
// pushes them apart). The exact test finds the overlap and the pair repels; with
// contact_test = "direct-area" the pair never gets a force.
#include "broadphase/contact_filter.hpp"
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using DirectAreaMiss = test::BackendTest;

/// An equilateral triangle of circumradius 0.1 about c, its first vertex at `angle`.
std::array<Vec2d, 3> equilateral(Vec2d c, double angle) {
  std::array<Vec2d, 3> v;
  for (int k = 0; k < 3; ++k) {
    const double a = angle + k * 2.0943951023931953;  // 120°
    v[k] = {c.x + 0.1 * std::cos(a), c.y + 0.1 * std::sin(a)};
  }
  return v;
}

/// The hexagram, the second triangle (turned by 180°) shifted by 0.01 along x: the edges
/// still cross six times and no vertex lies inside the other triangle.
Scene star_of_david() {
  Scene s = test::empty_scene(1e5);
  const auto a = equilateral({0, 0}, M_PI / 2), b = equilateral({0.01, 0}, -M_PI / 2);
  s.triangles.push_back(test::triangle(a[0], a[1], a[2]));
  s.triangles.push_back(test::triangle(b[0], b[1], b[2]));
  s.simulation.method = Method::SingleDomain;
  return s;
}

physics::Triangle<double> as_triangle(const std::array<Vec2d, 3>& v) {
  return {{v[0], v[1], v[2]}};
}

TEST(DirectAreaMissCase, OnlyTheExactTestFindsTheOverlap) {
  const Scene s = star_of_david();
  const auto a = as_triangle(s.triangles[0].vertices), b = as_triangle(s.triangles[1].vertices);
  EXPECT_TRUE(physics::triangles_overlap(a, b));
  EXPECT_FALSE(physics::direct_area_overlap(a, b));
  const auto box_a = physics::bounding_box(a), box_b = physics::bounding_box(b);
  for (bool prefilter : {true, false}) {
    EXPECT_TRUE(passes_contact_test(a, box_a, b, box_b, {ContactTest::Exact, prefilter}));
    EXPECT_FALSE(passes_contact_test(a, box_a, b, box_b, {ContactTest::DirectArea, prefilter}));
  }
}

/// The state after one step: the forces in it are those of the initial overlap.
Snapshot one_step(ContactTest test, Backend backend) {
  Scene s = star_of_david();
  s.simulation.contact_test = test;
  return test::run_to(s, backend, 1, Precision::Double, Method::SingleDomain);
}

TEST_P(DirectAreaMiss, ExactTestRepelsDirectAreaTestGivesNoForce) {
  const Snapshot exact = one_step(ContactTest::Exact, GetParam().backend);
  EXPECT_LT(exact.fx[0], 0) << "the left triangle must be pushed left";
  EXPECT_GT(exact.fx[1], 0) << "the right triangle must be pushed right";
  EXPECT_EQ(exact.fx[0], -exact.fx[1]);
  EXPECT_EQ(exact.contacts.size(), 1u);

  const Snapshot direct = one_step(ContactTest::DirectArea, GetParam().backend);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(direct.fx[i], 0) << "particle " << i;
    EXPECT_EQ(direct.fy[i], 0) << "particle " << i;
    EXPECT_EQ(direct.torque[i], 0) << "particle " << i;
    EXPECT_EQ(direct.vx[i], 0) << "particle " << i;
  }
  EXPECT_TRUE(direct.contacts.empty());
}

INSTANTIATE_TEST_SUITE_P(Cpu, DirectAreaMiss, ::testing::Values(Backend::Cpu));
INSTANTIATE_TEST_SUITE_P(Gpu, DirectAreaMiss, ::testing::Values(Backend::Cuda));

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
