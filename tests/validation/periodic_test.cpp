// Periodic boundaries (physics/periodic_frame.hpp): a collision through the boundary is
// the collision away from it, a contact survives its particles' wraps with its friction
// history, a periodic gas conserves momentum, and cells the rules cannot serve are refused.
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/scene_io.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace tridem {
namespace {

/// An equilateral triangle of circumradius r about c, turned by `angle`.
TriangleSpec grain(Vec2d c, double r, double angle, Vec2d v, double w = 0) {
  TriangleSpec t;
  for (int k = 0; k < 3; ++k) {
    const double a = angle + k * 2.0943951023931953;
    t.vertices[k] = {c.x + r * std::cos(a), c.y + r * std::sin(a)};
  }
  t.velocity = v;
  t.angular_velocity = w;
  return t;
}

/// An oblique, frictional collision of two grains along `axis` (0 = x, 1 = y), with a
/// common drift `drift` along it, its contact near `at` (the pair's midpoint).
Scene oblique_collision(int axis, double at, double drift) {
  Scene s = test::empty_scene(1e6, 1000, 0.8, 0.2);
  s.simulation.safety = 0.5;
  auto along = [&](double u, double v) { return axis == 0 ? Vec2d{u, v} : Vec2d{v, u}; };
  s.triangles.push_back(grain(along(at - 0.1, 2.50), 0.05, 0.3, along(1 + drift, 0.2), 3));
  s.triangles.push_back(grain(along(at + 0.1, 2.53), 0.05, 1.1, along(-1 + drift, -0.2), -2));
  return s;
}

// The cell [2.75, 3.75) along the axis. Every coordinate of these runs, the vertices'
// pairwise and triple sums of the centroids, and the wraps by 1 stay each on one grid of
// doubles ([2, 4), [4, 8), [8, 16)), so a pair through the boundary sees the very offsets
// it sees away from it (2.85 − 3.65 + 1 = 3.35 − 3.15 exactly), and the runs agree bit
// for bit.
constexpr double kLo = 2.75, kHi = 3.75;

/// The scene periodic along `axis` in [kLo, kHi), particle k moved by shift[k] along it.
Scene in_cell(Scene s, int axis, std::array<double, 2> shift) {
  (axis == 0 ? s.simulation.periodic.x : s.simulation.periodic.y) = PeriodicRange{kLo, kHi};
  for (std::size_t k = 0; k < 2; ++k)
    for (Vec2d& v : s.triangles[k].vertices) (axis == 0 ? v.x : v.y) += shift[k];
  return s;
}

struct Trajectory {
  std::vector<Snapshot> frames;
};

Trajectory run(const Scene& s, Backend backend, int chunks, int steps_per_chunk) {
  Scene scene = s;
  scene.simulation.backend = backend;
  auto solver = make_solver(scene, SolverConfig{});
  Trajectory t;
  for (int k = 0; k < chunks; ++k) {
    solver->advance(steps_per_chunk);
    Snapshot snap;
    solver->snapshot(snap, true);
    t.frames.push_back(snap);
  }
  return t;
}

/// The periodic run against the run away from the boundary, bit for bit: the same
/// velocities, and positions along the axis one of `shifts` (exact) from the others.
void expect_same_collision(const Trajectory& away, const Trajectory& through, int axis,
                           std::array<double, 2> shifts) {
  ASSERT_EQ(away.frames.size(), through.frames.size());
  for (std::size_t f = 0; f < away.frames.size(); ++f) {
    const Snapshot &a = away.frames[f], &b = through.frames[f];
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(a.vx[i], b.vx[i]) << "frame " << f << " particle " << i;
      EXPECT_EQ(a.vy[i], b.vy[i]) << "frame " << f << " particle " << i;
      EXPECT_EQ(a.omega[i], b.omega[i]) << "frame " << f << " particle " << i;
      EXPECT_EQ(a.theta[i], b.theta[i]) << "frame " << f << " particle " << i;
      const double along_a = axis == 0 ? a.x[i] : a.y[i], along_b = axis == 0 ? b.x[i] : b.y[i];
      const double across_a = axis == 0 ? a.y[i] : a.x[i], across_b = axis == 0 ? b.y[i] : b.x[i];
      EXPECT_TRUE(along_b == along_a + shifts[0] || along_b == along_a + shifts[1])
          << "frame " << f << " particle " << i << ": " << along_a << " and " << along_b;
      EXPECT_EQ(across_a, across_b) << "frame " << f;
      EXPECT_GE(along_b, kLo);
      EXPECT_LT(along_b, kHi);
    }
  }
}

/// Steps of the scene's dt that make `seconds`.
int steps_for(const Scene& s, double seconds) {
  return static_cast<int>(std::ceil(seconds / make_solver(s, SolverConfig{})->dt()));
}

class PeriodicCollision : public ::testing::TestWithParam<int> {};

TEST_P(PeriodicCollision, OnTheBoundaryEqualsAwayFromIt) {
  const int axis = GetParam();
  // Away: the contact at 3.25, no periodic boundary. Through: the first grain moved by
  // +0.5, the second by −0.5, so that they meet on the boundary at 3.75 (2.75).
  const Scene away = oblique_collision(axis, 3.25, 0);
  const Scene through = in_cell(away, axis, {0.5, -0.5});
  const int steps = steps_for(away, 0.0025);
  const Trajectory a = run(away, Backend::Cpu, 40, steps);
  const Trajectory b = run(through, Backend::Cpu, 40, steps);
  expect_same_collision(a, b, axis, {0.5, -0.5});
  std::size_t touching = 0;
  for (const Snapshot& s : b.frames) touching += s.contacts.size();
  EXPECT_GT(touching, 3u) << "the grains must touch through the boundary";
  const Snapshot& last = a.frames.back();
  EXPECT_LT(axis == 0 ? last.vx[0] : last.vy[0], 0.5) << "the collision must slow the first grain";
}

TEST_P(PeriodicCollision, ContactKeepsItsFrictionHistoryAcrossAWrap) {
  const int axis = GetParam();
  // Both grains drift at 4 m/s along the axis: they cross the boundary at 3.75 while
  // touching (away from the cell they reach 3.97).
  const Scene away = oblique_collision(axis, 3.52, 4);
  const Scene through = in_cell(away, axis, {0, 0});
  const int steps = steps_for(away, 0.0025);
  const Trajectory a = run(away, Backend::Cpu, 40, steps);
  const Trajectory b = run(through, Backend::Cpu, 40, steps);
  expect_same_collision(a, b, axis, {0, -1});
  // Some frame has the contact with a sticking (not sliding) tangential force while its
  // grains lie on the two sides of the boundary: the history crossed with them.
  bool crossed_in_contact = false;
  for (const Snapshot& s : b.frames) {
    const double u0 = axis == 0 ? s.x[0] : s.y[0], u1 = axis == 0 ? s.x[1] : s.y[1];
    for (const ContactRecord& c : s.contacts)
      if (std::abs(u0 - u1) > 0.5 && std::abs(c.tangential_force()) > 0) crossed_in_contact = true;
  }
  EXPECT_TRUE(crossed_in_contact);
}

INSTANTIATE_TEST_SUITE_P(Axis, PeriodicCollision, ::testing::Values(0, 1));

/// A dense frictional gas filling a cell periodic in x and y: no walls, so momentum is
/// conserved to rounding, and contacts through the boundaries are many.
Scene periodic_gas(int side, double pitch) {
  Scene s = test::empty_scene(1e7, 1000, 0.5, 0.1);
  s.simulation.safety = 0.3;
  s.simulation.periodic.x = PeriodicRange{0, side * pitch};
  s.simulation.periodic.y = PeriodicRange{0, side * pitch};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      s.triangles.push_back(grain({(i + 0.5) * pitch, (j + 0.5) * pitch}, 0.42 * pitch,
                                  3.14159 * u(rng), {2 * u(rng), 2 * u(rng)}, 20 * u(rng)));
  return s;
}

TEST(PeriodicGas, ConservesMomentumThroughTheBoundaries) {
  Scene s = periodic_gas(10, 0.1);
  s.simulation.backend = Backend::Cpu;
  auto solver = make_solver(s, SolverConfig{});
  Snapshot snap;
  solver->snapshot(snap, false);
  double px0 = 0, py0 = 0, scale = 0;
  for (std::size_t i = 0; i < snap.size(); ++i) {
    px0 += snap.mass[i] * snap.vx[i];
    py0 += snap.mass[i] * snap.vy[i];
    scale += snap.mass[i] * std::hypot(snap.vx[i], snap.vy[i]);
  }
  std::size_t through = 0;
  for (int chunk = 0; chunk < 20; ++chunk) {
    solver->advance(50);
    solver->snapshot(snap, true);
    double px = 0, py = 0;
    for (std::size_t i = 0; i < snap.size(); ++i) {
      px += snap.mass[i] * snap.vx[i];
      py += snap.mass[i] * snap.vy[i];
      ASSERT_GE(snap.x[i], 0);
      ASSERT_LT(snap.x[i], 1.0);
      ASSERT_GE(snap.y[i], 0);
      ASSERT_LT(snap.y[i], 1.0);
    }
    EXPECT_NEAR(px, px0, 1e-12 * scale);
    EXPECT_NEAR(py, py0, 1e-12 * scale);
    for (const ContactRecord& c : snap.contacts) through += c.image_dx != 0 || c.image_dy != 0;
  }
  EXPECT_GT(through, 5u) << "contacts through the boundaries";
}

// The grid and all-pairs find the same pairs in a periodic cell, and OpenMP computes them
// as the serial solver does: the same results bit for bit.
TEST(PeriodicGas, GridAllPairsAndOpenMPAgreeBitForBit) {
  Scene s = periodic_gas(8, 0.1);
  s.simulation.backend = Backend::Cpu;
  Scene all = s, threads = s;
  all.simulation.method = Method::AllPairs;
  threads.simulation.backend = Backend::OpenMP;
  std::vector<std::unique_ptr<Solver>> solvers;
  for (const Scene* scene : {&s, &all, &threads})
    solvers.push_back(make_solver(*scene, SolverConfig{}));
  std::size_t contacts = 0;
  for (int chunk = 0; chunk < 4; ++chunk) {
    std::vector<Snapshot> out(solvers.size());
    for (std::size_t k = 0; k < solvers.size(); ++k) {
      solvers[k]->advance(100);
      solvers[k]->snapshot(out[k], true);
    }
    for (std::size_t k = 1; k < out.size(); ++k) {
      EXPECT_EQ(out[0].x, out[k].x);
      EXPECT_EQ(out[0].y, out[k].y);
      EXPECT_EQ(out[0].vx, out[k].vx);
      EXPECT_EQ(out[0].omega, out[k].omega);
    }
    contacts += out[0].contacts.size();
  }
  EXPECT_GT(contacts, 0u);
}

std::string refusal(const Scene& s) {
  try {
    make_solver(s, SolverConfig{});
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

// Gravity along a periodic direction (a chute): a grain wrapped back up the slope gains
// the potential energy of a period, which the boundary gave it; energy.csv books it as wall
// work so that the budget's total stays put (here a grain falling freely along x).
TEST(PeriodicGas, GravityAlongThePeriodKeepsTheBudget) {
  Scene s = test::empty_scene(1e6, 1000);
  s.simulation.backend = Backend::Cpu;
  s.simulation.gravity = {6, 0};
  s.simulation.periodic.x = PeriodicRange{0, 0.6};
  s.triangles.push_back(grain({0.3, 0.3}, 0.05, 0.2, {0, 0}));
  auto solver = make_solver(s, SolverConfig{});
  Snapshot snap;
  solver->snapshot(snap, false);
  const EnergyRow first = compute_energy(snap, s.simulation.gravity, solver->energy());
  const auto every = static_cast<std::int64_t>(std::ceil(0.02 / solver->dt()));
  double worst = 0, travelled = 0, x_before = snap.x[0];
  EnergyRow last;
  for (int k = 0; k < 40; ++k) {
    solver->advance(every);
    solver->snapshot(snap, false);
    travelled += std::remainder(snap.x[0] - x_before, 0.6);
    x_before = snap.x[0];
    last = compute_energy(snap, s.simulation.gravity, solver->energy());
    worst = std::max(worst, std::abs(last.total() - first.total()));
  }
  const double work = last.budget.wall_work;
  ASSERT_GT(travelled, 1.2) << "the grain fell through the boundary at least twice";
  // The boundary put in the potential energy of the periods crossed, m·gx·Lx each.
  EXPECT_NEAR(work, snap.mass[0] * 6 * std::floor((0.3 + travelled) / 0.6) * 0.6, 1e-9 * work);
  EXPECT_LE(worst, 1e-3 * work);
}

TEST(PeriodicRefusal, CellShorterThanTwoGridCells) {
  Scene s = periodic_gas(3, 0.1);
  s.simulation.periodic.x = PeriodicRange{0, 0.1};
  EXPECT_NE(refusal(s).find("shorter than 2 cells of the pair grid"), std::string::npos)
      << refusal(s);
}

TEST(PeriodicRefusal, CellNotLongerThanFourReaches) {
  Scene s = periodic_gas(3, 0.1);
  // A fixed wall 0.3 long: its farthest vertex is too far for a cell 0.3 long.
  s.triangles.push_back(test::triangle({0.0, -0.2}, {0.3, -0.2}, {0.15, -0.25}, {}, Motion::Fixed));
  const std::string why = refusal(s);
  EXPECT_NE(why.find("could meet through two images"), std::string::npos) << why;
  EXPECT_NE(why.find("particle id 9"), std::string::npos) << why;
}

TEST(PeriodicRefusal, MethodsThatDoNotSeeAcrossTheBoundary) {
  for (Method m : {Method::SingleDomain, Method::Decomposition}) {
    Scene s = periodic_gas(4, 0.1);
    s.simulation.method = m;
    EXPECT_NE(refusal(s).find("does not find pairs across periodic boundaries"), std::string::npos);
  }
}

TEST(PeriodicRefusal, TheGpuBackend) {
  Scene s = periodic_gas(4, 0.1);
  s.simulation.backend = Backend::Cuda;
  EXPECT_NE(refusal(s).find("does not run periodic boundaries yet"), std::string::npos);
}

TEST(PeriodicRefusal, SceneKeys) {
  const std::string head = "[simulation]\nsteps = 1\n";
  const std::string tail =
      "[[material]]\nname = \"g\"\ndensity = 1000\npenalty = 1e7\n"
      "[[triangle]]\nvertices = [[0.1, 0.1], [0.2, 0.1], [0.15, 0.2]]\nmaterial = \"g\"\n";
  auto message = [&](const std::string& keys) {
    try {
      parse_scene(head + keys + tail, "periodic.toml");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message("periodic_x = [1, 0]\n").find("finite lo < hi"), std::string::npos);
  EXPECT_NE(message("periodic_x = [0, 1, 2]\n").find("expected [lo, hi]"), std::string::npos);
  EXPECT_NE(message("periodic_x = [0, 1]\nshear_rate = 2\n").find("needs both periodic_x"),
            std::string::npos);
  const Scene ok = parse_scene(
      head + "periodic_x = [0, 1]\nperiodic_y = [-1, 2]\nshear_rate = 3\n" + tail, "periodic.toml");
  ASSERT_TRUE(ok.simulation.periodic.y.has_value());
  EXPECT_EQ(ok.simulation.periodic.y->lo, -1);
  EXPECT_EQ(ok.simulation.periodic.y->hi, 2);
  EXPECT_EQ(ok.simulation.periodic.shear_rate, 3);
}

}  // namespace
}  // namespace tridem
