#pragma once
// How many steps the time loop runs between two looks at the clock, the progress bar and
// the interrupt flag: about 0.05 to 0.2 s of work.
#include <cstdint>

namespace tridem {

inline constexpr std::int64_t kMaxChunk = std::int64_t{1} << 20;

/// The chunk after one of `used` steps that took `seconds`: doubled after a full, quick
/// chunk, halved after a slow one, within [1, kMaxChunk]. Only a full chunk may double it:
/// when output events come every few steps the chunks are cut short, and doubling them
/// anyway overflowed the length after 63 events and stalled the run (advance(0) forever).
inline std::int64_t next_chunk(std::int64_t chunk, std::int64_t used, double seconds) {
  if (seconds < 0.05 && used == chunk && chunk < kMaxChunk) return chunk * 2;
  if (seconds > 0.2 && chunk > 1) return chunk / 2;
  return chunk;
}

}  // namespace tridem
