#include "core/runaway_message.hpp"

#include <fmt/format.h>

namespace tridem {

std::string runaway_message(std::int64_t step, std::int64_t particle, double x, double y,
                            double speed, double dt) {
  return fmt::format(
      "blow-up at step {}: particle {} (at x={:g}, y={:g}) would reach speed {:g} m/s and "
      "move more than half its size, or get a non-finite state, in one step; the time "
      "step {:g} s is too large for the contacts it meets (reduce dt or the penalty, or "
      "check for initially overlapping particles)",
      step, particle, x, y, speed, dt);
}

}  // namespace tridem
