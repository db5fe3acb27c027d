// Reads back our own frames, for the renderer and for checks; any other VTU is refused
// with the reason rather than guessed at.
#include "io/output/vtk_xml_reader.hpp"
#include "tridem/bonds_reader.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

namespace tridem {
namespace {

[[noreturn]] void bad_frame(const std::filesystem::path& file, std::string_view why) {
  throw Error(fmt::format("cannot read '{}' as a tridem frame: {}", file.string(), why));
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(fmt::format("cannot open '{}': {}", file.string(), std::strerror(errno)));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw Error(fmt::format("cannot read '{}': {}", file.string(), std::strerror(errno)));
  return std::move(text).str();
}

std::size_t count_attribute(const std::filesystem::path& file,
                            const std::map<std::string, std::string>& piece,
                            const std::string& key) {
  const auto it = piece.find(key);
  if (it == piece.end()) bad_frame(file, fmt::format("<Piece> has no {}", key));
  std::size_t value = 0;
  const std::string& text = it->second;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    bad_frame(file, fmt::format("<Piece> {}=\"{}\" is not a count", key, text));
  return value;
}

/// Converts an integer-valued array, refusing fractions and values outside [lo, hi].
std::vector<std::int64_t> integers(const std::filesystem::path& file, std::string_view name,
                                   const std::vector<double>& values, double lo, double hi) {
  std::vector<std::int64_t> out(values.size());
  for (std::size_t k = 0; k < values.size(); ++k) {
    const double v = values[k];
    if (!(v >= lo && v <= hi) || std::trunc(v) != v)
      bad_frame(file, fmt::format("{}[{}] = {} is not an integer in [{}, {}]", name, k, v, lo, hi));
    out[k] = static_cast<std::int64_t>(v);
  }
  return out;
}

/// member_body and body_first from each cell's body (cell order: `ids` gives the triangle),
/// when some body has several triangles; a frame of lone triangles stays bodiless. The
/// members of a body are consecutive triangles (the scene's numbering), which is checked.
void read_members(const std::filesystem::path& file, Snapshot& s,
                  const std::vector<std::int64_t>& body, const std::vector<std::int64_t>& ids) {
  const std::size_t n = s.size();
  std::vector<std::int64_t> of(n);
  bool several = false;
  for (std::size_t cell = 0; cell < n; ++cell) of[static_cast<std::size_t>(ids[cell])] = body[cell];
  for (std::size_t k = 0; k < n; ++k) several = several || of[k] != static_cast<std::int64_t>(k);
  if (!several) return;
  s.member_body.resize(n);
  s.body_first.assign(1, 0);
  for (std::size_t k = 0; k < n; ++k) {
    const std::int64_t expected = static_cast<std::int64_t>(s.body_first.size()) - 1;
    if (k > 0 && of[k] == expected + 1) {
      s.body_first.push_back(static_cast<std::int64_t>(k));
    } else if (of[k] != expected) {
      bad_frame(file, fmt::format("triangle {} is in body {}, but the members of a body are "
                                  "consecutive triangles and bodies are numbered in their "
                                  "order (body {} or {} expected)",
                                  k, of[k], expected, expected + 1));
    }
    s.member_body[k] = static_cast<std::int32_t>(of[k]);
  }
  s.body_first.push_back(static_cast<std::int64_t>(n));
}

}  // namespace

Snapshot read_vtu_frame(const std::filesystem::path& file, ArraySet<FrameArray>* arrays) {
  const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), read_text(file));
  if (const auto it = f.root.find("type"); it == f.root.end() || it->second != "UnstructuredGrid")
    bad_frame(file, "it is not a VTK UnstructuredGrid file");
  const std::size_t n = count_attribute(file, f.piece, "NumberOfCells");
  const std::size_t points = count_attribute(file, f.piece, "NumberOfPoints");

  const auto array = [&](std::string_view section, std::string_view name, int components,
                         std::size_t tuples) {
    const io::XmlDataArray* a = io::find_array(f, section, name);
    if (!a) bad_frame(file, fmt::format("no array '{}' in <{}>", name, section));
    return io::decode_array(f, *a, components, tuples);
  };
  const auto cells = [&](std::string_view name, int components) {
    return array("CellData", name, components, n);
  };

  // Points may be unnamed in files from other writers; ours name it.
  const io::XmlDataArray* point_array = nullptr;
  for (const io::XmlDataArray& a : f.arrays)
    if (a.section == "Points" && !point_array) point_array = &a;
  if (!point_array) bad_frame(file, "no <Points> array");
  const std::vector<double> xyz = io::decode_array(f, *point_array, 3, points);

  const double max_point = points == 0 ? 0 : static_cast<double>(points - 1);
  const auto connectivity = integers(file, "connectivity",
                                     array("Cells", "connectivity", 1, 3 * n), 0, max_point);
  const auto offsets = integers(file, "offsets", array("Cells", "offsets", 1, n), 0,
                                static_cast<double>(3 * n));
  const auto types = integers(file, "types", array("Cells", "types", 1, n), 0, 255);
  for (std::size_t k = 0; k < n; ++k) {
    if (types[k] != 5) bad_frame(file, fmt::format("cell {} is not a triangle", k));
    if (offsets[k] != static_cast<std::int64_t>(3 * (k + 1)))
      bad_frame(file, fmt::format("cell {} does not have 3 points", k));
  }

  const double max_id = n == 0 ? 0 : static_cast<double>(n - 1);
  const auto ids = integers(file, "id", cells("id", 1), 0, max_id);
  // The real fields are the scene's choice (`[output] frame_arrays`): those left out read
  // as zeros, and `arrays` says which.
  ArraySet<FrameArray> held = ArraySet<FrameArray>::none();
  for (const auto& [name, a] : kFrameArrayNames)
    if (io::find_array(f, "CellData", name)) held.add(a);
  if (arrays) *arrays = held;
  const auto field = [&](FrameArray a, int components) {
    return held.has(a) ? cells(name_in(kFrameArrayNames, a), components)
                       : std::vector<double>(static_cast<std::size_t>(components) * n, 0.0);
  };
  const auto velocity = field(FrameArray::Velocity, 3);
  const auto omega = field(FrameArray::AngularVelocity, 1);
  const auto force = field(FrameArray::Force, 3);
  const auto torque = field(FrameArray::Torque, 1);
  const auto material = integers(file, "material", cells("material", 1), 0, 2147483647.0);
  const auto motion = integers(file, "motion", cells("motion", 1), 0, 2);
  // Frames written before bodies existed have no body array: each triangle its own body.
  std::vector<std::int64_t> body;
  if (io::find_array(f, "CellData", "body"))
    body = integers(file, "body", cells("body", 1), 0, max_id);

  Snapshot s;
  if (const io::XmlDataArray* a = io::find_array(f, "FieldData", "step"))
    s.step = integers(file, "step", io::decode_array(f, *a, 1, 1), -9.0e15, 9.0e15)[0];
  if (const io::XmlDataArray* a = io::find_array(f, "FieldData", "TimeValue"))
    s.time = io::decode_array(f, *a, 1, 1)[0];
  s.resize(n);
  std::vector<bool> seen(n, false);
  for (std::size_t cell = 0; cell < n; ++cell) {
    const auto k = static_cast<std::size_t>(ids[cell]);
    if (seen[k]) bad_frame(file, fmt::format("id {} appears twice", k));
    seen[k] = true;
    double* vertex[3][2] = {{&s.x1[k], &s.y1[k]}, {&s.x2[k], &s.y2[k]}, {&s.x3[k], &s.y3[k]}};
    for (int v = 0; v < 3; ++v) {
      const auto point = static_cast<std::size_t>(connectivity[3 * cell + v]);
      *vertex[v][0] = xyz[3 * point];
      *vertex[v][1] = xyz[3 * point + 1];
    }
    s.x[k] = (s.x1[k] + s.x2[k] + s.x3[k]) / 3;
    s.y[k] = (s.y1[k] + s.y2[k] + s.y3[k]) / 3;
    s.vx[k] = velocity[3 * cell];
    s.vy[k] = velocity[3 * cell + 1];
    s.omega[k] = omega[cell];
    s.fx[k] = force[3 * cell];
    s.fy[k] = force[3 * cell + 1];
    s.torque[k] = torque[cell];
    s.material[k] = static_cast<int>(material[cell]);
    s.motion[k] = static_cast<Motion>(motion[cell]);
  }
  if (!body.empty()) read_members(file, s, body, ids);
  return s;
}

