// The energy quantities of a pair (PairForce::elastic_energy, damping_dissipation,
// friction_dissipation): the stored energy against the work of the force along a path, and
// the dissipation of dashpots and of sliding against their definitions.
#include "physics/contact_force.hpp"
#include "physics/restitution.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using V = Vec2<double>;

Body<double> make_body(Triangle<double> t, V v = {}, double w = 0, double mass = 1) {
  Body<double> b;
  b.tri = t;
  if (signed_area(b.tri) < 0) std::swap(b.tri.v[1], b.tri.v[2]);
  b.c = centroid(b.tri);
  b.area = signed_area(b.tri);
  b.v = v;
  b.w = w;
  b.mass = mass;
  return b;
}

Body<double> moved(Body<double> b, V shift) {
  for (V& v : b.tri.v) v += shift;
  b.c += shift;
  return b;
}

TEST(PairEnergy, FlatContactStoresTheNormalPotential) {
  // A wide contactor face at depth d in a wide floor: Ω is (up to corners of order d²) a
  // strip ℓ × d where φ_b = 3y/h_b and φ_a = 3(d − y)/h_a, so E = 1.5·p·ℓ·d²·(1/h_a + 1/h_b).
  const double d = 1e-4, p = 1e6;
  const auto floor = make_body({{{10, 0}, {-10, 0}, {0, -10}}}, {}, 0, 0);
  const auto c = make_body({{{-0.5, -d}, {0.5, -d}, {0, 1 - d}}});
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(c, floor, contact_law(p, 1e5, 0, 1), 1e-4, slip);
  const double h_floor = 10, h_c = 1;
  const double expect = 1.5 * p * 1.0 * d * d * (1 / h_floor + 1 / h_c);
  EXPECT_NEAR(f.elastic_energy, expect, 2e-3 * expect);
}

TEST(PairEnergy, ElasticEnergyIsMinusTheWorkOfTheForce) {
  // Frictionless, undamped: moving a through the overlap in small steps, the change of the
  // stored energy equals minus the work of the force on a (midpoint rule).
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0, 1);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto a0 = make_body({{{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}});
    const auto b = make_body({{{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}});
    if (a0.area < 0.05 || b.area < 0.05) continue;
    const V step = V{u(rng), u(rng)} * 2e-5;
    const int n = 2000;
    double work = 0;
    PairSlip<double> slip{};
    Body<double> a = a0;
    PairForce<double> f = pair_force(a, b, law, 1e-4, slip);
    const double e0 = f.elastic_energy;
    for (int i = 0; i < n; ++i) {
      const Body<double> next = moved(a, step);
      const PairForce<double> g = pair_force(next, b, law, 1e-4, slip);
      work += dot((f.force_a + g.force_a) * 0.5, step);
      a = next;
      f = g;
    }
    const double change = f.elastic_energy - e0;
    if (std::abs(change) < 1e-6 * law.penalty * 1e-6) continue;
    ++checked;
    const double scale = std::abs(work) + std::abs(change) + 1e-3;
    EXPECT_NEAR(change, -work, 2e-4 * scale) << "trial " << trial;
  }
  EXPECT_GT(checked, 10);
}

/// Munjiza's potential of triangle t at x: 3·min_k(area of (x, v_k, v_k+1))/area, 1 at the
/// centroid, 0 on the edges, negative outside.
double potential(const Triangle<double>& t, V x) {
  const double area = signed_area(t);
  double least = 1e300;
  for (int k = 0; k < 3; ++k)
    least = std::min(least, 0.5 * twice_signed_area(x, t.v[k], t.v[(k + 1) % 3]));
  return 3 * least / area;
}

/// p·∫_Ω (φ_a + φ_b) dA by the midpoint rule on an n × n grid over the two boxes' overlap.
double integrated_energy(const Body<double>& a, const Body<double>& b, double p, int n) {
  V lo{-1e300, -1e300}, hi{1e300, 1e300};
  for (const Body<double>* body : {&a, &b}) {
    V blo{1e300, 1e300}, bhi{-1e300, -1e300};
    for (const V& v : body->tri.v) {
      blo = {std::min(blo.x, v.x), std::min(blo.y, v.y)};
      bhi = {std::max(bhi.x, v.x), std::max(bhi.y, v.y)};
    }
    lo = {std::max(lo.x, blo.x), std::max(lo.y, blo.y)};
    hi = {std::min(hi.x, bhi.x), std::min(hi.y, bhi.y)};
  }
  const double hx = (hi.x - lo.x) / n, hy = (hi.y - lo.y) / n;
  double sum = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const V x{lo.x + (i + 0.5) * hx, lo.y + (j + 0.5) * hy};
      const double pa = potential(a.tri, x), pb = potential(b.tri, x);
      if (pa > 0 && pb > 0) sum += pa + pb;
    }
  return p * sum * hx * hy;
}

