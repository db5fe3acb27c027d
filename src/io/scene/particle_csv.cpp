// Reading triangles from a CSV file: columns by the names of the header, so that a run's
// final.csv (whatever columns later versions append that the reader knows) reads as is.
#include "io/scene/imported_particles.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <string_view>

namespace tridem::scene_detail {
namespace {

constexpr std::array<std::string_view, 6> kVertexColumns{"x1", "y1", "x2", "y2", "x3", "y3"};
constexpr std::array<std::string_view, 4> kOptionalColumns{"vx", "vy", "omega", "body"};
// final.csv's pose columns: the vertices already hold the pose.
constexpr std::array<std::string_view, 4> kUnusedColumns{"id", "x", "y", "theta"};

std::vector<std::string_view> split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    std::string_view cell =
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    while (!cell.empty() && (cell.front() == ' ' || cell.front() == '\t')) cell.remove_prefix(1);
    while (!cell.empty() && (cell.back() == ' ' || cell.back() == '\t' || cell.back() == '\r'))
      cell.remove_suffix(1);
    out.push_back(cell);
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

template <std::size_t N>
bool one_of(std::string_view name, const std::array<std::string_view, N>& names) {
  for (std::string_view n : names)
    if (n == name) return true;
  return false;
}

}  // namespace

ImportedParticles read_particle_csv(const std::filesystem::path& file) {
  const std::string name = file.string();
  // A regular file only: a device or pipe (/dev/zero, a FIFO) could be read forever.
  std::error_code fs_error;
  if (!std::filesystem::is_regular_file(file, fs_error))
    throw SceneError(fmt::format("{}: cannot open the particle file: {}", name,
                                 std::filesystem::exists(file, fs_error) ? "not a regular file"
                                                                         : "no such file"));
  std::ifstream in(file);
  if (!in) throw SceneError(fmt::format("{}: cannot open the particle file", name));
  std::string line;
  std::size_t line_number = 0;
  auto refuse = [&](const std::string& what) -> void {
    throw SceneError(fmt::format("{}:{}: {}", name, line_number, what));
  };
  // Header: the first line that is not empty.
  while (line.empty() && std::getline(in, line)) ++line_number;
  if (line.empty()) refuse("the file is empty: expected a header x1,y1,x2,y2,x3,y3,...");
  const std::vector<std::string_view> header = split(line);
  std::vector<std::optional<std::size_t>> vertex_at(6), optional_at(4);
  std::vector<std::string> header_names(header.begin(), header.end());
  for (std::size_t c = 0; c < header.size(); ++c) {
    const std::string_view h = header[c];
    bool known = one_of(h, kUnusedColumns);
    for (std::size_t k = 0; k < 6; ++k)
      if (h == kVertexColumns[k]) {
        if (vertex_at[k]) refuse(fmt::format("column '{}' appears twice", h));
        vertex_at[k] = c;
        known = true;
      }
    for (std::size_t k = 0; k < 4; ++k)
      if (h == kOptionalColumns[k]) {
        if (optional_at[k]) refuse(fmt::format("column '{}' appears twice", h));
        optional_at[k] = c;
        known = true;
      }
    if (!known)
      refuse(fmt::format("unknown column '{}' (expected x1, y1, x2, y2, x3, y3 and optionally "
                         "vx, vy, omega, body; id, x, y, theta are read and not used)",
                         h));
  }
  for (std::size_t k = 0; k < 6; ++k)
    if (!vertex_at[k])
      refuse(fmt::format("the header lacks column '{}' (the vertices x1,y1,x2,y2,x3,y3 are "
                         "required)",
                         kVertexColumns[k]));

  ImportedParticles out;
  while (std::getline(in, line)) {
    ++line_number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string_view> cells = split(line);
    if (cells.size() != header.size())
      refuse(fmt::format("{} values for the header's {} columns", cells.size(), header.size()));
    auto number = [&](std::size_t c) {
      double v = 0;
      const std::string_view cell = cells[c];
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
      if (ec != std::errc{} || end != cell.data() + cell.size() || !std::isfinite(v))
        refuse(fmt::format("column '{}': expected a finite number, got \"{}\"", header_names[c],
                           cell));
      return v;
    };
    std::array<Vec2d, 3> v{};
    for (std::size_t k = 0; k < 3; ++k)
      v[k] = {number(*vertex_at[2 * k]), number(*vertex_at[2 * k + 1])};
    out.vertices.push_back(v);
    out.velocity.push_back({optional_at[0] ? number(*optional_at[0]) : 0.0,
                            optional_at[1] ? number(*optional_at[1]) : 0.0});
    out.angular_velocity.push_back(optional_at[2] ? number(*optional_at[2]) : 0.0);
    std::int64_t body = -1;
    if (optional_at[3]) {
      const std::string_view cell = cells[*optional_at[3]];
      const auto [end, ec] = std::from_chars(cell.data(), cell.data() + cell.size(), body);
      if (ec != std::errc{} || end != cell.data() + cell.size() || body < 0)
        refuse(fmt::format("column 'body': expected an integer >= 0, got \"{}\"", cell));
    }
    out.body.push_back(body);
    out.where.push_back(line_number);
  }
  if (out.vertices.empty()) refuse("the file has a header but no triangles");
  return out;
}

}  // namespace tridem::scene_detail
