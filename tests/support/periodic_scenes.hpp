#pragma once
// Periodic scenes shared by the CPU's periodic tests (tests/validation/periodic_test.cpp,
// lees_edwards_test.cpp) and the GPU's (tests/parity/gpu_periodic_parity_test.cpp): grains,
// the oblique collision through a boundary and how its runs are compared, a periodic gas,
// a sheared gas, a periodic pile.
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/scene.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace tridem::test {

/// The shear rate of sheared_gas (1/s).
constexpr double kGasShearRate = 4.0;

/// An equilateral triangle of circumradius r about c, turned by `angle`.
inline TriangleSpec grain(Vec2d c, double r, double angle, Vec2d v, double w = 0) {
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
inline Scene oblique_collision(int axis, double at, double drift) {
  Scene s = empty_scene(1e6, 1000, 0.8, 0.2);
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
inline Scene in_cell(Scene s, int axis, std::array<double, 2> shift) {
  (axis == 0 ? s.simulation.periodic.x : s.simulation.periodic.y) = PeriodicRange{kLo, kHi};
  for (std::size_t k = 0; k < 2; ++k)
    for (Vec2d& v : s.triangles[k].vertices) (axis == 0 ? v.x : v.y) += shift[k];
  return s;
}

struct Trajectory {
  std::vector<Snapshot> frames;
};

/// `chunks` snapshots (with contacts), `steps_per_chunk` steps apart, of the scene on `backend`.
inline Trajectory run_frames(const Scene& s, Backend backend, int chunks, int steps_per_chunk) {
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
inline void expect_same_collision(const Trajectory& away, const Trajectory& through, int axis,
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
inline int steps_for(const Scene& s, double seconds) {
  return static_cast<int>(std::ceil(seconds / make_solver(s, SolverConfig{})->dt()));
}

/// A dense frictional gas filling a cell periodic in x and y: no walls, so momentum is
/// conserved to rounding, and contacts through the boundaries are many.
inline Scene periodic_gas(int side, double pitch, double reach = 0.42) {
  Scene s = empty_scene(1e7, 1000, 0.5, 0.1);
  s.simulation.safety = 0.3;
  s.simulation.periodic.x = PeriodicRange{0, side * pitch};
  s.simulation.periodic.y = PeriodicRange{0, side * pitch};
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      s.triangles.push_back(grain({(i + 0.5) * pitch, (j + 0.5) * pitch}, reach * pitch,
                                  3.14159 * u(rng), {2 * u(rng), 2 * u(rng)}, 20 * u(rng)));
  return s;
}

/// A gas of side × side triangles in a sheared periodic cell, its velocities the shear
/// profile (`profile`, else none) plus a random agitation of 0.3 m/s.
inline Scene sheared_gas(int side, double pitch, double reach, unsigned seed, bool profile = true) {
  Scene s = empty_scene(1e6, 1000, 0.3, 0.05);
  s.simulation.safety = 0.5;
  const double length = side * pitch;
  s.simulation.periodic.x = PeriodicRange{0, length};
  s.simulation.periodic.y = PeriodicRange{0, length};
  s.simulation.periodic.shear_rate = kGasShearRate;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      TriangleSpec t;
      const Vec2d c{(i + 0.5) * pitch, (j + 0.5) * pitch};
      const double a0 = 3.14159 * u(rng);
      for (int k = 0; k < 3; ++k) {
        const double a = a0 + k * 2.0943951023931953;
        t.vertices[k] = {c.x + reach * std::cos(a), c.y + reach * std::sin(a)};
      }
      t.velocity = {0.3 * u(rng) + (profile ? kGasShearRate * (c.y - 0.5 * length) : 0.0),
                    0.3 * u(rng)};
      s.triangles.push_back(t);
    }
  return s;
}

/// A settling, jostling pile periodic along x: jostling_pile (scene_builder.hpp) without
/// its floor and side walls, moved by a quarter pitch into the cell [0, columns · 0.1),
/// over a floor of short fixed triangles that tiles the cell. Its rows are staggered by
/// half a pitch, so that grains meet across the boundary as they do inside the cell.
inline Scene periodic_pile(int columns, int rows, unsigned seed = 5) {
  Scene s = jostling_pile(columns, rows, seed);
  const double pitch = 0.1;
  s.triangles.erase(s.triangles.begin(), s.triangles.begin() + 3);
  for (TriangleSpec& t : s.triangles)
    for (Vec2d& v : t.vertices) v.x += 0.25 * pitch;
  std::vector<TriangleSpec> floor;
  for (int i = 0; i < columns; ++i)
    floor.push_back(floor_triangle(i * pitch, (i + 1) * pitch, -0.06));
  s.triangles.insert(s.triangles.begin(), floor.begin(), floor.end());
  s.simulation.periodic.x = PeriodicRange{0, columns * pitch};
  return s;
}

/// A sheared gas with friction, the Lees-Edwards energy test's (lees_edwards_test.cpp).
inline Scene frictional_sheared_gas() {
  Scene s = sheared_gas(10, 0.1, 0.045, 3);
  s.materials[0].friction = 0.4;
  return s;
}

/// periodic_gas(side, 0.1, 0.49) (dense: grains meet within a few hundred steps) sheared at
/// kGasShearRate, on the shear profile, which the Lees-Edwards images keep.
inline Scene dense_sheared_gas(int side) {
  Scene s = periodic_gas(side, 0.1, 0.49);
  s.simulation.periodic.shear_rate = kGasShearRate;
  const double middle = 0.5 * side * 0.1;
  for (TriangleSpec& t : s.triangles)
    t.velocity.x +=
        kGasShearRate * ((t.vertices[0].y + t.vertices[1].y + t.vertices[2].y) / 3 - middle);
  return s;
}

/// How long the float runs of periodic scenes last: long enough for gravity to show by
/// the margin expect_float_follows_double asks (0.5·g·t² > 3e-6 m, g·t > 0.01 m/s), and
/// for the gases to collide.
constexpr double kPeriodicFloatSeconds = 1e-2;

/// The periodic scenes float runs are compared on, each with gravity (the float check's
/// proof of its margin) and in contact within kPeriodicFloatSeconds: the pile, a dense gas
/// falling through its periodic y, and that gas sheared, falling through its Lees-Edwards
/// boundary.
inline std::vector<Scene> periodic_float_scenes() {
  Scene gas = periodic_gas(6, 0.1, 0.49), sheared = dense_sheared_gas(6);
  gas.simulation.gravity = sheared.simulation.gravity = {0, -9.81};
  return {periodic_pile(8, 5), gas, sheared};
}

/// Contacts of the snapshot seen through a boundary (their partner's image is not itself).
inline std::size_t through_boundary(const Snapshot& s) {
  std::size_t n = 0;
  for (const ContactRecord& c : s.contacts) n += c.image_dx != 0 || c.image_dy != 0;
  return n;
}

/// A scene the GPU's periodic parity tests compare with the serial solver: from the state
/// the serial solver reaches after `warmup` steps, `steps` steps in chunks of `chunk`, over
/// which contacts through the boundaries must occur (periodic_test.cpp checks that on the
/// CPU).
struct PeriodicParityCase {
  std::string name;
  Scene scene;
  std::int64_t warmup, steps, chunk;
};

inline std::vector<PeriodicParityCase> periodic_parity_cases() {
  // examples/shear_flow.toml: 124 angular grains (bodies of triangles), started apart; by
  // step 3000 bodies have wrapped and grains touch through the boundaries.
  return {{"periodic pile", periodic_pile(12, 6), 0, 300, 50},
          {"periodic gas", periodic_gas(10, 0.1, 0.49), 0, 400, 50},
          {"sheared gas", frictional_sheared_gas(), 0, 600, 100},
          {"dense sheared gas", dense_sheared_gas(10), 0, 400, 50},
          {"shear-flow example",
           read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/shear_flow.toml"), 3500, 500,
           100}};
}

/// The serial solver of the case's scene (with `method`) at the end of its warm-up, and
/// that state, from which the compared runs start.
inline SolverState warmed_up_state(const PeriodicParityCase& c, Method method) {
  auto serial = advanced_solver(c.scene, Backend::Cpu, c.warmup, Precision::Double, method);
  SolverState state;
  serial->save_state(state);
  return state;
}

/// Single-domain with the exact test reproduces the grid on `backend` bit for bit in a
/// periodic pile and a sheared gas (600 steps, pre-filter on and off), which touch through
/// their boundaries.
inline void expect_periodic_single_domain_exact_is_the_grid(Backend backend) {
  for (const Scene& base : {periodic_pile(12, 6), dense_sheared_gas(10)}) {
    const Snapshot grid = run_to(base, backend, 600);
    for (bool prefilter : {true, false}) {
      SCOPED_TRACE(prefilter ? "bbox pre-filter on" : "bbox pre-filter off");
      Scene s = base;
      s.simulation.bbox_prefilter = prefilter;
      expect_identical(grid, run_to(s, backend, 600, Precision::Double, Method::SingleDomain));
    }
    EXPECT_GT(through_boundary(grid), 0u);
  }
}

/// Advances two solvers of the case chunk by chunk, calling compare(a, b) on their
/// snapshots (a's with contacts) after each chunk; returns how many contacts through the
/// boundaries a's snapshots held.
template <class Compare>
inline std::size_t run_side_by_side(const PeriodicParityCase& c, Solver& a, Solver& b,
                                    Compare&& compare) {
  std::size_t through = 0;
  for (std::int64_t done = 0; done < c.steps; done += c.chunk) {
    a.advance(c.chunk);
    b.advance(c.chunk);
    Snapshot sa, sb;
    a.snapshot(sa, true);
    b.snapshot(sb, true);
    through += through_boundary(sa);
    compare(sa, sb);
  }
  return through;
}

/// A solver of the case's scene on `backend` (with `method`), started from `state`.
inline std::unique_ptr<Solver> solver_from(const PeriodicParityCase& c, Backend backend,
                                           Method method, const SolverState& state) {
  Scene s = c.scene;
  s.simulation.backend = backend;
  s.simulation.method = method;
  auto solver = make_solver(s, SolverConfig{});
  solver->load_state(state);
  return solver;
}

}  // namespace tridem::test
