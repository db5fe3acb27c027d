// The live view's wire format (docs/live-view.md): the bytes the page reads, checked field
// by field on a hand-made state whose answers are known.
#include "live/frame_encoder.hpp"

#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <limits>

namespace tridem::live {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// Triangle k: local vertices L_k turned by theta_k about centroid c_k. 0 and 1 free,
/// 2 a fixed wall.
Snapshot three_triangles() {
  Snapshot s;
  s.resize(3);
  s.step = 1234567;
  s.time = 0.125;
  const double local[3][6] = {
      {-1, -1, 2, -1, -1, 2}, {0.5, -0.25, 0, 0.5, -0.5, -0.25}, {-3, -0.5, 3, -0.5, 0, 1}};
  const double cx[3] = {1, 4, 0}, cy[3] = {2, 2.5, -1}, th[3] = {0.5, -1.25, 0};
  for (std::size_t k = 0; k < 3; ++k) {
    s.x[k] = cx[k];
    s.y[k] = cy[k];
    s.theta[k] = th[k];
    const double c = std::cos(th[k]), sn = std::sin(th[k]);
    double* vx[3] = {&s.x1[k], &s.x2[k], &s.x3[k]};
    double* vy[3] = {&s.y1[k], &s.y2[k], &s.y3[k]};
    for (int v = 0; v < 3; ++v) {
      *vx[v] = cx[k] + c * local[k][2 * v] - sn * local[k][2 * v + 1];
      *vy[v] = cy[k] + sn * local[k][2 * v] + c * local[k][2 * v + 1];
    }
    s.material[k] = static_cast<int>(k);
  }
  s.vx = {3, 0, 0};
  s.vy = {4, -0.5, 0};
  s.fx = {1, 2, -6};
  s.fy = {0, 0, 8};
  s.motion = {Motion::Free, Motion::Free, Motion::Fixed};
  return s;
}

template <class T>
T at(const std::string& bytes, std::size_t offset) {
  T v{};
  EXPECT_LE(offset + sizeof(T), bytes.size());
  std::memcpy(&v, bytes.data() + offset, sizeof(T));
  return v;
}

TEST(LiveFrameEncoder, GeometryIsEachTriangleAboutItsCentroidAtAngleZero) {
  const std::string g = encode_geometry(three_triangles());
  ASSERT_EQ(g.size(), 16U + 3 * (24 + 12));
  EXPECT_EQ(at<std::uint32_t>(g, 0), kGeometryMessage);
  EXPECT_EQ(at<std::uint32_t>(g, 4), 3U);
  EXPECT_EQ(at<std::uint32_t>(g, 8), 0U);  // no bodies, no bonds
  const double local1[6] = {0.5, -0.25, 0, 0.5, -0.5, -0.25};
  for (int v = 0; v < 6; ++v)
    EXPECT_NEAR(at<float>(g, 16 + 24 + 4 * static_cast<std::size_t>(v)), local1[v], 1e-6) << v;
  const std::size_t ids = 16 + 24 * 3;
  for (std::uint32_t k = 0; k < 3; ++k) {
    EXPECT_EQ(at<std::uint32_t>(g, ids + 4 * k), k);       // material
    EXPECT_EQ(at<std::uint32_t>(g, ids + 12 + 4 * k), k);  // body: its own
  }
  EXPECT_EQ(at<std::uint32_t>(g, ids + 24 + 8), 1U);  // motion of the wall: fixed
}

TEST(LiveFrameEncoder, FrameCarriesPosesFieldsRangesAndWallForce) {
  const Snapshot s = three_triangles();
  EnergyRow e;
  e.kinetic = 2.5;
  e.budget.dissipated_friction = 0.25;
  e.budget.dissipated_local = 0.5;
  FrameData f;
  fill_frame(s, e, f);
  EXPECT_DOUBLE_EQ(f.wall_fx, -6);  // only the fixed triangle's force
  EXPECT_DOUBLE_EQ(f.wall_fy, 8);
  EXPECT_DOUBLE_EQ(f.dissipated, 0.75);
  const std::string b = encode_frame(f);
  ASSERT_EQ(b.size(), 32U + 2 * 8 + 3 * 4 * 5);
  EXPECT_EQ(at<std::uint32_t>(b, 0), kFrameMessage);
  EXPECT_EQ(at<std::uint32_t>(b, 4), 3U);
  EXPECT_EQ(at<std::uint32_t>(b, 8), 2U);  // speed and force
  EXPECT_EQ(at<double>(b, 16), 0.125);
  EXPECT_EQ(at<std::int64_t>(b, 24), 1234567);
  // Ranges over the free triangles (not the wall's 0 speed and force 10): speed 0.5 .. 5,
  // force 1 .. 2.
  EXPECT_FLOAT_EQ(at<float>(b, 32), 0.5);
  EXPECT_FLOAT_EQ(at<float>(b, 36), 5);
  EXPECT_FLOAT_EQ(at<float>(b, 40), 1);
  EXPECT_FLOAT_EQ(at<float>(b, 44), 2);
  const std::size_t base = 48;
  EXPECT_FLOAT_EQ(at<float>(b, base + 4), 4);           // x[1]
  EXPECT_FLOAT_EQ(at<float>(b, base + 12 + 4), 2.5);    // y[1]
  EXPECT_FLOAT_EQ(at<float>(b, base + 24 + 4), -1.25);  // angle[1]
  EXPECT_FLOAT_EQ(at<float>(b, base + 36), 5);          // speed[0]
  EXPECT_FLOAT_EQ(at<float>(b, base + 36 + 4), 0.5);    // speed[1]
  EXPECT_FLOAT_EQ(at<float>(b, base + 48 + 8), 10);     // force[2]
}

TEST(LiveFrameEncoder, BondDamageIsTheLargestOfATrianglesBonds) {
  Snapshot s = three_triangles();
  s.bond_a = {0, 1};
  s.bond_b = {1, 2};
  s.bond_damage = {0.25, 0.75};
  FrameData f;
  fill_frame(s, EnergyRow{}, f);
  ASSERT_EQ(f.fields.size(), 3U);
  EXPECT_FLOAT_EQ(f.fields[2][0], 0.25F);
  EXPECT_FLOAT_EQ(f.fields[2][1], 0.75F);
  EXPECT_FLOAT_EQ(f.fields[2][2], 0.75F);
  EXPECT_EQ(at<std::uint32_t>(encode_geometry(s), 8), kHasBonds);
}

TEST(LiveFrameEncoder, RefillReusesTheBuffersAndNonFiniteValuesBecomeZeroOrNull) {
  Snapshot s = three_triangles();
  FrameData f;
  fill_frame(s, EnergyRow{}, f);
  const float* x = f.x.data();
  const float* speed = f.fields[0].data();
  s.vx[1] = std::numeric_limits<double>::quiet_NaN();
  EnergyRow e;
  e.kinetic = std::numeric_limits<double>::infinity();
  fill_frame(s, e, f);
  EXPECT_EQ(f.x.data(), x);  // no allocation in the stepping thread once sized
  EXPECT_EQ(f.fields[0].data(), speed);
  EXPECT_EQ(f.fields[0][1], 0.0F);
  const std::string stats = encode_stats(f, true, 30);
  EXPECT_NE(stats.find("\"kinetic\":null"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"paused\":true"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"step\":1234567"), std::string::npos) << stats;
  EXPECT_NE(stats.find("\"wall_fy\":8"), std::string::npos) << stats;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::live
