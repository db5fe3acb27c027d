// The two line-set VTP files, contacts/*.vtp and bonds/*.vtp, come from one writer
// (io/output/vtk_xml_writer's VtkXmlWriter::line_set_vtp): its files in Float64,
// uncompressed, are byte for byte tests/data/line_sets/ (both encodings). Those were
// written by this writer at issue 12, which changed the files: the contact network's
// points became the particles' centroids, shared by their contacts, and indices Int32.
// The files written before (tests/data/former_line_sets/, by the two separate writers
// the line-set writer replaced) are still read. TRIDEM_WRITE_LINE_SET_FILES=dir writes
// the files to dir instead (how the reference files were made).
#include "io_test_support.hpp"
#include "tridem/bonds_reader.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Snapshot with_bonds_and_contacts() {
  Snapshot s = test::sample_snapshot();  // its two contacts
  s.bond_a = {0, 0, 1};
  s.bond_b = {1, 2, 2};
  s.bond_damage = {0.0, 0.25, 1.0 / 3.0};
  s.bond_broken = {0, 0, 1};
  s.bond_x0 = {0.0, 1.0, 2.0 / 7.0};
  s.bond_y0 = {0.0, 0.5, 0.0};
  s.bond_x1 = {0.5, 1.5, 2.5};
  s.bond_y1 = {1.0, 1.5, 1.0 / 9.0};
  return s;
}

TEST(LineSetVtp, ContactsAndBondsFilesAreTheReferenceBytes) {
  const Snapshot s = with_bonds_and_contacts();
  ASSERT_FALSE(s.contacts.empty());
  const std::filesystem::path reference =
      std::filesystem::path(TRIDEM_SOURCE_DIR) / "tests/data/line_sets";
  const char* write_to = std::getenv("TRIDEM_WRITE_LINE_SET_FILES");
  test::TempDir tmp;
  const std::filesystem::path dir = write_to != nullptr ? write_to : tmp.path();
  for (const auto& [encoding, tag] :
       {std::pair{Encoding::Ascii, "ascii"}, std::pair{Encoding::Binary, "binary"}}) {
    const std::string contacts = std::string("contacts_") + tag + ".vtp";
    const std::string bonds = std::string("bonds_") + tag + ".vtp";
    // Doubles, uncompressed: the format whose bytes are pinned.
    const VtkFormat former{encoding, VtkPrecision::Float64, VtkCompression::None};
    write_contacts_vtp(dir / contacts, s, former);
    write_bonds_vtp(dir / bonds, s, former);
    if (write_to != nullptr) continue;
    for (const std::string& name : {contacts, bonds}) {
      const std::string made = test::read_file(dir / name);
      const std::string expected = test::read_file(reference / name);
      ASSERT_FALSE(expected.empty()) << name;
      EXPECT_EQ(made, expected) << name;
    }
  }
  if (write_to != nullptr) GTEST_SKIP() << "wrote the reference files to " << write_to;
}

// The renderer reads a frame's bonds back (tridem render): both encodings give the bonds
// as written, exactly.
TEST(LineSetVtp, BondsReadBack) {
  const Snapshot s = with_bonds_and_contacts();
  test::TempDir tmp;
  for (const VtkFormat format :
       {VtkFormat{Encoding::Ascii, VtkPrecision::Float64},
        VtkFormat{Encoding::Binary, VtkPrecision::Float64, VtkCompression::None},
        VtkFormat{Encoding::Binary, VtkPrecision::Float64, VtkCompression::Zlib},
        VtkFormat{Encoding::Appended, VtkPrecision::Float64, VtkCompression::Lzma}}) {
    write_bonds_vtp(tmp.path() / "b.vtp", s, format);
    Snapshot r;
    read_bonds_vtp(tmp.path() / "b.vtp", r);
    EXPECT_EQ(r.bond_a, s.bond_a);
    EXPECT_EQ(r.bond_b, s.bond_b);
    EXPECT_EQ(r.bond_damage, s.bond_damage);
    EXPECT_EQ(r.bond_broken, s.bond_broken);
    EXPECT_EQ(r.bond_x0, s.bond_x0);
    EXPECT_EQ(r.bond_y1, s.bond_y1);
  }
  write_contacts_vtp(tmp.path() / "c.vtp", s, {Encoding::Ascii});
  Snapshot r;
  EXPECT_THROW(read_bonds_vtp(tmp.path() / "c.vtp", r), Error);  // no damage array
}

// Bonds files written before issue 12 (Int64 indices, two runs of the old writers) read as
// they did.
TEST(LineSetVtp, FormerBondsFilesReadBack) {
  const Snapshot s = with_bonds_and_contacts();
  const std::filesystem::path former =
      std::filesystem::path(TRIDEM_SOURCE_DIR) / "tests/data/former_line_sets";
  for (const char* name : {"bonds_ascii.vtp", "bonds_binary.vtp"}) {
    Snapshot r;
    read_bonds_vtp(former / name, r);
    EXPECT_EQ(r.bond_a, s.bond_a) << name;
    EXPECT_EQ(r.bond_b, s.bond_b) << name;
    EXPECT_EQ(r.bond_damage, s.bond_damage) << name;
    EXPECT_EQ(r.bond_broken, s.bond_broken) << name;
    EXPECT_EQ(r.bond_x0, s.bond_x0) << name;
    EXPECT_EQ(r.bond_y1, s.bond_y1) << name;
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
