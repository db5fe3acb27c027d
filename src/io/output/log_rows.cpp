#include "io/output/log_rows.hpp"

#include "io/output/snapshot_check.hpp"

namespace tridem::io {

void write_energy_row(OutFile& out, const EnergyRow& r) {
  out.print("{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},", r.step, r.time, r.kinetic,
            r.momentum_x, r.momentum_y, r.angular_momentum);
  const EnergyBudget& b = r.budget;
  out.print("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", r.potential,
            b.elastic, b.dissipated_damping, b.dissipated_friction, b.dissipated_local, b.wall_work,
            r.total(), b.dissipated_fracture);
}

void write_measure_row(OutFile& out, const Measurement& m) {
  out.print("{},{:.17g},{:.17g},{},{},{},", m.step, m.time, m.area, m.particles, m.contacts,
            m.rattlers);
  out.print("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},", m.sxx, m.sxy, m.syx, m.syy,
            m.pressure, m.deviatoric);
  out.print("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", m.packing_fraction,
            m.coordination, m.mechanical_coordination, m.fabric_xx, m.fabric_xy, m.fabric_yy,
            m.mean_overlap, m.max_overlap);
}

void write_wall_rows(OutFile& out, const Snapshot& s) {
  check_snapshot(s, out.path().string());
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.motion[k] != Motion::Free)
      out.print("{},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", s.step,
                s.time, k, s.fx[k], s.fy[k], s.torque[k], s.x[k], s.y[k], s.vx[k], s.vy[k]);
}

}  // namespace tridem::io
