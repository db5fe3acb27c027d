// Numbering the particles by place again mid-run (core/place_numbered_solver,
// make_renumbering_solver): a solver whose particles have mixed renumbers them at the next
// look and goes on within rounding of the scene's order; one that has not mixed keeps its
// bits; its saved state carries the order, so that a restart goes on bit for bit; a bad
// order is refused; and a frame's contact copy in flight holds the renumbering back.
#include "core/numbering_note.hpp"
#include "core/particle_model.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/solver_factory.hpp"
#include "core/time_step.hpp"
#include "support/body_scenes.hpp"
#include "support/forwarding_solver.hpp"
#include "support/gpu.hpp"
#include "support/place_order_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/contact_copy.hpp"
#include "tridem/error.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using test::expect_within_rounding;
using test::shuffled;
using test::shuffled_bodies;
using test::shuffled_bonded;
using test::snapshot_of;

constexpr std::int64_t kLook = 50;  ///< steps between the looks at the order

/// The CPU solver of a scene in its own order (the reference).
std::unique_ptr<Solver> scene_solver(Scene s) {
  s.simulation.backend = Backend::Cpu;
  SolverConfig config;
  config.particle_order = ParticleOrder::Scene;
  return make_solver(s, config);
}

/// Makes the CPU solver of a scene and model as make_solver would, the scene's order kept.
MakeInnerSolver cpu_maker(const Scene& s) {
  const ParticleModel model = build_particle_model(s);
  return scene_order_maker(estimate_time_step(s, model), {});
}

/// A small pile's caches hold it whole, so its spread (core/neighbour_blocks.hpp) is
/// measured on a finer scale and lies lower than a large one's: 1.1 for jostling_pile(80,
/// 10) by rows, 2.5 numbered at random; settling_body_pile's bodies 2.1 by rows, 3.2 at
/// random. The tests renumber between.
constexpr double kPileScattered = 1.8;
constexpr double kBodiesScattered = 2.6;

/// A solver of `s` stepping its particles in the scene's order that looks every kLook
/// steps (`make`: its inner solvers; `scattered`: mixed beyond that spread).
std::unique_ptr<Solver> renumbering(Scene s, MakeInnerSolver make = {},
                                    double scattered = kPileScattered) {
  s.simulation.backend = Backend::Cpu;
  const ParticleModel model = build_particle_model(s);
  if (!make) make = cpu_maker(s);
  return make_renumbering_solver(s, model, scene_order(model), make, kLook, scattered);
}

/// A pile numbered at random.
Scene mixed_pile() { return shuffled(test::jostling_pile(80, 10)); }

bool renumbered(const Solver& s) {
  return s.statistics().find("numbered by place again") != std::string::npos;
}

TEST(Renumbering, AMixedPileIsNumberedByPlaceAtTheNextLookAndGoesOnWithinRounding) {
  const Scene s = mixed_pile();
  auto reference = scene_solver(s);
  auto solver = renumbering(s);
  solver->advance(kLook - 1);
  EXPECT_FALSE(renumbered(*solver));
  EXPECT_EQ(solver->description().find("numbered by place"), std::string::npos)
      << "the scene's order until the first look";
  reference->advance(kLook - 1);
  test::expect_identical(snapshot_of(*reference), snapshot_of(*solver));
  solver->advance(301);
  reference->advance(301);
  EXPECT_TRUE(renumbered(*solver)) << solver->statistics();
  EXPECT_NE(solver->description().find("numbered by place"), std::string::npos);
  EXPECT_EQ(solver->step(), reference->step());
  EXPECT_EQ(solver->stage_times().steps, reference->stage_times().steps)
      << "the replaced solver's steps are counted";
  expect_within_rounding(snapshot_of(*reference), snapshot_of(*solver), 1e-9, reference->dt());

  // It renumbered once: the curve it put the grains on holds over these few steps.
  EXPECT_NE(solver->statistics().find("again 1 time"), std::string::npos) << solver->statistics();
}

