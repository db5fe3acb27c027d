// The run's output time, part by part (RunSummary::outputs and the wall-time line of
// tridem run): each part is measured where it is spent, and together they are the total.
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace tridem {
namespace {

TEST(OutputSeconds, PartsAreMeasuredAndMakeTheTotal) {
  test::TempDir dir;
  Scene s = test::jostling_pile(4, 3);
  s.simulation.backend = Backend::Cpu;
  s.simulation.steps = 40;
  s.output.every = 10;
  s.output.dir = (dir.path() / "out").string();
  RunOptions o;
  o.progress = false;
  const auto log_path = dir.path() / "log.txt";
  o.log = std::fopen(log_path.c_str(), "w");
  ASSERT_NE(o.log, nullptr);
  const RunSummary r = run_scene(s, o);
  std::fclose(o.log);
  const OutputSeconds& p = r.outputs;
  EXPECT_GT(p.snapshots, 0) << "five frames were taken";
  EXPECT_GT(p.final_files, 0) << "final.csv and bodies.csv were written";
  EXPECT_GE(p.frame_waits, 0);
  EXPECT_GE(p.rest, 0);
  EXPECT_NEAR(p.snapshots + p.final_files + p.frame_waits + p.rest, r.output_seconds,
              1e-9 * (1 + r.output_seconds));
  const std::string log = test::read_file(log_path);
  EXPECT_NE(log.find("(snapshots "), std::string::npos) << log;
  EXPECT_NE(log.find(", waiting for frames "), std::string::npos) << log;
  EXPECT_NE(log.find(", final.csv and bodies.csv "), std::string::npos) << log;
}

}  // namespace
}  // namespace tridem
