// io/output/block_compressor: each block a stream that the readers' libraries take back to
// the same bytes (zlib's uncompress for vtkZLibDataCompressor's blocks, which libdeflate
// writes; liblzma for vtkLZMADataCompressor's), within the bound it names, and a copy a
// compressor of its own (writers are copied into the run's std::function outputs).
#include "io/output/block_compressor.hpp"
#include "io/output/vtk_xml_writer.hpp"

#include <gtest/gtest.h>
#include <lzma.h>
#include <zlib.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace tridem::io {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// A block of float32s as a frame's arrays hold them: a slow ramp with noise in the low bits
/// (compressible), and a block of random bytes (not).
std::vector<std::uint8_t> float_block(std::size_t bytes) {
  std::vector<std::uint8_t> block(bytes);
  std::mt19937 random(7);
  std::normal_distribution<float> noise(0.0F, 1e-3F);
  for (std::size_t k = 0; k + 4 <= bytes; k += 4) {
    const float v = 10.0F + 0.01F * static_cast<float>(k / 4) + noise(random);
    std::memcpy(block.data() + k, &v, 4);
  }
  return block;
}
std::vector<std::uint8_t> random_block(std::size_t bytes) {
  std::vector<std::uint8_t> block(bytes);
  std::mt19937 random(11);
  for (std::uint8_t& b : block) b = static_cast<std::uint8_t>(random());
  return block;
}

std::vector<std::uint8_t> compressed(BlockCompressor& c, const std::vector<std::uint8_t>& block) {
  std::vector<std::uint8_t> out(c.bound(block.size()));
  int error = 1;
  const std::size_t used = c.compress(block.data(), block.size(), out.data(), out.size(), error);
  EXPECT_EQ(error, 0);
  EXPECT_GT(used, 0U);
  out.resize(used);
  return out;
}

std::vector<std::uint8_t> zlib_back(const std::vector<std::uint8_t>& stream, std::size_t size) {
  std::vector<std::uint8_t> back(size + 1);
  uLongf length = static_cast<uLongf>(back.size());
  EXPECT_EQ(uncompress(back.data(), &length, stream.data(), static_cast<uLong>(stream.size())),
            Z_OK);
  back.resize(length);
  return back;
}

std::vector<std::uint8_t> lzma_back(const std::vector<std::uint8_t>& stream, std::size_t size) {
  std::vector<std::uint8_t> back(size + 1);
  std::uint64_t limit = UINT64_MAX;
  std::size_t in = 0, out = 0;
  EXPECT_EQ(lzma_stream_buffer_decode(&limit, 0, nullptr, stream.data(), &in, stream.size(),
                                      back.data(), &out, back.size()),
            LZMA_OK);
  back.resize(out);
  return back;
}

TEST(BlockCompressor, ZlibBlocksReadBackThroughZlib) {
  BlockCompressor c(VtkCompression::Zlib);
  for (const std::size_t bytes : {VtkXmlWriter::kBlockSize, std::size_t{1000}, std::size_t{1}}) {
    for (const std::vector<std::uint8_t>& block : {float_block(bytes), random_block(bytes)}) {
      const std::vector<std::uint8_t> stream = compressed(c, block);
      EXPECT_LE(stream.size(), c.bound(bytes));
      EXPECT_EQ(zlib_back(stream, bytes), block) << bytes << " bytes";
    }
  }
  // The float ramp compresses (the random bytes cannot).
  EXPECT_LT(compressed(c, float_block(VtkXmlWriter::kBlockSize)).size(),
            VtkXmlWriter::kBlockSize * 9 / 10);
}

TEST(BlockCompressor, LzmaBlocksReadBackThroughLiblzma) {
  BlockCompressor c(VtkCompression::Lzma);
  for (const std::size_t bytes : {VtkXmlWriter::kBlockSize, std::size_t{1000}}) {
    for (const std::vector<std::uint8_t>& block : {float_block(bytes), random_block(bytes)}) {
      const std::vector<std::uint8_t> stream = compressed(c, block);
      EXPECT_LE(stream.size(), c.bound(bytes));
      EXPECT_EQ(lzma_back(stream, bytes), block) << bytes << " bytes";
    }
  }
}

TEST(BlockCompressor, CopiesAndMovesCompressOnTheirOwn) {
  const std::vector<std::uint8_t> block = float_block(VtkXmlWriter::kBlockSize);
  BlockCompressor original(VtkCompression::Zlib);
  BlockCompressor copy(original);
  BlockCompressor assigned(VtkCompression::Lzma);
  assigned = copy;  // now a zlib compressor of its own
  BlockCompressor moved(std::move(copy));
  const std::vector<std::uint8_t> expected = compressed(original, block);
  EXPECT_EQ(compressed(moved, block), expected);
  EXPECT_EQ(compressed(assigned, block), expected);
  EXPECT_EQ(zlib_back(compressed(assigned, block), block.size()), block);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::io
