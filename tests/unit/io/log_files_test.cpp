#include "io_test_support.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {

TEST(LogFiles, EnergyCsvHasOneRowPerLog) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  OutputSet out(OutputSettings{}, tmp.path());
  out.log(s);
  s.step += 100;
  s.time += 0.001;
  out.log(s);

  // Rows are flushed by log() itself: readable while the OutputSet is still open.
  const auto lines = test::read_lines(tmp.path() / "energy.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "step,time,kinetic,momentum_x,momentum_y,angular_momentum");
  const EnergyRow e = compute_energy(s);
  EXPECT_EQ(test::numbers(lines[2]),
            (std::vector<double>{double(s.step), s.time, e.kinetic, e.momentum_x, e.momentum_y,
                                 e.angular_momentum}));
  EXPECT_EQ(test::numbers(lines[1])[0], 1200);
}

TEST(LogFiles, WallsCsvHasRowsOnlyForNonFreeParticles) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.motion[1] = Motion::Prescribed;  // 1 and 2 are walls now, 0 stays free
  OutputSet out(OutputSettings{}, tmp.path());
  out.log(s);
  s.step = 1300;
  out.log(s);

  const auto lines = test::read_lines(tmp.path() / "walls.csv");
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "step,time,id,fx,fy,torque");
  const std::size_t ids[] = {1, 2, 1, 2};
  for (std::size_t r = 0; r < 4; ++r) {
    const std::size_t k = ids[r];
    EXPECT_EQ(test::numbers(lines[1 + r]),
              (std::vector<double>{r < 2 ? 1200.0 : 1300.0, s.time, double(k), s.fx[k], s.fy[k],
                                   s.torque[k]}))
        << "row " << r;
  }
}

}  // namespace
}  // namespace tridem
