// The solver that numbers the particles by place (core/place_numbered_solver) against the
// scene's order: without contacts the same bits; with them the same contacts, named and
// ordered as the scene's order names them, and states within rounding; checkpoints of
// either order continue in the other; messages name the scene's particles; and which
// scenes auto numbers by place.
#include "core/place_numbered_solver.hpp"
#include "core/particle_model.hpp"
#include "core/solver_factory.hpp"
#include "core/time_step.hpp"
#include "support/body_scenes.hpp"
#include "support/forwarding_solver.hpp"
#include "support/gpu.hpp"
#include "support/periodic_scenes.hpp"
#include "support/place_order_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/error.hpp"
#include "tridem/run.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <random>
#include <string>
#include <tuple>
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

std::unique_ptr<Solver> solver_for(Scene s, ParticleOrder order, Backend backend = Backend::Cpu,
                                   Precision precision = Precision::Double) {
  s.simulation.backend = backend;
  s.simulation.precision = precision;
  SolverConfig config;
  config.particle_order = order;
  return make_solver(s, config);
}

/// A solver of `s` in the scene's order and one numbering by place, both advanced `steps`.
struct BothOrders {
  std::unique_ptr<Solver> scene_order, by_place;
};
BothOrders both_orders(const Scene& s, std::int64_t steps, Backend backend = Backend::Cpu) {
  BothOrders out{solver_for(s, ParticleOrder::Scene, backend),
                 solver_for(s, ParticleOrder::Place, backend)};
  out.scene_order->advance(steps);
  out.by_place->advance(steps);
  return out;
}

TEST(PlaceNumbering, TheOrderMovesFreeParticlesOnlyAndPutsNeighboursTogether) {
  const Scene s = shuffled(test::jostling_pile(20, 12));
  const ParticleModel model = build_particle_model(s);
  const std::vector<std::int32_t> order = place_order(model).triangles;
  ASSERT_EQ(order.size(), model.size());
  std::vector<std::int32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < sorted.size(); ++i)
    ASSERT_EQ(sorted[i], static_cast<std::int32_t>(i));
  for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(order[k], static_cast<std::int32_t>(k)) << "a wall";
  const ParticleModel inner = reordered_model(s, model, place_order(model));
  double apart_scene = 0, apart_inner = 0;
  for (std::size_t k = 4; k < model.size(); ++k) {
    apart_scene += norm(model.centroid[k] - model.centroid[k - 1]);
    apart_inner += norm(inner.centroid[k] - inner.centroid[k - 1]);
  }
  EXPECT_LT(apart_inner, 0.25 * apart_scene);
  for (std::size_t k = 0; k < model.size(); ++k) {
    EXPECT_EQ(inner.shown_ids.of_particle(static_cast<std::int64_t>(k)), order[k]);
    EXPECT_EQ(inner.mass[k], model.mass[static_cast<std::size_t>(order[k])]);
  }
}

TEST(PlaceNumbering, WithoutContactsEveryParticleMovesBitForBitAsInTheScenesOrder) {
  Scene s = test::empty_scene();
  s.simulation.gravity = {0.3, -9.81};
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 300; ++k) {
    const Vec2d c{5.0 * u(random), 5.0 * u(random)};
    s.triangles.push_back(
        test::triangle({c.x, c.y}, {c.x + 0.01, c.y}, {c.x, c.y + 0.012}, {u(random), u(random)}));
    s.triangles.back().angular_velocity = u(random);
  }
  auto scene_order = solver_for(s, ParticleOrder::Scene);
  auto by_place = solver_for(s, ParticleOrder::Place);
  EXPECT_NE(by_place->description().find("numbered by place"), std::string::npos);
  EXPECT_EQ(scene_order->description().find("numbered by place"), std::string::npos);
  scene_order->advance(200);
  by_place->advance(200);
  test::expect_identical(snapshot_of(*scene_order), snapshot_of(*by_place));
}

