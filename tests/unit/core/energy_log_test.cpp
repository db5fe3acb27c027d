// energy.csv's own interval ([output] energy_every), independent of frames, and the
// budget columns a run writes.
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "tridem/scene_io.hpp"
#include "unit/io/io_test_support.hpp"
#include "unit/scene/scene_refusal.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

Scene pile(const fs::path& dir, std::int64_t every, std::optional<std::int64_t> energy_every) {
  Scene s = test::jostling_pile(4, 3);
  s.simulation.steps = 250;
  s.simulation.backend = Backend::Cpu;
  s.output.dir = dir.string();
  s.output.every = every;
  s.output.energy_every = energy_every;
  s.output.contacts = false;
  return s;
}

std::vector<double> logged_steps(const fs::path& file) {
  std::vector<double> steps;
  const auto lines = test::read_lines(file);
  for (std::size_t k = 1; k < lines.size(); ++k) steps.push_back(test::numbers(lines[k])[0]);
  return steps;
}

void run(const Scene& s) {
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  run_scene(s, o);
}

TEST(EnergyLog, HasItsOwnIntervalIndependentOfFrames) {
  test::TempDir dir;
  run(pile(dir.path(), 100, 30));
  EXPECT_EQ(logged_steps(dir.path() / "energy.csv"),
            (std::vector<double>{0, 30, 60, 90, 120, 150, 180, 210, 240, 250}));
  // walls.csv is logged with energy.csv: 3 walls per logged step.
  EXPECT_EQ(logged_steps(dir.path() / "walls.csv").size(), 30u);
  for (const char* frame :
       {"frame_000000000.vtu", "frame_000000100.vtu", "frame_000000200.vtu", "frame_000000250.vtu"})
    EXPECT_TRUE(fs::exists(dir.path() / "frames" / frame)) << frame;
  EXPECT_FALSE(fs::exists(dir.path() / "frames" / "frame_000000030.vtu"));
}

TEST(EnergyLog, DefaultsToTheFrameInterval) {
  test::TempDir dir;
  run(pile(dir.path(), 100, std::nullopt));
  EXPECT_EQ(logged_steps(dir.path() / "energy.csv"), (std::vector<double>{0, 100, 200, 250}));
  test::TempDir none;
  run(pile(none.path(), 0, std::nullopt));
  EXPECT_EQ(logged_steps(none.path() / "energy.csv"), (std::vector<double>{0, 250}));
  test::TempDir zero;
  run(pile(zero.path(), 100, 0));
  EXPECT_EQ(logged_steps(zero.path() / "energy.csv"), (std::vector<double>{0, 250}));
}

TEST(EnergyLog, RowsCarryTheBudget) {
  test::TempDir dir;
  run(pile(dir.path(), 0, 50));
  const auto lines = test::read_lines(dir.path() / "energy.csv");
  ASSERT_EQ(lines.size(), 7u);
  const auto first = test::numbers(lines[1]), last = test::numbers(lines.back());
  ASSERT_EQ(last.size(), 14u);  // dissipated_fracture appended after total (issue 14)
  EXPECT_NE(first[6], 0) << "potential under gravity";
  EXPECT_EQ(first[7], 0) << "no contact evaluated at step 0";
  EXPECT_GT(last[8], 0) << "damping dissipated";
  EXPECT_EQ(last[13], 0) << "no bonds, no fracture";
  // total = kinetic + potential + elastic + dissipations (fracture's too) - wall work
  EXPECT_DOUBLE_EQ(last[12], last[2] + last[6] + last[7] + last[8] + last[9] + last[10] + last[13] -
                                 last[11]);
}

TEST(EnergyLog, SceneKeyIsReadAndChecked) {
  const std::string head = std::string(test::kSceneHead) + std::string(test::kGoodTriangle);
  EXPECT_FALSE(parse_scene(head, "a.toml").output.energy_every);
  EXPECT_EQ(parse_scene(head + "[output]\nevery = 7\n", "a.toml").output.log_every(), 7);
  const Scene s = parse_scene(head + "[output]\nevery = 7\nenergy_every = 3\n", "a.toml");
  EXPECT_EQ(s.output.energy_every, 3);
  EXPECT_EQ(s.output.log_every(), 3);
  test::expect_refused(head + "[output]\nenergy_every = -1\n",
                       {"bad.toml:", "energy_every", "must be >= 0"});
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
