#include "io_test_support.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

void expect_round_trip(VtkFormat format) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  const auto file = tmp.path() / "frame.vtu";
  write_vtu_frame(file, s, format);
  const Snapshot r = read_vtu_frame(file);

  EXPECT_EQ(r.step, s.step);
  EXPECT_EQ(r.time, s.time);
  ASSERT_EQ(r.size(), s.size());
  // Doubles are exact in every encoding: raw bytes, or %.17g text.
  EXPECT_EQ(r.x1, s.x1);
  EXPECT_EQ(r.y1, s.y1);
  EXPECT_EQ(r.x2, s.x2);
  EXPECT_EQ(r.y2, s.y2);
  EXPECT_EQ(r.x3, s.x3);
  EXPECT_EQ(r.y3, s.y3);
  EXPECT_EQ(r.vx, s.vx);
  EXPECT_EQ(r.vy, s.vy);
  EXPECT_EQ(r.omega, s.omega);
  EXPECT_EQ(r.fx, s.fx);
  EXPECT_EQ(r.fy, s.fy);
  EXPECT_EQ(r.torque, s.torque);
  EXPECT_EQ(r.material, s.material);
  EXPECT_EQ(r.motion, s.motion);
  for (std::size_t k = 0; k < s.size(); ++k) {
    EXPECT_NEAR(r.x[k], s.x[k], 1e-15);  // recomputed as the vertex mean
    EXPECT_NEAR(r.y[k], s.y[k], 1e-15);
  }
}

TEST(Vtu, BinaryRoundTrip) {
  expect_round_trip({Encoding::Binary, VtkPrecision::Float64, VtkCompression::None});
}
TEST(Vtu, CompressedBinaryRoundTrip) {
  expect_round_trip({Encoding::Binary, VtkPrecision::Float64, VtkCompression::Zlib});
}
TEST(Vtu, AsciiRoundTrip) { expect_round_trip({Encoding::Ascii, VtkPrecision::Float64}); }
TEST(Vtu, AppendedRoundTrip) {
  expect_round_trip({Encoding::Appended, VtkPrecision::Float64, VtkCompression::None});
}
TEST(Vtu, CompressedAppendedRoundTrip) {
  expect_round_trip({Encoding::Appended, VtkPrecision::Float64, VtkCompression::Zlib});
}
TEST(Vtu, LzmaBinaryRoundTrip) {
  expect_round_trip({Encoding::Binary, VtkPrecision::Float64, VtkCompression::Lzma});
}
TEST(Vtu, LzmaAppendedRoundTrip) {
  expect_round_trip({Encoding::Appended, VtkPrecision::Float64, VtkCompression::Lzma});
}