/// Each vertex of t scaled by `s` about its centroid.
Triangle<double> enlarged(Triangle<double> t, double s) {
  const V c = centroid(t);
  for (V& v : t.v) v = c + (v - c) * s;
  return t;
}

// The stored energy is p∫_Ω(φ_a + φ_b): checked against that integral on lattice neighbours
// enlarged into each other, whose overlap has sides along both triangles' edges at once (a
// vertex-sharing pair's bottoms are collinear), and the same pairs turned and carried far
// from the origin. The stored energy once summed the loaded pieces' cross products for |Ω|,
// which left out such collinear sides: -96 J/m for a pair whose mirror image stored 0.0004.
TEST(PairEnergy, StoredEnergyIsTheIntegralOfBothPotentials) {
  const double p = 1e6, h = std::sqrt(3.0) / 2;
  const ContactLaw<double> law = contact_law(p, 1e5, 0, 1);
  const Triangle<double> up{{{0, 0}, {1, 0}, {0.5, h}}};
  const struct {
    const char* name;
    Triangle<double> other;
  } pairs[] = {{"edge-sharing", {{{1, 0}, {1.5, h}, {0.5, h}}}},
               {"vertex-sharing, bottoms collinear", {{{1, 0}, {2, 0}, {1.5, h}}}},
               {"apex on apex", {{{0.5, h}, {1.5, h}, {1, 2 * h}}}},
               {"apex beside apex", {{{-0.5, h}, {0.5, h}, {0, 2 * h}}}}};
  for (const auto& pair : pairs)
    for (double scale : {1.01, 1.1})
      for (double turn : {0.0, 0.7})
        for (double far : {0.0, 1e3}) {
          const double c = std::cos(turn), sn = std::sin(turn);
          auto placed = [&](Triangle<double> t) {
            for (V& v : t.v) v = V{c * v.x - sn * v.y + far, sn * v.x + c * v.y - 0.5 * far};
            return make_body(enlarged(t, scale));
          };
          const Body<double> a = placed(up), b = placed(pair.other);
          PairSlip<double> slip{};
          const PairForce<double> f = pair_force(a, b, law, 1e-4, slip);
          const double expect = integrated_energy(a, b, p, 1500);
          EXPECT_GT(f.elastic_energy, 0) << pair.name;
          EXPECT_NEAR(f.elastic_energy, expect, 1e-2 * expect + 1e-9 * p)
              << pair.name << ", scale " << scale << ", turned " << turn << ", at " << far;
        }
}

TEST(PairEnergy, SlidingDissipatesMuTimesNormalForceTimesSlip) {
  // Steady sliding: after the first step the spring sits at the cap, so each step's slip
  // is the whole tangential displacement v·dt.
  const double d = 1e-3, v = 50, dt = 1e-3;  // k_t·v·dt far above μ·f_n: sliding
  const auto floor = make_body({{{10, 0}, {-10, 0}, {0, -10}}}, {}, 0, 0);
  const auto c = make_body({{{-0.5, -d}, {0.5, -d}, {0, 1}}}, {v, 0});
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0.4, 1);
  PairSlip<double> slip{};
  pair_force(c, floor, law, dt, slip);
  const PairForce<double> f = pair_force(c, floor, law, dt, slip);
  EXPECT_NEAR(f.force_a.x, -0.4 * f.force_a.y, 1e-12 * f.force_a.y);
  EXPECT_NEAR(f.friction_dissipation, 0.4 * f.force_a.y * v * dt, 1e-9 * f.friction_dissipation);
  EXPECT_EQ(f.damping_dissipation, 0.0);  // e = 1: no dashpot
}

