#pragma once
// The one message of a runaway step, whichever backend detects it. Both name dt_crit, the
// contact that sets it, and the cure (TimeStep).
#include "core/time_step.hpp"

#include <cstdint>
#include <string>

namespace tridem {

std::string runaway_message(std::int64_t step, std::int64_t particle, double x, double y,
                            double speed, double dt, const TimeStep& ts);

/// The one message of a pair overlapping deeper than [simulation] max_penetration.
struct DeepPair {
  std::int64_t emitter, partner;
  double emitter_x, emitter_y, partner_x, partner_y;
  double depth;
};
std::string penetration_message(std::int64_t step, const DeepPair& pair, double limit,
                                double dt, const TimeStep& ts);

}  // namespace tridem