TEST(Vtu, DeclaresTheRequestedEncoding) {
  test::TempDir tmp;
  const Snapshot s = test::sample_snapshot();
  write_vtu_frame(tmp.path() / "b.vtu", s, {Encoding::Binary});
  write_vtu_frame(tmp.path() / "a.vtu", s, {Encoding::Ascii});
  const std::string binary = test::read_file(tmp.path() / "b.vtu");
  const std::string ascii = test::read_file(tmp.path() / "a.vtu");
  EXPECT_NE(binary.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(binary.find("format=\"binary\""), std::string::npos);
  EXPECT_EQ(binary.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(ascii.find("format=\"binary\""), std::string::npos);
  for (const char* name : {"\"id\"", "\"velocity\"", "\"angular_velocity\"", "\"force\"",
                           "\"torque\"", "\"material\"", "\"motion\""})
    EXPECT_NE(ascii.find(name), std::string::npos) << name;
  EXPECT_NE(ascii.find("NumberOfPoints=\"9\" NumberOfCells=\"3\""), std::string::npos);
}

TEST(Vtu, EmptyFrameRoundTrips) {
  test::TempDir tmp;
  Snapshot s;
  s.step = 3;
  write_vtu_frame(tmp.path() / "e.vtu", s);
  const Snapshot r = read_vtu_frame(tmp.path() / "e.vtu");
  EXPECT_EQ(r.size(), 0u);
  EXPECT_EQ(r.step, 3);
}

/// Writes the sample snapshot as an ASCII frame whose id array reads `ids` instead of
/// "0 1 2", and so does its body array (each of its triangles is its own body): the cells
/// of a frame reordered, all their data with them.
void write_frame_with_ids(const std::filesystem::path& file, const std::string& ids) {
  write_vtu_frame(file, test::sample_snapshot(), {Encoding::Ascii, VtkPrecision::Float64});
  std::string text = test::read_file(file);
  for (const char* name : {"id", "body"}) {
    const std::string header =
        std::string("Name=\"") + name + "\" NumberOfComponents=\"1\" format=\"ascii\">\n";
    const auto at = text.find(header + "0 1 2");
    ASSERT_NE(at, std::string::npos) << name;
    text.replace(at, header.size() + 5, header + ids);
  }
  std::ofstream(file, std::ios::binary) << text;
}

TEST(Vtu, CellsOutOfIdOrderAreReordered) {
  test::TempDir tmp;
  const auto file = tmp.path() / "f.vtu";
  // Swap the ids of cells 0 and 1; their data then belongs to the other particle.
  write_frame_with_ids(file, "1 0 2");
  const Snapshot s = test::sample_snapshot();
  const Snapshot r = read_vtu_frame(file);
  EXPECT_EQ(r.vx[0], s.vx[1]);
  EXPECT_EQ(r.x1[1], s.x1[0]);
  EXPECT_EQ(r.material[0], s.material[1]);
  EXPECT_TRUE(r.member_body.empty()) << "each triangle is still its own body";
}

TEST(Vtu, DuplicateIdIsRefused) {
  test::TempDir tmp;
  const auto file = tmp.path() / "f.vtu";
  write_frame_with_ids(file, "0 1 1");
  EXPECT_THROW(read_vtu_frame(file), Error);
}

/// Each malformation in the former format (Float64, uncompressed), the default one
/// (Float32, zlib) and with LZMA.
class VtuMalformed : public ::testing::TestWithParam<VtkFormat> {
 protected:
  void SetUp() override {
    file_ = tmp_.path() / "frame.vtu";
    write_vtu_frame(file_, test::sample_snapshot(), format());
    text_ = test::read_file(file_);
  }
  /// Replaces the first `from` by `to`, then expects an Error that names the file.
  void expect_refused(const std::string& from, const std::string& to) {
    std::string text = text_;
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(file_, std::ios::binary | std::ios::trunc) << text;
    try {
      read_vtu_frame(file_);
      ADD_FAILURE() << "accepted a frame with '" << from << "' replaced by '" << to << "'";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(file_.string()), std::string::npos) << e.what();
    }
  }
  virtual VtkFormat format() const { return GetParam(); }
  test::TempDir tmp_;
  std::filesystem::path file_;
  std::string text_;
};

TEST_P(VtuMalformed, MissingFile) { EXPECT_THROW(read_vtu_frame(tmp_.path() / "nope.vtu"), Error); }
TEST_P(VtuMalformed, Truncated) { expect_refused("</CellData>", ""); }
TEST_P(VtuMalformed, NotAFrame) { expect_refused("UnstructuredGrid\"", "PolyData\""); }
TEST_P(VtuMalformed, MissingArray) { expect_refused("Name=\"motion\"", "Name=\"moton\""); }
TEST_P(VtuMalformed, WrongComponents) {
  expect_refused("Name=\"velocity\" NumberOfComponents=\"3\"",
                 "Name=\"velocity\" NumberOfComponents=\"2\"");
}
TEST_P(VtuMalformed, BadBase64) {
  const std::string head = "Name=\"torque\" NumberOfComponents=\"1\" format=\"binary\">\n";
  expect_refused(head, head + "!");
}
TEST_P(VtuMalformed, WrongCellCount) {
  expect_refused("NumberOfCells=\"3\"", "NumberOfCells=\"4\"");
}
TEST_P(VtuMalformed, UnknownFormat) { expect_refused("format=\"binary\"", "format=\"appended\""); }

INSTANTIATE_TEST_SUITE_P(
    Formats, VtuMalformed,
    ::testing::Values(VtkFormat{Encoding::Binary, VtkPrecision::Float64, VtkCompression::None},
                      VtkFormat{},
                      VtkFormat{Encoding::Binary, VtkPrecision::Float32, VtkCompression::Lzma}),
    [](const ::testing::TestParamInfo<VtkFormat>& p) {
      return p.param.compression == VtkCompression::Lzma ? std::string("Lzma")
             : p.param.compressed()                      ? std::string("Compressed")
                                                         : std::string("Plain");
    });

/// A compressed frame with something else broken.
class VtuCompressedMalformed : public VtuMalformed {
 protected:
  VtkFormat format() const override { return {}; }
  /// The torque array's text is two base64 runs: the header (4 UInt64s: 44 characters with
  /// its padding) then the block; a changed character in the block breaks its stream or
  /// its checksum.
  void expect_corrupt_block_refused() {
    const std::string head = "Name=\"torque\" NumberOfComponents=\"1\" format=\"binary\">\n";
    const auto at = text_.find(head);
    ASSERT_NE(at, std::string::npos);
    const std::size_t block = at + head.size() + 44;
    const std::string original = text_.substr(block, 8);
    std::string changed = original;
    for (char& c : changed) c = c == 'A' ? 'B' : 'A';
    expect_refused(head + text_.substr(at + head.size(), 44) + original,
                   head + text_.substr(at + head.size(), 44) + changed);
  }
};

/// The same with vtkLZMADataCompressor's .xz blocks.
class VtuLzmaMalformed : public VtuCompressedMalformed {
 protected:
  VtkFormat format() const override {
    return {Encoding::Binary, VtkPrecision::Float32, VtkCompression::Lzma};
  }
};

TEST_F(VtuLzmaMalformed, DeclaresItsCompressor) {
  EXPECT_NE(text_.find("compressor=\"vtkLZMADataCompressor\""), std::string::npos);
  EXPECT_EQ(read_vtu_frame(file_).material, test::sample_snapshot().material);
}
TEST_F(VtuLzmaMalformed, CorruptBlock) { expect_corrupt_block_refused(); }
TEST_F(VtuLzmaMalformed, ZlibBlocksReadAsLzma) {
  // A zlib frame that claims LZMA: its blocks are no .xz streams.
  file_ = tmp_.path() / "zlib.vtu";
  write_vtu_frame(file_, test::sample_snapshot(), VtkFormat{});
  text_ = test::read_file(file_);
  expect_refused("vtkZLibDataCompressor", "vtkLZMADataCompressor");
}

TEST_F(VtuCompressedMalformed, OtherCompressor) {
  expect_refused("vtkZLibDataCompressor", "vtkLZ4DataCompressor");
}
TEST_F(VtuCompressedMalformed, UncompressedReadAsCompressed) {
  // The header of a plain array is no block table; nor do its bytes inflate.
  file_ = tmp_.path() / "plain.vtu";
  write_vtu_frame(file_, test::sample_snapshot(),
                  {Encoding::Binary, VtkPrecision::Float32, VtkCompression::None});
  text_ = test::read_file(file_);
  expect_refused("header_type=\"UInt64\"",
                 "header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\"");
}
TEST_F(VtuCompressedMalformed, CorruptBlock) { expect_corrupt_block_refused(); }

/// The appended encoding: the arrays' bytes after the XML, each element naming its offset.
class VtuAppendedMalformed : public VtuMalformed {
 protected:
  VtkFormat format() const override { return {Encoding::Appended}; }
};

TEST_F(VtuAppendedMalformed, DeclaresAppendedRawData) {
  EXPECT_NE(text_.find("format=\"appended\" offset=\"0\"/>"), std::string::npos);
  EXPECT_NE(text_.find("<AppendedData encoding=\"raw\">\n   _"), std::string::npos);
  EXPECT_EQ(text_.find("format=\"binary\""), std::string::npos);
  const Snapshot r = read_vtu_frame(file_);
  EXPECT_EQ(r.material, test::sample_snapshot().material);
}
TEST_F(VtuAppendedMalformed, BlockCutShort) {
  // The block ends halfway: the arrays of its second half run past it.
  const auto begin = text_.find("   _") + 4;
  const auto end = text_.rfind("\n  </AppendedData>");
  ASSERT_LT(begin, end);
  const auto half = begin + (end - begin) / 2;
  expect_refused(text_.substr(half), text_.substr(end));
}
TEST_F(VtuAppendedMalformed, OffsetPastTheData) {
  expect_refused("offset=\"0\"", "offset=\"99999999\"");
}
TEST_F(VtuAppendedMalformed, OffsetNotANumber) { expect_refused("offset=\"0\"", "offset=\"x\""); }
TEST_F(VtuAppendedMalformed, Base64AppendedData) {
  expect_refused("encoding=\"raw\"", "encoding=\"base64\"");
}
TEST_F(VtuAppendedMalformed, UnclosedBlock) { expect_refused("</AppendedData>", "</Appended>"); }

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
