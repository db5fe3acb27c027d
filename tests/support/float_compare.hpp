#pragma once
// How a mixed-precision run (double state, float pairs) of a short scene is compared with
// the serial double run. Pair forces rounded to float (relative 6e-8) move the 0.1 m
// grains of jostling_pile(8, 5) by 3.4e-10 m, turn them by 2.3e-8 rad and change their
// velocities by 2.5e-7 m/s and 1.8e-5 rad/s in 50 steps (measured on the CPU). The
// tolerances leave about two orders of magnitude above that for the GPU's other
// rounding, and stay two orders below what gravity alone does in those steps (1.9e-5 m,
// 0.019 m/s): a float run that ignored gravity, or lost any force of that size, fails.
// The check proves that margin on the scene it is given, from a double run without
// gravity, so that it cannot pass by a scene where gravity does not show.
#include "support/gpu_compare.hpp"
#include "support/scene_builder.hpp"

#include <gtest/gtest.h>

namespace tridem::test {

constexpr double kFloatPositionTolerance = 3e-8;  // m
constexpr double kFloatAngleTolerance = 2e-6;     // rad
constexpr double kFloatVelocityTolerance = 1e-4;  // m/s and rad/s × 0.1 m

/// `tried`, a float run of `scene` for `steps` steps, against the serial double run.
inline void expect_float_follows_double(const Scene& scene, std::int64_t steps,
                                        const Snapshot& tried) {
  const Snapshot reference = run_to(scene, Backend::Cpu, steps);
  Scene weightless = scene;
  weightless.simulation.gravity = {0, 0};
  const Difference gravity = max_difference(reference, run_to(weightless, Backend::Cpu, steps));
  ASSERT_GT(gravity.position, 100 * kFloatPositionTolerance) << "gravity must show in the run";
  ASSERT_GT(gravity.velocity, 100 * kFloatVelocityTolerance) << "gravity must show in the run";

  ASSERT_EQ(reference.size(), tried.size());
  const Difference d = max_difference(reference, tried);
  std::printf("float against double: max |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s; "
              "gravity alone: %.3g m, %.3g m/s\n",
              d.position, d.angle, d.velocity, gravity.position, gravity.velocity);
  EXPECT_LE(d.position, kFloatPositionTolerance);
  EXPECT_LE(d.angle, kFloatAngleTolerance);
  EXPECT_LE(d.velocity, kFloatVelocityTolerance);
}

}  // namespace tridem::test
