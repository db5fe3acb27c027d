// [simulation] periodic_x, periodic_y and shear_rate: the periodic cell and its
// Lees-Edwards shear (docs/scene-format.md, "Periodic boundaries").
#include "io/scene/scene_sections.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tridem::scene_detail {

std::optional<std::string> periodic_cell_problem(const PeriodicCell& cell, std::string& key) {
  for (const auto& [name, range] :
       {std::pair{"periodic_x", cell.x}, std::pair{"periodic_y", cell.y}}) {
    if (!range) continue;
    key = name;
    if (!(std::isfinite(range->lo) && std::isfinite(range->hi) && range->lo < range->hi))
      return fmt::format("must be [lo, hi] with finite lo < hi (the cell's two sides), got "
                         "[{}, {}]",
                         range->lo, range->hi);
  }
  key = "shear_rate";
  if (!std::isfinite(cell.shear_rate))
    return fmt::format("must be finite (1/s), got {}", cell.shear_rate);
  if (cell.shear_rate != 0 && !(cell.x && cell.y))
    return "sets Lees-Edwards shear, which needs both periodic_x and periodic_y (the shear "
           "moves the images across y along x)";
  return std::nullopt;
}

PeriodicCell parse_periodic_cell(TableReader& r) {
  PeriodicCell cell;
  for (const auto& [name, range] :
       {std::pair{"periodic_x", &cell.x}, std::pair{"periodic_y", &cell.y}}) {
    const auto v = r.reals(name);
    if (!v) continue;
    if (v->size() != 2)
      r.fail(name, fmt::format("expected [lo, hi], two numbers, got {} of them", v->size()));
    *range = PeriodicRange{(*v)[0], (*v)[1]};
  }
  cell.shear_rate = r.real("shear_rate").value_or(0.0);
  std::string key;
  if (auto why = periodic_cell_problem(cell, key)) r.fail(key, *why);
  return cell;
}

}  // namespace tridem::scene_detail
