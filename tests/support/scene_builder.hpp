#pragma once
// Scenes built in code for tests: a material, triangles, and a helper to run a scene to a
// snapshot with a chosen backend.
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <cstdint>

namespace tridem::test {

inline Scene empty_scene(double penalty = 1e8, double density = 1000, double friction = 0,
                         double damping = 0) {
  Scene s;
  s.source = "test";
  s.simulation.steps = 1;
  Material m;
  m.name = "grain";
  m.density = density;
  m.penalty = penalty;
  m.tangential_penalty = 0.1 * penalty;
  m.friction = friction;
  m.damping = damping;
  s.materials.push_back(m);
  return s;
}

inline TriangleSpec triangle(Vec2d a, Vec2d b, Vec2d c, Vec2d velocity = {},
                             Motion motion = Motion::Free, double angular_velocity = 0) {
  TriangleSpec t;
  t.vertices = {a, b, c};
  t.velocity = velocity;
  t.angular_velocity = angular_velocity;
  t.motion = motion;
  return t;
}

/// A fixed triangle whose top edge is the segment y = top, x in [x0, x1].
inline TriangleSpec floor_triangle(double x0, double x1, double top = 0) {
  const double depth = x1 - x0;
  return triangle({x1, top}, {x0, top}, {0.5 * (x0 + x1), top - depth}, {}, Motion::Fixed);
}

inline Snapshot run_to(const Scene& scene, Backend backend, std::int64_t steps,
                       Precision precision = Precision::Double, Method method = Method::Grid) {
  SolverConfig config;
  config.backend = backend;
  config.precision = precision;
  config.method = method;
  auto solver = make_solver(scene, config);
  solver->advance(steps);
  Snapshot snap;
  solver->snapshot(snap, true);
  return snap;
}

}  // namespace tridem::test
