// The contact network's new fields (normal, sliding, depth) and the measurements of
// tridem/measurements.hpp from a CUDA snapshot against the serial solver's (issue 15):
// the measurements are host functions of the snapshot, so they agree when the contact
// records do.
#include "support/gpu.hpp"
#include "support/gpu_compare.hpp"
#include "support/scene_builder.hpp"
#include "tridem/measurements.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(GpuMeasurements, ContactFieldsAndMeasurementsAgreeWithSerial) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = test::jostling_pile(20, 12);
  const Snapshot cpu = test::run_to(s, Backend::Cpu, 200);
  const Snapshot gpu = test::run_to(s, Backend::Cuda, 200);
  test::expect_agreement(cpu, gpu, "jostling pile");
  ASSERT_EQ(cpu.contacts.size(), gpu.contacts.size());
  ASSERT_GT(cpu.contacts.size(), 20u);
  // Records in the same order on both (rows by emitter, ascending partners).
  std::size_t sliding = 0, sliding_differs = 0;
  double normal = 0, depth = 0;
  for (std::size_t k = 0; k < cpu.contacts.size(); ++k) {
    const ContactRecord &c = cpu.contacts[k], &g = gpu.contacts[k];
    ASSERT_EQ(c.i, g.i);
    ASSERT_EQ(c.j, g.j);
    EXPECT_NEAR(std::hypot(c.nx, c.ny), 1, 1e-12);
    normal = std::max({normal, std::abs(c.nx - g.nx), std::abs(c.ny - g.ny)});
    depth = std::max(depth, std::abs(c.depth - g.depth));
    sliding += c.sliding ? 1 : 0;
    sliding_differs += c.sliding != g.sliding ? 1 : 0;
  }
  std::printf("contacts %zu, sliding %zu (differing %zu), max |dn| %.3g, |ddepth| %.3g\n",
              cpu.contacts.size(), sliding, sliding_differs, normal, depth);
  EXPECT_LE(normal, 1e-6);
  EXPECT_LE(depth, 1e-6);
  // A contact exactly at the Coulomb cap may tip either way under the device's rounding.
  EXPECT_LE(sliding_differs, cpu.contacts.size() / 100);

  for (const std::optional<MeasureRegion>& region :
       {std::optional<MeasureRegion>{},
        std::optional<MeasureRegion>{MeasureRegion{{0, 0}, {1, 0.6}}}}) {
    const Measurement a = measure_region(cpu, region), b = measure_region(gpu, region);
    EXPECT_EQ(a.particles, b.particles);
    EXPECT_EQ(a.contacts, b.contacts);
    EXPECT_EQ(a.rattlers, b.rattlers);
    const double stress = 1e-6 * (1 + std::abs(a.pressure));
    EXPECT_NEAR(a.sxx, b.sxx, stress);
    EXPECT_NEAR(a.syy, b.syy, stress);
    EXPECT_NEAR(a.sxy, b.sxy, stress);
    EXPECT_NEAR(a.packing_fraction, b.packing_fraction, 1e-9);
    EXPECT_EQ(a.coordination, b.coordination);
    EXPECT_NEAR(a.fabric_xx, b.fabric_xx, 1e-6);
    EXPECT_NEAR(a.max_overlap, b.max_overlap, 1e-6);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
