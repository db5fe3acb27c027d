// [[body]] blocks: one rigid body each, of explicit triangles or of a polygon that
// tridem triangulates.
#include "io/scene/polygon_triangulation.hpp"
#include "io/scene/scene_sections.hpp"
#include "io/scene/triangle_shape.hpp"

#include <fmt/format.h>

namespace tridem::scene_detail {
namespace {

constexpr std::string_view kPolygonShape = "an array of at least 3 points [[x, y], ...]";
constexpr std::string_view kTrianglesShape =
    "an array of triangles [[[x, y], [x, y], [x, y]], ...]";

std::vector<Vec2d> read_polygon(TableReader& r, const toml::array& array) {
  std::vector<Vec2d> out;
  for (const toml::node& element : array)
    out.push_back(r.point_at(element, "polygon", kPolygonShape));
  return out;
}

std::vector<std::array<Vec2d, 3>> read_triangles(TableReader& r, const toml::array& array) {
  std::vector<std::array<Vec2d, 3>> out;
  for (const toml::node& element : array) {
    const toml::array* t = element.as_array();
    if (!t || t->size() != 3)
      r.fail_at(element, "triangles",
                fmt::format("expected {}; each triangle is 3 points", kTrianglesShape));
    std::array<Vec2d, 3> v{};
    for (std::size_t k = 0; k < 3; ++k) v[k] = r.point_at(*t->get(k), "triangles", kTrianglesShape);
    out.push_back(v);
  }
  return out;
}

}  // namespace

BodySpec parse_body(const toml::table& table, const std::string& source, std::size_t number,
                    std::size_t id, const std::vector<Material>& materials,
                    std::vector<TriangleSpec>& triangles, std::vector<MotionProgram>& programs,
                    std::vector<ProgramKnot>& knots) {
  TableReader r(table, source, fmt::format("[[body]] #{} (body id {})", number, id));
  const int material = lookup_material(r, materials);
  const toml::node* polygon = r.node("polygon");
  const toml::node* explicit_triangles = r.node("triangles");
  if (polygon && explicit_triangles)
    r.fail("triangles", "give either polygon or triangles, not both");
  if (!polygon && !explicit_triangles)
    r.fail_table("missing its shape: give polygon = [[x, y], ...] or "
                 "triangles = [[[x, y], [x, y], [x, y]], ...]");
  std::vector<std::array<Vec2d, 3>> shapes;
  if (polygon) {
    const toml::array* array = polygon->as_array();
    if (!array)
      r.fail("polygon",
             fmt::format("expected {}, got {}", kPolygonShape, describe_type(polygon->type())));
    PolygonTriangulation cut = triangulate_polygon(read_polygon(r, *array));
    if (cut.problem) r.fail("polygon", *cut.problem);
    shapes = std::move(cut.triangles);
  } else {
    const toml::array* array = explicit_triangles->as_array();
    if (!array || array->empty())
      r.fail("triangles",
             fmt::format("expected {} (at least one), got {}", kTrianglesShape,
                         array ? "an empty array"
                               : std::string(describe_type(explicit_triangles->type()))));
    shapes = read_triangles(r, *array);
  }
  const Movement m = read_movement(r, "body", programs, knots);
  r.reject_unknown_keys();

  BodySpec body;
  body.first = triangles.size();
  body.count = shapes.size();
  body.velocity = m.velocity;
  body.angular_velocity = m.angular_velocity;
  body.motion = m.motion;
  body.program = m.program;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    std::array<Vec2d, 3>& v = shapes[k];
    if (auto problem = shape_problem(v))
      r.fail(polygon ? "polygon" : "triangles",
             fmt::format("member triangle {} of {}: {}", k + 1, shapes.size(), *problem));
    make_counter_clockwise(v);
    TriangleSpec t;
    t.material = material;
    t.vertices = v;
    t.motion = m.motion;  // walls' pairs are skipped by the members' own motion too
    triangles.push_back(t);
  }
  return body;
}

}  // namespace tridem::scene_detail
