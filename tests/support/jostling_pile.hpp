#pragma once
// A dense, jostling pile in a box, the scene of the parity and restart tests: walls,
// gravity, friction, damping, random shapes and velocities, so that every part of a step
// (contact history included) is exercised.
#include "support/scene_builder.hpp"

#include <cmath>
#include <random>

namespace tridem::test {

/// A dense, jostling pile in a box: walls, gravity, friction, damping, random shapes.
inline Scene jostling_pile(int columns, int rows) {
  Scene s = empty_scene(1e7, 2000, 0.4, 0.2);
  s.simulation.gravity = {0, -9.81};
  const double pitch = 0.1, r = 0.055;
  const double width = columns * pitch;
  s.triangles.push_back(floor_triangle(-1, width + 1, -0.06));
  s.triangles.push_back(triangle({-0.06, -0.1}, {-0.06, rows * pitch}, {-1, 0},
                                 {}, Motion::Fixed));
  s.triangles.push_back(triangle({width, rows * pitch}, {width, -0.1}, {width + 1, 0},
                                 {}, Motion::Fixed));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const Vec2d c{i * pitch + 0.5 * pitch * (j % 2), j * pitch};
      const double a0 = 3.14159 * u(rng);
      TriangleSpec t;
      for (int k = 0; k < 3; ++k) {
        const double a = a0 + k * 2.0943951023931953 + 0.25 * u(rng);
        t.vertices[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
      }
      t.velocity = {2.0 * u(rng), 2.0 * u(rng)};
      s.triangles.push_back(t);
    }
  return s;
}

}  // namespace tridem::test
