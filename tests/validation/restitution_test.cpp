// `restitution = e` gives e within 5% for face, edge and vertex impacts at 0.1, 1 and
// 10 m/s (docs/model.md, "Damping"): the dashpot scales with the contact's current
// stiffness and its ratio is calibrated for the load exponent of the contact's shape.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"

#include <cmath>
#include <cstdio>
#include <gtest/gtest.h>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

enum class Shape { Face, Edge, Vertex };

/// An equilateral triangle of side `side` with centroid c, one vertex at angle a0.
TriangleSpec equilateral(Vec2d c, double side, double a0, Vec2d velocity, Motion motion) {
  const double r = side / std::sqrt(3.0);
  TriangleSpec t;
  for (int k = 0; k < 3; ++k) {
    const double a = a0 + k * 2 * M_PI / 3;
    t.vertices[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  t.velocity = velocity;
  t.motion = motion;
  return t;
}

/// Relative normal speed after over before, no gravity, symmetric set-ups (no rotation).
///  Face:   two equilateral grains approaching flat side on flat side.
///  Edge:   two grains approaching corner on corner.
///  Vertex: a grain falling vertex-down on a fixed flat floor.
double measured_restitution(Shape shape, double speed, double e) {
  Scene s = test::empty_scene(1e8, 2000, 0.0, 0.0);
  s.materials[0].restitution = e;
  const double side = 0.1, r = side / std::sqrt(3.0), inradius = r / 2, gap = 1e-6;
  // A short step: about 1/250 of the shortest contact (the face impacts, 0.25 ms), so
  // that the model and not the integrator is measured.
  s.simulation.dt = 1e-6;
  int a = 0, b = 1;
  switch (shape) {
    case Shape::Face:  // flat sides facing along x
      s.triangles.push_back(equilateral({-inradius - gap, 0}, side, M_PI, {speed / 2, 0},
                                        Motion::Free));
      s.triangles.push_back(equilateral({inradius + gap, 0}, side, 0, {-speed / 2, 0},
                                        Motion::Free));
      break;
    case Shape::Edge:  // vertices facing along x
      s.triangles.push_back(equilateral({-r - gap, 0}, side, 0, {speed / 2, 0}, Motion::Free));
      s.triangles.push_back(equilateral({r + gap, 0}, side, M_PI, {-speed / 2, 0},
                                        Motion::Free));
      break;
    case Shape::Vertex:  // floor's top at x = 0 (its side y), the grain's vertex towards it
      s.triangles.push_back(test::triangle({0, -5}, {0, 5}, {10, 0}, {}, Motion::Fixed));
      s.triangles.push_back(equilateral({-r - gap, 0}, side, 0, {speed, 0}, Motion::Free));
      a = 1;
      b = 0;
      break;
  }
  auto solver = make_solver(s, SolverConfig{});
  Snapshot snap;
  solver->snapshot(snap, false);
  const double before = snap.vx[a] - snap.vx[b];
  // Run until the pair has separated: moving apart at a speed the last chunk left unchanged.
  double previous = before;
  for (int chunk = 0; chunk < 2000; ++chunk) {
    solver->advance(500);
    solver->snapshot(snap, false);
    const double now = snap.vx[a] - snap.vx[b];
    if (now < 0 && std::abs(now - previous) <= 1e-12 * std::abs(before)) break;
    previous = now;
  }
  // Symmetric up to rounding; a face contact lets a tiny asymmetry turn the grains a
  // little, which must stay negligible beside the impact speed.
  EXPECT_LT(std::abs(snap.omega[a]) * r, 0.01 * speed);
  return -(snap.vx[a] - snap.vx[b]) / before;
}

TEST(Restitution, FaceEdgeAndVertexImpactsOverTwoDecades) {
  for (double e : {0.5, 0.8})
    for (Shape shape : {Shape::Face, Shape::Edge, Shape::Vertex})
      for (double speed : {0.1, 1.0, 10.0}) {
        const double got = measured_restitution(shape, speed, e);
        // The table of docs/model.md comes from this line.
        std::printf("restitution %-6s %5.1f m/s  e %.2f  measured %.4f\n",
                    shape == Shape::Face ? "face" : shape == Shape::Edge ? "edge" : "vertex",
                    speed, e, got);
        EXPECT_NEAR(got, e, 0.05 * e) << "shape " << static_cast<int>(shape) << " speed "
                                      << speed << " e " << e;
      }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
