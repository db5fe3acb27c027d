// The mixed-precision rules of physics/local_frame.hpp on known cases, and the grid rule
// that keeps the cell grid complete when float boxes, rounded outward, are wider than the
// longest edge (far from the origin).
#include "broadphase/candidate_pairs.hpp"
#include "physics/local_frame.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(LocalFrame, DirectedRoundingBracketsTheValueTightly) {
  for (const double v : {1.0, 0.1, -0.1, 1e4 + 1e-9, -123.456789, 1e-30}) {
    const float lo = physics::round_down(v, 0.0f), hi = physics::round_up(v, 0.0f);
    EXPECT_LE(static_cast<double>(lo), v);
    EXPECT_GE(static_cast<double>(hi), v);
    EXPECT_LE(hi, std::nextafter(lo, INFINITY)) << "adjacent floats or equal, for " << v;
    if (static_cast<double>(static_cast<float>(v)) == v) {
      EXPECT_EQ(lo, hi);
    }
  }
  EXPECT_EQ(physics::round_down(0.1, 0.0), 0.1);  // the identity in double
}

TEST(LocalFrame, PairGeometryFarFromTheOriginIsResolvedAsAtTheOrigin) {
  // Two triangles 1e-3 m apart at 10 km: in absolute float coordinates (spacing 1e-3 m)
  // their gap would be lost; in the emitter's frame it is exact to 1e-10 m.
  const Vec2d far{1e4, 1e4};
  const Vec2<float> rel[3] = {{-0.01f, -0.01f}, {0.01f, -0.01f}, {0.0f, 0.02f}};
  const Vec2d ca = far, cb = far + Vec2d{0.021, 0.0};
  const physics::Triangle<float> b = physics::triangle_at(physics::offset_from<float>(ca, cb), rel);
  EXPECT_NEAR(static_cast<double>(b.v[0].x) - 0.01, 0.001, 1e-9);  // b's left corner - a's right
  const physics::Triangle<float> a = physics::triangle_at(physics::offset_from<float>(ca, ca), rel);
  EXPECT_EQ(a.v[1].x, rel[1].x);  // the emitter is its own vertices, exactly
}

TEST(LocalFrame, OutwardBoxContainsTheBodyInFloat) {
  const Vec2d c{1e4 + 0.3, -7e3 + 0.1};
  const Vec2<float> rel[3] = {{-0.01f, -0.01f}, {0.01f, -0.01f}, {0.0f, 0.02f}};
  const physics::Aabb<float> box = physics::outward_box(c, rel, 0.01f);
  for (const auto& r : rel) {
    EXPECT_LE(static_cast<double>(box.lo.x), c.x + static_cast<double>(r.x));
    EXPECT_LE(static_cast<double>(box.lo.y), c.y + static_cast<double>(r.y));
    EXPECT_GE(static_cast<double>(box.hi.x), c.x + static_cast<double>(r.x));
    EXPECT_GE(static_cast<double>(box.hi.y), c.y + static_cast<double>(r.y));
  }
}

TEST(LocalFrame, GridFindsOverlappingBoxesWiderThanItsBaseCell) {
  // Longest edge 1, so the base cell is 1; box 1 is 2.2 wide (an outward-rounded float box
  // far from the origin), and overlaps box 0 whose corner lies two base cells away. A
  // 3x3 scan over cells of 1 would miss the pair; cells as wide as the widest box do not.
  const std::vector<double> longest_edge{1.0, 1.0};
  const std::vector<Motion> motion{Motion::Free, Motion::Free};
  CandidatePairs<float> finder(longest_edge, motion);
  const float lo_x[2] = {2.2f, 0.1f}, lo_y[2] = {0.0f, 0.0f};
  const float hi_x[2] = {3.0f, 2.3f}, hi_y[2] = {1.0f, 1.0f};
  PairList pairs;
  finder.find({lo_x, lo_y, hi_x, hi_y}, Method::Grid, false, pairs);
  ASSERT_EQ(pairs.count(), 1);
  EXPECT_EQ(pairs.partner[0], 1);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
