// The rules both backends call (one function each): the emitter rule, the box test, the
// degeneracy threshold, the carrying of contact history, and the contact law's edge
// stiffness that the time step is bounded with.
#include "broadphase/emitter_rule.hpp"
#include "broadphase/history_carry.hpp"
#include "physics/contact_laws.hpp"
#include "physics/geometry.hpp"
#include "physics/local_frame.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(EmitterRule, LowerIndexEmitsAmongSmallTheSmallOneAgainstAWall) {
  EXPECT_TRUE(emits_pair(1, 2, true, true, true, true));
  EXPECT_FALSE(emits_pair(2, 1, true, true, true, true));
  EXPECT_TRUE(emits_pair(5, 2, true, false, true, false));   // small 5 emits to wall 2
  EXPECT_FALSE(emits_pair(2, 5, false, true, false, true));  // a wall emits nothing
  EXPECT_FALSE(emits_pair(1, 2, true, true, false, false));  // two walls: no pair
  EXPECT_TRUE(emits_pair(1, 2, true, true, false, true));
}

TEST(BoxTest, TouchingBoxesOverlap) {
  const auto a = physics::box_of(0.0, 0.0, 1.0, 1.0);
  EXPECT_TRUE(physics::boxes_overlap(a, physics::box_of(1.0, 0.5, 2.0, 2.0)));
  EXPECT_FALSE(physics::boxes_overlap(a, physics::box_of(1.0 + 1e-12, 0.5, 2.0, 2.0)));
  EXPECT_FALSE(physics::boxes_overlap(a, physics::box_of(0.0, -2.0, 1.0, -1e-12)));
}

TEST(Degenerate, ThresholdIsRelativeToTheLongestEdgeAndRefusesNaN) {
  EXPECT_TRUE(physics::is_degenerate(1e-12, 1.0));
  EXPECT_FALSE(physics::is_degenerate(2e-12, 1.0));
  EXPECT_FALSE(physics::is_degenerate(2e-20, 1e-8));  // scale-free
  EXPECT_TRUE(physics::is_degenerate(std::nan(""), 1.0));
}

TEST(HistoryCarry, PairsKeepTheirOldHistoryNewPairsStartAtZero) {
  using Slip = physics::PairSlip<double>;
  const std::vector<std::int32_t> old_partner = {2, 4, 7, 9};
  const std::vector<Slip> old_slip = {{{1, 1}}, {{2, -0.0}}, {{3, 3}}, {{4, 4}}};
  // The emitter's old row is slots 1..3 (partners 4, 7, 9): slot 0 belongs to another row.
  OldRow<std::int64_t, Slip> row{old_partner.data(), old_slip.data(), 1, 4};
  const Slip for_2 = row.history_of(2);  // in another row's slot: not this row's
  EXPECT_EQ(for_2.s[0], 0);
  const Slip for_4 = row.history_of(4);
  EXPECT_EQ(for_4.s[0], 2);
  EXPECT_TRUE(std::signbit(for_4.s[1])) << "-0.0 is history and is kept";
  EXPECT_EQ(row.history_of(5).s[0], 0);  // new pair
  EXPECT_EQ(row.history_of(9).s[0], 4);  // 7 left behind
  EXPECT_EQ(row.history_of(11).s[1], 0);
}

TEST(PlacedBody, VerticesAndOutwardBoxOfAPose) {
  const Vec2<float> body_frame[3] = {{1, 0}, {0, 1}, {-1, -1}};
  const physics::PlacedBody<float> b =
      physics::place_body(Vec2d{1e4, 0}, 0.5 * M_PI, body_frame, 1.0f);
  EXPECT_NEAR(b.rel[0].x, 0, 1e-6);
  EXPECT_NEAR(b.rel[0].y, 1, 1e-6);
  for (const auto& v : b.rel) {
    EXPECT_LE(static_cast<float>(b.box.lo.x), 1e4 + v.x);
    EXPECT_GE(static_cast<float>(b.box.hi.x), 1e4 + v.x);
  }
}

TEST(ContactLawSeam, EdgeStiffnessIsThePotentialLawsBound) {
  physics::LawParameters<double> law{2e6, 4e5, 0.5, {0.1, 0.3, 0.2}};
  const auto k = physics::SceneContactLaw::edge_stiffness(law, 0.01, 0.02);
  EXPECT_DOUBLE_EQ(k.normal, 3 * 2e6 * (1 / 0.01 + 1 / 0.02));
  EXPECT_DOUBLE_EQ(k.tangential_ratio, 0.2);
  EXPECT_DOUBLE_EQ(k.damping_ratio, 0.3);
  law.friction = 0;  // the tangential spring is capped at μ·f_n = 0: inert
  EXPECT_EQ(physics::SceneContactLaw::edge_stiffness(law, 0.01, 0.02).tangential_ratio, 0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
