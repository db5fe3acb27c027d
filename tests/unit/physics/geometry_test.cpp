// Geometry on known cases: signs, overlaps (including the edge-crossing case the paper's
// direct area method misses) and segment clipping.
#include "physics/geometry.hpp"

#include <gtest/gtest.h>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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

/// Clips p + t·d to the CCW triangle u with the half-plane of each edge, as edge_load does.
bool clip_to_triangle(V p, V d, const T& u, double& t0, double& t1) {
  t0 = 0;
  t1 = 1;
  for (int k = 0; k < 3; ++k) {
    const V e = u.v[(k + 1) % 3] - u.v[k];
    if (!clip_to_half_plane(cross(e, p - u.v[k]), cross(e, d), t0, t1)) return false;
  }
  return true;
}

TEST(Geometry, ClipSegmentThroughTriangle) {
  const T u{{{0, 0}, {4, 0}, {0, 4}}};
  double t0 = -1, t1 = -1;
  // Horizontal line y = 1 from x = -1 to x = 5: inside for x in [0, 3].
  ASSERT_TRUE(clip_to_triangle(V{-1, 1}, V{6, 0}, u, t0, t1));
  EXPECT_NEAR(t0, 1.0 / 6.0, 1e-15);
  EXPECT_NEAR(t1, 4.0 / 6.0, 1e-15);
  // Entirely outside, and parallel to an edge outside it.
  EXPECT_FALSE(clip_to_triangle(V{-1, 5}, V{6, 0}, u, t0, t1));
  EXPECT_FALSE(clip_to_triangle(V{-1, -1}, V{6, 0}, u, t0, t1));
  // Entirely inside.
  ASSERT_TRUE(clip_to_triangle(V{0.5, 0.5}, V{1, 0}, u, t0, t1));
  EXPECT_EQ(t0, 0.0);
  EXPECT_EQ(t1, 1.0);
  // Touching at one point only leaves nothing of positive length.
  EXPECT_FALSE(clip_to_triangle(V{-1, 4}, V{2, 0}, u, t0, t1));  // through the vertex (0, 4)
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
