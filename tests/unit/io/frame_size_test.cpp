// The size of a frame on disk and what a Float32 frame keeps of the state. Issue 12 asks
// for at most 100 bytes per triangle with the contact network; the default format gives
// 147 on this pile, 5.8 touching pairs per triangle (about 57 for the frame, 15 per
// contact; docs/output-format.md, "Size of a frame"), against 1,117 before (and 1,106 more
// for contacts.csv). The bound asserted is what is met, with a margin for the platform's
// zlib; the 100 is not met by the default files, and this test says so in its name rather
// than pretend. Fewer arrays in appended data (`[output] frame_arrays`, `contact_arrays`,
// `vtk_encoding = "appended"`) meet it.
#include "io/output/vtk_frames.hpp"
#include "io/output/vtk_xml_reader.hpp"
#include "io_test_support.hpp"
#include "tridem/output.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

/// dense_pile(3000) after kSteps steps, with its contacts: the lattice's neighbours all
/// still touch (about kDensity touching pairs per triangle).
constexpr std::int64_t kSteps = 20;
Snapshot dense_frame() {
  Scene scene = dense_pile(3000);
  scene.simulation.backend = Backend::Cpu;
  auto solver = make_solver(scene, {});
  solver->advance(kSteps);
  Snapshot s;
  solver->snapshot(s, true);
  return s;
}

const Snapshot& frame() {
  static const Snapshot s = dense_frame();
  return s;
}

double bytes_per_triangle(const fs::path& file, const Snapshot& s) {
  return static_cast<double>(fs::file_size(file)) / static_cast<double>(s.size());
}

TEST(FrameSize, DensePileFrameWithContactsIsAtMost160BytesPerTriangleNot100) {
  const Snapshot& s = frame();
  ASSERT_GE(static_cast<double>(s.contacts.size()) / static_cast<double>(s.size()), 5.5)
      << "the pile is meant to be dense";
  test::TempDir tmp;
  OutputSettings settings;
  settings.contacts_csv = false;  // the text copy of the network is not the VTK frame
  {
    OutputSet out(settings, tmp.path());
    out.write_frame(s);
  }
  const double frame_bytes = bytes_per_triangle(tmp.path() / "frames" / frame_file_name(s.step), s);
  const double contact_bytes =
      bytes_per_triangle(tmp.path() / "contacts" / (contacts_file_stem(s.step) + ".vtp"), s);
  EXPECT_LE(frame_bytes + contact_bytes, 160.0)
      << "frame " << frame_bytes << " B/triangle, contacts " << contact_bytes << " B/triangle, "
      << static_cast<double>(s.contacts.size()) / static_cast<double>(s.size())
      << " contacts per triangle";
  // Doubles, uncompressed, as before issue 12: over 5 times larger.
  const VtkFormat former{Encoding::Binary, VtkPrecision::Float64, VtkCompression::None};
  write_vtu_frame(tmp.path() / "former.vtu", s, former);
  write_contacts_vtp(tmp.path() / "former.vtp", s, former);
  EXPECT_GT(bytes_per_triangle(tmp.path() / "former.vtu", s) +
                bytes_per_triangle(tmp.path() / "former.vtp", s),
            5 * (frame_bytes + contact_bytes));
}

TEST(FrameSize, AppendedEncodingIsAQuarterSmallerAndReadsTheSame) {
  const Snapshot& s = frame();
  test::TempDir tmp;
  const VtkFormat appended{Encoding::Appended};
  write_vtu_frame(tmp.path() / "inline.vtu", s);
  write_contacts_vtp(tmp.path() / "inline.vtp", s);
  write_vtu_frame(tmp.path() / "appended.vtu", s, appended);
  write_contacts_vtp(tmp.path() / "appended.vtp", s, appended);
  const double inline_bytes = bytes_per_triangle(tmp.path() / "inline.vtu", s) +
                              bytes_per_triangle(tmp.path() / "inline.vtp", s);
  const double appended_bytes = bytes_per_triangle(tmp.path() / "appended.vtu", s) +
                                bytes_per_triangle(tmp.path() / "appended.vtp", s);
  // Base64 spends 4 characters on 3 bytes; the XML around the arrays is the same.
  EXPECT_LE(appended_bytes, 0.77 * inline_bytes)
      << "appended " << appended_bytes << " B/triangle, inline " << inline_bytes;
  const Snapshot a = read_vtu_frame(tmp.path() / "inline.vtu");
  const Snapshot b = read_vtu_frame(tmp.path() / "appended.vtu");
  EXPECT_EQ(a.x1, b.x1);
  EXPECT_EQ(a.vx, b.vx);
  EXPECT_EQ(a.torque, b.torque);
  EXPECT_EQ(a.material, b.material);
  const auto network = [&](const char* name) {
    const fs::path file = tmp.path() / name;
    const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), test::read_file(file));
    return io::decode_array(f, *io::find_array(f, "CellData", "force"), 3, s.contacts.size());
  };
  EXPECT_EQ(network("inline.vtp"), network("appended.vtp"));
}

