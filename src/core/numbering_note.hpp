#pragma once
// Whether a scene numbers its particles far from where they lie, which costs a large run
// up to half its rate (docs/performance.md, "The particles' order"), told at its start.
#include "core/particle_model.hpp"

#include <cstddef>
#include <string>

namespace tridem {

/// Runs of at least this many particles are told (smaller ones fit the caches).
inline constexpr std::size_t kLargeNumbering = 100000;
/// Consecutive free particles further apart than this many grain sizes on average: far.
inline constexpr double kFarNumbering = 20;

/// The free particles' mean size, the mean root of their areas; 0 without one.
double free_grain_size(const ParticleModel& model);

/// The mean distance between the centroids of consecutive free particles (ids i and i + 1)
/// over the free particles' mean size (the root of their area): about 1 for a scene
/// numbered row by row or along a curve, about a third of the domain's width in grains
/// for one numbered at random. 0 without two consecutive free particles.
double consecutive_id_distance(const ParticleModel& model);

/// consecutive_id_distance over the mean distance between two free particles drawn apart
/// in id (pairs i, i·2654435761 mod n: a fixed scramble): near 0 for a large scene
/// numbered by place, near 1 for one numbered at random, whatever its size. 0 without two
/// free particles.
double numbering_spread(const ParticleModel& model);

/// The note `tridem run` prints after its start line when a large scene is numbered far
/// from where it lies (empty otherwise): how to number it by place, or, when the solver
/// does (`by_place`, core/place_numbered_solver), that it does.
std::string numbering_note(const ParticleModel& model, bool by_place);

}  // namespace tridem
