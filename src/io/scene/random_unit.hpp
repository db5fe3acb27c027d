#pragma once
// Uniform doubles from raw mt19937_64 output. std::uniform_real_distribution is not used
// because its algorithm is implementation-defined: the same seed would give different
// packings with libstdc++, libc++ and MSVC. mt19937_64 itself is fully specified.
#include <random>

namespace tridem::scene_detail {

/// Uniform in [0, 1): the top 53 bits of one draw, exactly representable in a double.
inline double unit_double(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// Uniform in [-1, 1).
inline double signed_unit_double(std::mt19937_64& rng) { return 2 * unit_double(rng) - 1; }

}  // namespace tridem::scene_detail
