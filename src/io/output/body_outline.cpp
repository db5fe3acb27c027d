#include "io/output/body_outline.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace tridem::io {
namespace {

struct Edge {
  double ax, ay, bx, by;  ///< end points
  double mx;              ///< midpoint's x, the sort key
  std::size_t triangle;
  int index;
};

bool same_segment(const Edge& p, const Edge& q, double tol) {
  const auto near = [tol](double x0, double y0, double x1, double y1) {
    return std::abs(x0 - x1) <= tol && std::abs(y0 - y1) <= tol;
  };
  return (near(p.ax, p.ay, q.bx, q.by) && near(p.bx, p.by, q.ax, q.ay)) ||
         (near(p.ax, p.ay, q.ax, q.ay) && near(p.bx, p.by, q.bx, q.by));
}

}  // namespace

std::vector<std::uint8_t> inner_edges(const Snapshot& s) {
  std::vector<std::uint8_t> inner(s.size(), 0);
  if (s.member_body.empty() || s.body_first.size() < 2) return inner;
  std::vector<Edge> edges;
  for (std::size_t b = 0; b + 1 < s.body_first.size(); ++b) {
    const auto lo = static_cast<std::size_t>(s.body_first[b]);
    const auto hi = static_cast<std::size_t>(s.body_first[b + 1]);
    if (hi - lo < 2) continue;
    edges.clear();
    for (std::size_t k = lo; k < hi; ++k) {
      const std::array<double, 6> v = {s.x1[k], s.y1[k], s.x2[k], s.y2[k], s.x3[k], s.y3[k]};
      for (int e = 0; e < 3; ++e) {
        const int f = (e + 1) % 3;
        const Edge edge{v[2 * e], v[2 * e + 1], v[2 * f], v[2 * f + 1], 0, k, e};
        edges.push_back(edge);
        edges.back().mx = 0.5 * (edge.ax + edge.bx);
      }
    }
    std::sort(edges.begin(), edges.end(), [](const Edge& p, const Edge& q) { return p.mx < q.mx; });
    // Matching edges have (nearly) the same midpoint: only a short run of the sorted list
    // is compared with each edge.
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Edge& p = edges[i];
      const double tol = 1e-7 * std::hypot(p.bx - p.ax, p.by - p.ay);
      for (std::size_t j = i + 1; j < edges.size() && edges[j].mx - p.mx <= tol; ++j) {
        const Edge& q = edges[j];
        if (q.triangle == p.triangle || !same_segment(p, q, tol)) continue;
        inner[p.triangle] |= static_cast<std::uint8_t>(1u << p.index);
        inner[q.triangle] |= static_cast<std::uint8_t>(1u << q.index);
      }
    }
  }
  return inner;
}

}  // namespace tridem::io
