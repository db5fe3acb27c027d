#include "io/checkpoint/crc32.hpp"

#include <algorithm>
#include <limits>
#include <zlib.h>

namespace tridem::io {

static_assert(sizeof(z_off_t) >= 8, "zlib's offsets must hold a checkpoint's size");

std::uint32_t crc32(std::span<const std::uint8_t> bytes) {
  uLong c = ::crc32(0L, Z_NULL, 0);
  // zlib takes a 32-bit length: a large payload goes in chunks.
  constexpr std::size_t kChunk = std::numeric_limits<uInt>::max() / 2 + 1;
  for (std::size_t at = 0; at < bytes.size(); at += kChunk) {
    const std::size_t size = std::min(kChunk, bytes.size() - at);
    c = ::crc32(c, bytes.data() + at, static_cast<uInt>(size));
  }
  return static_cast<std::uint32_t>(c);
}

std::uint32_t crc32_combine(std::uint32_t crc_a, std::uint32_t crc_b, std::uint64_t size_b) {
  return static_cast<std::uint32_t>(::crc32_combine(crc_a, crc_b, static_cast<z_off_t>(size_b)));
}

}  // namespace tridem::io
