#pragma once
// Scenes of rigid bodies of several triangles built in code, for the parity, restart and
// hash suites: a few colliding polygons on a fixed body, and a pile of bodies settling on
// a floor (the standard body_pile, small).
#include "support/scene_builder.hpp"
#include "tridem/standard_scenes.hpp"

#include <cmath>
#include <numbers>

namespace tridem::test {

/// Appends a body of `count` triangles already in s.triangles from `first`.
inline void add_body(Scene& s, std::size_t first, Vec2d velocity = {}, double angular_velocity = 0,
                     Motion motion = Motion::Free) {
  BodySpec b;
  b.first = first;
  b.count = s.triangles.size() - first;
  b.velocity = velocity;
  b.angular_velocity = angular_velocity;
  b.motion = motion;
  for (std::size_t i = first; i < s.triangles.size(); ++i) s.triangles[i].motion = motion;
  s.bodies.push_back(b);
}

/// A regular `sides`-gon of circumradius r about c, turned by `phase`, as a fan of `sides`
/// triangles about its centre.
inline void add_polygon(Scene& s, Vec2d c, double r, int sides, double phase, Vec2d velocity,
                        double angular_velocity) {
  const std::size_t first = s.triangles.size();
  const double wedge = 2 * std::numbers::pi / sides;
  for (int k = 0; k < sides; ++k) {
    const double a0 = phase + k * wedge, a1 = a0 + wedge;
    s.triangles.push_back(triangle(c, c + Vec2d{std::cos(a0), std::sin(a0)} * r,
                                   c + Vec2d{std::cos(a1), std::sin(a1)} * r));
  }
  add_body(s, first, velocity, angular_velocity);
}

/// Three polygons (5, 7 and 6 triangles) and a lone triangle flying into one another and
/// onto a fixed slab of two triangles; no gravity, friction and damping; dt = 1 µs. Measured
/// on the CPU: the first contacts after 1000 steps, 2 touching pairs at steps 1500 and 2000,
/// 4 at 3000 and 3500, none at 4000.
inline Scene colliding_bodies() {
  Scene s = empty_scene(1e8, 2500, 0.5, 0.3);
  s.simulation.dt = 1e-6;
  add_polygon(s, {0, 0}, 0.01, 5, 0.0, {1.5, -0.6}, 30);
  add_polygon(s, {0.0235, 0.004}, 0.012, 7, 0.3, {-1.2, 0}, -15);
  add_polygon(s, {0.004, 0.0215}, 0.01, 6, 0.1, {0, -1.5}, 9);
  const std::size_t lone = s.triangles.size();
  s.triangles.push_back(triangle({0.021, 0.019}, {0.031, 0.019}, {0.026, 0.027}));
  add_body(s, lone, {-0.9, -1.2}, 0);
  const std::size_t slab = s.triangles.size();
  s.triangles.push_back(triangle({-0.015, -0.02}, {0.04, -0.02}, {0.04, -0.0105}));
  s.triangles.push_back(triangle({-0.015, -0.02}, {0.04, -0.0105}, {-0.015, -0.0105}));
  add_body(s, slab, {}, 0, Motion::Fixed);
  return s;
}

/// The standard body_pile of about 400 triangles in bodies of 10: pre-stressed like
/// dense_pile, it decompresses and settles on its floor, in contact from the first step.
inline Scene settling_body_pile(std::size_t triangles = 400) {
  Scene s = body_pile(triangles);
  s.source = "settling body pile";
  return s;
}

}  // namespace tridem::test
