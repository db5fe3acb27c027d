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

std::string penetration_message(std::int64_t step, const DeepPair& p, double limit) {
  return fmt::format(
      "blow-up at step {}: particles {} (at x={:g}, y={:g}) and {} (at x={:g}, y={:g}) "
      "overlap to depth {:.3g} (0 = touching, 1 = a boundary at the other's centroid), "
      "deeper than [simulation] max_penetration = {:g}; the contact is too soft for the "
      "loads or the time step too large (raise the penalty, reduce dt, or check for "
      "initially overlapping particles)",
      step, p.emitter, p.emitter_x, p.emitter_y, p.partner, p.partner_x, p.partner_y, p.depth,
      limit);
}

}  // namespace tridem
