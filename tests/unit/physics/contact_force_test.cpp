// The pair force: action and reaction, balance of moments, symmetry of the roles, and the
// friction spring-slider.
#include "physics/contact_force.hpp"
#include "physics/restitution.hpp"

#include <gtest/gtest.h>
#include <random>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using V = Vec2<double>;

Body<double> make_body(V a, V b, V c, V v = {}, double w = 0, double mass = 1) {
  Body<double> body;
  body.tri = {{a, b, c}};
  if (signed_area(body.tri) < 0) std::swap(body.tri.v[1], body.tri.v[2]);
  body.c = centroid(body.tri);
  body.v = v;
  body.w = w;
  body.area = signed_area(body.tri);
  body.mass = mass;
  return body;
}

/// Calibrated at the first use, not at the start of every process of the suite (a
/// restitution's calibration was a tenth of each test's start under the sanitizers).
const ContactLaw<double>& law() {
  static const ContactLaw<double> calibrated = contact_law(1e6, 1e5, 0.5, 0.4);
  return calibrated;
}

TEST(ContactForce, SeparatedPairHasNoForceAndDropsSlip) {
  const auto a = make_body({0, 0}, {1, 0}, {0, 1});
  const auto b = make_body({3, 0}, {4, 0}, {3, 1});
  PairSlip<double> slip{{1, 2}};
  const PairForce<double> f = pair_force(a, b, law(), 1e-4, slip);
  EXPECT_FALSE(f.touching);
  EXPECT_EQ(f.force_a.x, 0.0);
  for (double s : slip.s) EXPECT_EQ(s, 0.0);
}

TEST(ContactForce, MomentsBalanceForRandomOverlaps) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int touching = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const V shift{0.6 * u(rng), 0.6 * u(rng)};
    const auto a = make_body({u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)},
                             {u(rng), u(rng)}, u(rng));
    const auto b = make_body(V{u(rng), u(rng)} + shift, V{u(rng), u(rng)} + shift,
                             V{u(rng), u(rng)} + shift, {u(rng), u(rng)}, u(rng));
    if (a.area < 1e-3 || b.area < 1e-3) continue;
    PairSlip<double> slip{{1e-3 * u(rng), 1e-3 * u(rng)}};
    const PairForce<double> f = pair_force(a, b, law(), 1e-3, slip);
    if (!f.touching) continue;
    ++touching;
    // b receives −force_a; the total moment about the origin must vanish.
    const double moment =
        f.torque_a + f.torque_b + cross(a.c, f.force_a) + cross(b.c, -f.force_a);
    const double scale = norm(f.force_a) * 4 + std::abs(f.torque_a) + std::abs(f.torque_b);
    EXPECT_NEAR(moment, 0.0, 1e-12 * scale) << "trial " << trial;
  }
  EXPECT_GT(touching, 100);
}

TEST(ContactForce, SwappingRolesReversesTheForce) {
  ContactLaw<double> frictionless = law();
  frictionless.friction = 0;
  for (double& z : frictionless.damping) z = 0;
  const auto a = make_body({0, 0}, {1, 0}, {0.3, 1});
  const auto b = make_body({0.5, 0.7}, {1.5, 0.6}, {1.0, 1.8});
  PairSlip<double> s1{}, s2{};
  const auto ab = pair_force(a, b, frictionless, 1e-4, s1);
  const auto ba = pair_force(b, a, frictionless, 1e-4, s2);
  ASSERT_TRUE(ab.touching);
  EXPECT_NEAR(ab.force_a.x, -ba.force_a.x, 1e-9);
  EXPECT_NEAR(ab.force_a.y, -ba.force_a.y, 1e-9);
  EXPECT_NEAR(ab.torque_a, ba.torque_b, 1e-9);
  EXPECT_NEAR(ab.torque_b, ba.torque_a, 1e-9);
}

TEST(ContactForce, FlatContactPushesApartWithPotentialForce) {
  // Contactor's bottom edge of length 1 at depth d into a wide flat target (height 10):
  // both roles push the contactor up.
  const double d = 1e-3;
  const auto target = make_body({10, 0}, {-10, 0}, {0, -10}, {}, 0, 0);
  const auto c = make_body({-0.5, -d}, {0.5, -d}, {0, 1});
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0, 1);
  PairSlip<double> slip{};
  const auto f = pair_force(c, target, law, 1e-4, slip);
  EXPECT_NEAR(f.force_a.x, 0.0, 1e-6);
  // Lower bound: the contactor edge alone gives p·0.3·d.
  EXPECT_GT(f.force_a.y, law.penalty * 0.3 * d);
}

TEST(ContactForce, FrictionSpringSticksThenSlides) {
  const double d = 1e-3;
  const auto target = make_body({10, 0}, {-10, 0}, {0, -10}, {}, 0, 0);
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0.5, 1);
  // Slow tangential motion: the spring force −p_t·s stays under the cap.
  {
    const auto c = make_body({-0.5, -d}, {0.5, -d}, {0, 1}, {1e-3, 0});
    PairSlip<double> slip{};
    const auto f = pair_force(c, target, law, 1e-3, slip);
    EXPECT_LT(f.force_a.x, 0.0);       // opposes the motion
    // The history is u = √k_t·ξ along the contact's tangent x, ξ = v·dt = 1e-6, and the
    // spring force −√k_t·u: so u² = −f_x·ξ.
    EXPECT_GT(slip.s[0], 0.0);
    EXPECT_NEAR(slip.s[0] * slip.s[0], -f.force_a.x * 1e-6, 1e-12 * slip.s[0] * slip.s[0]);
    EXPECT_NEAR(slip.s[1], 0.0, 1e-15);
  }
  // Fast motion (k_t·v·dt far above μN): the tangential force is capped at μ·N and the
  // displacement is reset to match. One contact on the normal's tangent: exact.
  {
    const auto c = make_body({-0.5, -d}, {0.5, -d}, {0, 1}, {100, 0});
    PairSlip<double> slip{};
    const auto f = pair_force(c, target, law, 1e-3, slip);
    EXPECT_NEAR(f.force_a.x, -0.5 * f.force_a.y, 1e-12 * f.force_a.y);
    // The spring keeps ξ = μ·f_n/k_t of the step's 0.1 m; the rest slid. √k_t = |f_x|/u.
    EXPECT_GT(slip.s[0], 0.0);
    const double kept = slip.s[0] * slip.s[0] / std::abs(f.force_a.x);
    EXPECT_NEAR(f.friction_dissipation, 0.5 * f.force_a.y * (100 * 1e-3 - kept),
                1e-9 * f.friction_dissipation);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
