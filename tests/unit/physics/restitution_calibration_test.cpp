// The calibration of the dashpot (physics/restitution.hpp, damping.hpp): the integrated
// impact equation agrees with the closed form of the linear contact, the calibrated ζ
// gives back the asked restitution at every node, and the bound covers every shape.
#include "physics/damping.hpp"
#include "physics/restitution.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(RestitutionCalibration, IntegratedLinearContactMatchesTheClosedForm) {
  for (double zeta : {0.05, 0.2, 0.5, 0.8})
    EXPECT_NEAR(restitution_for(zeta, 1.0), restitution_of_damping_ratio(zeta), 1e-6)
        << "zeta " << zeta;
}

TEST(RestitutionCalibration, CalibratedDampingGivesTheRestitutionBack) {
  for (double e : {0.1, 0.5, 0.9}) {
    const ContactLaw<double> law = contact_law(1, 1, 0, e);
    for (int i = 0; i < kDampingNodes; ++i) {
      const double n = 1.0 + 0.5 * i;
      EXPECT_NEAR(restitution_for(law.damping[i], n), e, 1e-6) << "e " << e << " n " << n;
    }
    // A vertex contact needs less ζ than a face for the same e (its dashpot starts soft).
    EXPECT_LT(law.damping[2], law.damping[0]);
    for (double n = 0.5; n <= 2.5; n += 0.05) {
      EXPECT_LE(damping_ratio(law, n), max_damping_ratio(law) + 1e-15);
      EXPECT_GE(damping_ratio(law, n), 0.0);
    }
  }
  EXPECT_EQ(max_damping_ratio(contact_law(1, 1, 0, 1.0)), 0.0);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
