#include "io_test_support.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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
  // The first six columns are the contract of the first versions; the budget follows.
  EXPECT_EQ(lines[0], "step,time,kinetic,momentum_x,momentum_y,angular_momentum,potential,elastic,"
                      "dissipated_damping,dissipated_friction,dissipated_local,wall_work,total,"
                      "dissipated_fracture");
  const EnergyRow e = compute_energy(s);
  EXPECT_EQ(test::numbers(lines[2]),
            (std::vector<double>{double(s.step), s.time, e.kinetic, e.momentum_x, e.momentum_y,
                                 e.angular_momentum, 0, 0, 0, 0, 0, 0, e.kinetic, 0}));
  EXPECT_EQ(test::numbers(lines[1])[0], 1200);
}

TEST(LogFiles, EnergyCsvWritesTheBudgetAfterTheOldColumns) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  OutputSet out(OutputSettings{}, tmp.path());
  const EnergyBudget b{1.5, 0.25, 0.125, 0.0625, 2.0};
  const Vec2d g{0.5, -9.81};
  out.log(s, g, b);
  const auto lines = test::read_lines(tmp.path() / "energy.csv");
  ASSERT_EQ(lines.size(), 2u);
  const EnergyRow e = compute_energy(s, g, b);
  double potential = 0;
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.motion[k] == Motion::Free) potential -= s.mass[k] * (g.x * s.x[k] + g.y * s.y[k]);
  EXPECT_DOUBLE_EQ(e.potential, potential);
  EXPECT_NE(potential, 0);
  EXPECT_EQ(e.total(), e.kinetic + potential + 1.5 + 0.25 + 0.125 + 0.0625 - 2.0);
  EXPECT_EQ(test::numbers(lines[1]),
            (std::vector<double>{double(s.step), s.time, e.kinetic, e.momentum_x, e.momentum_y,
                                 e.angular_momentum, e.potential, 1.5, 0.25, 0.125, 0.0625, 2.0,
                                 e.total(), 0.0}));
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
  // The first six columns are the first version's contract; the wall's place came after.
  EXPECT_EQ(lines[0], "step,time,id,fx,fy,torque,x,y,vx,vy");
  const std::size_t ids[] = {1, 2, 1, 2};
  for (std::size_t r = 0; r < 4; ++r) {
    const std::size_t k = ids[r];
    EXPECT_EQ(test::numbers(lines[1 + r]),
              (std::vector<double>{r < 2 ? 1200.0 : 1300.0, s.time, double(k), s.fx[k], s.fy[k],
                                   s.torque[k], s.x[k], s.y[k], s.vx[k], s.vy[k]}))
        << "row " << r;
  }
}

TEST(LogFiles, WallsCsvEndsWithTheWallsCentroidAndVelocity) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.motion[0] = Motion::Prescribed;
  s.x[0] = 0.125;
  s.y[0] = -2.5;
  s.vx[0] = 0.75;
  s.vy[0] = -0.0625;
  OutputSet out(OutputSettings{}, tmp.path());
  out.log(s);
  const auto lines = test::read_lines(tmp.path() / "walls.csv");
  ASSERT_GE(lines.size(), 2u);
  const std::vector<double> row = test::numbers(lines[1]);
  ASSERT_EQ(row.size(), 10u);
  EXPECT_EQ(row[2], 0.0);  // the wall's id
  EXPECT_EQ((std::vector<double>(row.begin() + 6, row.end())),
            (std::vector<double>{0.125, -2.5, 0.75, -0.0625}));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
