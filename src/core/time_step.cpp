#include "core/time_step.hpp"

#include "tridem/error.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <vector>

namespace tridem {

TimeStep estimate_time_step(const Scene& scene, const ParticleModel& model) {
  // The stiffest contact a free particle can meet: its material against any material
  // present (pairs of two walls never interact).
  const std::size_t n_mat = scene.materials.size();
  std::vector<char> free_material(n_mat, 0), present(n_mat, 0);
  for (std::size_t i = 0; i < model.size(); ++i) {
    present[model.material[i]] = 1;
    if (model.motion[i] == Motion::Free) free_material[model.material[i]] = 1;
  }
  const auto laws = contact_law_table(scene.materials);
  double p_max = 0;
  for (std::size_t a = 0; a < n_mat; ++a)
    for (std::size_t b = 0; b < n_mat; ++b)
      if (free_material[a] && present[b]) p_max = std::max(p_max, laws[a * n_mat + b].penalty);
  double l_max = 0, h_min = std::numeric_limits<double>::infinity();
  double m_min = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (model.motion[i] != Motion::Free) continue;
    l_max = std::max(l_max, model.longest_edge[i]);
    h_min = std::min(h_min, model.smallest_height[i]);
    double r2_max = 0;
    for (const Vec2d& r : model.offsets[i]) r2_max = std::max(r2_max, dot(r, r));
    m_min = std::min({m_min, model.mass[i], model.inertia[i] / r2_max});
  }
  TimeStep ts;
  if (l_max > 0) {
    const double stiffness = 3.0 * p_max * l_max / h_min;
    ts.critical = 2.0 * std::sqrt(m_min / stiffness);
  } else {
    ts.critical = std::numeric_limits<double>::infinity();
  }
  ts.automatic = !scene.simulation.dt.has_value();
  if (!ts.automatic) {
    ts.chosen = *scene.simulation.dt;
  } else if (std::isfinite(ts.critical)) {
    ts.chosen = scene.simulation.safety * ts.critical;
  } else {
    throw SceneError(fmt::format(
        "{}: [simulation] dt: no free particle to estimate a time step from; give dt",
        scene.source));
  }
  return ts;
}

void check_time_step(const Scene& scene, const TimeStep& ts, bool force) {
  if (ts.automatic || force || ts.chosen <= ts.critical) return;
  throw RunError(fmt::format(
      "{}: [simulation] dt = {:g} s is above the stability limit dt_crit = {:g} s "
      "(ratio {:.3g}); use dt <= {:g} (safety 0.1), leave dt out for an automatic step, "
      "or pass --force to run anyway",
      scene.source, ts.chosen, ts.critical, ts.chosen / ts.critical, 0.1 * ts.critical));
}

}  // namespace tridem
