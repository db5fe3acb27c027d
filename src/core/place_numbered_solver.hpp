#pragma once
// A solver that steps the scene's particles numbered by place and shows them by the
// scene's ids. Grains numbered in no spatial order (poured, imported, mixed) put a pair's
// two grains far apart in memory: a run of 10^6 then steps at about half the rate
// (docs/performance.md, "The particles' order"). make_solver puts such a scene's free
// particles or bodies along core/space_filling_order's curve for the backend's solver, and
// this wrapper maps back whatever leaves it: snapshots (every per-particle and per-body
// array, the contacts' and bonds' ends), saved and loaded states (so checkpoints are in the
// scene's ids, and either numbering continues the other's), and the particles its
// messages name (ParticleModel::shown_ids).
#include "core/neighbour_blocks.hpp"
#include "core/numbering_note.hpp"
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace tridem {

/// Whether make_solver numbers `scene`'s particles by place under `order`: Place, or Auto
/// for a scene of at least kLargeNumbering particles numbered far from where they lie
/// (core/numbering_note). Place on a scene of over 2^31 particles throws RunError.
bool numbers_by_place(const Scene& scene, const ParticleModel& model, ParticleOrder order);

/// The order the solver keeps the particles in.
struct PlaceOrder {
  /// Entry k: the scene id of the solver's triangle k.
  std::vector<std::int32_t> triangles;
  /// Entry k: the scene id of the solver's body k; empty without bodies of several
  /// triangles.
  std::vector<std::int32_t> bodies;
};

/// Lone triangles: the free ones take the free ones' places in the order of their
/// centroids along the curve. Bodies of several triangles move as wholes, members in their
/// order: each run of consecutive free bodies is put in the order of the bodies' centroids
/// along the curve. Fixed and prescribed particles and bodies keep their ids, so that
/// their programs, servos and walls.csv rows are the scene's.
PlaceOrder place_order(const ParticleModel& model);

/// place_order by the centroids of `now` (a state in the scene's ids), not the model's:
/// the order of a run's particles where they are at that step.
PlaceOrder place_order(const ParticleModel& model, const SolverState& now);

/// The scene's own order: every triangle (and body) at its id.
PlaceOrder scene_order(const ParticleModel& model);

/// The order of `scene`'s bodies `bodies` (every body id once), their members with each:
/// a scene's bodies put in another order (benchmarks and tests shuffle them so).
PlaceOrder body_order(const Scene& scene, std::vector<std::int32_t> bodies);

/// `scene` with its triangles and bodies (when it has some of several triangles) in
/// `order`, its bonds between the same triangles in their order, each keeping its ends'
/// roles (so a bond's a may now be above its b): the scene the solver steps.
Scene reordered_scene(const Scene& scene, const PlaceOrder& order);

/// `model` (of `scene`) with its particles and bodies in `order`, its shown_ids naming
/// each by its scene id.
ParticleModel reordered_model(const Scene& scene, const ParticleModel& model,
                              const PlaceOrder& order);

/// Wraps `inner`, a solver of `scene` made from reordered_model(scene, model, order), so
/// that it shows the particles and bodies by the scene's ids. `model` is the scene's own
/// (its sizes and motions say which particle of a pair emits it,
/// broadphase/emitter_rule.hpp).
std::unique_ptr<Solver> make_place_numbered_solver(std::unique_ptr<Solver> inner, PlaceOrder order,
                                                   const Scene& scene, const ParticleModel& model);

/// Makes the backend's solver of a scene and its model (make_solver's choices made).
using MakeInnerSolver =
    std::function<std::unique_ptr<Solver>(const Scene& scene, const ParticleModel& model)>;

/// A solver of `scene` (its model `model`) whose inner solver, made by `make`, steps the
/// particles in `order` (scene_order(model) for the scene's own, then shown as they are),
/// and which, at every step that is a multiple of `check_steps` (0: never), numbers them
/// by place again (place_order(model, state)) when the neighbours of its consecutive free
/// particles (bodies of several triangles: bodies) have scattered in memory, their
/// neighbour_block_spread over `scattered` (core/neighbour_blocks.hpp): it saves its
/// state, makes the inner solver again in the new order and loads the state into it. Its saved
/// states then carry the order (SolverState::particle_order), which its load_state takes up, so
/// that a restart goes on bit for bit. It keeps a copy of the scene for that.
std::unique_ptr<Solver> make_renumbering_solver(const Scene& scene, const ParticleModel& model,
                                                PlaceOrder order, const MakeInnerSolver& make,
                                                std::int64_t check_steps,
                                                double scattered = kScatteredNeighbours);

}  // namespace tridem
