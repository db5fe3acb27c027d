#pragma once
// The stable time step (contact-model.md, "Time integration"): the stiffest contact,
// k = 3·p_max·L_max/h_min (p_max: the stiffest material pair a free particle can meet), on the lightest body gives dt_crit = 2·√(m_min/k). m_min takes
// rotation into account: a load at distance r from the centroid of a body of inertia I
// meets an effective mass I/r², smaller than m for slender triangles.
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"

namespace tridem {

struct TimeStep {
  double critical = 0;   ///< dt_crit, s (infinite when nothing moves by forces)
  double chosen = 0;     ///< the dt the run uses
  bool automatic = true; ///< dt was left out of the scene
};

TimeStep estimate_time_step(const Scene& scene, const ParticleModel& model);

/// Throws RunError when the scene's dt exceeds dt_crit and `force` is false.
void check_time_step(const Scene& scene, const TimeStep& ts, bool force);

}  // namespace tridem
