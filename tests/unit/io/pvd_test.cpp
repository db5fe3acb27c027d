#include "io/output/atomic_file.hpp"
#include "io/output/pvd_collection.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <regex>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

struct Listed {
  double time;
  std::string file;
};

std::vector<Listed> datasets(const std::filesystem::path& pvd) {
  const std::string text = test::read_file(pvd);
  const std::regex entry(R"re(<DataSet timestep="([^"]*)" group="" part="0" file="([^"]*)"/>)re");
  std::vector<Listed> out;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    out.push_back({std::stod((*it)[1]), (*it)[2]});
  return out;
}

TEST(Pvd, ListsEveryFrameWrittenInOrder) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  Snapshot s = test::sample_snapshot();
  const std::int64_t steps[] = {0, 500, 1000};
  for (const std::int64_t step : steps) {
    s.step = step;
    s.time = 1e-5 * static_cast<double>(step);
    out.write_frame(s);
    // Valid after every frame, not only at the end of the run.
    EXPECT_NE(test::read_file(tmp.path() / "tridem.pvd").find("</VTKFile>"), std::string::npos);
  }

  const auto frames = datasets(tmp.path() / "tridem.pvd");
  ASSERT_EQ(frames.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(frames[k].file, "frames/" + frame_file_name(steps[k]));
    EXPECT_EQ(frames[k].time, 1e-5 * static_cast<double>(steps[k]));
    EXPECT_TRUE(std::filesystem::exists(tmp.path() / frames[k].file)) << frames[k].file;
    EXPECT_EQ(read_vtu_frame(tmp.path() / frames[k].file).step, steps[k]);
  }
  EXPECT_EQ(frames[0].file, "frames/frame_000000000.vtu");
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "tridem.pvd.tmp"));

  const auto contacts = datasets(tmp.path() / "contacts.pvd");
  ASSERT_EQ(contacts.size(), 3u);
  EXPECT_EQ(contacts[2].file, "contacts/contacts_000001000.vtp");
}

TEST(Pvd, SameStepTwiceIsListedOnce) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  Snapshot s = test::sample_snapshot();
  out.write_frame(s);
  out.write_frame(s);
  EXPECT_EQ(datasets(tmp.path() / "tridem.pvd").size(), 1u);
}

// The collection is replaced as checkpoints are (atomic_file.hpp): when the replacement
// fails, the error names the file and no temporary file is left behind.
TEST(Pvd, FailedReplacementNamesTheFileAndLeavesNoTemporary) {
  test::TempDir tmp;
  const auto pvd = tmp.path() / "tridem.pvd";
  std::filesystem::create_directories(pvd / "in-the-way");  // a folder where the file goes
  io::PvdCollection collection(pvd);
  try {
    collection.add(0.5, tmp.path() / "frames" / frame_file_name(5));
    ADD_FAILURE() << "replaced a folder";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(pvd.string()), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(io::temporary_path(pvd)));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
