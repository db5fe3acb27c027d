// The pair's share of the energy budget (PairForce::elastic_energy and the dissipations):
// the force is minus the gradient of the elastic energy, and the dashpots dissipate the
// power of their own force.
#include "physics/contact_force.hpp"

#include <gtest/gtest.h>
#include <random>

namespace tridem::physics {
namespace {

using V = Vec2<double>;

Body<double> make_body(const V (&v)[3], V shift = {}, double turn = 0, V velocity = {}) {
  Body<double> body;
  const V c = (v[0] + v[1] + v[2]) / 3.0;
  const double cs = std::cos(turn), sn = std::sin(turn);
  for (int k = 0; k < 3; ++k) body.tri.v[k] = c + shift + rotate(v[k] - c, cs, sn);
  if (signed_area(body.tri) < 0) std::swap(body.tri.v[1], body.tri.v[2]);
  body.c = centroid(body.tri);
  body.v = velocity;
  body.w = 0;
  body.area = signed_area(body.tri);
  body.mass = 1;
  return body;
}

double elastic(const Body<double>& a, const Body<double>& b, const ContactLaw<double>& law) {
  PairSlip<double> slip{};
  return pair_force(a, b, law, 1e-4, slip).elastic_energy;
}

// E = p∫_Ω(φ_a + φ_b)dA is the potential of the contact force: F_a = −∂E/∂x_a and
// M_a = −∂E/∂θ_a, for random overlaps (finite differences, central).
TEST(PairEnergy, ForceIsMinusTheGradientOfTheElasticEnergy) {
  const ContactLaw<double> law{1e6, 1e5, 0, 0};
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int trial = 0; trial < 2000 && checked < 60; ++trial) {
    const V va[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const V vb[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const auto a = make_body(va), b = make_body(vb);
    if (a.area < 0.05 || b.area < 0.05) continue;
    PairSlip<double> slip{};
    const PairForce<double> f = pair_force(a, b, law, 1e-4, slip);
    if (!f.touching || f.depth > 0.5) continue;
    ++checked;
    EXPECT_GT(f.elastic_energy, 0) << "trial " << trial;
    const double h = 1e-6;
    const double dx = (elastic(make_body(va, {h, 0}), b, law) -
                       elastic(make_body(va, {-h, 0}), b, law)) / (2 * h);
    const double dy = (elastic(make_body(va, {0, h}), b, law) -
                       elastic(make_body(va, {0, -h}), b, law)) / (2 * h);
    const double dt = (elastic(make_body(va, {}, h), b, law) -
                       elastic(make_body(va, {}, -h), b, law)) / (2 * h);
    const double scale = norm(f.force_a) + std::abs(f.torque_a) + 1e-3 * law.penalty;
    EXPECT_NEAR(-dx, f.force_a.x, 1e-5 * scale) << "trial " << trial;
    EXPECT_NEAR(-dy, f.force_a.y, 1e-5 * scale) << "trial " << trial;
    EXPECT_NEAR(-dt, f.torque_a, 1e-5 * scale) << "trial " << trial;
  }
  EXPECT_GE(checked, 30);
}

TEST(PairEnergy, SeparatedOrTouchingPairsHoldNoEnergy) {
  const V va[3] = {{0, 0}, {1, 0}, {0, 1}};
  const V vb[3] = {{1, 0}, {2, 0}, {1, 1}};  // shares the vertex (1, 0)
  const ContactLaw<double> law{1e6, 1e5, 0.5, 0.3};
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(make_body(va), make_body(vb), law, 1e-4, slip);
  EXPECT_EQ(f.elastic_energy, 0);
  EXPECT_EQ(f.damping_dissipation, 0);
  EXPECT_EQ(f.friction_dissipation, 0);
}

// A pair in pure translation: every contact point has the same relative velocity, so the
// dashpots' dissipation over dt is minus the power of their force on a (damped minus
// undamped force) times dt.
TEST(PairEnergy, DashpotsDissipateThePowerOfTheirForce) {
  const V va[3] = {{0, 0}, {1, 0}, {0.5, 0.9}};
  const V vb[3] = {{0.2, 0.85}, {0.8, 0.85}, {0.5, 1.5}};
  const V v{0.3, -0.7};
  const double dt = 1e-4;
  const auto a = make_body(va, {}, 0, v), b = make_body(vb);
  PairSlip<double> s1{}, s2{};
  const PairForce<double> damped =
      pair_force(a, b, ContactLaw<double>{1e6, 1e5, 0, 0.4}, dt, s1);
  const PairForce<double> plain = pair_force(a, b, ContactLaw<double>{1e6, 1e5, 0, 0}, dt, s2);
  ASSERT_TRUE(damped.touching);
  const double expected = -dot(damped.force_a - plain.force_a, v) * dt;
  EXPECT_GT(expected, 0);
  EXPECT_NEAR(damped.damping_dissipation, expected, 1e-12 * expected);
  EXPECT_EQ(plain.damping_dissipation, 0);
  EXPECT_EQ(damped.friction_dissipation, 0) << "no friction";
}

// A sliding contact: the slider dissipates, and the springs keep ½p_t·s² at their caps.
TEST(PairEnergy, SlidingDissipatesAndTheSpringsKeepTheirEnergy) {
  const V va[3] = {{0, 0}, {1, 0}, {0.5, 0.9}};
  const V vb[3] = {{0.2, 0.85}, {0.8, 0.85}, {0.5, 1.5}};
  const double dt = 1e-3;
  const ContactLaw<double> law{1e6, 1e5, 0.3, 0};
  const auto a = make_body(va, {}, 0, {50.0, 0}), b = make_body(vb);
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(a, b, law, dt, slip);
  ASSERT_TRUE(f.touching);
  EXPECT_GT(f.friction_dissipation, 0);
  // Recompute each capped edge contact's share from the slips it kept.
  PairSlip<double> none{};
  const PairForce<double> frictionless =
      pair_force(a, b, ContactLaw<double>{1e6, 1e5, 0, 0}, dt, none);
  double spring = 0;
  for (double s : slip.s) spring += 0.5 * law.tangential_penalty * s * s;
  EXPECT_NEAR(f.elastic_energy - frictionless.elastic_energy, spring, 1e-12 * spring);
}

}  // namespace
}  // namespace tridem::physics