TEST(PairEnergy, DashpotsDissipateWhatTheyTakeAndStickingStoresTheSpring) {
  // A slow approach with damping: the normal dashpot takes c·v_n²·dt >= 0; a sticking
  // tangential displacement stores ½·k_t·ξ².
  const double d = 1e-3, dt = 1e-4;
  const auto floor = make_body({{{10, 0}, {-10, 0}, {0, -10}}}, {}, 0, 0);
  const auto c = make_body({{{-0.5, -d}, {0.5, -d}, {0, 1}}}, {1e-4, -0.01});
  const ContactLaw<double> damped = contact_law(1e6, 1e5, 0.5, 0.5);
  const ContactLaw<double> plain = contact_law(1e6, 1e5, 0.5, 1);
  PairSlip<double> s1{}, s2{};
  const PairForce<double> f = pair_force(c, floor, damped, dt, s1);
  const PairForce<double> g = pair_force(c, floor, plain, dt, s2);
  EXPECT_GT(f.damping_dissipation, 0.0);
  EXPECT_EQ(f.friction_dissipation, 0.0);
  // The normal dashpot adds c·v_n along y: its power is (f_y − g_y)·|v_y| and the
  // tangential one c_t·v_t².
  const double normal_part = (f.force_a.y - g.force_a.y) * 0.01 * dt;
  const double tangential_part = -(f.force_a.x - g.force_a.x) * 1e-4 * dt;
  EXPECT_NEAR(f.damping_dissipation, normal_part + tangential_part,
              1e-9 * f.damping_dissipation);
  // Spring energy: ½|u|² = ½k_t·ξ² with ξ = v_t·dt (u = √k_t·ξ; g has no dashpot), and
  // the spring force k_t·ξ = u²/ξ.
  EXPECT_NEAR(-g.force_a.x, s2.s[0] * s2.s[0] / (1e-4 * dt), 1e-9 * std::abs(g.force_a.x));
  EXPECT_NEAR(g.elastic_energy - (f.elastic_energy - 0.5 * s1.s[0] * s1.s[0]),
              0.5 * s2.s[0] * s2.s[0], 1e-12 * g.elastic_energy);
}

/// (From the energy budget's own tests, merged: bodies given by vertices, shifted and
/// turned about their centroid.)
Body<double> make_turned_body(const V (&v)[3], V shift = {}, double turn = 0, V velocity = {}) {
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
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0, 1);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int trial = 0; trial < 2000 && checked < 60; ++trial) {
    const V va[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const V vb[3] = {{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}};
    const auto a = make_turned_body(va), b = make_turned_body(vb);
    if (a.area < 0.05 || b.area < 0.05) continue;
    PairSlip<double> slip{};
    const PairForce<double> f = pair_force(a, b, law, 1e-4, slip);
    if (!f.touching || f.depth > 0.5) continue;
    ++checked;
    EXPECT_GT(f.elastic_energy, 0) << "trial " << trial;
    const double h = 1e-6;
    const double dx = (elastic(make_turned_body(va, {h, 0}), b, law) -
                       elastic(make_turned_body(va, {-h, 0}), b, law)) / (2 * h);
    const double dy = (elastic(make_turned_body(va, {0, h}), b, law) -
                       elastic(make_turned_body(va, {0, -h}), b, law)) / (2 * h);
    const double dt = (elastic(make_turned_body(va, {}, h), b, law) -
                       elastic(make_turned_body(va, {}, -h), b, law)) / (2 * h);
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
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0.5, 0.4);
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(make_turned_body(va), make_turned_body(vb), law, 1e-4, slip);
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
  const auto a = make_turned_body(va, {}, 0, v), b = make_turned_body(vb);
  PairSlip<double> s1{}, s2{};
  const PairForce<double> damped =
      pair_force(a, b, contact_law(1e6, 1e5, 0, 0.3), dt, s1);
  const PairForce<double> plain = pair_force(a, b, contact_law(1e6, 1e5, 0, 1), dt, s2);
  ASSERT_TRUE(damped.touching);
  const double expected = -dot(damped.force_a - plain.force_a, v) * dt;
  EXPECT_GT(expected, 0);
  EXPECT_NEAR(damped.damping_dissipation, expected, 1e-12 * expected);
  EXPECT_EQ(plain.damping_dissipation, 0);
  EXPECT_EQ(damped.friction_dissipation, 0) << "no friction";
}

