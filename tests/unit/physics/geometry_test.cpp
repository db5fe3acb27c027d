// Geometry on known cases: signs, overlaps (including the edge-crossing case the paper's
// direct area method misses) and segment clipping.
#include "physics/geometry.hpp"

#include <gtest/gtest.h>

namespace tridem::physics {
namespace {

using T = Triangle<double>;
using V = Vec2<double>;

T rotated_equilateral(V c, double r, double angle) {
  T t;
  for (int k = 0; k < 3; ++k) {
    const double a = angle + k * 2.0943951023931953;  // 120°
    t.v[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  return t;
}

TEST(Geometry, SignedAreaIsPositiveCounterClockwise) {
  const T ccw{{{0, 0}, {2, 0}, {0, 1}}};
  EXPECT_DOUBLE_EQ(signed_area(ccw), 1.0);
  const T cw{{{0, 0}, {0, 1}, {2, 0}}};
  EXPECT_DOUBLE_EQ(signed_area(cw), -1.0);
}

TEST(Geometry, CentroidAndSizes) {
  const T t{{{0, 0}, {3, 0}, {0, 4}}};
  EXPECT_DOUBLE_EQ(centroid(t).x, 1.0);
  EXPECT_DOUBLE_EQ(centroid(t).y, 4.0 / 3.0);
  EXPECT_DOUBLE_EQ(longest_edge(t), 5.0);
  EXPECT_DOUBLE_EQ(smallest_height(t), 12.0 / 5.0);
}

TEST(Geometry, PlaceRotatesOffsetsAboutCentroid) {
  const V r[3] = {{1, 0}, {-0.5, 0.5}, {-0.5, -0.5}};
  const T t = place(V{2, 3}, 1.5707963267948966, r);
  EXPECT_NEAR(t.v[0].x, 2.0, 1e-15);
  EXPECT_NEAR(t.v[0].y, 4.0, 1e-15);
  EXPECT_NEAR(t.v[1].x, 1.5, 1e-15);
  EXPECT_NEAR(t.v[1].y, 2.5, 1e-15);
}

TEST(Geometry, SeparatedTrianglesDoNotOverlap) {
  const T a{{{0, 0}, {1, 0}, {0, 1}}};
  const T b{{{2, 0}, {3, 0}, {2, 1}}};
  EXPECT_FALSE(triangles_overlap(a, b));
  EXPECT_FALSE(direct_area_overlap(a, b));
  // Boxes overlap but the hypotenuse separates them.
  const T c{{{0.8, 0.8}, {1.5, 0.8}, {0.8, 1.5}}};
  EXPECT_TRUE(boxes_overlap(bounding_box(a), bounding_box(c)));
  EXPECT_FALSE(triangles_overlap(a, c));
}

TEST(Geometry, TouchingTrianglesDoNotOverlap) {
  const T a{{{0, 0}, {1, 0}, {0, 1}}};
  const T b{{{1, 0}, {1, 1}, {0, 1}}};  // shares the hypotenuse
  EXPECT_FALSE(triangles_overlap(a, b));
}

TEST(Geometry, VertexInsideOverlapIsFoundByBothTests) {
  const T a{{{0, 0}, {1, 0}, {0, 1}}};
  const T b{{{0.2, 0.2}, {2, 0.2}, {2, 2}}};
  EXPECT_TRUE(triangles_overlap(a, b));
  EXPECT_TRUE(direct_area_overlap(a, b));
}

TEST(Geometry, EdgeCrossingWithNoVertexInsideIsMissedByDirectAreaMethod) {
  // A hexagram: two equilateral triangles about one centre, one turned by 180°. Their
  // edges cross six times and no vertex of either lies inside the other.
  const T a = rotated_equilateral({0, 0}, 1.0, 0.0);
  const T b = rotated_equilateral({0, 0}, 1.0, 3.141592653589793);
  EXPECT_TRUE(triangles_overlap(a, b));
  EXPECT_FALSE(direct_area_overlap(a, b));
}

TEST(Geometry, ClipSegmentThroughTriangle) {
  const V u0{0, 0}, u1{4, 0}, u2{0, 4};
  double t0 = -1, t1 = -1;
  // Horizontal line y = 1 from x = -1 to x = 5: inside for x in [0, 3].
  ASSERT_TRUE(clip_segment(V{-1, 1}, V{6, 0}, u0, u1, u2, t0, t1));
  EXPECT_NEAR(t0, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(t1, 4.0 / 6.0, 1e-15);
  // Entirely outside.
  EXPECT_FALSE(clip_segment(V{-1, 5}, V{6, 0}, u0, u1, u2, t0, t1));
  // Entirely inside.
  ASSERT_TRUE(clip_segment(V{0.5, 0.5}, V{1, 0}, u0, u1, u2, t0, t1));
  EXPECT_EQ(t0, 0.0);
  EXPECT_EQ(t1, 1.0);
}

}  // namespace
}  // namespace tridem::physics
