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

void write_wall_rows(OutFile& out, const Snapshot& s) {
  check_snapshot(s, out.path().string());
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.motion[k] != Motion::Free)
      out.print("{},{:.17g},{},{:.17g},{:.17g},{:.17g}\n", s.step, s.time, k, s.fx[k], s.fy[k],
                s.torque[k]);
}

}  // namespace tridem::io
