// Frames for ParaView: one triangle cell per particle over its own three points, so a
// frame needs no connectivity between particles and cell data maps one-to-one to ids.
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_xml_writer.hpp"
#include "tridem/measurements.hpp"
#include "tridem/output.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <span>
#include <vector>

namespace tridem {
namespace {

constexpr std::uint8_t kVtkTriangle = 5;

std::vector<double> interleave3(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> out(3 * a.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    out[3 * k] = a[k];
    out[3 * k + 1] = b[k];
  }
  return out;
}

}  // namespace

void write_vtu_frame(const std::filesystem::path& file, const Snapshot& s, Encoding encoding,
                     bool with_grain_stress) {
  io::check_snapshot(s, file.string());
  io::check_bodies(s, file.string(), /*members_only=*/s.body_x.empty());
  const std::size_t n = s.size();

  std::vector<double> points(9 * n);
  for (std::size_t k = 0; k < n; ++k) {
    const double xy[6] = {s.x1[k], s.y1[k], s.x2[k], s.y2[k], s.x3[k], s.y3[k]};
    for (int v = 0; v < 3; ++v) {
      points[9 * k + 3 * v] = xy[2 * v];
      points[9 * k + 3 * v + 1] = xy[2 * v + 1];
    }
  }
  std::vector<std::int64_t> connectivity(3 * n), offsets(n), ids(n), body(n);
  for (std::size_t k = 0; k < 3 * n; ++k) connectivity[k] = static_cast<std::int64_t>(k);
  for (std::size_t k = 0; k < n; ++k) {
    offsets[k] = static_cast<std::int64_t>(3 * (k + 1));
    ids[k] = static_cast<std::int64_t>(k);
    body[k] = s.body_of(k);
  }
  const std::vector<std::uint8_t> types(n, kVtkTriangle);
  std::vector<std::int32_t> material(n), motion(n);
  for (std::size_t k = 0; k < n; ++k) {
    material[k] = s.material[k];
    motion[k] = static_cast<std::int32_t>(s.motion[k]);
  }

  io::OutFile out(file);
  io::begin_vtk_file(out, "UnstructuredGrid");
  out.write("  <UnstructuredGrid>\n");
  io::write_time_field_data(out, s.step, s.time, encoding, 4);
  out.print("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", 3 * n, n);
  out.write("      <Points>\n");
  io::write_data_array<double>(out, "Points", points, 3, encoding, 8);
  out.write("      </Points>\n      <Cells>\n");
  io::write_data_array<std::int64_t>(out, "connectivity", connectivity, 1, encoding, 8);
  io::write_data_array<std::int64_t>(out, "offsets", offsets, 1, encoding, 8);
  io::write_data_array<std::uint8_t>(out, "types", types, 1, encoding, 8);
  out.write("      </Cells>\n      <CellData Scalars=\"angular_velocity\" Vectors=\"velocity\">\n");
  io::write_data_array<std::int64_t>(out, "id", ids, 1, encoding, 8);
  io::write_data_array<double>(out, "velocity", interleave3(s.vx, s.vy), 3, encoding, 8);
  io::write_data_array<double>(out, "angular_velocity", s.omega, 1, encoding, 8);
  io::write_data_array<double>(out, "force", interleave3(s.fx, s.fy), 3, encoding, 8);
  io::write_data_array<double>(out, "torque", s.torque, 1, encoding, 8);
  io::write_data_array<std::int32_t>(out, "material", material, 1, encoding, 8);
  io::write_data_array<std::int32_t>(out, "motion", motion, 1, encoding, 8);
  // The body of each triangle (its own id when it is a body of one member): ParaView
  // colours by it, and `tridem render --color body` reads it back.
  io::write_data_array<std::int64_t>(out, "body", body, 1, encoding, 8);
  // Each grain's own Love-Weber stress and contact count (tridem/measurements.hpp), on
  // every triangle of the grain; zeros where the snapshot holds no contacts (step 0).
  // Left out without the contacts: a frame would otherwise show zeros for every grain.
  if (with_grain_stress) {
    const GrainStress grain = grain_stress(s);
    std::vector<double> stress(9 * n), pressure(n);
    std::vector<std::int32_t> coordination(n);
    for (std::size_t k = 0; k < n; ++k) {
      const auto g = static_cast<std::size_t>(body[k]);
      stress[9 * k] = grain.sxx[g];
      stress[9 * k + 1] = grain.sxy[g];
      stress[9 * k + 3] = grain.syx[g];
      stress[9 * k + 4] = grain.syy[g];
      pressure[k] = 0.5 * (grain.sxx[g] + grain.syy[g]);
      coordination[k] = grain.coordination[g];
    }
    io::write_data_array<double>(out, "stress", stress, 9, encoding, 8);
    io::write_data_array<double>(out, "pressure", pressure, 1, encoding, 8);
    io::write_data_array<std::int32_t>(out, "coordination", coordination, 1, encoding, 8);
  }
  out.write("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n");
  io::end_vtk_file(out);
  out.close();
}

}  // namespace tridem
