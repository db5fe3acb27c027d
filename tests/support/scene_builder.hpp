#pragma once
// Scenes built in code for tests: a material, triangles, and a helper to run a scene to a
// snapshot with a chosen backend.
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <random>

namespace tridem::test {

/// The bonded rock of the fracture tests (issue 14's granite): contact and bond keys.
inline Material granite() {
  Material m;
  m.name = "granite";
  m.density = 2650;
  m.penalty = 5e10;
  m.tangential_penalty = 5e9;
  m.friction = 0.6;
  m.restitution = 0.5;
  m.young_modulus = 40e9;
  m.tensile_strength = 8e6;
  m.shear_strength = 25e6;
  m.friction_angle = 35;
  m.fracture_energy = 30;
  m.shear_fracture_energy = 150;
  return m;
}

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

/// A dense, jostling pile in a box: walls, gravity, friction, damping, random shapes.
inline Scene jostling_pile(int columns, int rows, unsigned seed = 5) {
  Scene s = empty_scene(1e7, 2000, 0.4, 0.2);
  s.simulation.gravity = {0, -9.81};
  // The step the tests' step counts were chosen with (0.1 of the former estimate, about
  // 0.3 of today's proven dt_crit): the pile jostles within a few hundred steps.
  s.simulation.safety = 0.3;
  const double pitch = 0.1, r = 0.055;
  const double width = columns * pitch;
  s.triangles.push_back(floor_triangle(-1, width + 1, -0.06));
  s.triangles.push_back(triangle({-0.06, -0.1}, {-0.06, rows * pitch}, {-1, 0},
                                       {}, Motion::Fixed));
  s.triangles.push_back(triangle({width, rows * pitch}, {width, -0.1}, {width + 1, 0},
                                       {}, Motion::Fixed));
  std::mt19937_64 rng(seed);
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

/// The scene with [simulation.decomposition] set (used when the method is decomposition).
inline Scene with_decomposition(Scene s, DecompositionLayout layout, int capacity, int rows = 0,
                                int columns = 0) {
  s.simulation.decomposition = {layout, rows, columns, capacity};
  return s;
}

/// A solver for the scene, advanced `steps` steps.
inline std::unique_ptr<Solver> advanced_solver(const Scene& scene, Backend backend,
                                               std::int64_t steps,
                                               Precision precision = Precision::Double,
                                               Method method = Method::Grid) {
  Scene s = scene;
  s.simulation.backend = backend;
  s.simulation.precision = precision;
  s.simulation.method = method;
  auto solver = make_solver(s, SolverConfig{});
  solver->advance(steps);
  return solver;
}

inline Snapshot run_to(const Scene& scene, Backend backend, std::int64_t steps,
                       Precision precision = Precision::Double, Method method = Method::Grid) {
  Snapshot snap;
  advanced_solver(scene, backend, steps, precision, method)->snapshot(snap, true);
  return snap;
}

}  // namespace tridem::test
