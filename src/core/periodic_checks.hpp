#pragma once
// What a periodic cell needs of a scene (docs/scene-format.md, "Periodic boundaries"),
// checked once the particle model is known: a cell long enough for the minimum-image rule
// of physics/periodic_frame.hpp, and the longer cell the GPU's pair list needs.
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"

#include <string>

namespace tridem {

/// Throws SceneError naming the setting to change when the scene's method cannot run its
/// periodic cell, or when the cell is too short for its particles. No-op without periodic
/// boundaries.
void check_periodic_cell(const Scene& scene, const ParticleModel& model);

/// The shortest periodic length for which the GPU's pair list, which takes each pair's
/// image from the centroids at its build, cannot miss a pair: 8 reaches (the farthest
/// vertex from a centroid) plus twice the skin (ARCHITECTURE.md). 0 without a periodic cell.
double gpu_exact_periodic_length(const Scene& scene, const ParticleModel& model);

/// Whether the scene's periodic cell is at least that long along each periodic axis.
bool gpu_lists_periodic_cell_exactly(const Scene& scene, const ParticleModel& model);

/// Why the GPU cannot run a periodic scene (its cell is too short for the GPU's pair list,
/// whatever the method): `refusal`, the error for backend = "cuda", and `reason`, the
/// note's for backend = "auto", which runs it on the CPU. Both empty when it can (or
/// without a periodic cell).
struct GpuPeriodicLimit {
  std::string refusal, reason;
};
GpuPeriodicLimit gpu_periodic_limit(const Scene& scene, const ParticleModel& model);

}  // namespace tridem
