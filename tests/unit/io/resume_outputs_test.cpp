// Taking over a stopped run's outputs: rows after the resume step and a row cut short by
// the stop are dropped, the collection keeps only earlier frames, later frames go.
#include "io/output/resume_outputs.hpp"
#include "tridem/output.hpp"
#include "unit/io/io_test_support.hpp"

#include <fmt/format.h>
#include <fstream>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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

// Every writer cuts its own files back to the resume point: frames and their renderings,
// both contact files, both collections and both logs.
TEST(ResumeOutputs, EveryFormatKeepsItsFilesUpToTheResumePointOnly) {
  test::TempDir dir;
  Snapshot s = test::sample_snapshot();
  {
    OutputSet first(OutputSettings{}, dir.path());
    for (int step : {0, 100, 200}) {
      s.step = step;
      s.time = 0.001 * step;
      first.write_frame(s);
      first.log(s);
    }
  }
  for (int step : {0, 100, 200})  // what `tridem render` writes beside a frame
    write(dir.path() / "frames" / fmt::format("frame_{:09}.png", step), "png");
  std::ofstream(dir.path() / "frames" / "frame_notes.png") << "mine";

  const OutputSet resumed(OutputSettings{}, dir.path(), {}, ResumePoint{100, 0.1});
  for (const char* kept : {"frames/frame_000000100.vtu", "frames/frame_000000100.png",
                           "contacts/contacts_000000100.csv", "contacts/contacts_000000100.vtp",
                           "frames/frame_notes.png"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / kept)) << kept;
  for (const char* gone : {"frames/frame_000000200.vtu", "frames/frame_000000200.png",
                           "contacts/contacts_000000200.csv", "contacts/contacts_000000200.vtp"})
    EXPECT_FALSE(std::filesystem::exists(dir.path() / gone)) << gone;
  for (const char* pvd : {"tridem.pvd", "contacts.pvd"}) {
    const std::string text = test::read_file(dir.path() / pvd);
    EXPECT_NE(text.find("_000000100."), std::string::npos) << pvd << ": " << text;
    EXPECT_EQ(text.find("_000000200."), std::string::npos) << pvd << ": " << text;
  }
  for (const char* log : {"energy.csv", "walls.csv"}) {
    const auto lines = test::read_lines(dir.path() / log);
    ASSERT_FALSE(lines.empty()) << log;
    EXPECT_EQ(lines.back().rfind("100,", 0), 0u) << log << ": " << lines.back();
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