TEST(PlaceNumbering, ACollidingPileHasTheScenesContactsWithinRounding) {
  const Scene s = shuffled(test::jostling_pile(20, 12));
  auto [scene_order, by_place] = both_orders(s, 600);
  const Snapshot a = snapshot_of(*scene_order), b = snapshot_of(*by_place);
  EXPECT_GT(a.contacts.size(), 40u);
  // Between two grains the lower id is i, as in the scene's order (the walls, larger than
  // the grid's cells, are always j).
  for (const ContactRecord& c : b.contacts) {
    if (c.j >= 3) {
      EXPECT_LT(c.i, c.j);
    }
  }
  expect_within_rounding(a, b, 1e-9, scene_order->dt());
  // OpenMP numbered by place is the serial one numbered by place, to the bit.
  auto parallel = solver_for(s, ParticleOrder::Place, Backend::OpenMP);
  parallel->advance(600);
  test::expect_identical(b, snapshot_of(*parallel));
}

/// A CPU solver with the contact copy every backend can give (make_snapshot_contact_copy),
/// as the CUDA solver has one of its own: the place-numbered solver maps it.
class CopyingSolver final : public test::ForwardingSolver {
 public:
  using ForwardingSolver::ForwardingSolver;
  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    return make_snapshot_contact_copy(inner());
  }
};

TEST(PlaceNumbering, AFramesContactCopyGivesTheSnapshotsContacts) {
  Scene s = shuffled(test::jostling_pile(20, 12));
  // On the CPU whatever the machine has: the copy under test is the snapshot's.
  s.simulation.backend = Backend::Cpu;
  const ParticleModel model = build_particle_model(s);
  const TimeStep ts = estimate_time_step(s, model);
  const PlaceOrder order = place_order(model);
  SolverConfig config;
  config.particle_order = ParticleOrder::Scene;
  auto inner = make_solver(s, reordered_model(s, model, order), ts, config);
  EXPECT_EQ(inner->make_contact_copy(), nullptr) << "the CPU takes them with the snapshot";
  auto by_place = make_place_numbered_solver(std::make_unique<CopyingSolver>(std::move(inner)),
                                             order, s, model);
  by_place->advance(400);
  const std::unique_ptr<ContactCopy> copy = by_place->make_contact_copy();
  ASSERT_TRUE(copy);
  Snapshot copied;
  by_place->snapshot(copied, false);
  EXPECT_TRUE(copied.contacts.empty());
  copy->start();
  copy->finish(copied);
  const Snapshot whole = snapshot_of(*by_place);
  EXPECT_GT(whole.contacts.size(), 30u);
  test::expect_identical(whole, copied);
}

/// A periodic scene numbered by place against its own order after `steps`, some contacts
/// through the boundary (`through`): the images' translations seen from the scene's emitter.
void expect_images_within_rounding(const Scene& s, std::int64_t steps,
                                   bool (*through)(const ContactRecord&)) {
  auto [scene_order, by_place] = both_orders(s, steps);
  const Snapshot a = snapshot_of(*scene_order);
  EXPECT_GT(std::count_if(a.contacts.begin(), a.contacts.end(), through), 0)
      << "some contact must be through the boundary";
  expect_within_rounding(a, snapshot_of(*by_place), 1e-9, scene_order->dt());
}

TEST(PlaceNumbering, PeriodicContactsKeepTheirImagesSeenFromTheScenesEmitter) {
  expect_images_within_rounding(shuffled(test::periodic_pile(12, 8)), 300,
                                [](const ContactRecord& c) { return c.image_dx != 0; });
}

// Lees-Edwards images: a sheared gas whose grains meet through the moving boundary.
TEST(PlaceNumbering, LeesEdwardsContactsKeepTheirImagesSeenFromTheScenesEmitter) {
  expect_images_within_rounding(shuffled(test::dense_sheared_gas(10)), 400,
                                [](const ContactRecord& c) { return c.image_dy != 0; });
}

