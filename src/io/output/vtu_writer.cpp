// Frames for ParaView: one triangle cell per particle over its own three points, so a
// frame needs no connectivity between particles and cell data maps one-to-one to ids.
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_frames.hpp"
#include "tridem/measurements.hpp"
#include "tridem/output.hpp"

#include <fmt/format.h>

#include <cstdint>

namespace tridem {
namespace io {
namespace {

constexpr std::uint8_t kVtkTriangle = 5;

/// (a, b, 0) of each particle, for a vector array of 3 components.
auto planar(const std::vector<double>& a, const std::vector<double>& b) {
  return [&a, &b](std::size_t k) {
    const std::size_t i = k / 3;
    return k % 3 == 0 ? a[i] : k % 3 == 1 ? b[i] : 0.0;
  };
}

}  // namespace

void write_vtu_frame(VtkXmlWriter& w, const std::filesystem::path& file, const Snapshot& s,
                     bool with_grain_stress, ArraySet<FrameArray> arrays) {
  check_snapshot(s, file.string());
  check_bodies(s, file.string(), /*members_only=*/s.body_x.empty());
  const std::size_t n = s.size();
  const std::vector<double>* vertex[6] = {&s.x1, &s.y1, &s.x2, &s.y2, &s.x3, &s.y3};
  const auto index = [](std::size_t k) { return static_cast<std::int64_t>(k); };

  OutFile out(file);
  w.begin_file(out, "UnstructuredGrid");
  out.write("  <UnstructuredGrid>\n");
  w.time_field_data(out, s.step, s.time, 4);
  out.print("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", 3 * n, n);
  out.write("      <Points>\n");
  // Point 3i + v is vertex v of particle i: x, y, 0.
  w.reals(
      out, "Points", 3, 9 * n,
      [&](std::size_t k) {
        const std::size_t i = k / 9, r = k % 9;
        return r % 3 == 2 ? 0.0 : (*vertex[2 * (r / 3) + r % 3])[i];
      },
      8);
  out.write("      </Points>\n      <Cells>\n");
  w.indices(out, "connectivity", 1, 3 * n, 3 * n, index, 8);
  w.indices(
      out, "offsets", 1, n, 3 * n,
      [](std::size_t k) { return static_cast<std::int64_t>(3 * (k + 1)); }, 8);
  w.integers<std::uint8_t>(
      out, "types", 1, n, [](std::size_t) { return kVtkTriangle; }, 8);
  // The active scalars and vectors ParaView colours by first, where the frame has them.
  out.print("      </Cells>\n      <CellData{}{}>\n",
            arrays.has(FrameArray::AngularVelocity) ? " Scalars=\"angular_velocity\"" : "",
            arrays.has(FrameArray::Velocity) ? " Vectors=\"velocity\"" : "");
  w.indices(out, "id", 1, n, n, index, 8);
  if (arrays.has(FrameArray::Velocity)) w.reals(out, "velocity", 3, 3 * n, planar(s.vx, s.vy), 8);
  if (arrays.has(FrameArray::AngularVelocity)) w.reals(out, "angular_velocity", s.omega, 8);
  if (arrays.has(FrameArray::Force)) w.reals(out, "force", 3, 3 * n, planar(s.fx, s.fy), 8);
  if (arrays.has(FrameArray::Torque)) w.reals(out, "torque", s.torque, 8);
  w.integers<std::int32_t>(
      out, "material", 1, n, [&](std::size_t k) { return s.material[k]; }, 8);
  w.integers<std::int32_t>(
      out, "motion", 1, n, [&](std::size_t k) { return static_cast<std::int32_t>(s.motion[k]); },
      8);
  // The body of each triangle (its own id when it is a body of one member): ParaView
  // colours by it, and `tridem render --color body` reads it back.
  w.indices(
      out, "body", 1, n, n, [&](std::size_t k) { return s.body_of(k); }, 8);
  // Each grain's own Love-Weber stress and contact count (tridem/measurements.hpp), on
  // every triangle of the grain; zeros where the snapshot holds no contacts (step 0).
  // Left out without the contacts: a frame would otherwise show zeros for every grain.
  const bool stress = arrays.has(FrameArray::Stress), pressure = arrays.has(FrameArray::Pressure),
             coordination = arrays.has(FrameArray::Coordination);
  if (with_grain_stress && (stress || pressure || coordination)) {
    const GrainStress grain = grain_stress(s);
    const auto g = [&](std::size_t i) { return static_cast<std::size_t>(s.body_of(i)); };
    // Row-major 3×3: sxx, sxy, 0, syx, syy, 0, 0, 0, 0.
    const std::vector<double>* tensor[5] = {&grain.sxx, &grain.sxy, nullptr, &grain.syx,
                                            &grain.syy};
    if (stress)
      w.reals(
          out, "stress", 9, 9 * n,
          [&](std::size_t k) {
            const std::size_t r = k % 9;
            return r < 5 && tensor[r] ? (*tensor[r])[g(k / 9)] : 0.0;
          },
          8);
    if (pressure)
      w.reals(
          out, "pressure", 1, n,
          [&](std::size_t k) { return 0.5 * (grain.sxx[g(k)] + grain.syy[g(k)]); }, 8);
    if (coordination)
      w.integers<std::int32_t>(
          out, "coordination", 1, n, [&](std::size_t k) { return grain.coordination[g(k)]; }, 8);
  }
  out.write("      </CellData>\n    </Piece>\n  </UnstructuredGrid>\n");
  w.end_file(out);
}

}  // namespace io

void write_vtu_frame(const std::filesystem::path& file, const Snapshot& s, VtkFormat format,
                     bool with_grain_stress, ArraySet<FrameArray> arrays) {
  io::VtkXmlWriter w(format);
  io::write_vtu_frame(w, file, s, with_grain_stress, arrays);
}

}  // namespace tridem
