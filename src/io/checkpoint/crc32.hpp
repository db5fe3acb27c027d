#pragma once
// CRC-32 (IEEE 802.3, the one of zlib and PNG): catches truncation and flipped bits in a
// checkpoint. Not a defence against deliberate tampering, which is not the threat here.
// zlib computes it (several bytes a cycle, where a byte-wise table took about one) and
// combines the checksums of pieces written apart (mpi/parallel_checkpoint).
#include <cstdint>
#include <span>

namespace tridem::io {

std::uint32_t crc32(std::span<const std::uint8_t> bytes);

/// The CRC-32 of A followed by B, from crc32(A), crc32(B) and B's size.
std::uint32_t crc32_combine(std::uint32_t crc_a, std::uint32_t crc_b, std::uint64_t size_b);

}  // namespace tridem::io
