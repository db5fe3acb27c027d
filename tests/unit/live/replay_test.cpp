// tridem view and render --movie: the frames of an output directory, read back.
#include "io/output/step_files.hpp"
#include "live/replay_view.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/render.hpp"
#include "unit/io/io_test_support.hpp"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <gtest/gtest.h>

namespace tridem::live {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

/// One free triangle at (x, 0) turned by `angle`, and a fixed one below it.
Snapshot turned(double x, double angle, std::int64_t step) {
  Snapshot s;
  s.resize(2);
  s.step = step;
  s.time = 0.01 * static_cast<double>(step);
  const double local[6] = {-1, -0.5, 1, -0.5, 0, 1};
  for (std::size_t k = 0; k < 2; ++k) {
    const double cx = k == 0 ? x : 0, cy = k == 0 ? 0 : -3, th = k == 0 ? angle : 0;
    s.x[k] = cx, s.y[k] = cy, s.theta[k] = th;
    const double c = std::cos(th), sn = std::sin(th);
    double* vx[3] = {&s.x1[k], &s.x2[k], &s.x3[k]};
    double* vy[3] = {&s.y1[k], &s.y2[k], &s.y3[k]};
    for (int v = 0; v < 3; ++v) {
      *vx[v] = cx + c * local[2 * v] - sn * local[2 * v + 1];
      *vy[v] = cy + sn * local[2 * v] + c * local[2 * v + 1];
    }
    s.mass[k] = 1;
  }
  s.vx = {x, 0};
  s.motion = {Motion::Free, Motion::Fixed};
  return s;
}

void write_frames(const fs::path& dir, int count, VtkFormat format = {}) {
  fs::create_directories(dir / "frames");
  for (int k = 0; k < count; ++k)
    write_vtu_frame(io::kFrameFiles.path(dir, 10 * k, ".vtu"), turned(k, 0.3 * k, 10 * k), format);
}

/// The angles angles_from_vertices recovers from frames of `precision`, to `tolerance`.
void expect_angles_recovered(VtkPrecision precision, double tolerance) {
  test::TempDir dir;
  VtkFormat format;
  format.precision = precision;
  write_frames(dir.path(), 3, format);
  const std::vector<fs::path> frames = replay_frames(dir.path());
  ASSERT_EQ(frames.size(), 3U);
  EXPECT_EQ(frames[2].filename(), "frame_000000020.vtu");
  const Snapshot first = read_vtu_frame(frames[0]);
  Snapshot third = read_vtu_frame(frames[2]);
  EXPECT_EQ(third.theta[0], 0);  // frames do not store the angle
  angles_from_vertices(first, third);
  EXPECT_NEAR(third.theta[0], 0.6, tolerance);
  EXPECT_NEAR(third.theta[1], 0, tolerance);
}

TEST(LiveReplay, FramesInStepOrderAndAnglesFromTheVertices) {
  expect_angles_recovered(VtkPrecision::Float64, 1e-12);
}

// Float32 frames (the default) hold the vertices to about 1e-7 of their coordinates (here
// up to 3 m on 1 m edges): the angle comes back to a few 1e-7 rad, never to 1e-12.
TEST(LiveReplay, AnglesFromFloat32FramesToTheirPrecision) {
  expect_angles_recovered(VtkPrecision::Float32, 2e-6);
}

TEST(LiveReplay, AnEmptyDirectorySaysWhatIsMissing) {
  test::TempDir dir;
  try {
    replay_frames(dir.path());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no frames/*.vtu"), std::string::npos) << e.what();
  }
}

TEST(RenderMovie, EveryFrameIntoAnMp4) {
  if (std::system("ffmpeg -version > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "the ffmpeg program is not installed (apt-get install ffmpeg)";
  test::TempDir dir;
  write_frames(dir.path(), 4);
  const fs::path mp4 = dir.path() / "movie.mp4";
  RenderOptions o;
  o.width = 160;
  EXPECT_EQ(render_movie(dir.path(), mp4, o, 10), 4U);
  std::ifstream in(mp4, std::ios::binary);
  char head[8] = {};
  in.read(head, 8);
  ASSERT_TRUE(in) << "no movie written";
  EXPECT_EQ(std::string(head + 4, 4), "ftyp");  // an ISO media file
  EXPECT_GT(fs::file_size(mp4), 200U);
  // The frames' PNGs were a temporary folder beside the movie, removed afterwards.
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(".movie.mp4.frames"), std::string::npos);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::live
