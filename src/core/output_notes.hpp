#pragma once
// Outputs that will cost a large run more than its steps, named before it starts.
#include "tridem/scene.hpp"

#include <cstddef>
#include <string>

#include <fmt/format.h>

namespace tridem {

/// Runs of at least this many particles are told what their contacts CSV will cost.
inline constexpr std::size_t kLargeContactsCsv = 100000;

/// The contacts CSV's bytes per triangle in a dense pile (5.98 contacts each; tridem_frame_bench
/// on dense_pile(2x10^5), 2026-12-06): float precision prints its forces, normals and depths
/// as float32s (docs/output-format.md).
inline double contacts_csv_bytes_per_triangle(Precision p) {
  return p == Precision::Float ? 880.0 : 1090.0;
}

/// The notes `tridem run` prints after its start line (empty: none). The contacts CSV is
/// some 1 kB of text per triangle in a dense pile: at 10^6 triangles its writing took
/// longer than 1000 float steps on the H200 (docs/performance.md, "Output frames").
inline std::string output_notes(const OutputSettings& o, std::size_t particles,
                                Precision precision) {
  if (o.every <= 0 || !o.contacts || !o.contacts_csv || particles < kLargeContactsCsv) return {};
  const double bytes = contacts_csv_bytes_per_triangle(precision);
  return fmt::format(
      "note: the contacts CSV of each frame will take about {:.0f} MB ({} triangles, about "
      "{:.0f} bytes each in a dense packing); [output] contacts_csv = false leaves it out "
      "(contacts/*.vtp holds the same network)\n",
      1e-6 * bytes * static_cast<double>(particles), particles, bytes);
}

}  // namespace tridem
