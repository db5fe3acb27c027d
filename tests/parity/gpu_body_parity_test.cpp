// Bodies of several triangles on the CUDA solver against the serial reference, every
// method, double and float: colliding polygons on a fixed body, and a pile of bodies
// settling on a floor. Both run the same rules (physics/rigid_body.hpp) and sum in the same
// order (members ascending), so in double they agree as single triangles do
// (support/gpu_compare.hpp); in float both compute pairs in float, and they agree within
// the float tolerances of support/float_compare.hpp. The measured differences are printed.
#include "support/backend_test.hpp"
#include "support/body_scenes.hpp"
#include "support/float_compare.hpp"
#include "support/gpu_compare.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// The largest difference of the bodies' own columns.
test::Difference body_difference(const Snapshot& a, const Snapshot& b) {
  test::Difference d;
  for (std::size_t k = 0; k < a.body_x.size(); ++k) {
    d.position = std::max(
        {d.position, std::abs(a.body_x[k] - b.body_x[k]), std::abs(a.body_y[k] - b.body_y[k])});
    d.angle = std::max(d.angle, std::abs(a.body_theta[k] - b.body_theta[k]));
    d.velocity = std::max({d.velocity, std::abs(a.body_vx[k] - b.body_vx[k]),
                           std::abs(a.body_vy[k] - b.body_vy[k]),
                           0.1 * std::abs(a.body_omega[k] - b.body_omega[k])});
  }
  return d;
}

/// Runs the scene on the serial CPU solver and on the choice (CUDA) side by side, and
/// compares every `every` steps up to `steps`; `contacts` counts the contacts the CPU saw.
void expect_bodies_agree(const test::SolverChoice& choice, const Scene& scene, std::int64_t steps,
                         std::int64_t every, std::size_t& contacts) {
  auto cpu =
      test::solver_for(scene, test::SolverChoice(Backend::Cpu, choice.method, choice.precision));
  auto gpu = test::solver_for(scene, choice);
  const bool in_float = choice.precision == Precision::Float;
  // In float, the scale of the bodies' loads: how far the serial solver's float loads are
  // from its double ones (below).
  auto cpu_double =
      in_float ? test::solver_for(scene, test::SolverChoice(Backend::Cpu, choice.method)) : nullptr;
  const double dx = in_float ? test::kFloatPositionTolerance : test::kPositionTolerance;
  const double da = in_float ? test::kFloatAngleTolerance : test::kAngleTolerance;
  const double dv = in_float ? test::kFloatVelocityTolerance : test::kVelocityTolerance;
  contacts = 0;
  Snapshot a, b, r;
  for (std::int64_t s = every; s <= steps; s += every) {
    cpu->advance(every);
    gpu->advance(every);
    cpu->snapshot(a, true);
    gpu->snapshot(b, true);
    if (cpu_double) {
      cpu_double->advance(every);
      cpu_double->snapshot(r, false);
    }
    const std::string what = scene.source + ", step " + std::to_string(s);
    ASSERT_EQ(a.size(), b.size());
    ASSERT_EQ(a.body_count(), b.body_count());
    ASSERT_EQ(a.member_body, b.member_body);
    ASSERT_EQ(a.body_first, b.body_first);
    EXPECT_EQ(a.body_mass, b.body_mass);
    EXPECT_EQ(a.body_inertia, b.body_inertia);
    contacts += a.contacts.size();
    const test::Difference t = test::max_difference(a, b), d = body_difference(a, b);
    std::printf("%s: triangles max |dx| %.3g m, |dtheta| %.3g rad, |dv| %.3g m/s; bodies "
                "%.3g m, %.3g rad, %.3g m/s; contacts %zu/%zu\n",
                what.c_str(), t.position, t.angle, t.velocity, d.position, d.angle, d.velocity,
                a.contacts.size(), b.contacts.size());
    EXPECT_LE(t.position, dx) << what;
    EXPECT_LE(t.angle, da) << what;
    EXPECT_LE(t.velocity, dv) << what;
    EXPECT_LE(d.position, dx) << what;
    EXPECT_LE(d.angle, da) << what;
    EXPECT_LE(d.velocity, dv) << what;
    if (!in_float) {
      EXPECT_EQ(a.contacts.size(), b.contacts.size()) << what;
    }
    // The bodies' loads, fixed bodies' included (summed on the GPU only for output). In
    // double they agree to rounding. In float a load is a sum of float pair forces in a
    // stiff packing: a position difference of 1e-10 m moves it by 1e-3 N, so a bound
    // relative to the load is no bound (1e-4 of it failed on the H200 with positions equal
    // to 1e-10 m: bench/results/gpu_bodies_2026-12-01_nvidia-h200). The GPU and the CPU
    // in float differ by float rounding (fused multiply-adds, division), as float differs
    // from double: the largest float-vs-double load difference of the serial solver at
    // that step, four times, is the bound.
    double spread = 0;
    for (std::size_t k = 0; cpu_double && k < a.body_fx.size(); ++k)
      spread = std::max(
          {spread, std::abs(a.body_fx[k] - r.body_fx[k]), std::abs(a.body_fy[k] - r.body_fy[k])});
    if (in_float)
      std::printf("%s: float against double, loads differ by up to %.3g N\n", what.c_str(), spread);
    for (std::size_t k = 0; k < a.body_fx.size(); ++k) {
      const double scale = 4 * spread + 1e-6 * (1 + std::hypot(a.body_fx[k], a.body_fy[k]));
      EXPECT_NEAR(a.body_fx[k], b.body_fx[k], scale) << what << ": body " << k;
      EXPECT_NEAR(a.body_fy[k], b.body_fy[k], scale) << what << ": body " << k;
    }
  }
}

using GpuBodyParity = test::BackendTest;

TEST_P(GpuBodyParity, CollidingBodiesAgreeWithSerial) {
  std::size_t contacts = 0;
  expect_bodies_agree(GetParam(), test::colliding_bodies(), 3000, 500, contacts);
  EXPECT_GT(contacts, 0u) << "the bodies must collide";
}

TEST_P(GpuBodyParity, SettlingPileOfBodiesAgreesWithSerial) {
  Scene s = test::settling_body_pile();
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Grid, 200);
  std::size_t contacts = 0;
  expect_bodies_agree(GetParam(), s, 400, 100, contacts);
  EXPECT_GT(contacts, 0u) << "the pile must be in contact";
}

// backend = auto takes the GPU for a scene with bodies (it fell back to the CPU before).
TEST_P(GpuBodyParity, AutoBackendRunsBodiesOnTheGpu) {
  test::expect_auto_backend_takes_the_gpu(test::colliding_bodies(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Gpu, GpuBodyParity, TRIDEM_SOLVER_CHOICES(::tridem::Backend::Cuda));

// All-pairs: the grid path's kernels with another list.
TEST(GpuBodyParityAllPairs, CollidingBodiesAgreeWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  std::size_t contacts = 0;
  expect_bodies_agree(test::SolverChoice(Backend::Cuda, Method::AllPairs), test::colliding_bodies(),
                      3000, 500, contacts);
  EXPECT_GT(contacts, 0u) << "the bodies must collide";
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
