#include "core/neighbour_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace tridem {

double neighbour_block_spread(const std::vector<Vec2d>& centroid,
                              const std::vector<std::uint8_t>& free, double grain_size) {
  std::vector<std::uint32_t> at;  // the index of each free particle, in order
  for (std::size_t i = 0; i < centroid.size(); ++i)
    if (free[i] != 0) at.push_back(static_cast<std::uint32_t>(i));
  const std::size_t m = at.size();
  // Small scenes get windows and blocks in proportion (tests; their caches hold them whole).
  const std::size_t window = std::min(kNeighbourWindow, m / 4);
  const std::size_t block = std::clamp<std::size_t>(window / 8, 1, kNeighbourBlock);
  if (window < 8 || !(grain_size > 0)) return 0;
  const double reach = 1.5 * grain_size;

  // The free particles binned in cells of at least `reach` (coarser where they are sparse,
  // so that the cells number at most 4 per particle), listed by cell.
  Vec2d lo = centroid[at[0]], hi = lo;
  for (const std::uint32_t i : at) {
    lo = {std::min(lo.x, centroid[i].x), std::min(lo.y, centroid[i].y)};
    hi = {std::max(hi.x, centroid[i].x), std::max(hi.y, centroid[i].y)};
  }
  const double area = std::max(hi.x - lo.x, reach) * std::max(hi.y - lo.y, reach);
  const double h = std::max(reach, std::sqrt(area / (4.0 * static_cast<double>(m))));
  const auto nx = static_cast<std::int64_t>((hi.x - lo.x) / h) + 1;
  const auto ny = static_cast<std::int64_t>((hi.y - lo.y) / h) + 1;
  auto cell_of = [&](Vec2d p) {
    return std::pair{static_cast<std::int64_t>((p.x - lo.x) / h),
                     static_cast<std::int64_t>((p.y - lo.y) / h)};
  };
  // By cell, in index order within a cell (a counting sort: the cells are at most ~4m).
  const auto cells = static_cast<std::size_t>(nx * ny);
  std::vector<std::uint32_t> first(cells + 1, 0), binned(m), cell_of_free(m);
  for (std::size_t k = 0; k < m; ++k) {
    const auto [cx, cy] = cell_of(centroid[at[k]]);
    cell_of_free[k] = static_cast<std::uint32_t>(cy * nx + cx);
    ++first[cell_of_free[k] + 1];
  }
  for (std::size_t c = 0; c < cells; ++c) first[c + 1] += first[c];
  {
    std::vector<std::uint32_t> next(first.begin(), first.end() - 1);
    for (std::size_t k = 0; k < m; ++k) binned[next[cell_of_free[k]]++] = at[k];
  }

  const std::size_t windows = std::min<std::size_t>(64, m / window);
  const std::size_t stride = m / windows;
  double spread = 0;
#pragma omp parallel for schedule(dynamic) reduction(+ : spread) if (windows * window > 65536)
  for (std::size_t w = 0; w < windows; ++w) {
    std::vector<std::uint32_t> blocks;
    for (std::size_t k = w * stride; k < w * stride + window; ++k) {
      const Vec2d p = centroid[at[k]];
      const auto [cx, cy] = cell_of(p);
      for (std::int64_t y = std::max<std::int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny - 1); ++y)
        for (std::int64_t x = std::max<std::int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx - 1);
             ++x) {
          const auto cell = static_cast<std::size_t>(y * nx + x);
          for (std::uint32_t q = first[cell]; q < first[cell + 1]; ++q)
            if (norm(centroid[binned[q]] - p) <= reach)
              blocks.push_back(binned[q] / static_cast<std::uint32_t>(block));
        }
    }
    std::sort(blocks.begin(), blocks.end());
    const auto distinct = std::unique(blocks.begin(), blocks.end()) - blocks.begin();
    spread +=
        static_cast<double>(distinct) / (static_cast<double>(window) / static_cast<double>(block));
  }
  return spread / static_cast<double>(windows);
}

}  // namespace tridem