// Every way of finding the pairs follows the one emitter rule: each, numbered by place,
// has the scene order's contacts (all-pairs: every particle small).
TEST(PlaceNumbering, EveryMethodHasTheScenesContactsWithinRounding) {
  for (const Method method : {Method::AllPairs, Method::SingleDomain, Method::Decomposition}) {
    Scene s = test::with_decomposition(shuffled(test::jostling_pile(12, 8)),
                                       DecompositionLayout::Strips, 64);
    s.simulation.method = method;
    auto [scene_order, by_place] = both_orders(s, 500);
    SCOPED_TRACE(scene_order->description());
    expect_within_rounding(snapshot_of(*scene_order), snapshot_of(*by_place), 1e-9,
                           scene_order->dt());
  }
}

/// The snapshots of a run continued in either order.
struct Continued {
  Snapshot reference;         ///< the scene order's run, not interrupted
  Snapshot place_from_scene;  ///< the scene order's state, continued numbered by place
  Snapshot scene_from_place;  ///< the state numbered by place, continued in the scene's order
};

/// The states of `scene_order` and `by_place` (solvers of `s` at one step) each continued
/// `steps` steps by a solver of the other order, and by_place's by one of its own: the
/// crossings within rounding of the uninterrupted scene order's run, the same order's
/// bit for bit the uninterrupted one's.
Continued expect_states_continue_in_either_order(const Scene& s, Solver& scene_order,
                                                 Solver& by_place, std::int64_t steps) {
  SolverState from_scene, from_place;
  scene_order.save_state(from_scene);
  by_place.save_state(from_place);
  auto place_from_scene = solver_for(s, ParticleOrder::Place);
  place_from_scene->load_state(from_scene);
  auto scene_from_place = solver_for(s, ParticleOrder::Scene);
  scene_from_place->load_state(from_place);
  auto place_again = solver_for(s, ParticleOrder::Place);
  place_again->load_state(from_place);
  for (Solver* solver :
       {&scene_order, &by_place, place_from_scene.get(), scene_from_place.get(), place_again.get()})
    solver->advance(steps);
  Continued out{snapshot_of(scene_order), snapshot_of(*place_from_scene),
                snapshot_of(*scene_from_place)};
  expect_within_rounding(out.reference, out.place_from_scene, 1e-9, scene_order.dt());
  expect_within_rounding(out.reference, out.scene_from_place, 1e-9, scene_order.dt());
  test::expect_identical(snapshot_of(by_place), snapshot_of(*place_again));
  return out;
}

/// The contact history as a map from (emitter, partner) to its slip, leaving out the zero
/// ones: a state lists a history of −0 (a bit pattern a restart keeps), and a pair whose
/// roles swap inside the solver has +0 for it, which needs no entry.
std::map<std::pair<std::int32_t, std::int32_t>, std::array<double, 2>> history(const Solver& s) {
  SolverState state;
  s.save_state(state);
  std::map<std::pair<std::int32_t, std::int32_t>, std::array<double, 2>> out;
  for (std::size_t k = 0; k < state.pairs(); ++k)
    if (state.pair_slip[k][0] != 0 || state.pair_slip[k][1] != 0)
      out[{state.pair_emitter[k], state.pair_partner[k]}] = state.pair_slip[k];
  return out;
}

TEST(PlaceNumbering, SavedStatesAreInTheScenesIdsAndContinueInEitherOrder) {
  const Scene s = shuffled(test::jostling_pile(20, 12));
  auto [scene_order, by_place] = both_orders(s, 500);

  // The same pairs with the same history, signs included: a pair whose roles swapped
  // inside the solver is shown from the scene's emitter.
  const auto ha = history(*scene_order), hb = history(*by_place);
  ASSERT_GT(ha.size(), 30u);
  ASSERT_EQ(ha.size(), hb.size());
  double largest = 0;
  for (const auto& [pair, slip] : ha)
    largest = std::max({largest, std::abs(slip[0]), std::abs(slip[1])});
  ASSERT_GT(largest, 0.0);
  for (const auto& [pair, slip] : ha) {
    const auto found = hb.find(pair);
    ASSERT_NE(found, hb.end()) << pair.first << "-" << pair.second;
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(found->second[c], slip[c], 1e-6 * largest);
  }

  // Each order's state continues the other's, within rounding of the uninterrupted runs.
  expect_states_continue_in_either_order(s, *scene_order, *by_place, 150);
}