TEST(FrameSize, LeanArraysInAppendedDataAreAtMost100BytesPerTriangleWithContacts) {
  const Snapshot& s = frame();
  test::TempDir tmp;
  // What a long run keeps to see motion and force chains: `[output] vtk_encoding =
  // "appended"`, `frame_arrays = ["velocity", "angular_velocity"]`, `contact_arrays =
  // ["force"]` (docs/performance.md, "Output frames", item 12).
  OutputSettings lean;
  lean.contacts_csv = false;
  lean.encoding = Encoding::Appended;
  lean.frame_arrays = ArraySet<FrameArray>::none();
  lean.frame_arrays.add(FrameArray::Velocity);
  lean.frame_arrays.add(FrameArray::AngularVelocity);
  lean.contact_arrays = ArraySet<ContactArray>::none();
  lean.contact_arrays.add(ContactArray::Force);
  OutputSettings every_array = lean;
  every_array.frame_arrays = {};
  every_array.contact_arrays = {};
  const auto bytes = [&](const OutputSettings& settings, const char* dir) {
    {
      OutputSet out(settings, tmp.path() / dir, settings.vtk_format());
      out.write_frame(s);
    }
    return bytes_per_triangle(tmp.path() / dir / "frames" / frame_file_name(s.step), s) +
           bytes_per_triangle(tmp.path() / dir / "contacts" / (contacts_file_stem(s.step) + ".vtp"),
                              s);
  };
  const double lean_bytes = bytes(lean, "lean"), all_bytes = bytes(every_array, "all");
  EXPECT_LE(lean_bytes, 100.0) << "every array: " << all_bytes << " B/triangle";
  EXPECT_LE(lean_bytes, 0.6 * all_bytes) << "lean " << lean_bytes << " B/triangle";
  // The network's lines and forces are those of the full file.
  const auto force = [&](const char* dir) {
    const fs::path file = tmp.path() / dir / "contacts" / (contacts_file_stem(s.step) + ".vtp");
    const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), test::read_file(file));
    return io::decode_array(f, *io::find_array(f, "CellData", "force"), 3, s.contacts.size());
  };
  EXPECT_EQ(force("lean"), force("all"));
}

/// Each value read within float32's rounding of the state's (or of `scale`, if larger).
void expect_float_close(const std::vector<double>& read, const std::vector<double>& state,
                        double scale, const char* what) {
  ASSERT_EQ(read.size(), state.size()) << what;
  const double eps = std::numeric_limits<float>::epsilon();
  std::size_t differ = 0;
  for (std::size_t k = 0; k < state.size(); ++k) {
    EXPECT_NEAR(read[k], state[k], eps * std::max(std::abs(state[k]), scale))
        << what << "[" << k << "]";
    differ += read[k] != state[k];
  }
  EXPECT_GT(differ, 0u) << what << ": a Float32 frame cannot hold every double exactly";
}

TEST(FrameSize, CompressedFloat32FrameReadsBackWithinFloatRoundOff) {
  const Snapshot& s = frame();
  test::TempDir tmp;
  const fs::path file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, s);  // the default: binary, Float32, zlib
  const std::string text = test::read_file(file);
  ASSERT_NE(text.find("compressor=\"vtkZLibDataCompressor\""), std::string::npos);
  ASSERT_NE(text.find("type=\"Float32\" Name=\"Points\""), std::string::npos);
  const Snapshot r = read_vtu_frame(file);
  EXPECT_EQ(r.step, s.step);
  EXPECT_EQ(r.time, s.time) << "the time stays a double";
  ASSERT_EQ(r.size(), s.size());
  for (const auto v :
       {&Snapshot::x1, &Snapshot::y1, &Snapshot::x2, &Snapshot::y2, &Snapshot::x3, &Snapshot::y3})
    expect_float_close(r.*v, s.*v, 0, "vertex");
  expect_float_close(r.vx, s.vx, 0, "vx");
  expect_float_close(r.vy, s.vy, 0, "vy");
  expect_float_close(r.fx, s.fx, 0, "fx");
  expect_float_close(r.fy, s.fy, 0, "fy");
  expect_float_close(r.omega, s.omega, 0, "omega");
  expect_float_close(r.torque, s.torque, 0, "torque");
  EXPECT_EQ(r.material, s.material);
  EXPECT_EQ(r.motion, s.motion);

  // The contact network likewise.
  const fs::path contacts = tmp.path() / "contacts.vtp";
  write_contacts_vtp(contacts, s);
  const io::VtkXmlFile f = io::parse_vtk_xml(contacts.string(), test::read_file(contacts));
  const std::size_t m = s.contacts.size();
  const auto force_read = io::decode_array(f, *io::find_array(f, "CellData", "force"), 3, m);
  const auto depth_read = io::decode_array(f, *io::find_array(f, "CellData", "depth"), 1, m);
  std::vector<double> fx(m), fx_read(m), depth(m);
  for (std::size_t k = 0; k < m; ++k) {
    fx[k] = s.contacts[k].fx;
    fx_read[k] = force_read[3 * k];
    depth[k] = s.contacts[k].depth;
  }
  expect_float_close(fx_read, fx, 0, "contact fx");
  expect_float_close(depth_read, depth, 0, "contact depth");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
