// load_state refuses a state that does not fit the solver, naming the problem, and leaves
// nothing half-loaded to crash on later.
#include "support/backend_test.hpp"
#include "support/scene_builder.hpp"
#include "tridem/error.hpp"
#include "tridem/solver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

std::unique_ptr<Solver> three_particle_solver(const test::SolverChoice& choice) {
  Scene s = test::empty_scene();
  s.triangles.push_back(test::triangle({0, 0}, {1, 0}, {0, 1}));
  s.triangles.push_back(test::triangle({2, 0}, {3, 0}, {2, 1}));
  s.triangles.push_back(test::triangle({4, 0}, {5, 0}, {4, 1}));
  return test::solver_for(s, choice);
}

void expect_refused(const test::SolverChoice& choice,
                    const std::function<void(SolverState&)>& spoil, const std::string& fragment) {
  auto solver = three_particle_solver(choice);
  SolverState s;
  solver->save_state(s);
  s.pair_emitter = {0, 1};
  s.pair_partner = {2, 2};
  s.pair_slip = {{1, 0}, {0, 1}};
  EXPECT_NO_THROW(solver->load_state(s));
  spoil(s);
  try {
    solver->load_state(s);
    ADD_FAILURE() << "accepted; expected '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
  }
}

using SolverStateLoad = test::BackendTest;

TEST_P(SolverStateLoad, RefusesStatesThatDoNotFit) {
  const test::SolverChoice b = GetParam();
  expect_refused(b, [](SolverState& s) { s.x.pop_back(); }, "2 values of x for 3 particles");
  expect_refused(b, [](SolverState& s) { s.omega.push_back(0); }, "omega");
  expect_refused(b, [](SolverState& s) { s.vy[1] = std::nan(""); }, "vy of particle 1");
  expect_refused(b, [](SolverState& s) { s.step = -1; }, "negative step");
  expect_refused(b, [](SolverState& s) { s.pair_partner[1] = 3; }, "pair 1 (1, 3)");
  expect_refused(b, [](SolverState& s) { s.pair_emitter[0] = -1; }, "pair 0");
  expect_refused(b, [](SolverState& s) { s.pair_partner[0] = 0; }, "pair 0 (0, 0)");
  expect_refused(b, [](SolverState& s) { std::swap(s.pair_emitter[0], s.pair_emitter[1]); },
                 "out of order");
  expect_refused(b, [](SolverState& s) { s.pair_emitter[1] = 0; s.pair_partner[1] = 2; },
                 "out of order");
  expect_refused(b, [](SolverState& s) { s.pair_slip.pop_back(); }, "differ in length");
  expect_refused(b, [](SolverState& s) { s.pair_slip[0][1] = INFINITY; }, "non-finite slip");
}


// What was loaded is what the solver saves again, history included, before any step.
TEST_P(SolverStateLoad, SaveGivesBackTheLoadedState) {
  auto solver = three_particle_solver(GetParam());
  SolverState in;
  solver->save_state(in);
  in.step = 7;
  in.time = 0.25;
  in.x[1] = 2.5;
  in.omega[2] = -1.0;
  in.pair_emitter = {0, 1};
  in.pair_partner = {2, 2};
  // Pair (1, 2) carries only a -0.0: it is history all the same (core/history_rows.hpp),
  // and a save that took it for +0.0 would drop the pair.
  in.pair_slip = {{1, 0}, {-0.0, 0.0}};
  solver->load_state(in);
  SolverState out;
  solver->save_state(out);
  EXPECT_EQ(out.step, 7);
  EXPECT_EQ(out.time, 0.25);
  EXPECT_EQ(out.x, in.x);
  EXPECT_EQ(out.omega, in.omega);
  EXPECT_EQ(out.pair_emitter, in.pair_emitter);
  EXPECT_EQ(out.pair_partner, in.pair_partner);
  ASSERT_EQ(out.pair_slip.size(), 2u);
  EXPECT_TRUE(std::signbit(out.pair_slip[1][0])) << "-0.0 is history and must survive";
  EXPECT_FALSE(std::signbit(out.pair_slip[1][1]));
  EXPECT_EQ(out.pair_slip, in.pair_slip);
}

INSTANTIATE_TEST_SUITE_P(Cpu, SolverStateLoad,
                         ::testing::Values(test::SolverChoice(Backend::Cpu),
                                           test::SolverChoice(Backend::OpenMP),
                                           test::SolverChoice(Backend::Cpu, Method::SingleDomain)));
INSTANTIATE_TEST_SUITE_P(Gpu, SolverStateLoad,
                         ::testing::Values(test::SolverChoice(Backend::Cuda),
                                           test::SolverChoice(Backend::Cuda, Method::SingleDomain)));

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