void read_bonds_vtp(const std::filesystem::path& file, Snapshot& s) {
  const io::VtkXmlFile f = io::parse_vtk_xml(file.string(), read_text(file));
  if (const auto it = f.root.find("type"); it == f.root.end() || it->second != "PolyData")
    bad_frame(file, "it is not a VTK PolyData file");
  const std::size_t m = count_attribute(file, f.piece, "NumberOfLines");
  const auto array = [&](std::string_view section, std::string_view name, int components,
                         std::size_t tuples) {
    const io::XmlDataArray* a = io::find_array(f, section, name);
    if (!a) bad_frame(file, fmt::format("no array '{}' in <{}>", name, section));
    return io::decode_array(f, *a, components, tuples);
  };
  const std::vector<double> xyz = array("Points", "Points", 3, 2 * m);
  const std::vector<double> damage = array("CellData", "damage", 1, m);
  const auto broken = integers(file, "broken", array("CellData", "broken", 1, m), 0, 1);
  const auto a = integers(file, "a", array("CellData", "a", 1, m), 0, 2147483647.0);
  const auto b = integers(file, "b", array("CellData", "b", 1, m), 0, 2147483647.0);
  s.bond_a.resize(m);
  s.bond_b.resize(m);
  s.bond_broken.resize(m);
  s.bond_damage = damage;
  for (auto* v : {&s.bond_x0, &s.bond_y0, &s.bond_x1, &s.bond_y1}) v->resize(m);
  for (std::size_t k = 0; k < m; ++k) {
    s.bond_a[k] = static_cast<std::int32_t>(a[k]);
    s.bond_b[k] = static_cast<std::int32_t>(b[k]);
    s.bond_broken[k] = static_cast<std::uint8_t>(broken[k]);
    s.bond_x0[k] = xyz[6 * k];
    s.bond_y0[k] = xyz[6 * k + 1];
    s.bond_x1[k] = xyz[6 * k + 3];
    s.bond_y1[k] = xyz[6 * k + 4];
  }
}

}  // namespace tridem
