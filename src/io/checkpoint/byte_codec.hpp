#pragma once
// Little-endian encoding of fixed-size numbers into a byte buffer and back. The reader
// never reads past its end: it throws RunError naming the source and what it was reading,
// which is how a truncated or lying checkpoint is refused.
#include "tridem/error.hpp"

#include <bit>
#include <cstdint>
#include <fmt/format.h>
#include <span>
#include <string>
#include <vector>

namespace tridem::io {

class ByteWriter {
 public:
  explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}
  void u32(std::uint32_t v) { unsigned_le(v, 4); }
  void u64(std::uint64_t v) { unsigned_le(v, 8); }
  void i32(std::int32_t v) { unsigned_le(static_cast<std::uint32_t>(v), 4); }
  void i64(std::int64_t v) { unsigned_le(static_cast<std::uint64_t>(v), 8); }
  void f64(double v) { unsigned_le(std::bit_cast<std::uint64_t>(v), 8); }
  /// u32 length, then the bytes.
  void text(const std::string& v) {
    u32(static_cast<std::uint32_t>(v.size()));
    out_.insert(out_.end(), v.begin(), v.end());
  }

 private:
  void unsigned_le(std::uint64_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) out_.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
  }
  std::vector<std::uint8_t>& out_;
};

class ByteReader {
 public:
  ByteReader(std::span<const std::uint8_t> bytes, const std::string& source)
      : bytes_(bytes), source_(source) {}
  std::uint32_t u32(const char* what) { return static_cast<std::uint32_t>(unsigned_le(4, what)); }
  std::uint64_t u64(const char* what) { return unsigned_le(8, what); }
  std::int32_t i32(const char* what) { return static_cast<std::int32_t>(u32(what)); }
  std::int64_t i64(const char* what) { return static_cast<std::int64_t>(u64(what)); }
  double f64(const char* what) { return std::bit_cast<double>(u64(what)); }
  std::string text(const char* what) {
    const std::uint32_t size = u32(what);
    need(size, what);
    std::string v(reinterpret_cast<const char*>(bytes_.data() + at_), size);
    at_ += size;
    return v;
  }
  std::size_t remaining() const { return bytes_.size() - at_; }

 private:
  void need(std::size_t size, const char* what) const {
    if (remaining() < size)
      throw RunError(fmt::format("{}: truncated: {} ends at byte {} of {}", source_, what,
                                 at_ + size, bytes_.size()));
  }
  std::uint64_t unsigned_le(int bytes, const char* what) {
    need(static_cast<std::size_t>(bytes), what);
    std::uint64_t v = 0;
    for (int k = 0; k < bytes; ++k) v |= std::uint64_t{bytes_[at_ + k]} << (8 * k);
    at_ += static_cast<std::size_t>(bytes);
    return v;
  }
  std::span<const std::uint8_t> bytes_;
  const std::string& source_;
  std::size_t at_ = 0;
};

}  // namespace tridem::io
