#include "io/output/block_compressor.hpp"

#include "io/output/vtk_xml_writer.hpp"

#include <libdeflate.h>
#include <lzma.h>

#include <algorithm>
#include <new>
#include <utility>

namespace tridem::io {
namespace {

/// libdeflate's level 2: on a settled pile's float32 frame and network it wrote 4 % fewer
/// bytes than zlib's level 1 (the writer's level until 2026-12-06) in 0.7-0.8 of the time;
/// its level 1 was a little faster but wrote 16 % more (docs/performance.md, "Output frames",
/// item 11).
constexpr int kDeflateLevel = 2;

/// LZMA's fastest preset with a dictionary of one block (a larger one finds nothing more in
/// a 32 KiB block and costs its set-up on every block: 1 MiB, the preset's own, compressed
/// a dense pile's frame some five times slower to the same bytes; docs/performance.md,
/// "Output frames", item 9).
constexpr std::uint32_t kLzmaPreset = 0;

}  // namespace

BlockCompressor::BlockCompressor(VtkCompression compression) : compression_(compression) {
  if (compression_ == VtkCompression::Zlib) {
    deflate_ = libdeflate_alloc_compressor(kDeflateLevel);
    if (!deflate_) throw std::bad_alloc();
  }
}

BlockCompressor::~BlockCompressor() { libdeflate_free_compressor(deflate_); }

BlockCompressor::BlockCompressor(BlockCompressor&& other) noexcept
    : compression_(other.compression_), deflate_(std::exchange(other.deflate_, nullptr)) {}

BlockCompressor& BlockCompressor::operator=(BlockCompressor&& other) noexcept {
  if (this != &other) {
    libdeflate_free_compressor(deflate_);
    compression_ = other.compression_;
    deflate_ = std::exchange(other.deflate_, nullptr);
  }
  return *this;
}

std::size_t BlockCompressor::bound(std::size_t size) const {
  return compression_ == VtkCompression::Lzma ? lzma_stream_buffer_bound(size)
                                              : libdeflate_zlib_compress_bound(deflate_, size);
}

std::size_t BlockCompressor::compress(const std::uint8_t* in, std::size_t size, std::uint8_t* out,
                                      std::size_t room, int& error) {
  if (compression_ == VtkCompression::Lzma) {
    lzma_options_lzma options;
    lzma_lzma_preset(&options, kLzmaPreset);
    options.dict_size = std::max<std::uint32_t>(
        LZMA_DICT_SIZE_MIN, static_cast<std::uint32_t>(VtkXmlWriter::kBlockSize));
    lzma_filter filters[] = {{LZMA_FILTER_LZMA2, &options}, {LZMA_VLI_UNKNOWN, nullptr}};
    std::size_t used = 0;
    const lzma_ret rc =
        lzma_stream_buffer_encode(filters, LZMA_CHECK_CRC64, nullptr, in, size, out, &used, room);
    error = rc == LZMA_OK ? 0 : static_cast<int>(rc);
    return error == 0 ? used : 0;
  }
  // Room for the bound: libdeflate returns 0 only if it cannot fit, which it always can.
  const std::size_t used = libdeflate_zlib_compress(deflate_, in, size, out, room);
  error = used == 0 ? -1 : 0;
  return used;
}

}  // namespace tridem::io
