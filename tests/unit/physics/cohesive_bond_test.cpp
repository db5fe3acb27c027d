// The cohesive bond law alone (physics/cohesive_bond.hpp; docs/fracture.md): its elastic
// slope, its peak at f_t, the energy under its softening curve (G_I per unit length in
// mode I, G_II in mode II), irreversibility, the Mohr-Coulomb shear strength under
// compression, and the forces of a bond between two triangles.
#include "physics/cohesive_bond.hpp"

#include <cmath>
#include <gtest/gtest.h>

namespace tridem::physics {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// Granite of issue 14, on a 1 mm mesh: k = E/h.
constexpr double kStiffness = 40e9 / 1e-3;
const BondStrength<double> kGranite{8e6, 25e6, std::tan(35.0 * M_PI / 180.0), 30, 150};

/// Opens a point monotonically from 0 to `end` in `steps` steps (mode I, or mode II when
/// `sliding`), returning the peak traction, the area under the traction-opening curve
/// (trapezoids) and the energy the law says it dissipated.
struct Path {
  double peak = 0, area = 0, dissipated = 0, damage = 0;
};
Path load_path(double end, int steps, bool sliding, double pressing = 0) {
  Path p;
  double d = 0, last_t = 0, last_x = 0;
  for (int i = 1; i <= steps; ++i) {
    const double x = end * i / steps;
    const BondPointResponse<double> r =
        sliding ? bond_point_response(-pressing, x, kStiffness, kGranite, d)
                : bond_point_response(x, 0.0, kStiffness, kGranite, d);
    const double t = sliding ? -r.shear : -r.normal;
    p.peak = std::max(p.peak, t);
    p.area += 0.5 * (t + last_t) * (x - last_x);
    p.dissipated += r.dissipated;
    d = r.damage;
    last_t = t;
    last_x = x;
  }
  p.damage = d;
  return p;
}

TEST(CohesiveBond, ElasticSlopeIsTheStiffness) {
  const double dn = 0.5 * kGranite.tensile / kStiffness;  // half way to the peak
  const auto r = bond_point_response(dn, 0.0, kStiffness, kGranite, 0.0);
  EXPECT_DOUBLE_EQ(-r.normal, kStiffness * dn);
  EXPECT_EQ(r.damage, 0.0);
  EXPECT_DOUBLE_EQ(r.elastic, 0.5 * kStiffness * dn * dn);
  const auto s = bond_point_response(0.0, -dn, kStiffness, kGranite, 0.0);
  EXPECT_DOUBLE_EQ(s.shear, kStiffness * dn);  // resists the sliding
  // Pressing: the same springs, never damaged, pushing b out.
  const auto c = bond_point_response(-10 * dn, 0.0, kStiffness, kGranite, 0.0);
  EXPECT_DOUBLE_EQ(c.normal, kStiffness * 10 * dn);
  EXPECT_EQ(c.damage, 0.0);
}

TEST(CohesiveBond, PeakTractionIsTheTensileStrength) {
  const double dn0 = kGranite.tensile / kStiffness;
  const Path p = load_path(3 * dn0, 30000, false);
  EXPECT_NEAR(p.peak, kGranite.tensile, 1e-3 * kGranite.tensile);
  // Just past the peak, damage has started and the traction falls.
  const auto r = bond_point_response(1.01 * dn0, 0.0, kStiffness, kGranite, 0.0);
  EXPECT_GT(r.damage, 0.0);
  EXPECT_LT(-r.normal, kGranite.tensile);
}

TEST(CohesiveBond, SofteningReleasesTheFractureEnergy) {
  const double dnf = 2 * kGranite.mode1_energy / kGranite.tensile;  // linear softening's end
  const Path p = load_path(1.2 * dnf, 200000, false);
  EXPECT_EQ(p.damage, 1.0);
  EXPECT_NEAR(p.area, kGranite.mode1_energy, 1e-3 * kGranite.mode1_energy);
  EXPECT_NEAR(p.dissipated, kGranite.mode1_energy, 2e-3 * kGranite.mode1_energy);
  // Mode II: G_II under the shear curve.
  const double dsf = 2 * kGranite.mode2_energy / kGranite.cohesion;
  const Path s = load_path(1.2 * dsf, 200000, true);
  EXPECT_EQ(s.damage, 1.0);
  EXPECT_NEAR(s.peak, kGranite.cohesion, 1e-3 * kGranite.cohesion);
  EXPECT_NEAR(s.area, kGranite.mode2_energy, 1e-3 * kGranite.mode2_energy);
}

TEST(CohesiveBond, DamageNeverHeals) {
  const double dn0 = kGranite.tensile / kStiffness;
  const auto r = bond_point_response(5 * dn0, 0.0, kStiffness, kGranite, 0.0);
  ASSERT_GT(r.damage, 0.0);
  ASSERT_LT(r.damage, 1.0);
  // Unloaded to a smaller opening: the damage stays, the slope is the damaged one.
  const auto back = bond_point_response(dn0, 0.0, kStiffness, kGranite, r.damage);
  EXPECT_EQ(back.damage, r.damage);
  EXPECT_EQ(back.dissipated, 0.0);
  EXPECT_DOUBLE_EQ(-back.normal, (1 - r.damage) * kStiffness * dn0);
  // Broken: nothing at all, whatever the gap (the contact law takes over).
  const auto broken = bond_point_response(-dn0, dn0, kStiffness, kGranite, 1.0);
  EXPECT_EQ(broken.normal, 0.0);
  EXPECT_EQ(broken.shear, 0.0);
  EXPECT_EQ(broken.elastic, 0.0);
  EXPECT_EQ(broken.damage, 1.0);
}

TEST(CohesiveBond, ShearStrengthGrowsUnderCompression) {
  const double sigma_c = 20e6;  // compressive normal stress
  const double pressing = sigma_c / kStiffness;
  const double expected = kGranite.cohesion + kGranite.tan_friction * sigma_c;
  const double ds0 = expected / kStiffness;
  const Path p = load_path(1.5 * ds0, 30000, true, pressing);
  EXPECT_NEAR(p.peak, expected, 1e-3 * expected);
  EXPECT_GT(p.damage, 0.0);
  // Without compression it fails at the cohesion.
  const Path free = load_path(1.5 * ds0, 30000, true, 0.0);
  EXPECT_NEAR(free.peak, kGranite.cohesion, 1e-3 * kGranite.cohesion);
}

TEST(CohesiveBond, MixedModeReleasesBetweenTheTwoEnergies) {
  // A proportional path at 45 degrees in the normalised openings: the released energy
  // meets the linear criterion G_n/G_I + G_s/G_II = 1.
  const double dn0 = kGranite.tensile / kStiffness, ds0 = kGranite.cohesion / kStiffness;
  double d = 0, gn = 0, gs = 0, last_n = 0, last_s = 0;
  const int steps = 200000;
  for (int i = 1; i <= steps; ++i) {
    const double u = 40.0 * i / steps;
    const auto r = bond_point_response(u * dn0, u * ds0, kStiffness, kGranite, d);
    gn += 0.5 * (-r.normal + last_n) * dn0 * 40.0 / steps;
    gs += 0.5 * (-r.shear + last_s) * ds0 * 40.0 / steps;
    last_n = -r.normal;
    last_s = -r.shear;
    d = r.damage;
  }
  EXPECT_EQ(d, 1.0);
  EXPECT_NEAR(gn / kGranite.mode1_energy + gs / kGranite.mode2_energy, 1.0, 2e-3);
}

TEST(CohesiveBond, TooCoarseAMeshBreaksAtThePeak) {
  // k so soft that the peak's elastic energy f_t^2/(2k) exceeds G_I: brittle.
  const double k = kGranite.tensile * kGranite.tensile / (2 * kGranite.mode1_energy) / 2;
  const auto r = bond_point_response(1.0001 * kGranite.tensile / k, 0.0, k, kGranite, 0.0);
  EXPECT_EQ(r.damage, 1.0);
  EXPECT_EQ(r.normal, 0.0);
}

TEST(CohesiveBond, BondOfTwoTrianglesPullsThemTogether) {
  // Two isosceles triangles sharing the edge x = 0 from (0,0) to (0,1), apexes at
  // (-1, 0.5) (a) and (1, 0.5) (b): centroids at (-1/3, 0.5) and (1/3, 0.5), level with
  // the edge's midpoint. b moved right by a small opening, both unrotated.
  const double ca = -1.0 / 3, cb = 1.0 / 3;
  BondGeometry<double> g{};
  for (int k = 0; k < kBondPoints; ++k) {
    const double y = bond_point_position(k);
    g.on_a[k] = Vec2d{0 - ca, y - 0.5};
    g.on_b[k] = Vec2d{0 - cb, y - 0.5};
  }
  g.normal = {1, 0};
  g.length = 1;
  g.stiffness = kStiffness;
  const double dn = 0.5 * kGranite.tensile / kStiffness;
  const double none[kBondPoints] = {0, 0};
  const BondForce<double> f = bond_force(
      BondSide<double>{{0, 0}, 0.0}, BondSide<double>{{cb - ca + dn, 0}, 0.0}, g, kGranite, none);
  EXPECT_NEAR(f.force_a.x, kStiffness * dn, 1e-9 * kStiffness * dn);  // a pulled to b
  EXPECT_NEAR(f.force_a.y, 0.0, 1e-9 * kStiffness * dn);
  EXPECT_NEAR(f.torque_a, 0.0, 1e-9 * kStiffness * dn);  // points symmetric about y = 0.5
  EXPECT_NEAR(f.elastic, 0.5 * kStiffness * dn * dn, 1e-9 * kStiffness * dn * dn);
  EXPECT_FALSE(f.broken);
  // Rotating b about its centroid opens one end and closes the other: a pure couple.
  const BondForce<double> r = bond_force(BondSide<double>{{0, 0}, 0.0},
                                         BondSide<double>{{cb - ca, 0}, 1e-7}, g, kGranite, none);
  EXPECT_LT(r.torque_b, 0.0);  // resists the rotation
  EXPECT_LT(std::abs(r.force_a.x), 1e-3 * std::abs(r.torque_b));
}

// Two triangles bonded along an edge of length `length` (x = 0, from y = 0 to y = length,
// normal +x from a to b); b is moved away from its bonded place along `direction` in
// `steps` equal steps to `end`, both unrotated: the energy the bond released on the way.
double energy_released(Vec2d direction, double length, double end, int steps) {
  const double ca = -length / 3, cb = length / 3;
  BondGeometry<double> g{};
  for (int k = 0; k < kBondPoints; ++k) {
    const double y = bond_point_position(k) * length;
    g.on_a[k] = Vec2d{0 - ca, y - 0.5 * length};
    g.on_b[k] = Vec2d{0 - cb, y - 0.5 * length};
  }
  g.normal = {1, 0};
  g.length = length;
  g.stiffness = kStiffness;
  double damage[kBondPoints] = {0, 0}, released = 0;
  for (int i = 1; i <= steps; ++i) {
    const Vec2d gap = direction * (end * i / steps);
    const BondForce<double> f =
        bond_force(BondSide<double>{{0, 0}, 0.0}, BondSide<double>{Vec2d{cb - ca, 0} + gap, 0.0}, g,
                   kGranite, damage);
    for (int k = 0; k < kBondPoints; ++k) damage[k] = f.damage[k];
    released += f.dissipated;
    if (f.broken) break;
  }
  EXPECT_EQ(damage[0], 1.0);
  EXPECT_EQ(damage[1], 1.0);
  return released;
}

// The definition of G per bond edge (issue 14): a bond across an edge of length L releases
// G_I L when pulled apart in pure mode I and G_II L when slid apart in pure mode II, to
// rounding, in small steps or in a few large ones. Opened at an angle theta to its normal
// (a bond inclined to a mode I crack's path: the crack's faces part along the crack's
// normal, not the bond's), the linear mixed-mode criterion gives
//   G(theta) = 1 / (cos^2 theta / G_I + sin^2 theta / G_II)
// per unit length (whatever the strengths: docs/fracture.md, "The notched beam").
TEST(CohesiveBond, BondReleasesGTimesItsLengthInEachMode) {
  const double length = 1.3e-3;
  const double end = 3 * 2 * kGranite.mode2_energy / kGranite.cohesion;  // past both ends
  const double gi = kGranite.mode1_energy * length, gii = kGranite.mode2_energy * length;
  for (int steps : {100000, 1000, 7}) {
    EXPECT_NEAR(energy_released({1, 0}, length, end, steps), gi, 1e-9 * gi) << steps;
    EXPECT_NEAR(energy_released({0, 1}, length, end, steps), gii, 1e-9 * gii) << steps;
    EXPECT_NEAR(energy_released({0, -1}, length, end, steps), gii, 1e-9 * gii) << steps;
  }
  for (double degrees : {10.0, 30.0, 45.0, -60.0}) {
    const double t = degrees * M_PI / 180;
    const double per_length = 1 / (std::cos(t) * std::cos(t) / kGranite.mode1_energy +
                                   std::sin(t) * std::sin(t) / kGranite.mode2_energy);
    EXPECT_NEAR(energy_released({std::cos(t), std::sin(t)}, length, end, 10000),
                per_length * length, 1e-9 * per_length * length)
        << degrees << " degrees";
  }
}

TEST(CohesiveBond, IntactBondSuppressesTheContact) {
  // Particle 0 bonded to 1 (bond 0, intact) and 2 (bond 1, broken).
  const std::int32_t first[] = {0, 2, 3, 4};
  const std::int32_t partner[] = {1, 2, 0, 0};
  const std::int32_t bond_of[] = {0, 1, 0, 1};
  const std::uint8_t broken[] = {0, 1};
  EXPECT_TRUE(intact_bond_between(first, partner, bond_of, broken, 0, 1));
  EXPECT_TRUE(intact_bond_between(first, partner, bond_of, broken, 1, 0));
  EXPECT_FALSE(intact_bond_between(first, partner, bond_of, broken, 0, 2));
  EXPECT_FALSE(intact_bond_between(first, partner, bond_of, broken, 1, 2));
  EXPECT_FALSE(intact_bond_between(nullptr, partner, bond_of, broken, 0, 1));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::physics