TEST(PlaceNumbering, ALoadedStateIsCheckedInTheScenesIds) {
  const Scene s = shuffled(test::jostling_pile(6, 4));
  auto by_place = solver_for(s, ParticleOrder::Place);
  SolverState state;
  by_place->save_state(state);
  state.pair_emitter = {5};
  state.pair_partner = {5};
  state.pair_slip = {{0.0, 1.0}};
  try {
    by_place->load_state(state);
    FAIL() << "a pair of a particle with itself was loaded";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pair 0 (5, 5)"), std::string::npos) << e.what();
  }
}

/// The message of the RunError that the first step of `s` numbered by place throws;
/// empty, and a failure, when it throws none.
std::string first_step_error(const Scene& s) {
  auto by_place = solver_for(s, ParticleOrder::Place);
  try {
    by_place->advance(1);
  } catch (const RunError& e) {
    return e.what();
  }
  ADD_FAILURE() << "the first step threw no RunError";
  return {};
}

TEST(PlaceNumbering, ABlowUpNamesTheScenesParticle) {
  Scene s = shuffled(test::jostling_pile(20, 12));
  const ParticleModel model = build_particle_model(s);
  const std::vector<std::int32_t> order = place_order(model).triangles;
  // A free particle that the solver keeps at another index.
  std::size_t fast = 3;
  while (order[fast] == static_cast<std::int32_t>(fast)) ++fast;
  const auto inner = static_cast<std::size_t>(
      std::find(order.begin(), order.end(), static_cast<std::int32_t>(fast)) - order.begin());
  ASSERT_NE(inner, fast);
  s.triangles[fast].velocity = {1e6, 0};  // blows up in the first step
  const std::string what = first_step_error(s);
  EXPECT_NE(what.find("particle " + std::to_string(fast) + " "), std::string::npos) << what;
}

TEST(PlaceNumbering, ADeepPairNamesTheScenesParticles) {
  Scene s = test::empty_scene();
  // Ten grains in a row, numbered from the right, the last two overlapping deeply.
  for (int k = 9; k >= 0; --k) {
    const double x = 0.05 * k;
    s.triangles.push_back(test::triangle({x, 0}, {x + 0.02, 0}, {x, 0.02}));
  }
  const double x = 0.004;  // over grain 9, the one at x = 0
  s.triangles.push_back(test::triangle({x, 0}, {x + 0.02, 0}, {x, 0.02}));
  s.simulation.max_penetration = 0.3;
  const ParticleModel model = build_particle_model(s);
  const std::vector<std::int32_t> order = place_order(model).triangles;
  ASSERT_NE(order[9], 9) << "the deep pair must be renumbered";
  const std::string what = first_step_error(s);
  const bool named = what.find("particles 9 (") != std::string::npos
                         ? what.find(" and 10 (") != std::string::npos
                         : what.find("particles 10 (") != std::string::npos &&
                               what.find(" and 9 (") != std::string::npos;
  EXPECT_TRUE(named) << what;
}

TEST(PlaceNumbering, AutoNumbersLargeScenesNumberedFarApart) {
  const Scene rows = dense_pile(100000);
  const Scene random = shuffled(rows);
  EXPECT_FALSE(numbers_by_place(rows, build_particle_model(rows), ParticleOrder::Auto));
  const ParticleModel random_model = build_particle_model(random);
  EXPECT_TRUE(numbers_by_place(random, random_model, ParticleOrder::Auto));
  EXPECT_FALSE(numbers_by_place(random, random_model, ParticleOrder::Scene));
  EXPECT_TRUE(describe_scene(random).numbered_by_place) << "tridem info tells it";
  EXPECT_FALSE(describe_scene(rows).numbered_by_place);
  const Scene small = shuffled(test::jostling_pile(20, 12));
  const ParticleModel small_model = build_particle_model(small);
  EXPECT_FALSE(numbers_by_place(small, small_model, ParticleOrder::Auto));
  EXPECT_TRUE(numbers_by_place(small, small_model, ParticleOrder::Place));
}

