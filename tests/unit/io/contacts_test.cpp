#include "io/output/vtk_xml_reader.hpp"
#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

TEST(Contacts, CsvHoldsEveryContact) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  OutputSet out(OutputSettings{}, tmp.path());
  out.write_frame(s);

  const auto lines = test::read_lines(tmp.path() / "contacts" / "contacts_000001200.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "i,j,fx,fy,px,py,nx,ny,fn,ft,sliding,depth");
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactRecord& c = s.contacts[k];
    EXPECT_EQ(test::numbers(lines[1 + k]),
              (std::vector<double>{double(c.i), double(c.j), c.fx, c.fy, c.px, c.py, c.nx, c.ny,
                                   c.normal_force(), c.tangential_force(), c.sliding ? 1.0 : 0.0,
                                   c.depth}));
  }
  // The split adds back to the force: f = −fn·n + ft·t, t = (−ny, nx). Contact 0: n = (0.6,
  // 0.8), t = (−0.8, 0.6), f = (−3, 2): fn = 1.8 − 1.6 = 0.2, ft = 2.4 + 1.2 = 3.6.
  const ContactRecord& c = s.contacts[0];
  EXPECT_NEAR(c.normal_force(), 0.2, 1e-15);
  EXPECT_NEAR(c.tangential_force(), 3.6, 1e-15);
  EXPECT_DOUBLE_EQ(-c.normal_force() * c.nx - c.tangential_force() * c.ny, c.fx);
  EXPECT_DOUBLE_EQ(-c.normal_force() * c.ny + c.tangential_force() * c.nx, c.fy);
  EXPECT_EQ(test::numbers(lines[1]).size(), 12u);
}

/// The sample with float precision's contacts: force, normal and depth float32s (set from
/// float literals: GCC 12's -O3 drops a double-to-float-to-double round trip of two
/// neighbouring fields, so they are not rounded here from doubles).
Snapshot float_sample() {
  Snapshot s = test::sample_snapshot();
  s.contact_precision = Precision::Float;
  ContactRecord &a = s.contacts[0], &b = s.contacts[1];
  a.fx = -3.0000002f, a.fy = 2.0000002f, a.nx = 0.6f, a.ny = 0.8f, a.depth = 0.0125f;
  b.fx = 0.25f, b.fy = 20.0f / 3.0f, b.nx = 0.0f, b.ny = -1.0f, b.depth = 1.0f / 3.0f;
  return s;
}

TEST(Contacts, FloatPrecisionCsvPrintsThePairsNumbersAsFloat32s) {
  test::TempDir tmp;
  Snapshot s = float_sample();
  s.contacts[0].px = 1.0 / 3.0;  // the point is a double: centroid plus a float offset
  write_contacts_csv(tmp.path() / "float.csv", s);
  Snapshot d = s;
  d.contact_precision = Precision::Double;
  write_contacts_csv(tmp.path() / "double.csv", d);

  const auto lines = test::read_lines(tmp.path() / "float.csv");
  const auto double_lines = test::read_lines(tmp.path() / "double.csv");
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "i,j,fx,fy,px,py,nx,ny,fn,ft,sliding,depth");
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactRecord& c = s.contacts[k];
    const std::vector<std::string> text = test::cells(lines[1 + k]);
    ASSERT_EQ(text.size(), 12u);
    // fx, fy, nx, ny, depth: read back as float32s, the same, and shortest.
    const std::pair<int, double> as_float[] = {
        {2, c.fx}, {3, c.fy}, {6, c.nx}, {7, c.ny}, {11, c.depth}};
    for (const auto& [column, value] : as_float) {
      EXPECT_EQ(std::strtof(text[column].c_str(), nullptr), static_cast<float>(value))
          << "column " << column << ": " << text[column];
      // No longer than 9 significant digits (what any float32 needs) would write it.
      EXPECT_LE(text[column].size(), fmt::format("{:.9g}", static_cast<float>(value)).size())
          << text[column];
    }
    // The rest are doubles, exact as before.
    const std::pair<int, double> as_double[] = {
        {4, c.px}, {5, c.py}, {8, c.normal_force()}, {9, c.tangential_force()}};
    for (const auto& [column, value] : as_double)
      EXPECT_EQ(std::strtod(text[column].c_str(), nullptr), value) << "column " << column;
    // In double precision the same numbers are printed as doubles, longer.
    EXPECT_EQ(test::numbers(double_lines[1 + k]),
              (std::vector<double>{double(c.i), double(c.j), c.fx, c.fy, c.px, c.py, c.nx, c.ny,
                                   c.normal_force(), c.tangential_force(), c.sliding ? 1.0 : 0.0,
                                   c.depth}));
    EXPECT_LT(lines[1 + k].size(), double_lines[1 + k].size());
  }
  // 0.6 for 0.60000002384185791, and so on: some 60 bytes fewer in row 1.
  EXPECT_LE(lines[1].size() + 40, double_lines[1].size());
  EXPECT_EQ(test::cells(lines[1])[4], "0.3333333333333333");
}

