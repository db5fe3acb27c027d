// libFuzzer target: any bytes handed to the checkpoint reader must end in a Checkpoint or
// a tridem::Error. Mutated inputs almost never keep their checksums, so each input is
// also decoded with its sizes and checksums restamped: that lets the fuzzer reach the
// payload's parsing and the state's validation, not only the checksum test.
#include "io/checkpoint/crc32.hpp"
#include "io/checkpoint/format.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace {

void put_le(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint64_t v, int width) {
  for (int k = 0; k < width; ++k) bytes[at + k] = static_cast<std::uint8_t>(v >> (8 * k));
}

/// The input with a true payload size, payload checksum and header checksum.
std::vector<std::uint8_t> restamped(std::span<const std::uint8_t> input) {
  namespace f = tridem::checkpoint_format;
  std::vector<std::uint8_t> bytes(input.begin(), input.end());
  if (bytes.size() < f::kHeaderSize) return bytes;
  const auto payload = std::span(bytes).subspan(f::kHeaderSize);
  put_le(bytes, 32, payload.size(), 8);
  put_le(bytes, f::kPayloadCrcOffset, tridem::io::crc32(payload), 4);
  put_le(bytes, f::kHeaderCrcOffset, tridem::io::crc32(std::span(bytes).first(f::kHeaderCrcOffset)), 4);
  return bytes;
}

void decode(std::span<const std::uint8_t> bytes) {
  try {
    tridem::decode_checkpoint(bytes, "fuzz.ckpt");
  } catch (const tridem::Error&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> input(data, size);
  decode(input);
  decode(restamped(input));
  return 0;
}
