#include "mpi/strip_plan.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

namespace tridem::mpi {

StripPlan plan_strips(const StripInput& in) {
  const std::size_t n = in.x.size();
  const auto ranks = static_cast<std::size_t>(std::max(1, in.ranks));
  StripPlan plan;
  plan.owner.assign(n, -1);
  plan.held.assign(ranks, {});
  plan.lo.assign(ranks, std::numeric_limits<double>::infinity());
  plan.hi.assign(ranks, -std::numeric_limits<double>::infinity());

  // The cell grid's size, as classify_for_grid takes it: the longest edge of a free
  // particle (of any when none is free). A wall no longer than that is binned and emits
  // its pairs with higher ids: it is owned like a grain, so that its row (and the energy
  // the row adds to it) is on one rank.
  double cell = -1, cell_all = -1;
  for (std::size_t i = 0; i < n; ++i) {
    cell_all = std::max(cell_all, in.longest_edge[i]);
    if (in.motion[i] != Motion::Free) continue;
    // The first of the longest, as classify_for_grid takes the maximum.
    if (in.longest_edge[i] > cell) {
      cell = in.longest_edge[i];
      plan.cell_setter = static_cast<std::int32_t>(i);
    }
  }
  if (cell < 0) cell = cell_all;
  std::vector<std::int32_t> free;  // grains and the walls that emit: the owned ones
  double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x, lo_y = lo_x, hi_y = -lo_x;
  double radius = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool grain = in.motion[i] == Motion::Free;
    if (!grain && !(in.longest_edge[i] <= cell)) continue;
    free.push_back(static_cast<std::int32_t>(i));
    radius = std::max(radius, in.radius[i]);
    if (!grain) continue;  // the strips' axis and cuts follow the grains
    lo_x = std::min(lo_x, in.x[i]);
    hi_x = std::max(hi_x, in.x[i]);
    lo_y = std::min(lo_y, in.y[i]);
    hi_y = std::max(hi_y, in.y[i]);
  }
  plan.axis = in.sheared || (hi_y - lo_y) > (hi_x - lo_x) ? 1 : 0;
  const bool ring = in.periodic[plan.axis];
  const double period = in.period[plan.axis];
  plan.margin = 2 * radius + in.skin;
  const std::vector<double>& c = plan.axis == 0 ? in.x : in.y;

  // Free particles along the axis (ties by id), cut where the running weight passes k/N
  // of the whole.
  std::vector<std::int32_t> order = free;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::int32_t a, std::int32_t b) { return c[a] < c[b]; });
  double total = 0;
  for (std::int32_t i : order) total += 1.0 + in.contacts[i];
  if (total <= 0) total = 1;
  double running = 0;
  for (std::int32_t i : order) {
    const double w = 1.0 + in.contacts[i];
    // The particle's strip is that of the middle of its weight, so that a heavy particle
    // goes where most of it lies.
    auto r = static_cast<std::size_t>((running + 0.5 * w) / total * static_cast<double>(ranks));
    r = std::min(r, ranks - 1);
    running += w;
    plan.owner[i] = static_cast<int>(r);
    plan.lo[r] = std::min(plan.lo[r], c[i]);
    plan.hi[r] = std::max(plan.hi[r], c[i]);
  }

  for (std::size_t r = 0; r < ranks; ++r) {
    std::vector<std::int32_t>& held = plan.held[r];
    for (std::size_t i = 0; i < n; ++i) {
      const auto id = static_cast<std::int32_t>(i);
      const bool wall = in.motion[i] != Motion::Free;
      const bool own = plan.owner[i] == static_cast<int>(r);
      auto within = [&](double v) {
        return v >= plan.lo[r] - plan.margin && v <= plan.hi[r] + plan.margin;
      };
      // Along a periodic axis, through the boundary too: the particle's images a period
      // either side.
      const bool near = plan.lo[r] <= plan.hi[r] &&
                        (within(c[i]) || (ring && (within(c[i] - period) || within(c[i] + period))));
      if (wall || own || near || id == plan.cell_setter) held.push_back(id);
    }
  }
  return plan;
}

}  // namespace tridem::mpi
