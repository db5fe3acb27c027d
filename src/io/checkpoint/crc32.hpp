#pragma once
// CRC-32 (IEEE 802.3, the one of zlib and PNG): catches truncation and flipped bits in a
// checkpoint. Not a defence against deliberate tampering, which is not the threat here.
#include <cstdint>
#include <span>

namespace tridem::io {

std::uint32_t crc32(std::span<const std::uint8_t> bytes);

}  // namespace tridem::io
