// `[output] frame_arrays` and `contact_arrays`: the frames and networks carry the arrays
// chosen and no others, what is left out reads back as zeros (and is said to be absent),
// and the programs that need an absent array refuse the frame instead of drawing zeros.
#include "io/output/vtk_xml_reader.hpp"
#include "io_test_support.hpp"
#include "live/replay_view.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/render.hpp"
#include "tridem/setting_names.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

std::vector<std::string> cell_arrays(const fs::path& file) {
  const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), test::read_file(file));
  std::vector<std::string> names;
  for (const io::XmlDataArray& a : f.arrays)
    if (a.section == "CellData") names.push_back(a.attributes.at("Name"));
  return names;
}

template <class E>
ArraySet<E> set_of(std::initializer_list<E> chosen) {
  auto set = ArraySet<E>::none();
  for (E e : chosen) set.add(e);
  return set;
}

TEST(FrameArrays, AFrameCarriesTheChosenFieldsAndItsIdentity) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  const fs::path file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, s, {}, true, set_of({FrameArray::Velocity, FrameArray::Pressure}));
  EXPECT_EQ(cell_arrays(file),
            (std::vector<std::string>{"id", "velocity", "material", "motion", "body", "pressure"}));
  // ParaView's active attributes name only arrays the file has.
  const std::string text = test::read_file(file);
  EXPECT_NE(text.find("<CellData Vectors=\"velocity\">"), std::string::npos);
  EXPECT_EQ(text.find("Scalars="), std::string::npos);
  // Every field by default, in the contract's order.
  write_vtu_frame(tmp.path() / "all.vtu", s);
  EXPECT_EQ(
      cell_arrays(tmp.path() / "all.vtu"),
      (std::vector<std::string>{"id", "velocity", "angular_velocity", "force", "torque", "material",
                                "motion", "body", "stress", "pressure", "coordination"}));
}

TEST(FrameArrays, FieldsLeftOutReadAsZerosAndAreSaidToBeAbsent) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  const fs::path file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, s, {Encoding::Binary, VtkPrecision::Float64}, true,
                  set_of({FrameArray::AngularVelocity, FrameArray::Torque}));
  ArraySet<FrameArray> held;
  const Snapshot r = read_vtu_frame(file, &held);
  EXPECT_EQ(held, set_of({FrameArray::AngularVelocity, FrameArray::Torque}));
  EXPECT_EQ(r.omega, s.omega);
  EXPECT_EQ(r.torque, s.torque);
  EXPECT_EQ(r.vx, std::vector<double>(3, 0.0));
  EXPECT_EQ(r.fy, std::vector<double>(3, 0.0));
  EXPECT_EQ(r.x3, s.x3);
  EXPECT_EQ(r.material, s.material);
  EXPECT_EQ(r.motion, s.motion);
  // A default frame holds every field.
  write_vtu_frame(tmp.path() / "all.vtu", s);
  (void)read_vtu_frame(tmp.path() / "all.vtu", &held);
  EXPECT_EQ(held, ArraySet<FrameArray>{});
}

TEST(FrameArrays, ANetworkCarriesTheChosenArraysAndEveryLine) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  const fs::path file = tmp.path() / "c.vtp";
  write_contacts_vtp(file, s, {Encoding::Binary, VtkPrecision::Float64},
                     set_of({ContactArray::Depth, ContactArray::Force}));
  EXPECT_EQ(cell_arrays(file), (std::vector<std::string>{"force", "depth"}));
  EXPECT_NE(test::read_file(file).find("<CellData Vectors=\"force\">"), std::string::npos);
  const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), test::read_file(file));
  EXPECT_EQ(f.piece.at("NumberOfLines"), "2");
  const auto depth = io::decode_array(f, *io::find_array(f, "CellData", "depth"), 1, 2);
  EXPECT_EQ(depth, (std::vector<double>{s.contacts[0].depth, s.contacts[1].depth}));
  write_contacts_vtp(tmp.path() / "none.vtp", s, {}, ArraySet<ContactArray>::none());
  EXPECT_TRUE(cell_arrays(tmp.path() / "none.vtp").empty());
  EXPECT_EQ(test::read_file(tmp.path() / "none.vtp").find("Vectors="), std::string::npos);
}

TEST(FrameArrays, ARunsOutputsFollowItsSettings) {
  test::TempDir tmp;
  OutputSettings settings;
  settings.frame_arrays = set_of({FrameArray::Velocity});
  settings.contact_arrays = set_of({ContactArray::Force});
  {
    OutputSet out(settings, tmp.path());
    out.write_frame(test::sample_snapshot());
  }
  EXPECT_EQ(cell_arrays(tmp.path() / "frames" / "frame_000001200.vtu"),
            (std::vector<std::string>{"id", "velocity", "material", "motion", "body"}));
  EXPECT_EQ(cell_arrays(tmp.path() / "contacts" / "contacts_000001200.vtp"),
            (std::vector<std::string>{"force"}));
}

TEST(FrameArrays, ColouringBySpeedRefusesAFrameWithoutVelocities) {
  test::TempDir tmp;
  const fs::path file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, test::sample_snapshot(), {}, true, set_of({FrameArray::Force}));
  RenderOptions by_speed;
  try {
    (void)read_frame_to_render(file, by_speed);
    ADD_FAILURE() << "coloured a frame without velocities by speed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("--color material"), std::string::npos) << e.what();
  }
  RenderOptions by_material;
  by_material.color_by = RenderOptions::ColorBy::Material;
  EXPECT_EQ(read_frame_to_render(file, by_material).size(), 3U);
  write_vtu_frame(tmp.path() / "all.vtu", test::sample_snapshot());
  EXPECT_EQ(read_frame_to_render(tmp.path() / "all.vtu", by_speed).vx[1], 2.5);
}

TEST(FrameArrays, TheReplayRefusesAFrameWithoutItsSpeeds) {
  test::TempDir tmp;
  const fs::path file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, test::sample_snapshot(), {}, true, set_of({FrameArray::Velocity}));
  try {
    (void)live::read_replay_frame(file);
    ADD_FAILURE() << "replayed a frame without angular velocities";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("angular_velocity"), std::string::npos) << e.what();
  }
  write_vtu_frame(tmp.path() / "both.vtu", test::sample_snapshot(), {}, true,
                  set_of({FrameArray::Velocity, FrameArray::AngularVelocity}));
  EXPECT_EQ(live::read_replay_frame(tmp.path() / "both.vtu").omega[1], -7.25);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
