#include "io/output/log_rows.hpp"

#include "io/output/exact_number.hpp"
#include "io/output/snapshot_check.hpp"

namespace tridem::io {

// The logs' numbers as every CSV prints them (exact_number.hpp: the shortest text that
// reads back the same double).
void write_energy_row(OutFile& out, const EnergyRow& r) {
  const EnergyBudget& b = r.budget;
  out.print("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", r.step, Exact{r.time}, Exact{r.kinetic},
            Exact{r.momentum_x}, Exact{r.momentum_y}, Exact{r.angular_momentum}, Exact{r.potential},
            Exact{b.elastic}, Exact{b.dissipated_damping}, Exact{b.dissipated_friction},
            Exact{b.dissipated_local}, Exact{b.wall_work}, Exact{r.total()},
            Exact{b.dissipated_fracture});
}

void write_measure_row(OutFile& out, const Measurement& m) {
  out.print("{},{},{},{},{},{},", m.step, Exact{m.time}, Exact{m.area}, m.particles, m.contacts,
            m.rattlers);
  out.print("{},{},{},{},{},{},", Exact{m.sxx}, Exact{m.sxy}, Exact{m.syx}, Exact{m.syy},
            Exact{m.pressure}, Exact{m.deviatoric});
  out.print("{},{},{},{},{},{},{},{}\n", Exact{m.packing_fraction}, Exact{m.coordination},
            Exact{m.mechanical_coordination}, Exact{m.fabric_xx}, Exact{m.fabric_xy},
            Exact{m.fabric_yy}, Exact{m.mean_overlap}, Exact{m.max_overlap});
}

void write_wall_rows(OutFile& out, const Snapshot& s) {
  check_snapshot(s, out.path().string());
  for (std::size_t k = 0; k < s.size(); ++k)
    if (s.motion[k] != Motion::Free)
      out.print("{},{},{},{},{},{},{},{},{},{}\n", s.step, Exact{s.time}, k, Exact{s.fx[k]},
                Exact{s.fy[k]}, Exact{s.torque[k]}, Exact{s.x[k]}, Exact{s.y[k]}, Exact{s.vx[k]},
                Exact{s.vy[k]});
}

}  // namespace tridem::io
