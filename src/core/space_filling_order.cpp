#include "core/space_filling_order.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>

namespace tridem {

namespace {
constexpr int kBits = 16;
constexpr std::uint32_t kSide = 1u << kBits;
}  // namespace

std::uint64_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint64_t d = 0;
  for (std::uint32_t s = kSide / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) != 0 ? 1 : 0;
    const std::uint32_t ry = (y & s) != 0 ? 1 : 0;
    d += static_cast<std::uint64_t>(s) * s * ((3 * rx) ^ ry);
    // Turn the quadrant so that the curve inside it starts and ends where the next
    // finer level expects.
    if (ry == 0) {
      if (rx == 1) {
        x = kSide - 1 - x;
        y = kSide - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

std::vector<std::size_t> space_filling_order(const std::vector<Vec2d>& points) {
  std::vector<std::size_t> order(points.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  if (points.empty()) return order;
  Vec2d lo = points.front(), hi = points.front();
  for (const Vec2d& p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  // One scale for both axes keeps the curve's cells square.
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  const double to_cell = span > 0 ? (kSide - 1) / span : 0.0;
  auto cell = [&](double v, double origin) {
    const double c = (v - origin) * to_cell;
    return static_cast<std::uint32_t>(std::clamp(c, 0.0, static_cast<double>(kSide - 1)));
  };
  // The curve's index (below 2^32) above the point's (below 2^32: 4x10^9 points would be
  // 64 GB of centroids), sorted as plain numbers: the points of one cell keep their order,
  // and at 10^6 points the sort reads no key at random (the solver's set-up sorts the
  // free particles so, core/place_numbered_solver).
  const auto n = static_cast<std::int64_t>(points.size());
  std::vector<std::uint64_t> keyed(points.size());
#pragma omp parallel for schedule(static) if (n > 65536)
  for (std::int64_t i = 0; i < n; ++i) {
    const Vec2d& p = points[static_cast<std::size_t>(i)];
    keyed[static_cast<std::size_t>(i)] =
        (hilbert_index(cell(p.x, lo.x), cell(p.y, lo.y)) << 32) | static_cast<std::uint64_t>(i);
  }
  std::sort(keyed.begin(), keyed.end());
  for (std::size_t k = 0; k < keyed.size(); ++k) order[k] = keyed[k] & 0xffffffffu;
  return order;
}

void number_by_place(std::vector<TriangleSpec>& triangles, std::size_t count) {
  std::vector<Vec2d> centroids(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto& v = triangles[i].vertices;
    centroids[i] = (v[0] + v[1] + v[2]) / 3.0;
  }
  std::vector<TriangleSpec> numbered;
  numbered.reserve(triangles.size());
  for (const std::size_t i : space_filling_order(centroids)) numbered.push_back(triangles[i]);
  numbered.insert(numbered.end(), triangles.begin() + static_cast<std::ptrdiff_t>(count),
                  triangles.end());
  triangles = std::move(numbered);
}

}  // namespace tridem
