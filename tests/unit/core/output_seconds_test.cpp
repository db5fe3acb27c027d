// The run's output time, part by part (RunSummary::outputs and the wall-time line of
// tridem run): each part is measured where it is spent, and together they are the total.
#include "core/output_notes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/run.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

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

// A large run with frames and the contacts CSV is told its size and how to leave it out;
// smaller runs, and runs without the CSV or without frames, are told nothing.
TEST(OutputNotes, ContactsCsvOfALargeRunIsNamed) {
  OutputSettings o;
  o.every = 1000;
  const std::string note = output_notes(o, 1000000, Precision::Double);
  EXPECT_NE(note.find("about 1090 MB"), std::string::npos) << note;
  EXPECT_NE(note.find("contacts_csv = false"), std::string::npos) << note;
  // Float precision prints the contacts' forces, normals and depths as float32s: shorter.
  EXPECT_NE(output_notes(o, 1000000, Precision::Float).find("about 880 MB"), std::string::npos);
  EXPECT_EQ(output_notes(o, kLargeContactsCsv - 1, Precision::Double), "");
  OutputSettings no_csv = o;
  no_csv.contacts_csv = false;
  EXPECT_EQ(output_notes(no_csv, 1000000, Precision::Double), "");
  OutputSettings no_frames = o;
  no_frames.every = 0;
  EXPECT_EQ(output_notes(no_frames, 1000000, Precision::Double), "");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