TEST(Renumbering, APileThatHasNotMixedKeepsItsBits) {
  const Scene s = test::jostling_pile(20, 12);
  auto reference = scene_solver(s);
  auto solver = renumbering(s);
  reference->advance(330);
  solver->advance(7);
  solver->advance(323);  // looks at 50, 100, ... whatever the calls' sizes
  EXPECT_FALSE(renumbered(*solver));
  test::expect_identical(snapshot_of(*reference), snapshot_of(*solver));
  SolverState state;
  solver->save_state(state);
  EXPECT_TRUE(state.particle_order.empty()) << "the scene's order goes without saying";
}

TEST(Renumbering, ARestartFromAStateSavedAfterRenumberingGoesOnBitForBit) {
  const Scene s = mixed_pile();
  auto run = renumbering(s);
  run->advance(kLook + 20);
  ASSERT_TRUE(renumbered(*run));
  SolverState state;
  run->save_state(state);
  ASSERT_EQ(state.particle_order.size(), s.triangles.size()) << "the order goes with the state";
  // and with a checkpoint file's bytes.
  Checkpoint file;
  file.state = state;
  state = decode_checkpoint(encode_checkpoint(file), "mem").state;
  run->advance(130);

  // A new solver of the scene takes the order up with the state, whichever order it starts
  // in, and renumbers again at the same looks.
  for (const bool from_place : {false, true}) {
    Scene cpu = s;
    cpu.simulation.backend = Backend::Cpu;
    const ParticleModel model = build_particle_model(cpu);
    auto restarted =
        make_renumbering_solver(cpu, model, from_place ? place_order(model) : scene_order(model),
                                cpu_maker(cpu), kLook, kPileScattered);
    restarted->load_state(state);
    restarted->advance(130);
    test::expect_identical(snapshot_of(*run), snapshot_of(*restarted));
    SolverState again;
    restarted->save_state(again);
    EXPECT_EQ(again.particle_order, state.particle_order);
  }

  // Without the order the restart steps the particles in another order: not the same bits
  // (so the test above can tell).
  SolverState without = state;
  without.particle_order.clear();
  auto other = renumbering(s);
  other->load_state(without);
  other->advance(130);
  const Snapshot a = snapshot_of(*run), b = snapshot_of(*other);
  bool differ = false;
  for (std::size_t i = 0; i < a.size() && !differ; ++i) differ = a.vx[i] != b.vx[i];
  EXPECT_TRUE(differ);
}

TEST(Renumbering, ASolverThatCannotBeMadeAgainKeepsTheOldOrderAndItsState) {
  const Scene s = mixed_pile();
  const MakeInnerSolver cpu = cpu_maker(s);
  int made = 0;
  auto solver = renumbering(s, [&](const Scene& scene, const ParticleModel& m) {
    if (++made == 2) throw RunError("out of memory (a test's)");
    return cpu(scene, m);
  });
  EXPECT_THROW(solver->advance(kLook + 10), RunError);
  // What a failed run reads next: its state at the look, in the scene's order.
  EXPECT_EQ(solver->step(), kLook);
  EXPECT_FALSE(renumbered(*solver));
  auto reference = scene_solver(s);
  reference->advance(kLook);
  SolverState state, expected;
  solver->save_state(state);
  reference->save_state(expected);
  EXPECT_TRUE(state.particle_order.empty());
  EXPECT_EQ(state.x, expected.x);
  EXPECT_EQ(state.omega, expected.omega);
  EXPECT_EQ(state.pair_slip, expected.pair_slip);
  // And it steps on from there as the scene's order does (up to the next look).
  solver->advance(kLook - 10);
  reference->advance(kLook - 10);
  test::expect_identical(snapshot_of(*reference), snapshot_of(*solver));
}

TEST(Renumbering, AStateWithAnOrderItCannotHaveIsRefused) {
  const Scene s = mixed_pile();
  auto run = renumbering(s);
  run->advance(kLook);
  ASSERT_TRUE(renumbered(*run));
  SolverState state;
  run->save_state(state);

  auto refused = [&](void (*spoil)(SolverState&), const char* why) {
    SolverState bad = state;
    spoil(bad);
    auto solver = renumbering(s);
    try {
      solver->load_state(bad);
      ADD_FAILURE() << "accepted: " << why;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("particle order"), std::string::npos) << e.what();
    }
  };
  refused([](SolverState& st) { st.particle_order.pop_back(); }, "an entry short");
  refused([](SolverState& st) { st.particle_order[5] = st.particle_order[6]; }, "twice");
  refused([](SolverState& st) { st.particle_order[7] = -1; }, "out of range");
  refused([](SolverState& st) { std::swap(st.particle_order[0], st.particle_order[10]); },
          "a wall moved");
}

