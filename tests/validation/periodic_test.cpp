// Periodic boundaries (physics/periodic_frame.hpp): a collision through the boundary is
// the collision away from it, a contact survives its particles' wraps with its friction
// history, a periodic gas conserves momentum, and cells the rules cannot serve are refused.
#include "core/particle_model.hpp"
#include "core/periodic_checks.hpp"
#include "support/float_compare.hpp"
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"

#include <array>
#include <cmath>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <random>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_same_collision;
using test::grain;
using test::in_cell;
using test::oblique_collision;
using test::periodic_gas;
using test::steps_for;
using test::Trajectory;

class PeriodicCollision : public ::testing::TestWithParam<int> {};

TEST_P(PeriodicCollision, OnTheBoundaryEqualsAwayFromIt) {
  const int axis = GetParam();
  // Away: the contact at 3.25, no periodic boundary. Through: the first grain moved by
  // +0.5, the second by −0.5, so that they meet on the boundary at 3.75 (2.75).
  const Scene away = oblique_collision(axis, 3.25, 0);
  const Scene through = in_cell(away, axis, {0.5, -0.5});
  const int steps = steps_for(away, 0.0025);
  const Trajectory a = test::run_frames(away, Backend::Cpu, 40, steps);
  const Trajectory b = test::run_frames(through, Backend::Cpu, 40, steps);
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
  const Trajectory a = test::run_frames(away, Backend::Cpu, 40, steps);
  const Trajectory b = test::run_frames(through, Backend::Cpu, 40, steps);
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

// The mixed mode (float pairs, double state) in periodic cells, against the serial double
// run with the float tolerances the GPU's float tests use (gpu_periodic_parity_test.cpp
// runs the CUDA float solver on the same scenes).
TEST(PeriodicFloat, CpuFloatStaysCloseToSerialDouble) {
  for (const Scene& s : test::periodic_float_scenes()) {
    const std::int64_t steps = steps_for(s, test::kPeriodicFloatSeconds);
    const Snapshot tried = test::run_to(s, Backend::Cpu, steps, Precision::Float);
    EXPECT_GT(tried.contacts.size(), 0u) << "the float pairs must carry forces";
    test::expect_float_follows_double(s, steps, tried);
  }
}

// The cases of the GPU's periodic parity tests (support/periodic_scenes.hpp,
// gpu_periodic_parity_test.cpp) touch through their boundaries on the way, and OpenMP runs
// them as the serial solver does, bit for bit, from the same warmed-up state.
TEST(PeriodicScenes, GpuParityCasesTouchThroughTheBoundaries) {
  for (const test::PeriodicParityCase& c : test::periodic_parity_cases())
    for (Method m : {Method::Grid, Method::AllPairs, Method::SingleDomain}) {
      if (m != Method::Grid && c.scene.triangles.size() > 200) continue;
      const SolverState start = test::warmed_up_state(c, m);
      auto serial = test::solver_from(c, Backend::Cpu, m, start);
      auto threads = test::solver_from(c, Backend::OpenMP, m, start);
      const std::size_t through =
          test::run_side_by_side(c, *serial, *threads, [&](const Snapshot& a, const Snapshot& b) {
            EXPECT_EQ(a.x, b.x) << c.name;
            EXPECT_EQ(a.vx, b.vx) << c.name;
            EXPECT_EQ(a.omega, b.omega) << c.name;
          });
      EXPECT_GT(through, 0u) << c.name << ", " << method_name(m);
    }
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

// The decomposition sees across the boundaries on every backend
// (decomposition_parity_test.cpp, gpu_decomposition_test.cpp): cuda takes it in a cell long
// enough for its list, as it takes the other methods, and refuses it in a shorter one.
TEST(PeriodicRefusal, DecompositionOnTheGpu) {
  Scene s = periodic_gas(4, 0.1);  // long enough for the GPU's list
  s.simulation.method = Method::Decomposition;
  for (Backend b : {Backend::Cpu, Backend::OpenMP}) {
    s.simulation.backend = b;
    EXPECT_EQ(refusal(s), "") << backend_name(b);
  }
  EXPECT_EQ(gpu_periodic_limit(s, build_particle_model(s)).refusal, "");
  Scene shorter = periodic_gas(3, 0.1);
  shorter.simulation.method = Method::Decomposition;
  const std::string why = gpu_periodic_limit(shorter, build_particle_model(shorter)).refusal;
  EXPECT_NE(why.find("the periodic cell is too short for backend 'cuda'"), std::string::npos)
      << why;
}

// Single-domain in a periodic cell tests each partner at its nearest image
// (passes_periodic_contact_test): with the exact test it drops only pairs whose force
// pair_force would find zero, so it reproduces the grid bit for bit, pre-filter on or
// off, as it does without a cell (CpuParity.SingleDomainExactReproducesGridBitForBit).
TEST(PeriodicSingleDomain, ExactReproducesTheGridBitForBit) {
  test::expect_periodic_single_domain_exact_is_the_grid(Backend::Cpu);
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

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

// The GPU's periodic pair list takes each pair's image at its build, exact in cells longer
// than 8 reaches plus twice the skin (ARCHITECTURE.md); between that and the CPU's 4 reaches
// the cuda backend refuses the scene (auto runs it on the CPU), never risking a missed pair.
TEST(PeriodicRefusal, CellTooShortForTheGpuList) {
  Scene s = test::periodic_gas(3, 0.1);  // 3 pitches = 7.1 reaches: fine on the CPU
  const ParticleModel model = build_particle_model(s);
  const double exact = gpu_exact_periodic_length(s, model);
  EXPECT_GT(exact, 0.3);
  EXPECT_FALSE(gpu_lists_periodic_cell_exactly(s, model));
  EXPECT_EQ(refusal(s), "");  // the CPU runs it
  s.simulation.backend = Backend::Cuda;
  const std::string why = refusal(s);
  EXPECT_NE(why.find("too short for backend 'cuda'"), std::string::npos) << why;
  EXPECT_NE(why.find(fmt::format("{}", exact)), std::string::npos) << why;
  s.simulation.periodic.x = PeriodicRange{0, 1.01 * exact};
  s.simulation.periodic.y = PeriodicRange{0, 1.01 * exact};
  EXPECT_TRUE(gpu_lists_periodic_cell_exactly(s, build_particle_model(s)));
}

// The GPU tests' periodic scenes are all long enough for the GPU's list.
TEST(PeriodicRefusal, GpuTestScenesAreLongEnoughForTheGpuList) {
  std::vector<std::pair<std::string, Scene>> scenes;
  for (const auto& c : test::periodic_parity_cases()) scenes.emplace_back(c.name, c.scene);
  for (const Scene& f : test::periodic_float_scenes()) scenes.emplace_back("float", f);
  scenes.emplace_back("gas 4", test::periodic_gas(4, 0.1));
  scenes.emplace_back("dense sheared gas 5", test::dense_sheared_gas(5));
  scenes.emplace_back("pile 12x8", test::periodic_pile(12, 8));
  scenes.emplace_back("shear flow",
                      read_scene(std::string(TRIDEM_SOURCE_DIR) + "/examples/shear_flow.toml"));
  for (const auto& [name, s] : scenes) {
    const ParticleModel model = build_particle_model(s);
    EXPECT_TRUE(gpu_lists_periodic_cell_exactly(s, model))
        << name << ": needs " << gpu_exact_periodic_length(s, model);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
