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
#include "tridem/error.hpp"

#include <gtest/gtest.h>
#include <limits>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

/// f(array) for each State array of the solver (x, y, theta, vx, vy, w).
template <class Real, class F>
void for_each_state(CpuSolver<Real>& s, F&& f) {
  for_each_particle_field([&](auto field) {
    if constexpr (decltype(field)::role == FieldRole::State)
      for_each_array(s.column(field), [&](std::vector<double>& v, int) { f(v); });
  });
}

/// A solver on the split step whose every third free grain plays a received ghost: before
/// each step its State is NaN, and the take hook writes the true State back.
template <class Real>
class SplitRun {
 public:
  explicit SplitRun(const Scene& s)
      : model_(build_particle_model(s)),
        solver_(s, model_, estimate_time_step(s, model_), SolverConfig{}, false) {
    std::vector<std::uint8_t> received(model_.size(), 0);
    for (std::size_t i = 0; i < model_.size(); ++i)
      if (model_.motion[i] == Motion::Free && i % 3 == 0) {
        received[i] = 1;
        ghosts_.push_back(i);
      }
    solver_.set_ghost_hooks(
        received,
        [this] {
          std::size_t at = 0;
          for (std::size_t i : ghosts_)
            for_each_state(solver_, [&](std::vector<double>& v) { v[i] = stash_[at++]; });
          ++takes_;
        },
        [] {});
  }
  CpuSolver<Real>& solver() { return solver_; }
  std::int64_t takes() const { return takes_; }
  /// `steps` steps, one advance each (as MPI ranks step).
  void advance(std::int64_t steps) {
    for (std::int64_t k = 0; k < steps; ++k) {
      stash_.clear();
      for (std::size_t i : ghosts_)
        for_each_state(solver_, [&](std::vector<double>& v) {
          stash_.push_back(v[i]);
          v[i] = std::numeric_limits<double>::quiet_NaN();
        });
      solver_.advance(1);
    }
  }

 private:
  ParticleModel model_;
  CpuSolver<Real> solver_;
  std::vector<std::size_t> ghosts_;
  std::vector<double> stash_;
  std::int64_t takes_ = 0;
};

template <class Real>
void expect_split_step_is_serial(Precision precision) {
  Scene s = test::jostling_pile(20, 12);
  s.simulation.precision = precision;
  const std::int64_t steps = 400;
  const Snapshot serial = test::run_to(s, Backend::Cpu, steps, precision);
  SplitRun<Real> split(s);
  ASSERT_TRUE(split.solver().can_take_ghosts_mid_step());
  split.advance(steps);
  Snapshot got;
  split.solver().snapshot(got, true);
  test::expect_identical(serial, got);
  EXPECT_EQ(split.takes(), steps) << "the hook runs once a step";
  const GhostOverlapCounts& c = split.solver().overlap_counts();
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

// A pair too deep is reported once both passes are done: the lowest emitter, own or ghost,
// at the step one solver reports it. Here an own grain's pair with a ghost (its pass after
// the take), on a step that kept its list.
TEST(MpiSplitStep, ADeepPairIsTheOneTheSerialSolverReports) {
  Scene s = test::jostling_pile(20, 12);
  s.simulation.max_penetration = 0.2;
  auto message = [](auto&& advance) {
    try {
      advance();
    } catch (const RunError& e) {
      return std::string(e.what());
    }
    return std::string("no blow-up");
  };
  const ParticleModel model = build_particle_model(s);
  CpuSolver<double> serial(s, model, estimate_time_step(s, model), SolverConfig{}, false);
  const std::string expected = message([&] { serial.advance(400); });
  ASSERT_NE(expected.find("deeper than"), std::string::npos) << expected;
  SplitRun<double> split(s);
  split.advance(serial.step());
  const std::int64_t overlapped = split.solver().overlap_counts().overlapped;
  EXPECT_EQ(message([&] { split.advance(1); }), expected);
  EXPECT_EQ(split.solver().step(), serial.step());
  EXPECT_EQ(split.solver().overlap_counts().overlapped, overlapped + 1)
      << "the failing step kept its list";
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

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
