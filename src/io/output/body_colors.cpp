#include "io/output/body_colors.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <utility>

namespace tridem::io {
namespace {

struct Box {
  double x0, y0, x1, y1;
};

bool overlap(const Box& a, const Box& b) {
  return a.x0 <= b.x1 && b.x0 <= a.x1 && a.y0 <= b.y1 && b.y0 <= a.y1;
}

/// Pairs of neighbouring bodies (a < b), sorted and unique: the free triangles binned on
/// a grid of cells at least as large as any grown box, so that each triangle meets only
/// the triangles of the 3 × 3 cells around its own (box corner's) cell.
std::vector<std::pair<std::int64_t, std::int64_t>> neighbours(const Snapshot& s, double reach) {
  std::vector<std::size_t> free;
  std::vector<Box> box(s.size());
  double cell = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s.motion[k] != Motion::Free) continue;
    const double xs[3] = {s.x1[k], s.x2[k], s.x3[k]}, ys[3] = {s.y1[k], s.y2[k], s.y3[k]};
    const Box b{*std::min_element(xs, xs + 3) - reach, *std::min_element(ys, ys + 3) - reach,
                *std::max_element(xs, xs + 3) + reach, *std::max_element(ys, ys + 3) + reach};
    if (!std::isfinite(b.x0 + b.y0 + b.x1 + b.y1)) continue;  // a blown-up particle
    box[k] = b;
    free.push_back(k);
    cell = std::max({cell, b.x1 - b.x0, b.y1 - b.y0});
  }
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  if (free.empty() || !(cell > 0)) return pairs;
  const auto key = [](std::int64_t i, std::int64_t j) {
    return (static_cast<std::uint64_t>(i) << 32) ^ static_cast<std::uint64_t>(j & 0xffffffff);
  };
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> grid;
  const auto cell_of = [&](double v) { return static_cast<std::int64_t>(std::floor(v / cell)); };
  for (const std::size_t k : free) grid[key(cell_of(box[k].x0), cell_of(box[k].y0))].push_back(k);
  for (const std::size_t k : free) {
    const std::int64_t ci = cell_of(box[k].x0), cj = cell_of(box[k].y0);
    for (std::int64_t di = -1; di <= 1; ++di)
      for (std::int64_t dj = -1; dj <= 1; ++dj) {
        const auto it = grid.find(key(ci + di, cj + dj));
        if (it == grid.end()) continue;
        for (const std::size_t m : it->second) {
          const std::int64_t a = s.body_of(k), b = s.body_of(m);
          if (a < b && overlap(box[k], box[m])) pairs.emplace_back(a, b);
        }
      }
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

}  // namespace

std::vector<int> body_colors(const Snapshot& s, double reach, int palette) {
  const std::size_t bodies = s.body_count();
  std::vector<int> color(bodies, -1);
  std::vector<bool> is_free(bodies, false);
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.motion[k] == Motion::Free) is_free[static_cast<std::size_t>(s.body_of(k))] = true;

  // Neighbours of each body as rows (both directions).
  const auto pairs = neighbours(s, reach);
  std::vector<std::size_t> first(bodies + 1, 0);
  for (const auto& [a, b] : pairs) ++first[a + 1], ++first[b + 1];
  for (std::size_t b = 0; b < bodies; ++b) first[b + 1] += first[b];
  std::vector<std::int64_t> next(pairs.size() * 2);
  std::vector<std::size_t> fill(first.begin(), first.end() - 1);
  for (const auto& [a, b] : pairs) {
    next[fill[a]++] = b;
    next[fill[b]++] = a;
  }

  std::vector<int> used(static_cast<std::size_t>(palette));
  for (std::size_t b = 0; b < bodies; ++b) {
    if (!is_free[b]) continue;
    std::fill(used.begin(), used.end(), 0);
    for (std::size_t e = first[b]; e < first[b + 1]; ++e)
      if (const int c = color[static_cast<std::size_t>(next[e])]; c >= 0) ++used[c];
    // Start the search at a colour that varies along the ids (a stride prime to the
    // palette's size), so that a packing is not dominated by the first few colours.
    const int start = static_cast<int>((b * 5) % static_cast<std::size_t>(palette));
    int best = start;
    for (int t = 0; t < palette; ++t) {
      const int c = (start + t) % palette;
      if (used[c] < used[best]) best = c;
      if (used[c] == 0) break;
    }
    color[b] = best;
  }
  return color;
}

}  // namespace tridem::io
