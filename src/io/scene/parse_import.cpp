// [[import]] blocks: triangles read from a CSV file (a run's final.csv among them) or a
// Gmsh mesh, with the grouping into bodies the file gives (a CSV's body column, a mesh's
// physical groups named in `bodies`).
#include "io/scene/generator_checks.hpp"
#include "io/scene/imported_particles.hpp"
#include "io/scene/scene_sections.hpp"
#include "io/scene/triangle_shape.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <unordered_map>
#include <utility>

namespace tridem::scene_detail {
namespace {

enum class Format { Csv, Gmsh };
constexpr std::array<std::pair<std::string_view, Format>, 2> kFormatNames{
    {{"csv", Format::Csv}, {"gmsh", Format::Gmsh}}};

// A relative path is taken from the scene file's folder, so that a scene and its data
// can be moved together.
std::filesystem::path resolve(const std::string& scene_source, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_absolute()) return p;
  return std::filesystem::path(scene_source).parent_path() / p;
}

std::vector<std::string> read_group_names(TableReader& r) {
  std::vector<std::string> names;
  const toml::node* n = r.node("bodies");
  if (!n) return names;
  const toml::array* array = n->as_array();
  if (!array)
    r.fail("bodies", fmt::format("expected an array of physical group names [\"name\", ...], "
                                 "got {}",
                                 describe_type(n->type())));
  for (const toml::node& element : *array) {
    const auto* s = element.as_string();
    if (!s || s->get().empty())
      r.fail_at(element, "bodies", "expected the name of a physical group (a non-empty string)");
    names.push_back(s->get());
  }
  return names;
}

double area_of(const std::array<Vec2d, 3>& v) { return 0.5 * std::abs(twice_signed_area(v)); }

}  // namespace

bool parse_import(const toml::table& table, const std::string& source, std::size_t number,
                  const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                  std::vector<BodySpec>& bodies) {
  TableReader r(table, source,
                fmt::format("[[import]] #{} (particle ids from {})", number, out.size()));
  const std::string file = r.required(r.string("file"), "file");
  if (file.empty()) r.fail("file", "must name a file");
  const std::filesystem::path path = resolve(source, file);
  std::optional<Format> format = r.choice_in<Format>("format", kFormatNames);
  if (!format) {
    const std::string ext = path.extension().string();
    if (ext == ".csv")
      format = Format::Csv;
    else if (ext == ".msh")
      format = Format::Gmsh;
    else
      r.fail("file", fmt::format("cannot tell the format from the extension \"{}\": give "
                                 "format = \"csv\" or \"gmsh\"",
                                 ext));
  }
  const int material = lookup_material(r, materials);
  const bool fixed = r.boolean("fixed").value_or(false);
  const bool keep_overlaps = r.boolean("keep_overlaps").value_or(false);
  const std::vector<std::string> groups = read_group_names(r);
  if (!groups.empty() && *format != Format::Gmsh)
    r.fail("bodies", "applies only to a Gmsh mesh; a CSV file groups bodies by its body column");
  r.reject_unknown_keys();

  ImportedParticles in;
  try {
    in = *format == Format::Csv ? read_particle_csv(path) : read_gmsh_mesh(path, groups);
  } catch (const SceneError& e) {
    r.fail("file", e.what());
  }
  const std::size_t n = in.vertices.size();
  if (n > kMaxGeneratedTriangles)
    r.fail("file",
           fmt::format("holds {} triangles, more than the limit of {}", n, kMaxGeneratedTriangles));
  if (const std::string why = memory_shortfall(out.size() + n, available_memory_bytes());
      !why.empty())
    r.fail("file", why);
  auto refuse_at = [&](std::size_t k, const std::string& what) {
    r.fail("file", fmt::format("{} {} of {}: {}", in.where_name, in.where[k], path.string(), what));
  };

  // Bodies in the order of their first triangle; a lone triangle is a body of its own.
  std::vector<std::vector<std::size_t>> units;
  std::unordered_map<std::int64_t, std::size_t> unit_of;
  for (std::size_t k = 0; k < n; ++k) {
    if (in.body[k] < 0) {
      units.push_back({k});
      continue;
    }
    const auto [it, fresh] = unit_of.emplace(in.body[k], units.size());
    if (fresh) units.emplace_back();
    units[it->second].push_back(k);
  }
  const Motion motion = fixed ? Motion::Fixed : Motion::Free;
  for (const std::vector<std::size_t>& members : units) {
    // The body's velocity is the area-weighted mean of its members' (v_k = V + ω × r_k and
    // Σ A_k r_k = 0 about the centroid); all members turn at one ω.
    double area = 0;
    Vec2d momentum{};
    const double omega = in.angular_velocity[members.front()];
    for (std::size_t k : members) {
      if (auto problem = shape_problem(in.vertices[k])) refuse_at(k, *problem);
      const double tolerance = 1e-9 * std::max(1.0, std::abs(omega));
      if (std::abs(in.angular_velocity[k] - omega) > tolerance)
        refuse_at(k, fmt::format("its omega {} differs from {} of the first triangle of its body "
                                 "{} (a body turns as one)",
                                 in.angular_velocity[k], omega, in.body[k]));
      if (fixed && (in.velocity[k].x != 0 || in.velocity[k].y != 0 || in.angular_velocity[k] != 0))
        refuse_at(k, "fixed = true, but the file gives it a velocity (remove fixed, or the "
                     "vx, vy, omega columns)");
      area += area_of(in.vertices[k]);
      momentum += in.velocity[k] * area_of(in.vertices[k]);
    }
    BodySpec body{out.size(), members.size(), momentum / area, omega, motion};
    for (std::size_t k : members) {
      TriangleSpec t;
      t.material = material;
      t.vertices = in.vertices[k];
      make_counter_clockwise(t.vertices);
      t.motion = motion;
      if (members.size() == 1) {
        t.velocity = in.velocity[k];
        t.angular_velocity = in.angular_velocity[k];
        body.velocity = t.velocity;
      }
      out.push_back(t);
    }
    bodies.push_back(body);
  }
  return keep_overlaps;
}

}  // namespace tridem::scene_detail
