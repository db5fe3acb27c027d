#include "mpi/strip_plan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace tridem::mpi {

StripPlan plan_strips(const StripInput& in) {
  const std::size_t n = in.x.size();
  const auto ranks = static_cast<std::size_t>(std::max(1, in.ranks));
  StripPlan plan;
  plan.owner.assign(n, -1);
  plan.held.assign(ranks, {});
  constexpr double kInf = std::numeric_limits<double>::infinity();
  plan.lo.assign(ranks, {kInf, kInf});
  plan.hi.assign(ranks, {-kInf, -kInf});

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
  // The factoring of N with the shortest inner borders across the grains' extent: nx
  // columns put nx - 1 borders as long as the extent's height, and their ny rows ny - 1
  // as long as its width in all. Under Lees-Edwards shear the images across y slide along
  // x: strips along y.
  const double width = std::isfinite(hi_x - lo_x) ? hi_x - lo_x : 0;
  const double height = std::isfinite(hi_y - lo_y) ? hi_y - lo_y : 0;
  const auto n_ranks = static_cast<int>(ranks);
  double best = std::numeric_limits<double>::infinity();
  for (int nx = n_ranks; nx >= 1; --nx) {
    if (n_ranks % nx != 0 || (in.sheared && nx > 1)) continue;
    const int ny = n_ranks / nx;
    const double cost = (nx - 1) * height + (ny - 1) * width;
    if (cost < best) {
      best = cost;
      plan.cuts[0] = nx;
      plan.cuts[1] = ny;
    }
  }
  plan.axis = plan.cuts[0] == 1 && plan.cuts[1] > 1 ? 1 : 0;
  plan.margin = 2 * radius + in.skin;
  const std::vector<double>* coord[2] = {&in.x, &in.y};

  // A body's members go with its first member (its head): only heads are cut, each
  // weighing its members' weights together.
  auto head = [&](std::size_t i) {
    return in.unit.empty() ? static_cast<std::int32_t>(i) : in.unit[i];
  };
  std::vector<double> weight(n, 0.0);
  for (const std::int32_t i : free)
    weight[static_cast<std::size_t>(head(static_cast<std::size_t>(i)))] += 1.0 + in.contacts[i];
  std::vector<std::int32_t> heads;
  for (const std::int32_t i : free)
    if (head(static_cast<std::size_t>(i)) == i) heads.push_back(i);

  // Cuts `ids` (any order) along `axis` into `parts` runs of about equal weight (ties by
  // id): part(i, k) for each. A particle's part is that of the middle of its weight, so
  // that a heavy particle goes where most of it lies.
  auto cut = [&](std::vector<std::int32_t> ids, int axis, int parts, auto&& part) {
    const std::vector<double>& c = *coord[axis];
    std::stable_sort(ids.begin(), ids.end(),
                     [&](std::int32_t a, std::int32_t b) { return c[a] < c[b]; });
    double total = 0;
    for (std::int32_t i : ids) total += weight[static_cast<std::size_t>(i)];
    if (total <= 0) total = 1;
    double running = 0;
    for (std::int32_t i : ids) {
      const double w = weight[static_cast<std::size_t>(i)];
      const int k = std::min(
          parts - 1, static_cast<int>((running + 0.5 * w) / total * static_cast<double>(parts)));
      running += w;
      part(i, k);
    }
  };
  std::vector<std::vector<std::int32_t>> columns(static_cast<std::size_t>(plan.cuts[0]));
  cut(heads, 0, plan.cuts[0],
      [&](std::int32_t i, int k) { columns[static_cast<std::size_t>(k)].push_back(i); });
  for (int col = 0; col < plan.cuts[0]; ++col)
    cut(columns[static_cast<std::size_t>(col)], 1, plan.cuts[1],
        [&](std::int32_t i, int row) { plan.owner[i] = col * plan.cuts[1] + row; });
  for (const std::int32_t i : free) {
    const int r = plan.owner[static_cast<std::size_t>(head(static_cast<std::size_t>(i)))];
    plan.owner[i] = r;
    for (int a = 0; a < 2; ++a) {
      plan.lo[static_cast<std::size_t>(r)][a] =
          std::min(plan.lo[static_cast<std::size_t>(r)][a], (*coord[a])[i]);
      plan.hi[static_cast<std::size_t>(r)][a] =
          std::max(plan.hi[static_cast<std::size_t>(r)][a], (*coord[a])[i]);
    }
  }

  for (std::size_t r = 0; r < ranks; ++r) {
    std::vector<std::int32_t>& held = plan.held[r];
    const std::array<double, 2>& lo = plan.lo[r];
    const std::array<double, 2>& hi = plan.hi[r];
    // Along each cut axis: within the margin of the own particles' extent, and along a
    // periodic axis through the boundary too (the particle's images a period either
    // side). An axis that is not cut is the whole extent.
    auto near_along = [&](int a, double v) {
      if (plan.cuts[a] == 1) return true;
      auto within = [&](double u) { return u >= lo[a] - plan.margin && u <= hi[a] + plan.margin; };
      return within(v) ||
             (in.periodic[a] && (within(v - in.period[a]) || within(v + in.period[a])));
    };
    // A body is held whole where any of its members is: its members follow its pose.
    std::vector<std::uint8_t> hold(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto id = static_cast<std::int32_t>(i);
      const bool wall = in.motion[i] != Motion::Free;
      const bool own = plan.owner[i] == static_cast<int>(r);
      const bool near = lo[0] <= hi[0] && near_along(0, in.x[i]) && near_along(1, in.y[i]);
      if (wall || own || near || id == plan.cell_setter)
        hold[static_cast<std::size_t>(head(i))] = hold[i] = 1;
    }
    for (const auto& [a, b] : in.bonds) {
      if (plan.owner[static_cast<std::size_t>(a)] == static_cast<int>(r))
        hold[static_cast<std::size_t>(head(static_cast<std::size_t>(b)))] = 1;
      if (plan.owner[static_cast<std::size_t>(b)] == static_cast<int>(r))
        hold[static_cast<std::size_t>(head(static_cast<std::size_t>(a)))] = 1;
    }
    for (std::size_t i = 0; i < n; ++i)
      if (hold[i] || hold[static_cast<std::size_t>(head(i))])
        held.push_back(static_cast<std::int32_t>(i));
  }
  return plan;
}

}  // namespace tridem::mpi
