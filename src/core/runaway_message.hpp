#pragma once
// The one message of a runaway step, whichever backend detects it. `stability` is
// TimeStep::describe(): dt_crit and the contact that sets it.
#include <cstdint>
#include <string>

namespace tridem {

std::string runaway_message(std::int64_t step, std::int64_t particle, double x, double y,
                            double speed, double dt, const std::string& stability);

/// The one message of a pair overlapping deeper than [simulation] max_penetration.
struct DeepPair {
  std::int64_t emitter, partner;
  double emitter_x, emitter_y, partner_x, partner_y;
  double depth;
};
std::string penetration_message(std::int64_t step, const DeepPair& pair, double limit,
                                double dt, double dt_crit, const std::string& stability);

}  // namespace tridem
