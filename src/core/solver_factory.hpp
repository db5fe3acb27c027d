#pragma once
// make_solver for callers that already built the particle model and the time step (the
// run loop prints both), so that start-up does that work once.
#include "core/particle_model.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

namespace tridem {

std::unique_ptr<Solver> make_solver(const Scene& scene, const ParticleModel& model,
                                    const TimeStep& ts, const SolverConfig& config);

}  // namespace tridem
