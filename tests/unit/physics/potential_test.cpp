// Munjiza's potential and its edge integral against values known by hand and against
// brute-force quadrature.
#include "physics/contact_force.hpp"

#include <gtest/gtest.h>
#include <random>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using T = Triangle<double>;
using V = Vec2<double>;

// Flat top edge from (10, 0) to (-10, 0), apex (0, -10): height 10 over the top edge.
const T kTarget{{{10, 0}, {-10, 0}, {0, -10}}};

TEST(Potential, OneAtCentroidZeroOnBoundary) {
  const double a = signed_area(kTarget);
  EXPECT_NEAR(potential(kTarget, a, centroid(kTarget)), 1.0, 1e-14);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(potential(kTarget, a, kTarget.v[k]), 0.0, 1e-14);
    EXPECT_NEAR(potential(kTarget, a, (kTarget.v[k] + kTarget.v[(k + 1) % 3]) * 0.5), 0.0,
                1e-14);
  }
  // Halfway from the top edge's midpoint to the centroid.
  EXPECT_NEAR(potential(kTarget, a, V{0, -10.0 / 6.0}), 0.5, 1e-14);
}

TEST(Potential, EdgeAtUniformDepthCarriesKnownLoad) {
  // A contactor edge of length 1 at depth d under the flat top: φ = 3d/h = 0.3 d all along.
  const double d = 0.01;
  const T contactor{{{-0.5, -d}, {0.5, -d}, {0, 1}}};
  const EdgeLoad<double> load =
      edge_load(contactor, 0, kTarget, signed_area(kTarget), centroid(kTarget));
  EXPECT_NEAR(load.integral, 0.3 * d, 1e-15);
  EXPECT_NEAR(load.centroid().x, 0.0, 1e-14);
  EXPECT_NEAR(load.centroid().y, -d, 1e-14);
  EXPECT_NEAR(load.stiffness, 3.0 * 1.0 / 10.0, 1e-14);
}

TEST(Potential, EdgeLoadMatchesQuadratureOfThePotential) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-12, 12);
  const double area = signed_area(kTarget);
  int crossing = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const V p0{u(rng), u(rng) * 0.5 - 4}, p1{u(rng), u(rng) * 0.5 - 4};
    const T contactor{{p0, p1, V{0, 50}}};
    const EdgeLoad<double> load = edge_load(contactor, 0, kTarget, area, centroid(kTarget));
    // Midpoint rule over the whole segment with φ clamped at zero outside the target.
    const int n = 20000;
    double integral = 0;
    V moment{};
    const double len = norm(p1 - p0);
    for (int i = 0; i < n; ++i) {
      const V q = p0 + (p1 - p0) * ((i + 0.5) / n);
      const double phi = std::max(0.0, potential(kTarget, area, q));
      integral += phi * len / n;
      moment += q * (phi * len / n);
    }
    EXPECT_NEAR(load.integral, integral, 1e-6 * (1 + integral)) << "trial " << trial;
    if (integral > 1e-3) {
      ++crossing;
      EXPECT_NEAR(load.centroid().x, moment.x / integral, 1e-4) << "trial " << trial;
      EXPECT_NEAR(load.centroid().y, moment.y / integral, 1e-4) << "trial " << trial;
    }
  }
  EXPECT_GT(crossing, 50);  // the test exercised real overlaps
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
