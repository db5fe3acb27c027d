// [[mesh]] blocks: a disc, rectangle or polygon meshed by Gmsh, or a 2D Gmsh .msh file,
// into free triangles (one body each); bonded = true joins every two of them that share an
// edge by a cohesive bond (docs/fracture.md).
#include "io/scene/imported_particles.hpp"
#include "io/scene/polygon_triangulation.hpp"
#include "io/scene/scene_sections.hpp"
#include "io/scene/triangle_shape.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

namespace tridem::scene_detail {
namespace {

enum class Kind { Disc, Rectangle, Polygon, File };
constexpr std::array<std::pair<std::string_view, Kind>, 4> kKindNames{
    {{"disc", Kind::Disc},
     {"rectangle", Kind::Rectangle},
     {"polygon", Kind::Polygon},
     {"file", Kind::File}}};

std::filesystem::path resolve(const std::string& scene_source, const std::string& file) {
  std::filesystem::path p(file);
  if (p.is_absolute()) return p;
  return std::filesystem::path(scene_source).parent_path() / p;
}

// About 0.43 size² per triangle of a regular mesh: refuse before meshing what would go
// past the limit (a size in mm for a region in m).
void check_expected_count(TableReader& r, double area, double size) {
  const double expected = area / (0.433 * size * size);
  if (expected > static_cast<double>(kMaxGeneratedTriangles))
    r.fail("size", fmt::format("would make about {:.3g} triangles, more than the limit of {} "
                               "(check the units of size)",
                               expected, kMaxGeneratedTriangles));
}

MeshRegion read_region(TableReader& r, Kind kind) {
  MeshRegion m;
  m.size = r.required(r.real("size"), "size");
  if (!(m.size > 0)) r.fail("size", fmt::format("must be > 0 (m), got {}", m.size));
  if (kind != Kind::Disc && r.real("flat_angle"))
    r.fail("flat_angle", "is for kind = \"disc\" only");
  if (kind == Kind::Disc) {
    m.kind = MeshRegion::Kind::Disc;
    m.center = r.required(r.vec2("center"), "center");
    m.radius = r.required(r.real("radius"), "radius");
    if (!(m.radius > 0)) r.fail("radius", fmt::format("must be > 0 (m), got {}", m.radius));
    const double flat = r.real("flat_angle").value_or(0.0);
    if (!(flat >= 0 && flat <= 90))
      r.fail("flat_angle", fmt::format("must be in [0, 90] degrees, got {}", flat));
    m.flat_angle = flat * M_PI / 180.0;
    if (!(m.size < m.radius))
      r.fail("size", fmt::format("must be below the radius {} m, got {}", m.radius, m.size));
    check_expected_count(r, M_PI * m.radius * m.radius, m.size);
  } else if (kind == Kind::Polygon) {
    m.kind = MeshRegion::Kind::Polygon;
    m.polygon = r.required(r.point_list("polygon", "an array of at least 3 points [[x, y], ...]"),
                           "polygon");
    // The checks of a [[body]]'s polygon (at least 3 distinct finite points, simple, not
    // flat); its triangulation also gives the area that the count's estimate needs.
    const PolygonTriangulation cut = triangulate_polygon(m.polygon);
    if (cut.problem) r.fail("polygon", *cut.problem);
    double area = 0;
    for (const auto& t : cut.triangles) area += 0.5 * cross(t[1] - t[0], t[2] - t[0]);
    Vec2d lo = m.polygon[0], hi = m.polygon[0];
    for (const Vec2d& v : m.polygon) {
      lo = {std::min(lo.x, v.x), std::min(lo.y, v.y)};
      hi = {std::max(hi.x, v.x), std::max(hi.y, v.y)};
    }
    if (!(m.size < std::min(hi.x - lo.x, hi.y - lo.y)))
      r.fail("size", fmt::format("must be below the smaller side of the polygon's bounding box, "
                                 "got {}",
                                 m.size));
    check_expected_count(r, area, m.size);
  } else {
    m.kind = MeshRegion::Kind::Rectangle;
    const auto region = r.required(r.points<2>("region"), "region");
    m.lo = region[0];
    m.hi = region[1];
    if (!(m.hi.x > m.lo.x && m.hi.y > m.lo.y))
      r.fail("region", fmt::format("max corner ({}, {}) must exceed min corner ({}, {}) in x and y",
                                   m.hi.x, m.hi.y, m.lo.x, m.lo.y));
    if (!(m.size < std::min(m.hi.x - m.lo.x, m.hi.y - m.lo.y)))
      r.fail("size", fmt::format("must be below the rectangle's smaller side, got {}", m.size));
    check_expected_count(r, (m.hi.x - m.lo.x) * (m.hi.y - m.lo.y), m.size);
  }
  return m;
}

using Point = std::pair<double, double>;
Point key_of(Vec2d v) { return {v.x, v.y}; }

}  // namespace

std::vector<BondSpec> shared_edge_bonds(const std::vector<TriangleSpec>& triangles,
                                        std::size_t first) {
  // An edge by its two end points (exact: the mesh's triangles share the node's very
  // coordinates), lower point first; the first triangle seen on it.
  std::map<std::pair<Point, Point>, std::size_t> seen;
  std::vector<BondSpec> bonds;
  for (std::size_t i = first; i < triangles.size(); ++i)
    for (int e = 0; e < 3; ++e) {
      const Vec2d p = triangles[i].vertices[static_cast<std::size_t>(e)];
      const Vec2d q = triangles[i].vertices[static_cast<std::size_t>((e + 1) % 3)];
      auto edge = std::make_pair(key_of(p), key_of(q));
      if (edge.second < edge.first) std::swap(edge.first, edge.second);
      const auto [it, fresh] = seen.emplace(edge, i);
      if (!fresh) bonds.push_back({std::min(it->second, i), std::max(it->second, i), p, q});
    }
  std::sort(bonds.begin(), bonds.end(), [](const BondSpec& x, const BondSpec& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return bonds;
}

void parse_mesh(const toml::table& table, const std::string& source, std::size_t number,
                const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                std::vector<BodySpec>& bodies, std::vector<BondSpec>& bonds) {
  const std::string what = fmt::format("[[mesh]] #{}", number);
  TableReader r(table, source, fmt::format("{} (particle ids from {})", what, out.size()));
  const Kind kind = r.required(r.choice_in<Kind>("kind", kKindNames), "kind");
  const int material = lookup_material(r, materials);
  const bool bonded = r.boolean("bonded").value_or(false);
  if (bonded && !materials[static_cast<std::size_t>(material)].bondable())
    r.fail("bonded", fmt::format("material \"{}\" has no bond properties: give it young_modulus, "
                                 "tensile_strength, shear_strength, friction_angle, "
                                 "fracture_energy and shear_fracture_energy",
                                 materials[static_cast<std::size_t>(material)].name));
  std::filesystem::path path;
  MeshRegion region;
  if (kind == Kind::File) {
    const std::string file = r.required(r.string("file"), "file");
    if (file.empty()) r.fail("file", "must name a 2D Gmsh .msh file");
    path = resolve(source, file);
  } else {
    region = read_region(r, kind);
  }
  r.reject_unknown_keys();

  ImportedParticles in;
  try {
    in = kind == Kind::File ? read_gmsh_mesh(path, {}) : mesh_region(region, what);
  } catch (const SceneError& e) {
    r.fail(kind == Kind::File ? "file" : "kind", e.what());
  }
  if (in.vertices.size() > kMaxGeneratedTriangles)
    r.fail(kind == Kind::File ? "file" : "size",
           fmt::format("makes {} triangles, more than the limit of {}", in.vertices.size(),
                       kMaxGeneratedTriangles));
  const std::size_t first = out.size();
  for (std::size_t k = 0; k < in.vertices.size(); ++k) {
    if (auto problem = shape_problem(in.vertices[k]))
      r.fail(kind == Kind::File ? "file" : "size",
             fmt::format("element {}: {}", in.where[k], *problem));
    TriangleSpec t;
    t.material = material;
    t.vertices = in.vertices[k];
    make_counter_clockwise(t.vertices);
    out.push_back(t);
    bodies.push_back({out.size() - 1, 1, {}, 0, Motion::Free});
  }
  if (!bonded) return;
  const std::vector<BondSpec> made = shared_edge_bonds(out, first);
  bonds.insert(bonds.end(), made.begin(), made.end());
}

}  // namespace tridem::scene_detail
