// Replays the reference pair forces of tests/data/regression/pair_forces.csv: any change
// in what the contact model computes shows here, and every backend can be checked against
// the same numbers (the LAMMPS-style reference-data test).
#include "physics/contact_force.hpp"

#include <cmath>
#include <fstream>
#include <gtest/gtest.h>
#include <sstream>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using namespace physics;

TEST(Regression, PairForcesMatchReferenceData) {
  std::ifstream in(std::string(TRIDEM_SOURCE_DIR) + "/tests/data/regression/pair_forces.csv");
  ASSERT_TRUE(in) << "reference file missing";
  std::string line;
  int cases = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    Body<double> body[2];
    for (auto& b : body) {
      for (auto& v : b.tri.v) row >> v.x >> v.y;
      row >> b.v.x >> b.v.y >> b.w >> b.mass;
      b.c = centroid(b.tri);
      b.area = signed_area(b.tri);
    }
    ContactLaw<double> law{};
    double dt = 0;
    row >> law.penalty >> law.tangential_penalty >> law.friction;
    for (double& z : law.damping) row >> z;
    row >> dt;
    PairSlip<double> slip{};
    for (double& s : slip.s) row >> s;
    double expect[6], expect_slip[kHistoryValues], expect_energy[3];
    for (double& e : expect) row >> e;
    for (double& e : expect_slip) row >> e;
    for (double& e : expect_energy) row >> e;
    ASSERT_FALSE(row.fail()) << "malformed row " << cases;
    const PairForce<double> f = pair_force(body[0], body[1], law, dt, slip);
    const double got[6] = {f.force_a.x, f.force_a.y, f.torque_a, f.torque_b, f.point.x, f.point.y};
    const double scale = std::abs(expect[0]) + std::abs(expect[1]) + 1e-300;
    for (int k = 0; k < 4; ++k)
      EXPECT_NEAR(got[k], expect[k], 1e-12 * scale * 10) << "case " << cases << " value " << k;
    for (int k = 4; k < 6; ++k)
      EXPECT_NEAR(got[k], expect[k], 1e-12) << "case " << cases << " point " << k;
    for (int k = 0; k < kHistoryValues; ++k)
      EXPECT_NEAR(slip.s[k], expect_slip[k], 1e-15) << "case " << cases << " slip " << k;
    const double energy[3] = {f.elastic_energy, f.damping_dissipation, f.friction_dissipation};
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(energy[k], expect_energy[k], 1e-12 * (std::abs(expect_energy[k]) + 1e-9))
          << "case " << cases << " energy " << k;
    ++cases;
  }
  EXPECT_EQ(cases, 40);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
