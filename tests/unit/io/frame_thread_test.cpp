// Frames written beside the stepping (OutputSet::write_frame_beside, io/output/
// frame_thread): the same bytes as frames written inline, every frame written, the
// caller's snapshot swapped not copied, and a failure on the output thread thrown on the
// caller's.
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>

namespace tridem {
namespace {

namespace fs = std::filesystem;

/// The sample state moved on by `k`: every frame differs from the one before.
Snapshot frame_at(int k) {
  Snapshot s = test::sample_snapshot();
  s.step = 10 * k;
  s.time = 0.25 * k;
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.vx[i] += 0.125 * k;
    s.fy[i] -= 3.0 * k;
  }
  return s;
}

/// Every file under `dir` (path relative to it) with its contents.
std::map<std::string, std::string> files_under(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = test::read_file(e.path());
  return out;
}

TEST(FrameThread, WritesTheBytesOfInlineFrames) {
  test::TempDir tmp;
  OutputSettings settings;
  {
    OutputSet inline_set(settings, tmp.path() / "inline");
    OutputSet beside_set(settings, tmp.path() / "beside");
    for (int k = 0; k < 4; ++k) {
      inline_set.write_frame(frame_at(k));
      Snapshot s = frame_at(k);
      beside_set.write_frame_beside(s);
    }
    beside_set.finish_frames();
  }
  const auto made = files_under(tmp.path() / "beside");
  const auto expected = files_under(tmp.path() / "inline");
  // 4 frames, 4 contact networks as .vtp and .csv, the two collections, energy.csv and
  // walls.csv (their headers).
  EXPECT_EQ(expected.size(), 4u * 3u + 2u + 2u);
  ASSERT_EQ(made.size(), expected.size());
  for (const auto& [name, bytes] : expected) {
    ASSERT_TRUE(made.count(name)) << name;
    EXPECT_EQ(made.at(name), bytes) << name;
  }
}

TEST(FrameThread, TakesTheSnapshotBySwap) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  Snapshot first = frame_at(1);
  out.write_frame_beside(first);
  EXPECT_EQ(first.size(), 0u) << "the caller gets the thread's (empty) buffer back";
  Snapshot second = frame_at(2);
  out.write_frame_beside(second);
  EXPECT_EQ(second.step, 10) << "...then the buffer of the frame before";
  out.finish_frames();
  EXPECT_EQ(read_vtu_frame(tmp.path() / "frames" / frame_file_name(20)).step, 20);
}

TEST(FrameThread, FailureOnTheThreadIsThrownOnTheCaller) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  // A directory where the frame of step 10 is to be written: opening it fails, as a full
  // disk or a missing permission would (and does so even for root).
  const fs::path blocked = tmp.path() / "frames" / frame_file_name(10);
  fs::create_directories(blocked);
  Snapshot s = frame_at(1);
  out.write_frame_beside(s);  // returns at once; the thread fails on its own
  try {
    out.finish_frames();
    ADD_FAILURE() << "the failure on the output thread was lost";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(blocked.string()), std::string::npos) << e.what();
  }
  // Reported once; the next frame is written.
  fs::remove(blocked);
  Snapshot next = frame_at(2);
  out.write_frame_beside(next);
  EXPECT_NO_THROW(out.finish_frames());
  EXPECT_TRUE(fs::is_regular_file(tmp.path() / "frames" / frame_file_name(20)));
}

TEST(FrameThread, FailureSurfacesAtTheNextHandOver) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  fs::create_directories(tmp.path() / "frames" / frame_file_name(10));
  Snapshot s = frame_at(1);
  out.write_frame_beside(s);
  Snapshot next = frame_at(2);
  EXPECT_THROW(out.write_frame_beside(next), RunError);
}

}  // namespace
}  // namespace tridem
