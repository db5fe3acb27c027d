#pragma once
// What a periodic cell needs of a scene (docs/scene-format.md, "Periodic boundaries"),
// checked once the particle model is known: a method and a backend that see across the
// boundary, and a cell long enough for the minimum-image rule of physics/periodic_frame.hpp.
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"

namespace tridem {

/// Throws SceneError naming the setting to change when `backend` (resolved) cannot run the
/// scene's periodic cell, or when the cell is too short for its particles. No-op without
/// periodic boundaries.
void check_periodic_cell(const Scene& scene, const ParticleModel& model, Backend backend);

}  // namespace tridem