/// bonded_pile(n) with its grains in a random order: the bonds follow their triangles
/// (each with its lower id first, in ascending order, as a scene lists them).
TEST(PlaceNumbering, ABondedPileHasTheScenesBondsAndContactsWithinRounding) {
  Scene s = shuffled_bonded(2000);
  s.materials[0].tensile_strength *= 1e-3;  // some bonds break within the run
  s.materials[0].shear_strength *= 1e-3;
  auto [scene_order, by_place] = both_orders(s, 300);
  const Snapshot a = snapshot_of(*scene_order), b = snapshot_of(*by_place);
  expect_within_rounding(a, b, 1e-9, scene_order->dt());
  EXPECT_EQ(a.bond_a, b.bond_a);
  EXPECT_EQ(a.bond_b, b.bond_b);
  EXPECT_EQ(a.bond_broken, b.bond_broken);
  ASSERT_EQ(a.bond_damage.size(), b.bond_damage.size());
  double damage = 0;
  for (std::size_t k = 0; k < a.bond_damage.size(); ++k) {
    damage += a.bond_damage[k];
    ASSERT_NEAR(a.bond_damage[k], b.bond_damage[k], 1e-9) << "bond " << k;
    ASSERT_NEAR(a.bond_x0[k], b.bond_x0[k], 1e-12) << "bond " << k;
    ASSERT_NEAR(a.bond_y1[k], b.bond_y1[k], 1e-12) << "bond " << k;
  }
  EXPECT_GT(damage, 0.0) << "the bonds must be loaded";

  // The bonds' state continues in either order.
  const Continued c = expect_states_continue_in_either_order(s, *scene_order, *by_place, 100);
  for (std::size_t k = 0; k < c.reference.bond_damage.size(); ++k) {
    ASSERT_NEAR(c.reference.bond_damage[k], c.scene_from_place.bond_damage[k], 1e-9) << k;
    ASSERT_NEAR(c.reference.bond_damage[k], c.place_from_scene.bond_damage[k], 1e-9) << k;
  }
}

/// The body pile with its free bodies in a random order (members in theirs; the walls,
/// last, stay).
TEST(PlaceNumbering, BodiesMoveAsWholesAndWallBodiesKeepTheirIds) {
  const Scene s = shuffled_bodies(test::settling_body_pile());
  ASSERT_TRUE(s.has_bodies());
  const ParticleModel model = build_particle_model(s);
  const PlaceOrder order = place_order(model);
  ASSERT_EQ(order.bodies.size(), s.bodies.size());
  std::size_t moved = 0;
  for (std::size_t k = 0; k < order.bodies.size(); ++k) {
    const BodySpec& body = s.bodies[static_cast<std::size_t>(order.bodies[k])];
    if (body.motion != Motion::Free) {
      EXPECT_EQ(order.bodies[k], static_cast<std::int32_t>(k));
    }
    moved += order.bodies[k] != static_cast<std::int32_t>(k);
  }
  EXPECT_GT(moved, order.bodies.size() / 2);
  // Each body's members follow one another, in their order.
  std::size_t t = 0;
  for (const std::int32_t b : order.bodies) {
    const BodySpec& body = s.bodies[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < body.count; ++k, ++t)
      ASSERT_EQ(order.triangles[t], static_cast<std::int32_t>(body.first + k));
  }
  EXPECT_EQ(t, s.triangles.size());
  const ParticleModel inner = reordered_model(s, model, order);
  for (std::size_t k = 0; k < order.bodies.size(); ++k) {
    const auto b = static_cast<std::size_t>(order.bodies[k]);
    EXPECT_EQ(inner.bodies.mass[k], model.bodies.mass[b]);
    EXPECT_EQ(inner.bodies.inertia[k], model.bodies.inertia[b]);
  }
}

