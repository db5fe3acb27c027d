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
/// onto a fixed slab of two triangles; no gravity, friction and damping. The first
/// contacts come after about 1000 steps, and the bodies are in contact to step 4000.
inline Scene colliding_bodies() {
  Scene s = empty_scene(1e8, 2500, 0.5, 0.3);
  s.simulation.dt = 1e-6;
  add_polygon(s, {0, 0}, 0.01, 5, 0.0, {0.5, -0.2}, 10);
  add_polygon(s, {0.0235, 0.004}, 0.012, 7, 0.3, {-0.4, 0}, -5);
  add_polygon(s, {0.004, 0.0215}, 0.01, 6, 0.1, {0, -0.5}, 3);
  const std::size_t lone = s.triangles.size();
  s.triangles.push_back(triangle({0.021, 0.019}, {0.031, 0.019}, {0.026, 0.027}));
  add_body(s, lone, {-0.3, -0.4}, 0);
  const std::size_t slab = s.triangles.size();
  s.triangles.push_back(triangle({-0.015, -0.02}, {0.04, -0.02}, {0.04, -0.0105}));
  s.triangles.push_back(triangle({-0.015, -0.02}, {0.04, -0.0105}, {-0.015, -0.0105}));
  add_body(s, slab, {}, 0, Motion::Fixed);
  return s;
}

/// A pile of `bodies` decagons (10 triangles each) settling on a floor between walls.
inline Scene settling_body_pile(std::size_t bodies = 40) {
  Scene s = body_pile(bodies * 10, 0.01, 10, 3);
  s.source = "settling body pile";
  return s;
}

}  // namespace tridem::test
