// The cohesive bonds' outputs (issue 14): bonds.csv's rows (counts and fracture energy),
// the per-frame line set of bonds with its damage, and no bond files for scenes without
// bonds.
#include "io_test_support.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Snapshot with_bonds() {
  Snapshot s = test::sample_snapshot();
  s.bond_a = {0, 0, 1};
  s.bond_b = {1, 2, 2};
  s.bond_damage = {0.0, 0.25, 1.0};
  s.bond_broken = {0, 0, 1};
  s.bond_x0 = {0.0, 1.0, 2.0};
  s.bond_y0 = {0.0, 0.5, 0.0};
  s.bond_x1 = {0.5, 1.5, 2.5};
  s.bond_y1 = {1.0, 1.5, 1.0};
  return s;
}

TEST(BondOutputs, BondsCsvCountsAndEnergy) {
  test::TempDir tmp;
  Snapshot s = with_bonds();
  {
    OutputSet out(OutputSettings{}, tmp.path());
    EnergyBudget b;
    b.dissipated_fracture = 0.125;
    out.log(s, {}, b);
  }
  const auto lines = test::read_lines(tmp.path() / "bonds.csv");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "step,time,intact,damaged,broken,fracture_energy");
  EXPECT_EQ(test::numbers(lines[1]), (std::vector<double>{double(s.step), s.time, 1, 1, 1, 0.125}));
  // energy.csv carries the same energy in its last column.
  const auto energy = test::read_lines(tmp.path() / "energy.csv");
  EXPECT_EQ(test::numbers(energy[1]).back(), 0.125);
}

TEST(BondOutputs, FramesShowTheBondsAsLines) {
  test::TempDir tmp;
  OutputSettings settings;
  settings.every = 1;
  {
    OutputSet out(settings, tmp.path(), {Encoding::Ascii});
    out.write_frame(with_bonds());
  }
  const auto files = std::filesystem::directory_iterator(tmp.path() / "bonds");
  std::filesystem::path file;
  for (const auto& f : files) file = f.path();
  ASSERT_FALSE(file.empty());
  const std::string text = test::read_file(file);
  EXPECT_NE(text.find("NumberOfLines=\"3\""), std::string::npos) << text;
  EXPECT_NE(text.find("Name=\"damage\""), std::string::npos);
  EXPECT_NE(text.find("Name=\"broken\""), std::string::npos);
  EXPECT_NE(text.find("0.25"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(tmp.path() / "bonds.pvd"));
}

TEST(BondOutputs, NoBondFilesWithoutBonds) {
  test::TempDir tmp;
  OutputSettings settings;
  settings.every = 1;
  {
    OutputSet out(settings, tmp.path());
    const Snapshot s = test::sample_snapshot();
    out.write_frame(s);
    out.log(s);
  }
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "bonds.csv"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "bonds"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "bonds.pvd"));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
