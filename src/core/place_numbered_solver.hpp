#pragma once
// A solver that steps the scene's particles numbered by place and shows them by the
// scene's ids. Grains numbered in no spatial order (poured, imported, mixed) put a pair's
// two grains far apart in memory: a run of 10^6 then steps at about half the rate
// (docs/performance.md, "The particles' order"). make_solver puts such a scene's free
// particles along core/space_filling_order's curve for the backend's solver, and this
// wrapper maps back whatever leaves it: snapshots (every per-particle array, the contacts'
// i and j), saved and loaded states (so checkpoints are in the scene's ids, and either
// numbering continues the other's), and the particles its messages name (shown_id).
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"

#include <cstdint>
#include <memory>
#include <vector>

namespace tridem {

/// Whether make_solver numbers `scene`'s particles by place under `order`: Place, or Auto
/// for a scene of at least kLargeNumbering particles numbered far from where they lie
/// (core/numbering_note). Scenes of lone triangles without bonds only: Place on another
/// throws RunError saying why.
bool numbers_by_place(const Scene& scene, const ParticleModel& model, ParticleOrder order);

/// The order the solver keeps the particles in: entry k is the scene id of its particle k.
/// The free particles take the free particles' places in the order of their centroids
/// along the curve; fixed and prescribed ones keep their ids, so that their programs,
/// servos and walls.csv rows are the scene's.
std::vector<std::int32_t> place_order(const ParticleModel& model);

/// `model`'s particles in `order` (place_order), shown_id naming each by its scene id.
ParticleModel reordered_model(const ParticleModel& model, const std::vector<std::int32_t>& order);

/// Wraps `inner`, a solver of `scene` made from reordered_model(model, order), so that it
/// shows the particles by the scene's ids. `model` is the scene's own (its sizes and
/// motions say which particle of a pair emits it, broadphase/emitter_rule.hpp).
std::unique_ptr<Solver> make_place_numbered_solver(std::unique_ptr<Solver> inner,
                                                   std::vector<std::int32_t> order,
                                                   const Scene& scene, const ParticleModel& model);

}  // namespace tridem
