// The cohesive bonds' outputs (docs/output-format.md, docs/fracture.md): per frame, the
// bonds as a line set along their shared edges with their damage and broken flag as cell
// data (ParaView: colour by damage; cracks are the broken lines), and bonds.csv's rows.
#include "io/output/exact_number.hpp"
#include "io/output/log_rows.hpp"
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_frames.hpp"
#include "tridem/output.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

namespace io {

void write_bonds_vtp(VtkXmlWriter& w, const std::filesystem::path& file, const Snapshot& s) {
  check_snapshot(s, file.string());
  const std::size_t m = s.bond_a.size();
  // Segment k joins points 2k and 2k + 1, the ends of bond k's edge.
  const auto at = [](const std::vector<double>& first, const std::vector<double>& second) {
    return [&first, &second](std::size_t p) { return p % 2 == 0 ? first[p / 2] : second[p / 2]; };
  };
  w.line_set_vtp(
      file, s.step, s.time, 2 * m, at(s.bond_x0, s.bond_x1), at(s.bond_y0, s.bond_y1), m,
      [](std::size_t k) { return static_cast<std::int64_t>(2 * k); },
      [](std::size_t k) { return static_cast<std::int64_t>(2 * k + 1); }, "Scalars=\"damage\"",
      [&](OutFile& out) {
        w.reals(out, "damage", s.bond_damage, 8);
        w.reals(
            out, "broken", 1, m,
            [&](std::size_t k) { return static_cast<double>(s.bond_broken[k]); }, 8);
        w.integers<std::int64_t>(
            out, "a", 1, m, [&](std::size_t k) { return s.bond_a[k]; }, 8);
        w.integers<std::int64_t>(
            out, "b", 1, m, [&](std::size_t k) { return s.bond_b[k]; }, 8);
      });
}

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
  out.print("{},{},{},{},{},{}\n", s.step, io::Exact{s.time}, intact, damaged, broken,
            io::Exact{fracture_energy});
}

}  // namespace io

void write_bonds_vtp(const std::filesystem::path& file, const Snapshot& s, VtkFormat format) {
  io::VtkXmlWriter w(format);
  io::write_bonds_vtp(w, file, s);
}

}  // namespace tridem
