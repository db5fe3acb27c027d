// The split step of CPU ranks (CpuSolver::set_ghost_hooks, docs/scaling.md "Overlap") on
// one solver, without MPI: some free particles play received ghosts. Before each step their
// State is poisoned (NaN), as a ghost's is stale until the exchange completes, and the take
// hook writes it back, as the exchange does. Nothing before the hook may read it, and the
// kept list (build boxes grown by the skin, its stale pairs zeroed) and the passes (own
// pairs first, then those on ghosts) must give the serial solver's bits.
#include "backends/cpu/cpu_solver.hpp"
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace tridem {
namespace {

/// f(array) for each State array of the solver (x, y, theta, vx, vy, w).
template <class Real, class F>
void for_each_state(CpuSolver<Real>& s, F&& f) {
  for_each_particle_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State)
      for_each_array(s.column(field), [&](std::vector<double>& v, int) { f(v); });
  });
}

template <class Real>
void expect_split_step_is_serial(Precision precision) {
  Scene s = test::jostling_pile(20, 12);
  s.simulation.precision = precision;
  const std::int64_t steps = 400;
  const Snapshot serial = test::run_to(s, Backend::Cpu, steps, precision);
  const ParticleModel model = build_particle_model(s);
  CpuSolver<Real> split(s, model, estimate_time_step(s, model), SolverConfig{}, false);
  ASSERT_TRUE(split.can_take_ghosts_mid_step());
  // A third of the grains, spread through the pile: on most steps some touch the others.
  std::vector<std::uint8_t> received(model.size(), 0);
  std::vector<std::size_t> ghosts;
  for (std::size_t i = 0; i < model.size(); ++i)
    if (model.motion[i] == Motion::Free && i % 3 == 0) {
      received[i] = 1;
      ghosts.push_back(i);
    }
  std::vector<double> stash;
  std::int64_t takes = 0;
  split.set_ghost_hooks(
      received,
      [&] {
        std::size_t at = 0;
        for (std::size_t i : ghosts)
          for_each_state(split, [&](std::vector<double>& v) { v[i] = stash[at++]; });
        ++takes;
      },
      [] {});
  for (std::int64_t k = 0; k < steps; ++k) {
    stash.clear();
    for (std::size_t i : ghosts)
      for_each_state(split, [&](std::vector<double>& v) {
        stash.push_back(v[i]);
        v[i] = std::numeric_limits<double>::quiet_NaN();
      });
    split.advance(1);
  }
  Snapshot got;
  split.snapshot(got, true);
  test::expect_identical(serial, got);
  EXPECT_EQ(takes, steps) << "the hook runs once a step";
  const GhostOverlapCounts& c = split.overlap_counts();
  EXPECT_EQ(c.steps, steps);
  EXPECT_GT(c.overlapped, steps / 2) << "most steps keep their list and split their pairs";
  EXPECT_GT(c.rebuilt, 1);
  EXPECT_EQ(c.overlapped + c.rebuilt, steps);
  EXPECT_GT(c.ghost_contacts, steps / 2) << "pairs on ghosts touch on most steps";
  EXPECT_GT(serial.contacts.size(), 30u);
}

TEST(MpiSplitStep, GhostsTakenMidStepGiveTheSerialBitsInDouble) {
  expect_split_step_is_serial<double>(Precision::Double);
}

TEST(MpiSplitStep, GhostsTakenMidStepGiveTheSerialBitsInFloat) {
  expect_split_step_is_serial<float>(Precision::Float);
}

// Where the list is built every step from every box, ghosts' included, nothing of a step
// can go before the exchange: those solvers keep the blocking exchange.
TEST(MpiSplitStep, OnlyTheGridWithoutAPeriodicCellAndWithASkinSplitsItsStep) {
  auto splits = [](const Scene& s) {
    const ParticleModel model = build_particle_model(s);
    return CpuSolver<double>(s, model, estimate_time_step(s, model), SolverConfig{}, false)
        .can_take_ghosts_mid_step();
  };
  const Scene pile = test::jostling_pile(6, 4);
  EXPECT_TRUE(splits(pile));
  Scene single = pile;
  single.simulation.method = Method::SingleDomain;
  EXPECT_FALSE(splits(single));
  Scene no_skin = pile;
  no_skin.simulation.skin = 0;
  EXPECT_FALSE(splits(no_skin));
}

}  // namespace
}  // namespace tridem
