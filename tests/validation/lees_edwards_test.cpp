// Lees-Edwards boundaries (physics/periodic_frame.hpp): a granular gas in simple shear
// keeps the imposed linear velocity profile vx = γ̇·(y − y_c), which its collisions would
// wipe out through plain periodic boundaries; and a particle crossing the top re-enters at
// the bottom shifted back along x and slowed by γ̇·Ly.
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/output.hpp"

#include <cmath>
#include <gtest/gtest.h>
#include <iostream>
#include <random>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

constexpr double kShearRate = test::kGasShearRate;
using test::sheared_gas;

struct Profile {
  double slope = 0, worst = 0;  ///< the least-squares slope, the worst layer off the line
};

/// The mean vx of 5 layers, averaged over `samples` samples 0.01 s apart after `settle`
/// seconds, and the line through them.
Profile shear_profile(double shear_rate, double settle, int samples) {
  const int side = 10;
  const double pitch = 0.1, length = side * pitch;
  Scene s = sheared_gas(side, pitch, 0.035, 7);
  s.simulation.periodic.shear_rate = shear_rate;
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, SolverConfig{});
  const auto steps_per_sample = static_cast<std::int64_t>(std::ceil(0.01 / solver->dt()));
  solver->advance(static_cast<std::int64_t>(settle / 0.01) * steps_per_sample);
  constexpr int kLayers = 5;
  std::vector<double> sum(kLayers, 0), count(kLayers, 0);
  Snapshot snap;
  for (int k = 0; k < samples; ++k) {
    solver->advance(steps_per_sample);
    solver->snapshot(snap, false);
    for (std::size_t i = 0; i < snap.size(); ++i) {
      const auto layer = std::min(kLayers - 1, static_cast<int>(snap.y[i] / length * kLayers));
      sum[layer] += snap.vx[i];
      count[layer] += 1;
    }
  }
  double sy = 0, sv = 0, syy = 0, syv = 0;
  std::vector<double> y(kLayers), v(kLayers);
  for (int l = 0; l < kLayers; ++l) {
    y[l] = (l + 0.5) * length / kLayers;
    v[l] = sum[l] / count[l];
    sy += y[l];
    sv += v[l];
    syy += y[l] * y[l];
    syv += y[l] * v[l];
  }
  Profile p;
  p.slope = (kLayers * syv - sy * sv) / (kLayers * syy - sy * sy);
  const double intercept = (sv - p.slope * sy) / kLayers;
  for (int l = 0; l < kLayers; ++l)
    p.worst = std::max(p.worst, std::abs(v[l] - (intercept + p.slope * y[l])));
  return p;
}

TEST(LeesEdwards, ShearedGasKeepsTheImposedProfile) {
  // 4 shear times (1/γ̇) to settle, 2 to average.
  const Profile sheared = shear_profile(kShearRate, 1.0, 50);
  const Profile plain = shear_profile(0, 1.0, 50);
  const double across = kShearRate * 1.0;  // the velocity jump across the cell
  std::cout << "Lees-Edwards: slope " << sheared.slope << " (imposed " << kShearRate
            << "), worst layer " << sheared.worst << " m/s off the line; plain periodic: slope "
            << plain.slope << "\n";
  EXPECT_NEAR(sheared.slope, kShearRate, 0.1 * kShearRate);
  EXPECT_LT(sheared.worst, 0.05 * across);
  EXPECT_LT(std::abs(plain.slope), 0.75 * kShearRate) << "without the shear the profile decays";
}

TEST(LeesEdwards, CrossingTheTopShiftsAndSlowsTheParticle) {
  // One grain flying up through the top of a sheared cell: it re-enters at the bottom
  // shifted back by the images' offset γ̇·Ly·t and slowed by γ̇·Ly along x.
  Scene s = sheared_gas(1, 0.5, 0.05, 1);
  s.simulation.backend = Backend::Cpu;
  s.triangles[0].velocity = {0, 5};
  auto solver = make_solver(s, SolverConfig{});
  const auto steps = static_cast<std::int64_t>(std::ceil(0.06 / solver->dt()));
  Snapshot before, after;
  solver->snapshot(before, false);
  solver->advance(steps);
  solver->snapshot(after, false);
  const double t = static_cast<double>(steps) * solver->dt();
  const double ly = 0.5, y_unwrapped = before.y[0] + 5 * t;
  ASSERT_GT(y_unwrapped, ly);  // crossed once
  ASSERT_LT(y_unwrapped, 2 * ly);
  EXPECT_NEAR(after.y[0], y_unwrapped - ly, 1e-12);
  EXPECT_NEAR(after.vx[0], -kShearRate * ly, 1e-12);
  // Shifted back by γ̇·Ly·t_k at the crossing's step t_k, then moving at −γ̇·Ly: at t the
  // grain is γ̇·Ly·t behind where it started, modulo the cell, whatever t_k.
  const double behind = before.x[0] - kShearRate * ly * t;
  const double off = after.x[0] - behind;
  EXPECT_NEAR(off - ly * std::round(off / ly), 0, 1e-12);
}

// The sheared cell's boundaries do work on the grains (the images above and below drag
// them, and a grain crossing the top or bottom is slowed or sped up by γ̇·Ly): energy.csv
// books it as wall work, so that its budget closes as it does for a moving wall. Without it
// the dissipation of the steady shear would pile up in `total`. What is left is the O(dt)
// drift of symplectic Euler (measured: 3.1, 1.6, 0.8 % of the dissipated energy at safety
// 0.5, 0.25, 0.125; 130 % without the boundary's work).
TEST(LeesEdwards, EnergyBudgetClosesWithTheBoundarysWork) {
  Scene s = sheared_gas(10, 0.1, 0.045, 3);
  s.materials[0].friction = 0.4;
  s.simulation.safety = 0.25;
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, SolverConfig{});
  Snapshot snap;
  solver->snapshot(snap, false);
  const EnergyRow first = compute_energy(snap, {}, solver->energy());
  const auto every = static_cast<std::int64_t>(std::ceil(0.05 / solver->dt()));
  double worst = 0;
  EnergyRow last;
  for (int k = 0; k < 20; ++k) {  // 1 s: 4 shear times
    solver->advance(every);
    solver->snapshot(snap, false);
    last = compute_energy(snap, {}, solver->energy());
    worst = std::max(worst, std::abs(last.total() - first.total()));
  }
  const EnergyBudget& e = last.budget;
  const double dissipated = e.dissipated_damping + e.dissipated_friction;
  std::cout << "Lees-Edwards budget: kinetic " << first.kinetic << " -> " << last.kinetic
            << " J/m, boundary work " << e.wall_work << ", dissipated " << dissipated
            << ", worst |total - total(0)| " << worst << "\n";
  EXPECT_GT(dissipated, 0.1 * first.kinetic) << "the shear keeps the gas going: a real budget";
  EXPECT_GT(e.wall_work, 0.5 * dissipated);
  EXPECT_LE(worst, 0.03 * dissipated);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
