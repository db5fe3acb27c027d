#include "core/runaway_message.hpp"

#include <fmt/format.h>

namespace tridem {

std::string runaway_message(std::int64_t step, std::int64_t particle, double x, double y,
                            double speed, double dt, const TimeStep& ts) {
  // The cause is a step too long for the stiffest contact: dt_crit names it. A larger
  // penalty would stiffen the contacts further, so it is not advised.
  return fmt::format(
      "blow-up at step {}: particle {} (at x={:g}, y={:g}) would reach speed {:g} m/s and "
      "move more than half its size, or get a non-finite state, in one step; the time "
      "step {:g} s is too large for the stiffest contact it meets ({}): {}, or check for "
      "initially overlapping particles",
      step, particle, x, y, speed, dt, ts.describe(), ts.cure());
}

std::string penetration_message(std::int64_t step, const DeepPair& p, double limit,
                                double dt, const TimeStep& ts) {
  // Deep overlap has two causes with opposite cures. Above dt_crit the step is the cause,
  // and a larger penalty would make it worse; at or below it, the contact is too soft for
  // the loads (raise the penalty: the automatic step follows it; a given dt must stay
  // below the new dt_crit) or the particles overlapped from the start.
  const std::string cure =
      dt > ts.critical
          ? fmt::format("the step is {:.3g} x dt_crit, too large for this contact: {}",
                        dt / ts.critical, ts.cure())
          : "the contact is too soft for the loads: raise the penalty (the automatic step "
            "shrinks with it; a given dt must stay below the new dt_crit)";
  return fmt::format(
      "blow-up at step {}: particles {} (at x={:g}, y={:g}) and {} (at x={:g}, y={:g}) "
      "overlap to depth {:.3g} (0 = touching, 1 = a boundary at the other's centroid), "
      "deeper than [simulation] max_penetration = {:g}; dt = {:g} s, {}: {}, or check for "
      "initially overlapping particles",
      step, p.emitter, p.emitter_x, p.emitter_y, p.partner, p.partner_x, p.partner_y, p.depth,
      limit, dt, ts.describe(), cure);
}

}  // namespace tridem
