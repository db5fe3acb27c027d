#pragma once
// The stable time step (docs/model.md, "The time step"): for every free particle, the
// stiffest set of contacts it can meet in this scene (each edge pressed along its whole
// length, by the thinnest partner of each kind and both roles of the contact; walls and
// prescribed triangles included), with the tangential springs and dashpots of the contact
// law (physics/stability.hpp), gives the limit of symplectic Euler; dt_crit is the
// smallest over the particles. A body of several triangles is bounded as one: the outer
// edges of its members on the body's mass and inertia.
#include "core/particle_model.hpp"
#include "tridem/scene.hpp"

#include <string>

namespace tridem {

/// Where dt_crit comes from, for messages.
struct StepLimit {
  std::int64_t particle = -1;  ///< the free particle with the smallest limit
  std::int64_t partner = -1;   ///< the thinnest partner of the kind that sets it
  bool partner_free = true;    ///< false: a fixed or prescribed triangle
  double partner_height = 0;   ///< its smallest height, m
  double particle_height = 0;  ///< the particle's smallest height, m
  double damping_ratio = 0;    ///< the largest ζ it meets
  /// The body of several triangles the limit belongs to (then `particle` is its thinnest
  /// member), or -1 for a single triangle.
  std::int64_t body = -1;
  std::int64_t body_members = 0;
  bool bonds = false;  ///< set by the cohesive bonds' springs instead (docs/fracture.md)

  /// "particle 3 pressed on every edge by fixed or prescribed particle 0 (0.0001 m
  /// thick: a thin wall ...)", or "" when no particle is free.
  std::string describe() const;
  /// True when the partner is a wall much thinner than the particle: its contact is stiff.
  bool thin_wall() const { return !partner_free && partner_height < 0.5 * particle_height; }
};

struct TimeStep {
  double critical = 0;    ///< dt_crit, s (infinite when nothing moves by forces)
  double chosen = 0;      ///< the dt the run uses
  bool automatic = true;  ///< dt was left out of the scene
  StepLimit limit;        ///< what sets dt_crit

  /// "dt_crit = 1.2e-05 s, set by particle 3 pressed on every edge by ..." for messages.
  std::string describe() const;
  /// "lower dt or [simulation] safety", and ", or make the thin wall (particle 0) thicker"
  /// when a thin wall sets dt_crit. Never a larger penalty: it would stiffen the contact.
  std::string cure() const;
};

TimeStep estimate_time_step(const Scene& scene, const ParticleModel& model);

/// The run's length in steps of `dt`: [simulation] steps, or for [simulation] time = T the
/// fewest steps whose end reaches T (T/dt rounded up, a whole number of steps within
/// rounding counting as reached). Throws RunError when T/dt is more steps than a run can
/// count.
std::int64_t steps_to_reach(const SimulationSettings& s, double dt);

/// Throws RunError when the scene's dt exceeds dt_crit and `force` is false.
void check_time_step(const Scene& scene, const TimeStep& ts, bool force);

}  // namespace tridem
