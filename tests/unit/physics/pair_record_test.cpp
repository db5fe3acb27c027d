// The GPU keeps a pair's result as a load (read every step) and a detail (read by output):
// taken apart and joined again it is the same PairForce, and the sums every backend makes
// of a row (forces, torques, energy) read the same numbers from either record.
#include "physics/pair_record.hpp"
#include "broadphase/pair_sums.hpp"
#include "broadphase/row_energy.hpp"
#include "physics/restitution.hpp"

#include <gtest/gtest.h>
#include <vector>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using V = Vec2<double>;

Body<double> body(Triangle<double> t, V v, double w) {
  Body<double> b;
  b.tri = t;
  b.c = centroid(t);
  b.area = signed_area(t);
  b.v = v;
  b.w = w;
  b.mass = 1;
  return b;
}

// A sliding, damped contact: every field of the result is non-zero.
PairForce<double> sliding_pair(double shift) {
  const auto a = body({{{-0.5 + shift, -0.02}, {0.5 + shift, -0.02}, {shift, 1}}}, {3, -0.2}, 1);
  const auto b = body({{{-2, 0}, {0, -2}, {2, -0.01}}}, {}, 0);
  PairSlip<double> slip{{50, 0}};
  return pair_force(a, b, contact_law(1e6, 1e5, 0.3, 0.5), 1e-4, slip);
}

TEST(PairRecord, LoadAndDetailJoinToTheWholeResult) {
  const PairForce<double> r = sliding_pair(0);
  ASSERT_TRUE(r.touching);
  ASSERT_TRUE(r.sliding);
  ASSERT_GT(r.damping_dissipation, 0);
  ASSERT_GT(r.friction_dissipation, 0);
  const PairForce<double> back = joined(load_of(r), detail_of(r));
  EXPECT_EQ(back.force_a.x, r.force_a.x);
  EXPECT_EQ(back.force_a.y, r.force_a.y);
  EXPECT_EQ(back.torque_a, r.torque_a);
  EXPECT_EQ(back.torque_b, r.torque_b);
  EXPECT_EQ(back.point.x, r.point.x);
  EXPECT_EQ(back.point.y, r.point.y);
  EXPECT_EQ(back.depth, r.depth);
  EXPECT_EQ(back.elastic_energy, r.elastic_energy);
  EXPECT_EQ(back.damping_dissipation, r.damping_dissipation);
  EXPECT_EQ(back.friction_dissipation, r.friction_dissipation);
  EXPECT_EQ(back.normal.x, r.normal.x);
  EXPECT_EQ(back.normal.y, r.normal.y);
  EXPECT_EQ(back.touching, r.touching);
  EXPECT_EQ(back.sliding, r.sliding);
}

TEST(PairRecord, RowSumsReadTheSameFromLoadsAsFromWholeResults) {
  // Particle 0 emits pairs 0 and 1 (to 1 and 2); particle 1 emits pair 2 (to 2).
  const std::vector<int> offset{0, 2, 3, 3}, partner{1, 2, 2};
  const std::vector<int> reverse_offset{0, 0, 1, 3}, reverse_slot{0, 1, 2};
  std::vector<PairForce<double>> whole;
  std::vector<PairLoad<double>> loads;
  for (double shift : {0.0, 0.1, -0.15}) {
    whole.push_back(sliding_pair(shift));
    loads.push_back(load_of(whole.back()));
  }
  auto moving_wall = [](std::int64_t j, Vec2d& v, double& w) {
    if (j != 2) return false;
    v = {0.1, -0.3};
    w = 0.2;
    return true;
  };
  for (int i = 0; i < 3; ++i) {
    V f_whole, f_load;
    double t_whole = 0, t_load = 0;
    tridem::sum_pair_forces(i, offset.data(), reverse_offset.data(), reverse_slot.data(),
                            whole.data(), f_whole, t_whole);
    tridem::sum_pair_forces(i, offset.data(), reverse_offset.data(), reverse_slot.data(),
                            loads.data(), f_load, t_load);
    EXPECT_EQ(f_whole.x, f_load.x);
    EXPECT_EQ(f_whole.y, f_load.y);
    EXPECT_EQ(t_whole, t_load);
    const tridem::RowEnergy a =
        tridem::row_energy(i, offset.data(), partner.data(), whole.data(), moving_wall, 1e-4);
    const tridem::RowEnergy b =
        tridem::row_energy(i, offset.data(), partner.data(), loads.data(), moving_wall, 1e-4);
    EXPECT_EQ(a.damping, b.damping);
    EXPECT_EQ(a.friction, b.friction);
    EXPECT_EQ(a.wall_work, b.wall_work);
  }
  // The rows are not empty: the comparison above compared something.
  V f;
  double t = 0;
  tridem::sum_pair_forces(0, offset.data(), reverse_offset.data(), reverse_slot.data(),
                          loads.data(), f, t);
  EXPECT_NE(f.x, 0);
}

TEST(PairRecord, AStepMovesLessThanHalfTheBytesOfAWholeResult) {
  EXPECT_LT(2 * sizeof(PairLoad<double>), sizeof(PairForce<double>) + 1);
  EXPECT_LT(2 * sizeof(PairLoad<float>), sizeof(PairForce<float>) + 1);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