/// `s` in its own order and renumbered at its first look (spread over kBodiesScattered),
/// both `after` steps past kLook + 10, within rounding of each other; a restart from the
/// renumbered run's state at kLook + 10 ends bit for bit as it (bonds' damage included).
/// The two snapshots (the scene's order, renumbered) and the saved state.
struct Renumbered {
  Snapshot scene_order, renumbered;
  SolverState saved;
};
Renumbered renumbered_and_restarted(const Scene& s, std::int64_t after) {
  Renumbered out;
  auto reference = scene_solver(s);
  auto run = renumbering(s, {}, kBodiesScattered);
  run->advance(kLook + 10);
  EXPECT_TRUE(renumbered(*run)) << run->statistics();
  run->save_state(out.saved);
  run->advance(after);
  reference->advance(kLook + 10 + after);
  out.scene_order = snapshot_of(*reference);
  out.renumbered = snapshot_of(*run);
  expect_within_rounding(out.scene_order, out.renumbered, 1e-9, reference->dt());
  auto restarted = renumbering(s, {}, kBodiesScattered);
  restarted->load_state(out.saved);
  restarted->advance(after);
  const Snapshot again = snapshot_of(*restarted);
  test::expect_identical(out.renumbered, again);
  EXPECT_EQ(out.renumbered.bond_damage, again.bond_damage);
  return out;
}

TEST(Renumbering, ABodyPileRenumbersItsBodiesAsWholesAndRestartsBitForBit) {
  const Scene s = shuffled_bodies(test::settling_body_pile());
  const Renumbered r = renumbered_and_restarted(s, 140);
  EXPECT_EQ(r.saved.body_order.size(), s.bodies.size());
  const Snapshot &a = r.scene_order, &b = r.renumbered;
  EXPECT_EQ(a.member_body, b.member_body);
  for (std::size_t k = 0; k < a.body_count(); ++k) {
    ASSERT_NEAR(a.body_x[k], b.body_x[k], 1e-12) << "body " << k;
    ASSERT_NEAR(a.body_omega[k], b.body_omega[k], 1e-6) << "body " << k;
  }
}

TEST(Renumbering, ABondedPileRenumbersWithItsBondsAndRestartsBitForBit) {
  Scene s = shuffled_bonded(2000);
  s.materials[0].tensile_strength *= 1e-3;  // some bonds break within the run
  s.materials[0].shear_strength *= 1e-3;
  const Renumbered r = renumbered_and_restarted(s, 90);
  const Snapshot &a = r.scene_order, &b = r.renumbered;
  EXPECT_EQ(a.bond_a, b.bond_a);
  EXPECT_EQ(a.bond_b, b.bond_b);
  double damage = 0;
  for (std::size_t k = 0; k < a.bond_damage.size(); ++k) {
    damage += a.bond_damage[k];
    ASSERT_NEAR(a.bond_damage[k], b.bond_damage[k], 1e-9) << "bond " << k;
  }
  EXPECT_GT(damage, 0.0) << "the bonds must be loaded";
}

/// A frame's contacts copied by `copy` from step kLook - 5, the frame thread finishing the
/// copy while `solver` steps on past its first look (to kLook + 5): the frame.
Snapshot copied_across_the_first_look(Solver& solver, ContactCopy& copy) {
  solver.advance(kLook - 5 - solver.step());
  Snapshot frame;
  solver.snapshot(frame, false);
  copy.start();
  std::thread frame_thread([&] { copy.finish(frame); });
  solver.advance(10);
  frame_thread.join();
  return frame;
}

