#pragma once
// Spec checks shared by the two generators, so code that calls them directly gets the same
// refusals as a scene file (whose reader checks first, to name the offending key).
#include "tridem/vec2.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace tridem::scene_detail {

/// Throws SceneError unless material >= 0, region finite with max > min on both axes,
/// size finite and > 0, gap finite and >= 0, velocity finite.
void check_generator_common(std::string_view generator, int material, Vec2d region_min,
                            Vec2d region_max, double size, double gap, Vec2d velocity);

/// Throws SceneError if `n` triangles is none at all or more than kMaxGeneratedTriangles.
void check_generated_count(std::string_view generator, std::size_t n);

/// Bytes of host memory that reading a scene of n triangles and building its particle
/// model take at the peak (the list of triangles may be copied once as it grows).
std::size_t bytes_to_read(std::size_t n);

/// The host memory available now (MemAvailable of /proc/meminfo; the physical memory where
/// that cannot be read).
std::size_t available_memory_bytes();

/// Why `total` generated triangles in all cannot be read on a machine with `available`
/// bytes free, or an empty string when they can: the reader refuses before generating, so
/// that a units slip ends with a message rather than the kernel's out-of-memory kill.
std::string memory_shortfall(std::size_t total, std::size_t available);

/// Converts a non-negative count computed in double (which may be astronomically large for
/// a units mistake) to size_t without overflow: anything too big saturates.
std::size_t saturating_count(double n);

/// floor(x) tolerant of rounding just below an integer, so that a region exactly k pitches
/// wide holds k items and not k-1.
double tolerant_floor(double x);

}  // namespace tridem::scene_detail
