#include "io/output/snapshot_check.hpp"
#include "tridem/output.hpp"

namespace tridem {

double EnergyRow::total() const {
  return kinetic + potential + budget.elastic + budget.dissipated_damping +
         budget.dissipated_friction + budget.dissipated_local + budget.dissipated_fracture -
         budget.wall_work;
}

EnergyRow compute_energy(const Snapshot& s, Vec2d gravity, const EnergyBudget& budget) {
  io::check_snapshot(s, "energy.csv");
  EnergyRow row;
  row.step = s.step;
  row.time = s.time;
  row.budget = budget;
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s.motion[k] != Motion::Free) continue;
    const double m = s.mass[k], inertia = s.inertia[k];
    const double vx = s.vx[k], vy = s.vy[k], w = s.omega[k];
    row.kinetic += 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * w * w;
    row.momentum_x += m * vx;
    row.momentum_y += m * vy;
    // Orbital part about the origin plus spin about the centroid.
    row.angular_momentum += m * (s.x[k] * vy - s.y[k] * vx) + inertia * w;
    row.potential -= m * (gravity.x * s.x[k] + gravity.y * s.y[k]);
  }
  return row;
}

}  // namespace tridem