/// A solver whose contact copy reads it in finish(), as the CUDA copy's download does, and
/// fails the test if the solver has gone by then.
class WatchedSolver final : public test::ForwardingSolver {
 public:
  WatchedSolver(std::unique_ptr<Solver> inner, std::shared_ptr<std::atomic<int>> copies_of_gone)
      : ForwardingSolver(std::move(inner)), gone_(std::move(copies_of_gone)) {}
  ~WatchedSolver() override { alive_->store(false); }
  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    return std::make_unique<Copy>(*this, alive_, gone_);
  }

 private:
  class Copy final : public ContactCopy {
   public:
    Copy(const Solver& solver, std::shared_ptr<std::atomic<bool>> alive,
         std::shared_ptr<std::atomic<int>> gone)
        : solver_(solver), alive_(std::move(alive)), gone_(std::move(gone)) {}
    void start() override {}
    void finish(Snapshot& s) override {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      if (!alive_->load()) {
        ++*gone_;
        return;
      }
      Snapshot whole;
      solver_.snapshot(whole, true);
      s.contacts = std::move(whole.contacts);
    }

   private:
    const Solver& solver_;
    std::shared_ptr<std::atomic<bool>> alive_;
    std::shared_ptr<std::atomic<int>> gone_;
  };
  std::shared_ptr<std::atomic<bool>> alive_ = std::make_shared<std::atomic<bool>>(true);
  std::shared_ptr<std::atomic<int>> gone_;
};

TEST(Renumbering, AContactCopyInFlightHoldsTheRenumberingBackAndFollowsIt) {
  const Scene s = mixed_pile();
  auto gone = std::make_shared<std::atomic<int>>(0);
  const MakeInnerSolver cpu = cpu_maker(s);
  auto solver = renumbering(s, [&](const Scene& scene, const ParticleModel& m) {
    return std::make_unique<WatchedSolver>(cpu(scene, m), gone);
  });
  const std::unique_ptr<ContactCopy> copy = solver->make_contact_copy();
  ASSERT_TRUE(copy);
  const Snapshot frame = copied_across_the_first_look(*solver, *copy);
  EXPECT_TRUE(renumbered(*solver));
  EXPECT_EQ(gone->load(), 0) << "the solver was replaced while its contacts were copied";
  EXPECT_FALSE(frame.contacts.empty());

  // The next frame's copy is the new solver's, in the scene's ids.
  solver->advance(20);
  Snapshot next;
  solver->snapshot(next, false);
  copy->start();
  copy->finish(next);
  const Snapshot whole = snapshot_of(*solver);
  EXPECT_GT(whole.contacts.size(), 30u);
  test::expect_identical(whole, next);
}

TEST(GpuRenumbering, AMixedPileRenumbersWithinRoundingRestartsBitForBitAndCopiesItsContacts) {
  TRIDEM_SKIP_WITHOUT_GPU();
  Scene s = mixed_pile();
  s.simulation.backend = Backend::Cuda;
  const ParticleModel model = build_particle_model(s);
  const MakeInnerSolver cuda = scene_order_maker(estimate_time_step(s, model), {});
  auto reference = cuda(s, model);
  auto run = make_renumbering_solver(s, model, scene_order(model), cuda, kLook, kPileScattered);
  const std::unique_ptr<ContactCopy> copy = run->make_contact_copy();
  ASSERT_TRUE(copy);
  const Snapshot frame = copied_across_the_first_look(*run, *copy);
  ASSERT_TRUE(renumbered(*run)) << run->statistics();
  EXPECT_FALSE(frame.contacts.empty());
  SolverState state;
  run->save_state(state);
  ASSERT_EQ(state.particle_order.size(), s.triangles.size());
  run->advance(200);
  reference->advance(kLook + 205);
  expect_within_rounding(snapshot_of(*reference), snapshot_of(*run), 1e-9, reference->dt());

  // The next frame's copy is the new solver's, in the scene's ids.
  Snapshot next;
  run->snapshot(next, false);
  copy->start();
  copy->finish(next);
  test::expect_identical(snapshot_of(*run), next);

  auto restarted =
      make_renumbering_solver(s, model, scene_order(model), cuda, kLook, kPileScattered);
  restarted->load_state(state);
  restarted->advance(200);
  test::expect_identical(snapshot_of(*run), snapshot_of(*restarted));
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
