// Frames written beside the stepping (OutputSet::write_frame_beside, io/output/
// frame_thread): the same bytes as frames written inline, every frame written, the
// caller's snapshot swapped not copied, and a failure on the output thread thrown on the
// caller's.
#include "io/output/frame_thread.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <thread>

#include <sys/resource.h>
#include <unistd.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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
  const auto made = test::files_under(tmp.path() / "beside");
  const auto expected = test::files_under(tmp.path() / "inline");
  // 4 frames, 4 contact networks as .vtp and .csv, the two collections, energy.csv and
  // walls.csv (their headers).
  EXPECT_EQ(expected.size(), 4u * 3u + 2u + 2u);
  ASSERT_EQ(made.size(), expected.size());
  for (const auto& [name, bytes] : expected) {
    ASSERT_TRUE(made.count(name)) << name;
    EXPECT_EQ(made.at(name), bytes) << name;
  }
}

/// contacts_000000042.csv (or .vtp): a frame's contact files.
std::string contacts_file(std::int64_t step, const char* extension) {
  return fmt::format("contacts_{:09d}{}", step, extension);
}

/// The sample state tiled `copies` times along x: a frame large enough for the set's
/// writers to run side by side (OutputSet's threshold, 2^16 particles and contacts).
Snapshot tiled_frame(std::size_t copies) {
  const Snapshot one = test::sample_snapshot();
  Snapshot s = one;
  s.resize(0);
  s.contacts.clear();
  for (std::size_t c = 0; c < copies; ++c) {
    const double dx = 5.0 * static_cast<double>(c);
    const auto base = static_cast<std::int64_t>(s.size());
    for (std::size_t i = 0; i < one.size(); ++i) {
      for (auto [to, from] :
           {std::pair{&s.x, &one.x}, {&s.x1, &one.x1}, {&s.x2, &one.x2}, {&s.x3, &one.x3}})
        to->push_back((*from)[i] + dx);
      for (auto [to, from] : {std::pair{&s.y, &one.y},
                              {&s.y1, &one.y1},
                              {&s.y2, &one.y2},
                              {&s.y3, &one.y3},
                              {&s.theta, &one.theta},
                              {&s.vx, &one.vx},
                              {&s.vy, &one.vy},
                              {&s.omega, &one.omega},
                              {&s.fx, &one.fx},
                              {&s.fy, &one.fy},
                              {&s.torque, &one.torque},
                              {&s.mass, &one.mass},
                              {&s.inertia, &one.inertia}})
        to->push_back((*from)[i]);
      s.material.push_back(one.material[i]);
      s.motion.push_back(one.motion[i]);
    }
    for (ContactRecord r : one.contacts) {
      r.i += base;
      r.j += base;
      r.px += dx;
      s.contacts.push_back(r);
    }
  }
  return s;
}

// A large frame's files, its writers side by side, are those each writes alone.
TEST(FrameThread, LargeFrameIsWhatEachWriterWritesAlone) {
  test::TempDir tmp;
  const Snapshot big = tiled_frame(22000);
  ASSERT_GE(big.size(), std::size_t{1} << 16);
  {
    OutputSet out(OutputSettings{}, tmp.path() / "set");
    Snapshot s = big;
    out.write_frame_beside(s);
    out.finish_frames();
  }
  const fs::path alone = tmp.path() / "alone";
  fs::create_directories(alone);
  write_vtu_frame(alone / "frame.vtu", big);
  write_contacts_vtp(alone / "contacts.vtp", big);
  write_contacts_csv(alone / "contacts.csv", big);
  const fs::path set = tmp.path() / "set";
  EXPECT_TRUE(test::read_file(set / "frames" / frame_file_name(big.step)) ==
              test::read_file(alone / "frame.vtu"));
  EXPECT_TRUE(test::read_file(set / "contacts" / contacts_file(big.step, ".csv")) ==
              test::read_file(alone / "contacts.csv"));
  EXPECT_TRUE(test::read_file(set / "contacts" / contacts_file(big.step, ".vtp")) ==
              test::read_file(alone / "contacts.vtp"));
}

// A large run's final files, written side by side, are those each writes alone.
TEST(FrameThread, LargeFinalFilesAreWhatEachWriterWritesAlone) {
  test::TempDir tmp;
  const Snapshot big = tiled_frame(22000);
  ASSERT_GE(big.size(), std::size_t{1} << 16);
  OutputSet(OutputSettings{}, tmp.path() / "set").write_final(big);
  const fs::path alone = tmp.path() / "alone";
  fs::create_directories(alone);
  write_final_csv(alone / "final.csv", big);
  write_bodies_csv(alone / "bodies.csv", big);
  for (const char* name : {"final.csv", "bodies.csv"}) {
    const std::string made = test::read_file(tmp.path() / "set" / name);
    EXPECT_GT(made.size(), big.size()) << name;
    EXPECT_TRUE(made == test::read_file(alone / name)) << name;
  }
}

// A failure of a writer that ran beside the first is thrown, once all have returned.
TEST(FrameThread, LargeFrameFailureOfAnyWriterIsThrown) {
  test::TempDir tmp;
  OutputSet out(OutputSettings{}, tmp.path());
  const Snapshot big = tiled_frame(22000);
  const fs::path blocked = tmp.path() / "contacts" / contacts_file(big.step, ".vtp");
  fs::create_directories(blocked);
  try {
    out.write_frame(big);
    ADD_FAILURE() << "the failure of the .vtp writer was lost";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find(blocked.string()), std::string::npos) << e.what();
  }
}

// The writers run below the stepping thread's priority, and so do the threads they start.
TEST(FrameThread, WritesAtALowerPriorityThanTheCaller) {
  const int caller = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
  ASSERT_LT(caller, 19) << "this test's thread is already as nice as can be";
  int writer = caller, helper = caller;
  {
    io::FrameThread thread([&](const Snapshot&) {
      writer = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
      std::thread([&] { helper = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())); }).join();
    });
    Snapshot s = frame_at(1);
    thread.submit(s);
    thread.wait();
  }
  EXPECT_EQ(writer, std::min(caller + io::FrameThread::kNicer, 19));
  EXPECT_EQ(helper, writer);
  EXPECT_EQ(getpriority(PRIO_PROCESS, static_cast<id_t>(gettid())), caller);
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

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
