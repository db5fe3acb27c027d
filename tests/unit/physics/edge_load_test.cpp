// The edge load against an independent answer: fine midpoint quadrature of Munjiza's φ
// (physics::potential, the minimum of the three linear forms) along the edge. Includes
// edges lying exactly on a line from the target's centroid to a vertex, which the former
// sub-triangle clipping counted in both sub-triangles (twice the force).
#include "physics/contact_force.hpp"
#include "physics/restitution.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <random>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using V = Vec2<double>;

struct Quadrature {
  double integral = 0;
  V moment{};
};

/// ∫ max(φ_T, 0) ds and ∫ max(φ_T, 0)·x ds along [p0, p1] by the midpoint rule.
Quadrature quadrature(V p0, V p1, const Triangle<double>& t, int n = 200000) {
  Quadrature q;
  const double area = signed_area(t);
  const double h = norm(p1 - p0) / n;
  for (int i = 0; i < n; ++i) {
    const V x = p0 + (p1 - p0) * ((i + 0.5) / n);
    const double phi = std::max(potential(t, area, x), 0.0);
    q.integral += phi * h;
    q.moment += x * (phi * h);
  }
  return q;
}

const Triangle<double> kTarget{{{-1, 0}, {1, 0}, {0, 3}}};  // centroid (0, 1): median x = 0

EdgeLoad<double> load_of(V p0, V p1, const Triangle<double>& t = kTarget) {
  return edge_load(p0, p1, target_shape(t, signed_area(t), centroid(t)));
}

TEST(EdgeLoad, EdgeOnAMedianIsCountedOnce) {
  // Along x = 0: φ = y below the centroid, (3 − y)/2 above it (two sub-triangles tie).
  const EdgeLoad<double> l = load_of({0, 0.5}, {0, 2.5});
  EXPECT_NEAR(l.integral, 0.375 + 0.9375, 1e-14);
  const Quadrature q = quadrature({0, 0.5}, {0, 2.5}, kTarget);
  EXPECT_NEAR(l.integral, q.integral, 1e-9);
  EXPECT_NEAR(l.centroid().y, q.moment.y / q.integral, 1e-9);
  EXPECT_NEAR(l.centroid().x, 0.0, 1e-15);
  // Σ 3ℓ/h: 0.5 of the edge in the bottom sub-triangle (h = 3), 1.5 in a top one
  // (h = 6/√10).
  EXPECT_NEAR(l.stiffness, 0.5 + 0.75 * std::sqrt(10.0), 1e-13);
  EXPECT_NEAR(l.peak, 1.0, 1e-15);
  // Downward along the same median, and through the vertex: the same integral.
  EXPECT_NEAR(load_of({0, 2.5}, {0, 0.5}).integral, l.integral, 1e-14);
  EXPECT_NEAR(load_of({0, -1}, {0, 4}).integral, quadrature({0, -1}, {0, 4}, kTarget).integral,
              1e-9);
}

TEST(EdgeLoad, LatticeMediansOfAnEquilateralTarget) {
  // An equilateral target placed as in a lattice: edges along its three medians, from the
  // centroid outwards and across, as neighbouring grains' edges lie in such packings.
  const double s = 0.1, hgt = s * std::sqrt(3.0) / 2;
  const Triangle<double> t{{{0, 0}, {s, 0}, {s / 2, hgt}}};
  const V c = centroid(t);
  for (int k = 0; k < 3; ++k) {
    const V v = t.v[k];
    const V p0 = c + (c - v) * 0.5, p1 = v + (v - c) * 0.25;  // crosses the whole median
    const EdgeLoad<double> l = load_of(p0, p1, t);
    const Quadrature q = quadrature(p0, p1, t);
    EXPECT_NEAR(l.integral, q.integral, 1e-9 * s) << "median " << k;
    EXPECT_NEAR(l.centroid().x, q.moment.x / q.integral, 1e-8 * s) << "median " << k;
    EXPECT_NEAR(l.centroid().y, q.moment.y / q.integral, 1e-8 * s) << "median " << k;
  }
}

TEST(EdgeLoad, RandomEdgesMatchQuadrature) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  int inside = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const V p0{u(rng), u(rng) + 1}, p1{u(rng), u(rng) + 1};
    const EdgeLoad<double> l = load_of(p0, p1);
    const Quadrature q = quadrature(p0, p1, kTarget, 20000);
    EXPECT_NEAR(l.integral, q.integral, 1e-7) << "trial " << trial;
    if (q.integral > 1e-3) {
      ++inside;
      EXPECT_NEAR(l.centroid().x, q.moment.x / q.integral, 1e-5) << "trial " << trial;
      EXPECT_NEAR(l.centroid().y, q.moment.y / q.integral, 1e-5) << "trial " << trial;
    }
  }
  EXPECT_GT(inside, 50);
}

TEST(EdgeLoad, PairOnALatticeMedianGetsTheExactForce) {
  // A contactor whose left edge lies on the target's median x = 0: the pair's potential
  // force against quadrature of both roles' edges.
  const ContactLaw<double> law = contact_law(1e6, 1e5, 0, 1);
  Body<double> a, b;
  a.tri = {{{0, 2.2}, {0, 0.6}, {0.9, 1.4}}};
  b.tri = kTarget;
  for (Body<double>* x : {&a, &b}) {
    if (signed_area(x->tri) < 0) std::swap(x->tri.v[1], x->tri.v[2]);
    x->c = centroid(x->tri);
    x->area = signed_area(x->tri);
    x->v = {};
    x->w = 0;
    x->mass = 1;
  }
  PairSlip<double> slip{};
  const PairForce<double> f = pair_force(a, b, law, 1e-4, slip);
  V expect{};
  double moment = 0;  // about a.c
  for (int role = 0; role < 2; ++role) {
    const Triangle<double>& c = role == 0 ? a.tri : b.tri;
    const Triangle<double>& t = role == 0 ? b.tri : a.tri;
    for (int e = 0; e < 3; ++e) {
      const V p0 = c.v[e], p1 = c.v[(e + 1) % 3], d = p1 - p0;
      const V n = V{d.y, -d.x} / norm(d);
      const Quadrature q = quadrature(p0, p1, t);
      const double sign = role == 0 ? -1 : 1;
      expect += n * (sign * law.penalty * q.integral);
      moment += sign * law.penalty * cross(q.moment - a.c * q.integral, n);
    }
  }
  EXPECT_NEAR(f.force_a.x, expect.x, 1e-8 * norm(expect));
  EXPECT_NEAR(f.force_a.y, expect.y, 1e-8 * norm(expect));
  EXPECT_NEAR(f.torque_a, moment, 1e-8 * norm(expect));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
