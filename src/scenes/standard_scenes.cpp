#include "tridem/standard_scenes.hpp"

#include "tridem/generate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>

namespace tridem {

namespace {

TriangleSpec fixed_triangle(Vec2d a, Vec2d b, Vec2d c) {
  TriangleSpec t;
  t.vertices = {a, b, c};
  t.motion = Motion::Fixed;
  return t;
}

/// The bonds of every two triangles that share an edge: end points equal to `tolerance`
/// (a lattice's neighbours compute their common vertices by different sums, so they agree
/// to rounding only), sorted by (a, b) as Scene::bonds wants them.
std::vector<BondSpec> shared_edge_bonds(const std::vector<TriangleSpec>& triangles,
                                        std::size_t count, double tolerance) {
  using Key = std::array<std::int64_t, 4>;
  auto point = [tolerance](Vec2d v) {
    return std::array<std::int64_t, 2>{std::llround(v.x / tolerance),
                                       std::llround(v.y / tolerance)};
  };
  std::map<Key, std::size_t> seen;
  std::vector<BondSpec> bonds;
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t e = 0; e < 3; ++e) {
      const Vec2d p = triangles[i].vertices[e], q = triangles[i].vertices[(e + 1) % 3];
      auto lo = point(p), hi = point(q);
      if (hi < lo) std::swap(lo, hi);
      const auto [it, fresh] = seen.emplace(Key{lo[0], lo[1], hi[0], hi[1]}, i);
      if (!fresh) bonds.push_back({std::min(it->second, i), std::max(it->second, i), p, q});
    }
  std::sort(bonds.begin(), bonds.end(), [](const BondSpec& x, const BondSpec& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return bonds;
}

}  // namespace

Scene dense_pile(std::size_t n, double size, double aspect) {
  return dense_pile_with_edges(n, size, aspect, nullptr);
}

Scene dense_pile_with_edges(std::size_t n, double size, double aspect,
                            std::vector<BondSpec>* edges) {
  Scene s;
  s.source = "dense_pile";
  s.simulation.steps = 100;
  s.simulation.gravity = {0, -9.81};
  s.materials.push_back({"sand", 2650, 1e8, 1e7, 0.5, 0.3});
  // A lattice row holds about 2·width/size triangles, a row is size·√3/2 high: choose the
  // width and height for n triangles at the asked aspect ratio.
  const double row_height = size * std::sqrt(3.0) / 2;
  const double per_area = 2.0 / (size * row_height);
  const double area = static_cast<double>(n) / per_area;
  const double width = std::sqrt(area * aspect), height = width / aspect;
  LatticeSpec lattice;
  lattice.region_min = {0, 0};
  lattice.region_max = {width + size, height + row_height};
  lattice.size = size;
  lattice.gap = 0;
  s.triangles = generate_lattice(lattice);
  // bonded_pile bonds the lattice's edges as they are, before the growth.
  if (edges) *edges = shared_edge_bonds(s.triangles, s.triangles.size(), 1e-6 * size);
  // Grow each grain by 0.2% about its centroid: every lattice neighbour now overlaps.
  for (TriangleSpec& t : s.triangles) {
    const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
    for (Vec2d& v : t.vertices) v = c + (v - c) * 1.002;
  }
  const double w = lattice.region_max.x, h = lattice.region_max.y, depth = w + 2 * size;
  const double skin = 0.001 * size;  // walls touch the outer grains
  s.triangles.push_back(fixed_triangle({w + depth, -skin + 0}, {-depth, -skin}, {0.5 * w, -skin - depth}));
  s.triangles.push_back(fixed_triangle({skin, -2 * size}, {skin, h + size}, {-depth + skin, 0.5 * h}));
  s.triangles.push_back(fixed_triangle({w - skin, h + size}, {w - skin, -2 * size}, {w + depth - skin, 0.5 * h}));
  return s;
}

Scene bonded_pile(std::size_t n, double size) {
  std::vector<BondSpec> bonds;
  Scene s = dense_pile_with_edges(n, size, 1.0, &bonds);
  s.source = "bonded_pile";
  // The sand made bondable: bonds as stiff as the contacts (E = p) and strong enough that
  // the pile's own weight and the start-up push of its overlapping contacts break none (the
  // benchmark measures intact bonds, the dearer case: a broken bond is skipped). The bonds
  // start unstressed: their points sit on the lattice's edges about the centroids, which
  // the growth leaves in place.
  Material& m = s.materials.front();
  m.young_modulus = m.penalty;
  m.tensile_strength = 1e6;
  m.shear_strength = 2e6;
  m.friction_angle = 30;
  m.fracture_energy = 10;
  m.shear_fracture_energy = 50;
  s.bonds = std::move(bonds);
  return s;
}

Scene body_pile(std::size_t n, double size, int members) {
  if (members < 1) throw std::invalid_argument("body_pile: members >= 1");
  Scene s = dense_pile(n, size);
  s.source = "body_pile";
  const std::size_t grains = s.triangles.size() - 3;  // dense_pile's walls come last
  // dense_pile's lattice rows: every grain's lowest vertex is on its row's base line.
  const double row_height = size * std::sqrt(3.0) / 2;
  auto row_of = [&](const TriangleSpec& t) {
    const double low = std::min({t.vertices[0].y, t.vertices[1].y, t.vertices[2].y});
    return std::llround(low / row_height);
  };
  for (std::size_t i = 0; i < grains;) {
    BodySpec b;
    b.first = i;
    const long long row = row_of(s.triangles[i]);
    while (i < grains && b.count < static_cast<std::size_t>(members) &&
           row_of(s.triangles[i]) == row) {
      ++b.count;
      ++i;
    }
    s.bodies.push_back(b);
  }
  for (std::size_t i = grains; i < s.triangles.size(); ++i) {
    BodySpec wall;
    wall.first = i;
    wall.count = 1;
    wall.motion = s.triangles[i].motion;
    s.bodies.push_back(wall);
  }
  return s;
}

}  // namespace tridem
