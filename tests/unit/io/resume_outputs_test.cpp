// Taking over a stopped run's outputs: rows after the resume step and a row cut short by
// the stop are dropped, the collection keeps only earlier frames, later frames go.
#include "io/output/pvd_collection.hpp"
#include "io/output/resume_outputs.hpp"
#include "unit/io/io_test_support.hpp"

#include <fstream>
#include <gtest/gtest.h>

namespace tridem {
namespace {

void write(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

TEST(ResumeOutputs, TrimLogKeepsRowsUpToTheStepAndDropsACutRow) {
  test::TempDir dir;
  const auto file = dir.path() / "energy.csv";
  write(file, "step,time\n0,0\n100,0.1\n150,0.15\n200,0.2\n25");
  io::trim_log(file, "step,time\n", 150);
  EXPECT_EQ(test::read_file(file), "step,time\n0,0\n100,0.1\n150,0.15\n");
  io::trim_log(dir.path() / "walls.csv", "step,id\n", 10);  // missing: header only
  EXPECT_EQ(test::read_file(dir.path() / "walls.csv"), "step,id\n");
}

TEST(ResumeOutputs, LaterFramesAndCollectionEntriesGo) {
  test::TempDir dir;
  std::filesystem::create_directories(dir.path() / "frames");
  for (int step : {0, 100, 200}) {
    const auto frame = dir.path() / "frames" / ("frame_" + std::to_string(step) + ".vtu");
    write(frame, "x");
  }
  io::PvdCollection first(dir.path() / "tridem.pvd");
  first.add(0.0, dir.path() / "frames" / "frame_0.vtu");
  first.add(0.1, dir.path() / "frames" / "frame_100.vtu");
  first.add(0.2, dir.path() / "frames" / "frame_200.vtu");

  io::remove_frames_after(dir.path(), 100);
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "frames" / "frame_100.vtu"));
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "frames" / "frame_200.vtu"));
  io::PvdCollection resumed(dir.path() / "tridem.pvd");
  resumed.restore(0.1);
  const std::string pvd = test::read_file(dir.path() / "tridem.pvd");
  EXPECT_NE(pvd.find("frame_100.vtu"), std::string::npos) << pvd;
  EXPECT_EQ(pvd.find("frame_200.vtu"), std::string::npos) << pvd;
}

}  // namespace
}  // namespace tridem
