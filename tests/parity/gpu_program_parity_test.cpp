// Motion programs and servo walls on the CUDA solver against the serial reference, in
// double (every method): a pile between a servo wall and an oscillating one, and a drum
// body turned by a rotation program with grains inside. The programs are the same TRIDEM_HD
// functions on both, and a servo reads the same summed force (the walls' gather runs every
// step on the GPU when a servo is present), so they agree as the other GPU parity tests do
// (support/gpu_compare.hpp); likewise a servo whose length follows a lid, on an unstable
// pile, within a rounding twin's envelope (support/program_compare.hpp;
// validation/unstable_parity_test.cpp proves that comparison on the CPU). Skipped without a GPU;
// label gpu.
#include "support/backend_test.hpp"
#include "support/body_scenes.hpp"
#include "support/gpu_compare.hpp"
#include "support/program_compare.hpp"
#include "support/program_scenes.hpp"
#include "support/rounding_twin.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

void expect_programs_agree(const test::SolverChoice& choice, const Scene& scene, std::int64_t steps,
                           std::int64_t every) {
  auto cpu = test::solver_for(scene, test::SolverChoice(Backend::Cpu, choice.method));
  auto gpu = test::solver_for(scene, choice);
  test::expect_runs_agree(*cpu, *gpu, steps, every);
}

using GpuProgramParity = test::BackendTest;

TEST_P(GpuProgramParity, ServoAndOscillatingWallsAgreeWithSerial) {
  Scene s = test::programmed_pile(10, 6);
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Strips, 24);
  expect_programs_agree(GetParam(), s, 600, 200);
}

TEST_P(GpuProgramParity, RotatingDrumBodyAgreesWithSerial) {
  // A ring of 24 triangles as one body turned about the origin at 5 rad/s, a few grains
  // resting in it under gravity.
  Scene s = test::empty_scene(1e7, 2000, 0.5, 0.3);
  s.simulation.gravity = {0, -9.81};
  s.simulation.dt = 2e-5;
  const std::size_t first = s.triangles.size();
  const int segments = 12;
  for (int k = 0; k < segments; ++k) {
    const double a0 = 2 * 3.141592653589793 * k / segments;
    const double a1 = 2 * 3.141592653589793 * (k + 1) / segments;
    const Vec2d p0{0.3 * std::cos(a0), 0.3 * std::sin(a0)},
        p1{0.3 * std::cos(a1), 0.3 * std::sin(a1)};
    const Vec2d q0 = p0 * (1.0 / 0.3 * 0.33), q1 = p1 * (1.0 / 0.3 * 0.33);
    s.triangles.push_back(test::triangle(p0, q1, p1));
    s.triangles.push_back(test::triangle(p0, q0, q1));
  }
  test::add_body(s, first, {}, 0, Motion::Prescribed);
  MotionProgram rotation;
  rotation.kind = ProgramKind::Rotation;
  rotation.angular_velocity = 5;
  s.programs.push_back(rotation);
  s.bodies.back().program = 0;
  for (int k = 0; k < 6; ++k) {
    const double x = -0.15 + 0.06 * k;
    s.triangles.push_back(test::triangle({x, -0.2}, {x + 0.05, -0.2}, {x + 0.025, -0.16}));
    test::add_body(s, s.triangles.size() - 1);
  }
  if (GetParam().method == Method::Decomposition)
    s = test::with_decomposition(s, DecompositionLayout::Strips, 40);
  expect_programs_agree(GetParam(), s, 3000, 1000);
}

// A servo whose target follows the gap between the floor and a lid coming down
// (length_between): the target is computed by servo_target_kernel on the GPU, by
// update_servo_targets on the CPU, from the same poses with the same function. The box's
// pile of single triangles parts from the serial run from its first contacts (step ~382: a
// shallow overlap's depth, the difference of nearly equal coordinates, carries their
// rounding), then about tenfold per 50-100 steps until it is another pile (H200, bench/
// results/gpu_checks_2026-12-02_nvidia-h200): so it is compared pointwise within
// kProgramEnvelope times a serial rounding twin's spread until then (the pile of bodies,
// which keeps to its twin, over the whole run), and throughout by the servo law on the
// GPU's own state, the programmed walls and the servo wall's spread
// (support/program_compare.hpp), which a servo of 1 % other gain or of a fixed length fails
// (validation/unstable_parity_test.cpp).
TEST_P(GpuProgramParity, ServoFollowingALengthAgreesWithSerial) {
  for (const bool bodies : {false, true}) {
    Scene s = bodies ? test::servo_box_of_bodies(true) : test::servo_box(true);
    if (GetParam().method == Method::Decomposition)
      s = test::with_decomposition(s, DecompositionLayout::Strips, 40);
    const test::SolverChoice serial(Backend::Cpu, GetParam().method);
    auto cpu = test::solver_for(s, serial);
    auto gpu = test::solver_for(s, GetParam());
    test::RoundingTwin twin(test::solver_for(s, serial), 0x1p-53,
                            test::RoundingTwin::Kicks::VelocitiesAndPositions);
    test::expect_servo_box_runs_agree(s, *cpu, *gpu, twin, 3000, 100,
                                      test::servo_box_pointwise_steps(bodies, 3000));
  }
}

INSTANTIATE_TEST_SUITE_P(Gpu, GpuProgramParity,
                         TRIDEM_DOUBLE_SOLVER_CHOICES(::tridem::Backend::Cuda));

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
