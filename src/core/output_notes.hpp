#pragma once
// Outputs that will cost a large run more than its steps, named before it starts.
#include "tridem/scene.hpp"

#include <cstddef>
#include <string>

#include <fmt/format.h>

namespace tridem {

/// Runs of at least this many particles are told what their contacts CSV will cost.
inline constexpr std::size_t kLargeContactsCsv = 100000;

/// The notes `tridem run` prints after its start line (empty: none). The contacts CSV is
/// 17-digit text, some 1.1 kB per triangle in a dense pile: at 10^6 triangles its writing
/// took longer than 1000 float steps on the H200 (docs/performance.md, "Output frames").
inline std::string output_notes(const OutputSettings& o, std::size_t particles) {
  if (o.every <= 0 || !o.contacts || !o.contacts_csv || particles < kLargeContactsCsv) return {};
  return fmt::format(
      "note: the contacts CSV of each frame will take about {:.0f} MB ({} triangles, about "
      "1 kB each in a dense packing); [output] contacts_csv = false leaves it out "
      "(contacts/*.vtp holds the same network)\n",
      1.1e-3 * static_cast<double>(particles), particles);
}

}  // namespace tridem
