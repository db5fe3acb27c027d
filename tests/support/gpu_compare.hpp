#pragma once
// How a CUDA run is compared with the serial reference. Both run the same physics functions and
// sum every particle's pair forces in the same order, so in double precision they differ
// only by the device's own rounding: its sin and cos (within 2 ulp of glibc's) and fused
// multiply-adds. Those differences, about 1e-16 relative per operation, grow through the
// contacts of a dense pile; over 200 steps they stay many orders of magnitude below the
// tolerances used here (positions to 1e-9 m for 0.1 m grains, i.e. 1e-8 of a grain, and
// velocities to 1e-7 m/s for speeds of order 1 m/s), which a single missing or wrongly
// signed pair force exceeds by far. The measured differences are printed.
#include "tridem/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem::test {

constexpr double kPositionTolerance = 1e-9;  // m
constexpr double kAngleTolerance = 1e-8;     // rad
constexpr double kVelocityTolerance = 1e-7;  // m/s and rad/s × 0.1 m

struct Difference {
  double position = 0, angle = 0, velocity = 0;
};

inline Difference max_difference(const Snapshot& a, const Snapshot& b) {
  Difference d;
  for (std::size_t i = 0; i < a.size(); ++i) {
    d.position = std::max({d.position, std::abs(a.x[i] - b.x[i]), std::abs(a.y[i] - b.y[i])});
    d.angle = std::max(d.angle, std::abs(a.theta[i] - b.theta[i]));
    d.velocity = std::max({d.velocity, std::abs(a.vx[i] - b.vx[i]), std::abs(a.vy[i] - b.vy[i]),
                           0.1 * std::abs(a.omega[i] - b.omega[i])});
  }
  return d;
}

inline void expect_agreement(const Snapshot& cpu, const Snapshot& gpu, const char* what) {
  ASSERT_EQ(cpu.size(), gpu.size());
  ASSERT_EQ(cpu.step, gpu.step);
  const Difference d = max_difference(cpu, gpu);
  std::printf("%s: max |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s, contacts %zu/%zu\n", what,
              d.position, d.angle, d.velocity, cpu.contacts.size(), gpu.contacts.size());
  EXPECT_LE(d.position, kPositionTolerance) << what;
  EXPECT_LE(d.angle, kAngleTolerance) << what;
  EXPECT_LE(d.velocity, kVelocityTolerance) << what;
  EXPECT_EQ(cpu.contacts.size(), gpu.contacts.size()) << what;
  // Forces on the walls too: they are summed on the GPU only for output.
  for (std::size_t i = 0; i < cpu.size(); ++i)
    if (cpu.motion[i] != Motion::Free) {
      const double scale = 1e-6 * (1 + std::hypot(cpu.fx[i], cpu.fy[i]));
      EXPECT_NEAR(cpu.fx[i], gpu.fx[i], scale) << what << ": wall " << i;
      EXPECT_NEAR(cpu.fy[i], gpu.fy[i], scale) << what << ": wall " << i;
    }
}

}  // namespace tridem::test
