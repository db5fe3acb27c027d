#include "io/scene/generator_checks.hpp"

#include "core/particle_model.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace tridem::scene_detail {
namespace {

bool finite(Vec2d v) { return std::isfinite(v.x) && std::isfinite(v.y); }

[[noreturn]] void refuse(std::string_view generator, const std::string& what) {
  throw SceneError(fmt::format("{} generator: {}", generator, what));
}

}  // namespace

void check_generator_common(std::string_view generator, int material, Vec2d region_min,
                            Vec2d region_max, double size, double gap, Vec2d velocity) {
  if (material < 0) refuse(generator, fmt::format("material index {} is negative", material));
  if (!finite(region_min) || !finite(region_max))
    refuse(generator, "region corners must be finite");
  if (!(region_max.x > region_min.x) || !(region_max.y > region_min.y))
    refuse(generator, fmt::format("region max ({}, {}) must exceed min ({}, {}) on both axes",
                                  region_max.x, region_max.y, region_min.x, region_min.y));
  if (!std::isfinite(size) || !(size > 0))
    refuse(generator, fmt::format("size must be finite and > 0, got {}", size));
  if (!std::isfinite(gap) || !(gap >= 0))
    refuse(generator, fmt::format("gap must be finite and >= 0, got {}", gap));
  if (!finite(velocity)) refuse(generator, "velocity must be finite");
}

void check_generated_count(std::string_view generator, std::size_t n) {
  if (n == 0) refuse(generator, "the region holds no whole triangle of this size and gap");
  if (n > kMaxGeneratedTriangles)
    refuse(generator, fmt::format("would make {} triangles, more than the limit of {}", n,
                                  kMaxGeneratedTriangles));
}

std::size_t saturating_count(double n) {
  // 2^62 is far beyond any real limit yet exactly representable and below SIZE_MAX.
  constexpr double kCap = 4611686018427387904.0;
  if (!(n > 0)) return 0;
  if (n >= kCap) return static_cast<std::size_t>(kCap);
  return static_cast<std::size_t>(n);
}

double tolerant_floor(double x) { return std::floor(x + 1e-9); }

std::size_t bytes_to_read(std::size_t n) {
  // Two TriangleSpec lists while the vector grows, and the particle model's per-particle
  // arrays (centroid, offsets, velocities, mass terms, sizes, material, motion).
  return n * (2 * sizeof(TriangleSpec) + kParticleModelBytes);
}

std::size_t available_memory_bytes() {
  if (std::FILE* f = std::fopen("/proc/meminfo", "r")) {
    char line[256];
    unsigned long long kib = 0;
    bool found = false;
    while (!found && std::fgets(line, sizeof line, f))
      found = std::sscanf(line, "MemAvailable: %llu kB", &kib) == 1;
    std::fclose(f);
    if (found) return static_cast<std::size_t>(kib) * 1024;
  }
  return static_cast<std::size_t>(sysconf(_SC_PHYS_PAGES)) *
         static_cast<std::size_t>(sysconf(_SC_PAGE_SIZE));
}

std::string memory_shortfall(std::size_t total, std::size_t available) {
  const std::size_t need = bytes_to_read(total);
  if (need <= available) return {};
  constexpr double kGiB = 1024.0 * 1024.0 * 1024.0;
  return fmt::format("{} triangles in all would need about {:.1f} GiB of memory just to be "
                     "read, and this machine has {:.1f} GiB available (check the units of "
                     "region and size)",
                     total, static_cast<double>(need) / kGiB,
                     static_cast<double>(available) / kGiB);
}

}  // namespace tridem::scene_detail
