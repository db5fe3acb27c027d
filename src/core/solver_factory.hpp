#pragma once
// make_solver for callers that already built the particle model and the time step (the
// run loop prints both), so that start-up does that work once.
#include "core/particle_model.hpp"
#include "core/place_numbered_solver.hpp"
#include "core/time_step.hpp"
#include "tridem/solver.hpp"

namespace tridem {

std::unique_ptr<Solver> make_solver(const Scene& scene, const ParticleModel& model,
                                    const TimeStep& ts, const SolverConfig& config);

/// make_solver with `ts` and `config`, each scene in the order it is given: the inner
/// solvers of a make_renumbering_solver made in code (tests, benchmarks).
MakeInnerSolver scene_order_maker(const TimeStep& ts, SolverConfig config);

}  // namespace tridem
