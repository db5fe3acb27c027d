#include "io/output/out_file.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace tridem {
namespace {

/// Runs `make` and checks that it throws RunError whose message names `path`.
template <class F>
void expect_run_error_naming(F make, const std::filesystem::path& path) {
  try {
    make();
    ADD_FAILURE() << "no RunError for " << path;
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(OutputSet, CreatesDirectoryAndWritesEveryFile) {
  test::TempDir tmp;
  const auto dir = tmp.path() / "nested" / "run";
  OutputSet out(OutputSettings{}, dir);
  EXPECT_EQ(out.dir(), dir);
  const Snapshot s = test::sample_snapshot();
  out.write_frame(s);
  out.log(s);
  out.write_final(s);
  for (const char* file : {"energy.csv", "walls.csv", "final.csv", "bodies.csv", "tridem.pvd",
                           "contacts.pvd", "frames/frame_000001200.vtu",
                           "contacts/contacts_000001200.csv", "contacts/contacts_000001200.vtp"})
    EXPECT_TRUE(std::filesystem::is_regular_file(dir / file)) << file;
}

TEST(OutputSet, RemovesFilesOfAnEarlierRunAndNothingElse) {
  test::TempDir tmp;
  const auto dir = tmp.path() / "run";
  std::filesystem::create_directories(dir / "frames");
  std::filesystem::create_directories(dir / "contacts");
  for (const char* stale : {"frames/frame_000099999.vtu", "frames/frame_000099999.png",
                            "contacts/contacts_000099999.csv", "contacts/contacts_000099999.vtp",
                            "final.csv", "tridem.pvd", "last_good.ckpt", "checkpoint.ckpt"})
    std::ofstream(dir / stale) << "old";
  std::ofstream(dir / "notes.txt") << "mine";
  std::ofstream(dir / "frames" / "sketch.png") << "mine";
  OutputSet out(OutputSettings{}, dir);
  for (const char* stale : {"frames/frame_000099999.vtu", "frames/frame_000099999.png",
                            "contacts/contacts_000099999.csv", "contacts/contacts_000099999.vtp",
                            "final.csv", "last_good.ckpt"})
    EXPECT_FALSE(std::filesystem::exists(dir / stale)) << stale;
  EXPECT_TRUE(std::filesystem::exists(dir / "checkpoint.ckpt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "notes.txt"));
  EXPECT_TRUE(std::filesystem::exists(dir / "frames" / "sketch.png"));
}

TEST(OutputSet, NoFramesLeaveNoFrameFolders) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  out.log(test::sample_snapshot());
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "frames"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "tridem.pvd"));
}

TEST(OutputSet, ThrowsRunErrorForDirectoryUnderAFile) {
  test::TempDir tmp;
  const auto file = tmp.path() / "plain-file";
  std::ofstream(file) << "not a directory\n";
  expect_run_error_naming([&] { OutputSet(OutputSettings{}, file / "out"); }, file / "out");
  expect_run_error_naming([&] { OutputSet(OutputSettings{}, file); }, file);
}

TEST(OutputSet, ThrowsRunErrorWhenFramesCannotBeWritten) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  // A regular file where the frames folder should go.
  std::ofstream(tmp.path() / "frames") << "in the way\n";
  expect_run_error_naming([&] { out.write_frame(test::sample_snapshot()); },
                          tmp.path() / "frames");
}

TEST(OutputSet, ThrowsRunErrorWhenFinalCsvCannotBeWritten) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  std::filesystem::create_directory(tmp.path() / "final.csv");
  expect_run_error_naming([&] { out.write_final(test::sample_snapshot()); },
                          tmp.path() / "final.csv");
}

TEST(OutFile, FailedWriteIsReportedWithTheSystemReason) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full here";
  io::OutFile out("/dev/full");
  out.write("more than nothing\n");
  try {
    out.close();
    ADD_FAILURE() << "writing to /dev/full succeeded";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace tridem
