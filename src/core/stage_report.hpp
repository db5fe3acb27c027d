#pragma once
// The per-stage times of a run as `tridem run` prints them at the end.
#include "tridem/solver.hpp"

#include <string>

namespace tridem {

/// A short table: one line per stage with its time, share and time per step; a stage
/// fused into another one's kernel says where its time went. Empty when no step ran.
std::string stage_table(const StageTimes& times);

}  // namespace tridem
