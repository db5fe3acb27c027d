#pragma once
// One 32 KiB block of a VTK array, compressed as VTK's compressors write it: a zlib stream
// (vtkZLibDataCompressor) or an .xz stream (vtkLZMADataCompressor). Each OpenMP thread of
// a writer keeps one: the zlib streams come from libdeflate, whose compressor is allocated
// once and reused (docs/performance.md, "Output frames": compression was most of a frame's
// time).
#include "tridem/output.hpp"

#include <cstddef>
#include <cstdint>

struct libdeflate_compressor;

namespace tridem::io {

class BlockCompressor {
 public:
  explicit BlockCompressor(VtkCompression compression);
  ~BlockCompressor();
  BlockCompressor(BlockCompressor&&) noexcept;
  BlockCompressor& operator=(BlockCompressor&&) noexcept;
  /// A copy is a compressor of its own, of the same kind (a writer kept in a
  /// std::function is copied).
  BlockCompressor(const BlockCompressor& other) : BlockCompressor(other.compression_) {}
  BlockCompressor& operator=(const BlockCompressor& other) {
    if (this != &other) *this = BlockCompressor(other.compression_);
    return *this;
  }

  /// The most bytes a block of `size` bytes may take compressed.
  std::size_t bound(std::size_t size) const;
  /// `size` bytes at `in` compressed into `out` (room for bound(size) bytes): the
  /// compressed size, or 0 with `error` set to the library's code.
  std::size_t compress(const std::uint8_t* in, std::size_t size, std::uint8_t* out,
                       std::size_t room, int& error);

 private:
  VtkCompression compression_;
  libdeflate_compressor* deflate_ = nullptr;
};

}  // namespace tridem::io
