// The rounding twin (support/rounding_twin.hpp) that sets the bond parity tests' envelope:
// without kicks it is the reference bit for bit (the save/load round trip of each step
// changes nothing), and on the loaded bonded disc its spread at the parity tests' first
// comparison (step 100) is far under their fixed position tolerance and a tenth of the
// velocity one (measured: 1e-17 m, 3.2e-9 m/s), so the first comparison keeps the other
// suites' strictness, then grows by orders of magnitude as the bonds soften and break
// (1.1e-12 m, 8.4e-5 m/s at step 600).
#include "support/rounding_twin.hpp"
#include "support/backend_test.hpp"
#include "support/bonded_disc.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <cstdio>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(RoundingTwin, WithoutKicksIsTheReferenceBitForBit) {
  bool skip = false;
  const Scene s = test::loaded_bonded_disc_or_skip(skip);
  if (skip) GTEST_SKIP() << "no Gmsh";
  auto reference = make_solver(s, {});
  test::RoundingTwin twin(make_solver(s, {}), 0);
  reference->advance(120);
  twin.advance(120);
  Snapshot a;
  reference->snapshot(a, true);
  const test::Difference d = twin.spread_from(a);
  EXPECT_EQ(d.position, 0);
  EXPECT_EQ(d.angle, 0);
  EXPECT_EQ(d.velocity, 0);
}

TEST(RoundingTwin, SpreadOnTheLoadedDiscGrowsFromRoundingSize) {
  bool skip = false;
  const Scene s = test::loaded_bonded_disc_or_skip(skip);
  if (skip) GTEST_SKIP() << "no Gmsh";
  auto reference = make_solver(s, {});
  test::RoundingTwin twin(make_solver(s, {}), 0x1p-53);
  Snapshot a;
  reference->advance(100);
  twin.advance(100);
  reference->snapshot(a, true);
  const test::Difference early = twin.spread_from(a);
  reference->advance(test::kLoadedDiscSteps - 100);
  twin.advance(test::kLoadedDiscSteps - 100);
  reference->snapshot(a, true);
  const test::Difference late = twin.spread_from(a);
  std::printf("rounding twin: step 100 |dx| %.3g m |dv| %.3g m/s; step %lld |dx| %.3g m |dv| %.3g "
              "m/s\n",
              early.position, early.velocity, static_cast<long long>(test::kLoadedDiscSteps),
              late.position, late.velocity);
  // Kicked, so it parts; at step 100 still far under the fixed position tolerance and a
  // tenth of the velocity one.
  EXPECT_GT(early.velocity, 0);
  EXPECT_LT(early.velocity, test::kVelocityTolerance / 10);
  EXPECT_LT(early.position, test::kPositionTolerance / 1e4);
  // The instability the envelope is there for: orders of magnitude by the last step.
  EXPECT_GT(late.velocity, 1e3 * early.velocity);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
