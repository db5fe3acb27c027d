// load_state refuses a state that does not fit the solver, naming the problem, and leaves
// nothing half-loaded to crash on later.
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace tridem {
namespace {

std::unique_ptr<Solver> three_particle_solver() {
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({2, 0}, {3, 0}, {2, 1}));
  s.triangles.push_back(test::triangle({4, 0}, {5, 0}, {4, 1}));
  SolverConfig config;
  config.backend = Backend::Cpu;
  return make_solver(s, config);
}

void expect_refused(const std::function<void(SolverState&)>& spoil, const std::string& fragment) {
  auto solver = three_particle_solver();
  SolverState s;
  solver->save_state(s);
  s.pair_emitter = {0, 1};
  s.pair_partner = {2, 2};
  s.pair_slip = {{1, 0, 0, 0, 0, 0}, {0, 1, 0, 0, 0, 0}};
  EXPECT_NO_THROW(solver->load_state(s));
  spoil(s);
  try {
    solver->load_state(s);
    ADD_FAILURE() << "accepted; expected '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

TEST(SolverState, LoadRefusesStatesThatDoNotFit) {
  expect_refused([](SolverState& s) { s.x.pop_back(); }, "2 values of x for 3 particles");
  expect_refused([](SolverState& s) { s.omega.push_back(0); }, "omega");
  expect_refused([](SolverState& s) { s.vy[1] = std::nan(""); }, "vy of particle 1");
  expect_refused([](SolverState& s) { s.step = -1; }, "negative step");
  expect_refused([](SolverState& s) { s.pair_partner[1] = 3; }, "pair 1 (1, 3)");
  expect_refused([](SolverState& s) { s.pair_emitter[0] = -1; }, "pair 0");
  expect_refused([](SolverState& s) { s.pair_partner[0] = 0; }, "pair 0 (0, 0)");
  expect_refused([](SolverState& s) { std::swap(s.pair_emitter[0], s.pair_emitter[1]); },
                 "out of order");
  expect_refused([](SolverState& s) { s.pair_emitter[1] = 0; s.pair_partner[1] = 2; },
                 "out of order");
  expect_refused([](SolverState& s) { s.pair_slip.pop_back(); }, "differ in length");
  expect_refused([](SolverState& s) { s.pair_slip[0][3] = INFINITY; }, "non-finite slip");
}

}  // namespace
}  // namespace tridem
