// The Brazilian disc test of issue 14 (docs/fracture.md): the peak platen force of a bonded
// granite disc gives the tensile strength 2F/(pi D) within 15% of the input f_t on the
// finest mesh of the docs' study; the study itself and the diagnosis behind the loading
// (flats, Delaunay mesh, a brittle enough disc) are disabled tests the docs name.
#include "support/brazilian_disc.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// The finest mesh of the docs' study (2.5 mm: 20 elements across the diameter), flattened
// by 20 degree flats, the platen at 0.1 m/s (0.3 m/s read 7% higher: not quasi-static);
// OpenMP, bit for bit the serial solver, to keep it short.
TEST(BrazilianDisc, PeakForceGivesTheTensileStrength) {
  Scene scene;
  try {
    scene = test::brazilian_scene(0.0025, 0.1);
  } catch (const SceneError& e) {
    GTEST_SKIP() << e.what();  // a build without Gmsh
  }
  scene.simulation.backend = Backend::OpenMP;
  const test::BrazilianResult r = test::run_brazilian(scene, 60000);
  RecordProperty("sigma_t", std::to_string(r.sigma_t));
  std::printf("Brazilian disc, size 2.5 mm: %zu triangles, %zu bonds, %zu broken, %lld steps "
              "of %.3g s, peak %.4g N/m, sigma_t = %.4g Pa (f_t %.4g)\n",
              r.triangles, r.bonds, r.broken, static_cast<long long>(r.steps), r.dt, r.peak_force,
              r.sigma_t, r.tensile_strength);
  EXPECT_NEAR(r.sigma_t, r.tensile_strength, 0.15 * r.tensile_strength);
  EXPECT_GT(r.broken, 0u);
  EXPECT_LT(r.steps, 60000) << "the force must fall after its peak (a crack), not run out";
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// The docs' mesh study (docs/fracture.md), too long for CI: run it with
//   tridem_tests --gtest_also_run_disabled_tests --gtest_filter='*BrazilianMeshStudy*'
// optionally with TRIDEM_BRAZILIAN_SIZES="0.005 0.0035 0.0025".
TEST(BrazilianDisc, DISABLED_BrazilianMeshStudy) {
  std::vector<double> sizes = {0.005, 0.0035, 0.0025};
  if (const char* env = std::getenv("TRIDEM_BRAZILIAN_SIZES")) {
    sizes.clear();
    std::istringstream in(env);
    for (double s; in >> s;) sizes.push_back(s);
  }
  for (double size : sizes) {
    Scene scene = test::brazilian_scene(size, 0.1);
    scene.simulation.backend = Backend::OpenMP;
    const test::BrazilianResult r = test::run_brazilian(scene, 200000);
    std::printf("size %g m: %zu triangles, %zu bonds, %zu broken, %lld steps of %.3g s, peak "
                "%.4g N/m, sigma_t = %.4g Pa = %.3f f_t\n",
                size, r.triangles, r.bonds, r.broken, static_cast<long long>(r.steps), r.dt,
                r.peak_force, r.sigma_t, r.sigma_t / r.tensile_strength);
    std::fflush(stdout);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// The diagnosis behind docs/fracture.md's "Why the first disc was low": the force, the
// disc's shortening near the poles and at mid-radius, and where bonds are damaged and
// broken, printed along the run. Configure with TRIDEM_BRAZILIAN_TRACE="size speed
// flat_angle damping steps G_I G_II", e.g. "0.0025 0.1 0 0.2 40000 30 150" (the first disc).
TEST(BrazilianDisc, DISABLED_Diagnosis) {
  double size = 0.0025, speed = 0.1, flat = 0, damping = 0.2, steps = 40000;
  double g1 = test::kBrazilianMode1Energy, g2 = test::kBrazilianMode2Energy;
  if (const char* env = std::getenv("TRIDEM_BRAZILIAN_TRACE")) {
    std::istringstream in(env);
    in >> size >> speed >> flat >> damping >> steps >> g1 >> g2;
  }
  Scene scene = test::brazilian_scene(size, speed, flat, damping, g1, g2);
  const test::BrazilianResult r =
      test::run_brazilian(scene, static_cast<std::int64_t>(steps), 20, 1000);
  std::printf("size %g speed %g flat %g damping %g: %zu triangles, %zu bonds, %zu broken, "
              "dt %.3g, peak %.4g N/m = %.3f f_t\n",
              size, speed, flat, damping, r.triangles, r.bonds, r.broken, r.dt, r.peak_force,
              r.sigma_t / r.tensile_strength);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