// A sliding contact: the slider dissipates, and the spring keeps ½|u|² = ½k_t·|ξ|² at its
// cap, where k_t·|ξ| = |f_t| = μ·f_n (one contact per pair since issue 10).
TEST(PairEnergy, SlidingDissipatesAndTheSpringsKeepTheirEnergy) {
  const V va[3] = {{0, 0}, {1, 0}, {0.5, 0.9}};
  const V vb[3] = {{0.2, 0.85}, {0.8, 0.85}, {0.5, 1.5}};
  const double dt = 1e-3;
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0.3, 1);
  const auto a = make_turned_body(va, {}, 0, {50.0, 0}), b = make_turned_body(vb);
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(a, b, law, dt, slip);
  ASSERT_TRUE(f.touching);
  EXPECT_GT(f.friction_dissipation, 0);
  PairSlip<double> none{};
  const PairForce<double> frictionless =
      pair_force(a, b, contact_law(1e6, 1e5, 0, 1), dt, none);
  const double f_t = norm(f.force_a - frictionless.force_a);
  EXPECT_NEAR(f_t, 0.3 * norm(frictionless.force_a), 1e-12 * f_t);
  const double spring = 0.5 * (slip.s[0] * slip.s[0] + slip.s[1] * slip.s[1]);  // ½|u|²
  EXPECT_NEAR(f.elastic_energy - frictionless.elastic_energy, spring, 1e-9 * spring);
}

/// Every result of a pair but its stored energy, and its new history.
template <class Real>
std::vector<Real> compared(const PairForce<Real>& f, const PairSlip<Real>& h) {
  return {f.force_a.x,
          f.force_a.y,
          f.torque_a,
          f.torque_b,
          f.point.x,
          f.point.y,
          f.depth,
          f.damping_dissipation,
          f.friction_dissipation,
          f.normal.x,
          f.normal.y,
          h.s[0],
          h.s[1]};
}

// The steps whose results nobody reads skip the stored energy (pair_force<false>, issue 12):
// everything else must be the same bits, in double and float, touching, sliding and apart.
template <class Real>
void expect_energy_free_force_is_the_same(std::uint64_t seed) {
  using R = Vec2<Real>;
  const ContactLaw<Real> law = law_cast<Real>(contact_law(1e6, 1e5, 0.4, 0.5));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  int touching = 0, sliding = 0;
  for (int trial = 0; trial < 400; ++trial) {
    Body<Real> body[2];
    for (Body<Real>& b : body) {
      const auto d = make_body({{{u(rng), u(rng)}, {u(rng), u(rng)}, {u(rng), u(rng)}}},
                               V{u(rng), u(rng)}, u(rng), 1 + u(rng) * u(rng));
      for (int k = 0; k < 3; ++k) b.tri.v[k] = R{Real(d.tri.v[k].x), Real(d.tri.v[k].y)};
      b.c = centroid(b.tri);
      b.area = signed_area(b.tri);
      b.v = R{Real(d.v.x), Real(d.v.y)};
      b.w = Real(d.w);
      b.mass = Real(d.mass);
    }
    if (!(body[0].area > Real(0.01)) || !(body[1].area > Real(0.01))) continue;
    // Springs of up to some 10^5 N: some pairs stick, some slide.
    const PairSlip<Real> history{{Real(300 * u(rng)), Real(300 * u(rng))}};
    PairSlip<Real> with = history, without = history;
    const PairForce<Real> f = pair_force<true>(body[0], body[1], law, Real(1e-4), with);
    const PairForce<Real> g = pair_force<false>(body[0], body[1], law, Real(1e-4), without);
    touching += f.touching;
    sliding += f.sliding;
    EXPECT_EQ(g.elastic_energy, Real(0));
    const std::vector<Real> f_fields = compared(f, with), g_fields = compared(g, without);
    EXPECT_EQ(std::memcmp(f_fields.data(), g_fields.data(), f_fields.size() * sizeof(Real)), 0)
        << "trial " << trial;
    EXPECT_EQ(f.touching, g.touching);
    EXPECT_EQ(f.sliding, g.sliding);
    if (f.touching) {
      EXPECT_NE(f.elastic_energy, Real(0)) << "trial " << trial;
    }
  }
  EXPECT_GT(touching, 50);
  EXPECT_GT(sliding, 10);
}

TEST(PairEnergy, WithoutEnergyTheForceAndHistoryAreTheSameBits) {
  expect_energy_free_force_is_the_same<double>(5);
  expect_energy_free_force_is_the_same<float>(6);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