TEST(PlaceNumbering, ABodyPileHasTheScenesContactsAndBodiesWithinRounding) {
  const Scene s = shuffled_bodies(test::settling_body_pile());
  auto [scene_order, by_place] = both_orders(s, 200);
  const Snapshot a = snapshot_of(*scene_order), b = snapshot_of(*by_place);
  expect_within_rounding(a, b, 1e-9, scene_order->dt());
  ASSERT_EQ(a.body_count(), b.body_count());
  EXPECT_EQ(a.member_body, b.member_body);
  EXPECT_EQ(a.body_first, b.body_first);
  EXPECT_EQ(a.body_mass, b.body_mass);
  for (std::size_t k = 0; k < a.body_count(); ++k) {
    ASSERT_NEAR(a.body_x[k], b.body_x[k], 1e-12) << "body " << k;
    ASSERT_NEAR(a.body_vy[k], b.body_vy[k], 1e-9) << "body " << k;
    ASSERT_NEAR(a.body_omega[k], b.body_omega[k], 1e-6) << "body " << k;
  }

  // States in the scene's ids continue in either order.
  SolverState from_place;
  by_place->save_state(from_place);
  EXPECT_EQ(from_place.body_x.size(), s.bodies.size());
  expect_states_continue_in_either_order(s, *scene_order, *by_place, 100);
}

TEST(PlaceNumbering, ABodysBlowUpNamesTheScenesBody) {
  Scene s = shuffled_bodies(test::settling_body_pile());
  const PlaceOrder order = place_order(build_particle_model(s));
  std::size_t fast = 0;
  while (order.bodies[fast] == static_cast<std::int32_t>(fast)) ++fast;
  const auto body = static_cast<std::size_t>(order.bodies[fast]);  // kept at index `fast`
  s.bodies[body].velocity = {1e6, 0};
  const std::string what = first_step_error(s);
  EXPECT_EQ(what.find("body id " + std::to_string(body) + ": "), 0u) << what;
  EXPECT_NE(what.find("particle " + std::to_string(s.bodies[body].first) + " "), std::string::npos)
      << what;
}

TEST(GpuPlaceNumbering, ACollidingPileHasTheScenesContactsWithinRounding) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = shuffled(test::jostling_pile(20, 12));
  auto [scene_order, by_place] = both_orders(s, 250, Backend::Cuda);
  expect_within_rounding(snapshot_of(*scene_order), snapshot_of(*by_place), 1e-9,
                         scene_order->dt());
  // The frames' contact copy (beside the steps) is the snapshot's, to the bit.
  const std::unique_ptr<ContactCopy> copy = by_place->make_contact_copy();
  ASSERT_TRUE(copy) << "the CUDA solver's copy, mapped";
  Snapshot copied;
  by_place->snapshot(copied, false);
  copy->start();
  copy->finish(copied);
  test::expect_identical(snapshot_of(*by_place), copied);
  // Its state, in the scene's ids, continues in the scene's order.
  SolverState state;
  by_place->save_state(state);
  auto continued = solver_for(s, ParticleOrder::Scene, Backend::Cuda);
  continued->load_state(state);
  continued->advance(100);
  scene_order->advance(100);
  expect_within_rounding(snapshot_of(*scene_order), snapshot_of(*continued), 1e-9,
                         scene_order->dt());
}

TEST(GpuPlaceNumbering, ABodyPileHasTheScenesContactsAndBodiesWithinRounding) {
  TRIDEM_SKIP_WITHOUT_GPU();
  const Scene s = shuffled_bodies(test::settling_body_pile());
  auto [scene_order, by_place] = both_orders(s, 200, Backend::Cuda);
  const Snapshot a = snapshot_of(*scene_order), b = snapshot_of(*by_place);
  expect_within_rounding(a, b, 1e-9, scene_order->dt());
  EXPECT_EQ(a.member_body, b.member_body);
  ASSERT_EQ(a.body_count(), b.body_count());
  for (std::size_t k = 0; k < a.body_count(); ++k)
    ASSERT_NEAR(a.body_x[k], b.body_x[k], 1e-12) << "body " << k;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
