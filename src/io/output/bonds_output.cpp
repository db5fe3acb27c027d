// The cohesive bonds' outputs (docs/output-format.md, docs/fracture.md): per frame, the
// bonds as a line set along their shared edges with their damage and broken flag as cell
// data (ParaView: colour by damage; cracks are the broken lines), and bonds.csv's rows.
#include "io/output/log_rows.hpp"
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_xml_writer.hpp"
#include "tridem/output.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

void write_bonds_vtp(const std::filesystem::path& file, const Snapshot& s, Encoding encoding) {
  io::check_snapshot(s, file.string());
  const std::size_t m = s.bond_a.size();
  std::vector<double> points(6 * m), damage(m), broken(m);
  std::vector<std::int64_t> a(m), b(m);
  for (std::size_t k = 0; k < m; ++k) {
    points[6 * k] = s.bond_x0[k];
    points[6 * k + 1] = s.bond_y0[k];
    points[6 * k + 3] = s.bond_x1[k];
    points[6 * k + 4] = s.bond_y1[k];
    damage[k] = s.bond_damage[k];
    broken[k] = s.bond_broken[k];
    a[k] = s.bond_a[k];
    b[k] = s.bond_b[k];
  }
  io::write_line_set_vtp(file, s.step, s.time, points, "Scalars=\"damage\"", encoding,
                         [&](io::OutFile& out) {
                           io::write_data_array<double>(out, "damage", damage, 1, encoding, 8);
                           io::write_data_array<double>(out, "broken", broken, 1, encoding, 8);
                           io::write_data_array<std::int64_t>(out, "a", a, 1, encoding, 8);
                           io::write_data_array<std::int64_t>(out, "b", b, 1, encoding, 8);
                         });
}

namespace io {

void write_bond_row(OutFile& out, const Snapshot& s, double fracture_energy) {
  std::size_t intact = 0, damaged = 0, broken = 0;
  for (std::size_t k = 0; k < s.bond_a.size(); ++k) {
    if (s.bond_broken[k])
      ++broken;
    else if (s.bond_damage[k] > 0)
      ++damaged;
    else
      ++intact;
  }
  out.print("{},{:.17g},{},{},{},{:.17g}\n", s.step, s.time, intact, damaged, broken,
            fracture_energy);
}

}  // namespace io
}  // namespace tridem
