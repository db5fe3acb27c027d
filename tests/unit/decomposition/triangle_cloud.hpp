#pragma once
// Random triangles as the decomposition sees them (centroids, boxes, sizes), with a few
// walls longer than the grid cell, and the pairs the cell grid finds among them.
#include "broadphase/candidate_pairs.hpp"
#include "decomposition/decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace tridem::test {

struct TriangleCloud {
  std::vector<double> x, y, lo_x, lo_y, hi_x, hi_y, longest_edge;
  std::vector<Motion> motion;

  std::size_t size() const { return x.size(); }
  DomainInput<double> input() const {
    return {x.data(), y.data(), lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data()};
  }
  BoxArrays<double> boxes() const { return {lo_x.data(), lo_y.data(), hi_x.data(), hi_y.data()}; }

  void add(const Vec2d (&v)[3], Motion m) {
    x.push_back((v[0].x + v[1].x + v[2].x) / 3);
    y.push_back((v[0].y + v[1].y + v[2].y) / 3);
    lo_x.push_back(std::min({v[0].x, v[1].x, v[2].x}));
    lo_y.push_back(std::min({v[0].y, v[1].y, v[2].y}));
    hi_x.push_back(std::max({v[0].x, v[1].x, v[2].x}));
    hi_y.push_back(std::max({v[0].y, v[1].y, v[2].y}));
    double l = 0;
    for (int k = 0; k < 3; ++k) l = std::max(l, norm(v[(k + 1) % 3] - v[k]));
    longest_edge.push_back(l);
    motion.push_back(m);
  }

  /// Moves particle p by d (centroid and box).
  void shift(std::size_t p, Vec2d d) {
    x[p] += d.x;
    y[p] += d.y;
    lo_x[p] += d.x;
    hi_x[p] += d.x;
    lo_y[p] += d.y;
    hi_y[p] += d.y;
  }
};

/// n triangles of circumradius up to r, centred at random in [0, w] × [0, h], every
/// tenth one fixed; a floor and a wall longer than the grid cell.
inline TriangleCloud random_cloud(int n, double w, double h, double r, unsigned seed) {
  TriangleCloud c;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < n; ++i) {
    const Vec2d centre{w * u(rng), h * u(rng)};
    const double size = r * (0.5 + 0.5 * u(rng)), a0 = 6.283185307179586 * u(rng);
    Vec2d v[3];
    for (int k = 0; k < 3; ++k) {
      const double a = a0 + k * 2.0943951023931953 + 0.3 * (u(rng) - 0.5);
      v[k] = {centre.x + size * std::cos(a), centre.y + size * std::sin(a)};
    }
    c.add(v, i % 10 == 9 ? Motion::Fixed : Motion::Free);
  }
  const Vec2d floor[3] = {{-1, 0.02}, {w + 1, 0.02}, {0.5 * w, -1}};
  const Vec2d wall[3] = {{w - 0.02, -1}, {w - 0.02, h + 1}, {w + 1, 0.5 * h}};
  c.add(floor, Motion::Fixed);
  c.add(wall, Motion::Prescribed);
  return c;
}

using PairSet = std::vector<std::pair<std::int32_t, std::int32_t>>;

/// (emitter, partner) of every pair the cell grid finds, in row order.
inline PairSet grid_pairs(const TriangleCloud& c) {
  CandidatePairs<double> finder(c.longest_edge, c.motion);
  PairList list;
  finder.find(c.boxes(), Method::Grid, false, list);
  PairSet out;
  for (std::size_t i = 0; i + 1 < list.offset.size(); ++i)
    for (auto s = list.offset[i]; s < list.offset[i + 1]; ++s)
      out.emplace_back(static_cast<std::int32_t>(i), list.partner[s]);
  return out;
}

}  // namespace tridem::test
