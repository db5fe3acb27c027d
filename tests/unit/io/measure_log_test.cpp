// A [[measure]]'s file as a run writes it: its rows at its own interval, the values of
// measure_region() on those steps, and the per-grain stress and coordination of frames.
#include "io/output/vtk_xml_reader.hpp"
#include "io_test_support.hpp"
#include "support/scene_builder.hpp"
#include "tridem/measurements.hpp"
#include "tridem/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

Scene pile(const fs::path& dir) {
  Scene s = test::jostling_pile(4, 3);
  s.simulation.steps = 250;
  s.simulation.backend = Backend::Cpu;
  s.output.dir = dir.string();
  s.output.every = 100;
  s.output.energy_every = 50;
  s.output.contacts = false;  // the measures take the contacts all the same
  MeasureSpec all;
  all.name = "all";  // every: energy_every's 50
  MeasureSpec box;
  box.name = "box";
  box.region = MeasureRegion{{-0.1, -0.1}, {0.5, 0.3}};
  box.every = 40;
  box.file = "box.csv";
  s.output.measures = {all, box};
  return s;
}

std::vector<double> column(const std::vector<std::string>& lines, std::size_t k) {
  std::vector<double> out;
  for (std::size_t r = 1; r < lines.size(); ++r) out.push_back(test::numbers(lines[r]).at(k));
  return out;
}

void run(const Scene& s) {
  RunOptions o;
  o.progress = false;
  o.log = nullptr;
  run_scene(s, o);
}

TEST(MeasureLog, RowsAtItsOwnStepsWithTheDocumentedColumns) {
  test::TempDir dir;
  const Scene scene = pile(dir.path());
  run(scene);
  const auto all = test::read_lines(dir.path() / "measure_all.csv");
  ASSERT_FALSE(all.empty());
  EXPECT_EQ(all[0],
            "step,time,area,particles,contacts,rattlers,sxx,sxy,syx,syy,pressure,deviatoric,"
            "packing_fraction,coordination,mechanical_coordination,fabric_xx,fabric_xy,fabric_yy,"
            "mean_overlap,max_overlap");
  // No row at step 0: no contact force exists before the first step.
  EXPECT_EQ(column(all, 0), (std::vector<double>{50, 100, 150, 200, 250}));
  const auto box = test::read_lines(dir.path() / "box.csv");
  EXPECT_EQ(column(box, 0), (std::vector<double>{40, 80, 120, 160, 200, 240, 250}));
  EXPECT_FALSE(fs::exists(dir.path() / "measure_box.csv"));
  // energy.csv keeps its own steps.
  EXPECT_EQ(column(test::read_lines(dir.path() / "energy.csv"), 0),
            (std::vector<double>{0, 50, 100, 150, 200, 250}));

  // The last row is measure_region() of the final state.
  Snapshot last;
  test::advanced_solver(scene, Backend::Cpu, 250)->snapshot(last, true);
  const Measurement m = measure_region(last, std::nullopt);
  const std::vector<double> row = test::numbers(all.back());
  ASSERT_EQ(row.size(), 20u);
  EXPECT_EQ(row[3], double(m.particles));
  EXPECT_EQ(row[3], 12) << "the pile's 12 grains; the 3 walls are not counted";
  EXPECT_EQ(row[4], double(m.contacts));
  EXPECT_GT(m.contacts, 0);
  EXPECT_EQ(row[6], m.sxx);
  EXPECT_EQ(row[9], m.syy);
  EXPECT_EQ(row[12], m.packing_fraction);
  EXPECT_EQ(row[13], m.coordination);
  EXPECT_EQ(row[14], m.mechanical_coordination);
  EXPECT_EQ(row[19], m.max_overlap);
  EXPECT_NEAR(row[15] + row[17], 1, 1e-12) << "the fabric's trace";
}

TEST(MeasureLog, FramesCarryEachGrainsStressAndCoordination) {
  test::TempDir dir;
  Scene scene = pile(dir.path());
  scene.output.contacts = true;  // the frames' stress arrays come with the contacts
  run(scene);
  const fs::path frame = dir.path() / "frames" / "frame_000000200.vtu";
  const io::VtkXmlFile f = io::parse_vtk_xml(frame.string(), test::read_file(frame));
  const std::size_t n = scene.triangles.size();
  const auto stress = io::decode_array(f, *io::find_array(f, "CellData", "stress"), 9, n);
  const auto pressure = io::decode_array(f, *io::find_array(f, "CellData", "pressure"), 1, n);
  const auto coordination =
      io::decode_array(f, *io::find_array(f, "CellData", "coordination"), 1, n);
  Snapshot s;
  test::advanced_solver(scene, Backend::Cpu, 200)->snapshot(s, true);
  const GrainStress g = grain_stress(s);
  // Frames are float32 by default ([output] vtk_precision): each value is the double
  // rounded once to the nearest float, exactly.
  const auto written = [](double v) { return static_cast<double>(static_cast<float>(v)); };
  double total = 0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(stress[9 * i], written(g.sxx[i]));
    EXPECT_EQ(stress[9 * i + 1], written(g.sxy[i]));
    EXPECT_EQ(stress[9 * i + 3], written(g.syx[i]));
    EXPECT_EQ(stress[9 * i + 4], written(g.syy[i]));
    EXPECT_EQ(stress[9 * i + 8], 0);
    EXPECT_EQ(pressure[i], written(0.5 * (g.sxx[i] + g.syy[i])));
    EXPECT_EQ(coordination[i], g.coordination[i]);
    total += coordination[i];
  }
  EXPECT_GT(total, 0);
  // Frames at step 0 have no contacts yet: zeros.
  const fs::path first = dir.path() / "frames" / "frame_000000000.vtu";
  const io::VtkXmlFile f0 = io::parse_vtk_xml(first.string(), test::read_file(first));
  const auto c0 = io::decode_array(f0, *io::find_array(f0, "CellData", "coordination"), 1, n);
  for (double c : c0) EXPECT_EQ(c, 0);
}

// Without [output] contacts a frame is the state alone: no stress arrays (not zeros), and
// the measures still get their contacts.
TEST(MeasureLog, FramesWithoutContactsLeaveTheStressArraysOut) {
  test::TempDir dir;
  const Scene scene = pile(dir.path());
  run(scene);
  const fs::path frame = dir.path() / "frames" / "frame_000000200.vtu";
  const io::VtkXmlFile f = io::parse_vtk_xml(frame.string(), test::read_file(frame));
  for (const char* name : {"stress", "pressure", "coordination"})
    EXPECT_FALSE(io::find_array(f, "CellData", name)) << name;
  EXPECT_TRUE(io::find_array(f, "CellData", "body"));
  const auto rows = test::read_lines(dir.path() / "measure_all.csv");
  ASSERT_GT(rows.size(), 2u);
  EXPECT_GT(test::numbers(rows.back()).at(4), 0) << "the measure counted no contact";
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
