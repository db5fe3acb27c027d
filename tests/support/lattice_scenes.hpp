#pragma once
// Packings of equilateral triangles on a triangular lattice, pressed together: every
// triangle is enlarged about its centroid, so each face overlaps its lattice neighbour's.
// They test the time step where it matters, in contacts on all sides.
#include "support/scene_builder.hpp"

#include <cmath>
#include <random>

namespace tridem::test {

/// Triangle k of lattice row j (side a, rows of height a·√3/2, row j shifted by j·a/2):
/// even k point up, odd k down; scaled by `scale` about its centroid.
inline TriangleSpec lattice_triangle(int k, int j, double a, double scale,
                                     Motion motion = Motion::Free) {
  const double h = a * std::sqrt(3.0) / 2, x0 = (j + k) * a / 2, y0 = j * h;
  TriangleSpec t = k % 2 == 0 ? triangle({x0, y0}, {x0 + a, y0}, {x0 + a / 2, y0 + h})
                              : triangle({x0, y0 + h}, {x0 + a / 2, y0}, {x0 + a, y0 + h});
  const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
  for (Vec2d& v : t.vertices) v = c + (v - c) * scale;
  t.motion = motion;
  return t;
}

/// Undamped, frictionless, no gravity: what keeps the energy bounded is the integrator.
inline Scene lattice_scene() { return empty_scene(1e7, 2000, 0, 0); }

/// Random velocities (up to `speed`, and speed/a in rotation) for the free triangles: a
/// squeezed lattice alone is in equilibrium by symmetry and would not vibrate.
inline void shake(Scene& s, double speed, double a, unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (TriangleSpec& t : s.triangles)
    if (t.motion == Motion::Free) {
      t.velocity = {speed * u(rng), speed * u(rng)};
      t.angular_velocity = speed / a * u(rng);
    }
}

/// A channel: ten free triangles in a row (row 0, k = 0..9), fixed lattice triangles
/// above and below and two at each end, all pressed together by `squeeze`.
inline Scene channel_packing(double squeeze = 0.01, double a = 0.1) {
  Scene s = lattice_scene();
  for (int k = 0; k < 10; ++k) s.triangles.push_back(lattice_triangle(k, 0, a, 1 + squeeze));
  for (int k = -2; k < 12; ++k)
    if (k < 0 || k >= 10) s.triangles.push_back(lattice_triangle(k, 0, a, 1 + squeeze, Motion::Fixed));
  for (int j : {-1, 1})
    for (int k = -3; k < 13; ++k)
      s.triangles.push_back(lattice_triangle(k, j, a, 1 + squeeze, Motion::Fixed));
  shake(s, 0.01, a);
  return s;
}

/// A hexagon: the six free triangles around a lattice node, in a ring of the 18 fixed
/// lattice triangles around them, all pressed together by `squeeze`.
inline Scene hexagon_packing(double squeeze = 0.01, double a = 0.1) {
  Scene s = lattice_scene();
  for (int pass = 0; pass < 2; ++pass)
    for (int j = -3; j <= 3; ++j)
      for (int k = -8; k <= 8; ++k) {
        const TriangleSpec t = lattice_triangle(k, j, a, 1);
        const Vec2d c = (t.vertices[0] + t.vertices[1] + t.vertices[2]) / 3.0;
        const double r = std::hypot(c.x, c.y);
        const bool inner = r < 0.6 * a, ring = !inner && r < 1.6 * a;
        if ((pass == 0 && inner) || (pass == 1 && ring))
          s.triangles.push_back(
              lattice_triangle(k, j, a, 1 + squeeze, inner ? Motion::Free : Motion::Fixed));
      }
  shake(s, 0.01, a);
  return s;
}

}  // namespace tridem::test
