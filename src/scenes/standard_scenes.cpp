#include "tridem/standard_scenes.hpp"

#include "tridem/generate.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

namespace tridem {

namespace {

TriangleSpec fixed_triangle(Vec2d a, Vec2d b, Vec2d c) {
  TriangleSpec t;
  t.vertices = {a, b, c};
  t.motion = Motion::Fixed;
  return t;
}

/// A body of one member: a triangle in a scene with bodies of several triangles.
void add_lone(Scene& s, const TriangleSpec& t) {
  BodySpec b;
  b.first = s.triangles.size();
  b.count = 1;
  b.motion = t.motion;
  s.triangles.push_back(t);
  s.bodies.push_back(b);
}

}  // namespace

Scene dense_pile(std::size_t n, double size, double aspect) {
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

Scene body_pile(std::size_t n, double radius, int sides, unsigned seed) {
  if (sides < 3 || !(radius > 0)) throw std::invalid_argument("body_pile: sides >= 3, radius > 0");
  Scene s;
  s.source = "body_pile";
  s.simulation.steps = 100;
  s.simulation.gravity = {0, -9.81};
  s.materials.push_back({"sand", 2650, 1e8, 1e7, 0.5, 0.3});
  const std::size_t bodies = std::max<std::size_t>(1, (n + sides / 2) / sides);
  // A hexagonal lattice about square: columns × rows of pitch p and row height p·√3/2.
  const double pitch = 2 * radius * 0.998, row_height = pitch * std::sqrt(3.0) / 2;
  const auto columns = static_cast<std::size_t>(
      std::max(1.0, std::ceil(std::sqrt(static_cast<double>(bodies) * row_height / pitch))));
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> turn(0, 2 * std::numbers::pi);
  const double wedge = 2 * std::numbers::pi / sides;
  for (std::size_t k = 0; k < bodies; ++k) {
    const std::size_t row = k / columns, column = k % columns;
    const Vec2d c{radius + static_cast<double>(column) * pitch + (row % 2 ? 0.5 * pitch : 0.0),
                  radius + static_cast<double>(row) * row_height};
    const double phase = turn(rng);
    BodySpec b;
    b.first = s.triangles.size();
    b.count = static_cast<std::size_t>(sides);
    for (int m = 0; m < sides; ++m) {
      const double a0 = phase + m * wedge, a1 = a0 + wedge;
      TriangleSpec t;
      t.vertices = {c, c + Vec2d{std::cos(a0), std::sin(a0)} * radius,
                    c + Vec2d{std::cos(a1), std::sin(a1)} * radius};
      s.triangles.push_back(t);
    }
    s.bodies.push_back(b);
  }
  const std::size_t rows = (bodies + columns - 1) / columns;
  const double w = 2 * radius + (static_cast<double>(columns) - 0.5) * pitch;
  const double h = 2 * radius + static_cast<double>(rows) * row_height;
  const double depth = w + 4 * radius, skin = 0.001 * radius;  // walls touch the outer bodies
  add_lone(s, fixed_triangle({w + depth, -skin}, {-depth, -skin}, {0.5 * w, -skin - depth}));
  add_lone(s,
           fixed_triangle({skin, -4 * radius}, {skin, h + 2 * radius}, {-depth + skin, 0.5 * h}));
  add_lone(s, fixed_triangle({w - skin, h + 2 * radius}, {w - skin, -4 * radius},
                             {w + depth - skin, 0.5 * h}));
  return s;
}

}  // namespace tridem