TEST(Contacts, FloatPrecisionContactThatIsNotFloat32IsRefused) {
  test::TempDir tmp;
  Snapshot s = float_sample();
  s.contacts[1].depth = 0.1;  // not a float32: printed as one it would lose digits
  EXPECT_THROW(write_contacts_csv(tmp.path() / "c.csv", s), Error);
  s.contacts[1].depth = 0.1f;
  EXPECT_NO_THROW(write_contacts_csv(tmp.path() / "c.csv", s));
}

TEST(Contacts, VtpHasOneLinePerContactBetweenCentroids) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  const auto file = tmp.path() / "c.vtp";
  write_contacts_vtp(file, s, {Encoding::Binary, VtkPrecision::Float64});

  const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), test::read_file(file));
  EXPECT_EQ(f.root.at("type"), "PolyData");
  EXPECT_EQ(f.piece.at("NumberOfLines"), "2");
  // One point per particle, its centroid; each line joins those of its i and j.
  const auto points = io::decode_array(f, *io::find_array(f, "Points", "Points"), 3, s.size());
  const auto ends = io::decode_array(f, *io::find_array(f, "Lines", "connectivity"), 1, 4);
  const auto offsets = io::decode_array(f, *io::find_array(f, "Lines", "offsets"), 1, 2);
  const auto force = io::decode_array(f, *io::find_array(f, "CellData", "force"), 3, 2);
  const auto magnitude = io::decode_array(f, *io::find_array(f, "CellData", "magnitude"), 1, 2);
  const auto normal = io::decode_array(f, *io::find_array(f, "CellData", "normal"), 3, 2);
  const auto fn = io::decode_array(f, *io::find_array(f, "CellData", "normal_force"), 1, 2);
  const auto ft = io::decode_array(f, *io::find_array(f, "CellData", "tangential_force"), 1, 2);
  const auto sliding = io::decode_array(f, *io::find_array(f, "CellData", "sliding"), 1, 2);
  const auto depth = io::decode_array(f, *io::find_array(f, "CellData", "depth"), 1, 2);
  EXPECT_EQ(sliding, (std::vector<double>{1, 0}));
  EXPECT_EQ(offsets, (std::vector<double>{2, 4}));
  for (std::size_t k = 0; k < 2; ++k) {
    const ContactRecord& c = s.contacts[k];
    const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
    EXPECT_EQ(ends[2 * k], static_cast<double>(i));
    EXPECT_EQ(ends[2 * k + 1], static_cast<double>(j));
    EXPECT_EQ(points[3 * i], s.x[i]);
    EXPECT_EQ(points[3 * i + 1], s.y[i]);
    EXPECT_EQ(points[3 * j], s.x[j]);
    EXPECT_EQ(points[3 * j + 1], s.y[j]);
    EXPECT_EQ(force[3 * k], c.fx);
    EXPECT_EQ(force[3 * k + 1], c.fy);
    EXPECT_EQ(force[3 * k + 2], 0);
    EXPECT_DOUBLE_EQ(magnitude[k], std::hypot(c.fx, c.fy));
    EXPECT_EQ(normal[3 * k], c.nx);
    EXPECT_EQ(normal[3 * k + 1], c.ny);
    EXPECT_EQ(fn[k], c.normal_force());
    EXPECT_EQ(ft[k], c.tangential_force());
    EXPECT_EQ(depth[k], c.depth);
  }
}

TEST(Contacts, NoContactsGiveHeaderOnlyAndEmptyNetwork) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.contacts.clear();
  write_contacts_csv(tmp.path() / "c.csv", s);
  write_contacts_vtp(tmp.path() / "c.vtp", s, {Encoding::Ascii});
  EXPECT_EQ(test::read_lines(tmp.path() / "c.csv"),
            (std::vector<std::string>{"i,j,fx,fy,px,py,nx,ny,fn,ft,sliding,depth"}));
  const io::VtkXmlFile f =
      io::parse_vtk_xml("c.vtp", test::read_file(tmp.path() / "c.vtp"));
  EXPECT_EQ(f.piece.at("NumberOfLines"), "0");
}

TEST(Contacts, ContactWithUnknownParticleIsRefused) {
  test::TempDir tmp;
  Snapshot s = test::sample_snapshot();
  s.contacts.push_back({0, 3, 0, 0, 0, 0});
  EXPECT_THROW(write_contacts_csv(tmp.path() / "c.csv", s), Error);
  EXPECT_THROW(write_contacts_vtp(tmp.path() / "c.vtp", s), Error);
}

TEST(Contacts, NotWrittenWhenSettingsSayNo) {
  test::TempDir tmp;
  OutputSettings settings;
  settings.contacts = false;
  OutputSet out(settings, tmp.path());
  out.write_frame(test::sample_snapshot());
  EXPECT_TRUE(std::filesystem::exists(tmp.path() / "frames" / "frame_000001200.vtu"));
  EXPECT_FALSE(std::filesystem::exists(tmp.path() / "contacts"));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
