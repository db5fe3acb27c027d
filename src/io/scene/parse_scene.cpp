// The document level of a scene file: syntax errors, which tables exist, and the order in
// which sections are read (materials before the triangles that name them).
#include "io/scene/scene_sections.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "tridem/scene_io.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace tridem {
namespace {

using scene_detail::where;

// [[name]] blocks, or none. `[name]` (a single table) is a common slip and gets its own
// message, since toml++ would otherwise happily accept it as a different shape.
std::vector<const toml::table*> blocks(const toml::table& root, std::string_view name,
                                       const std::string& source) {
  std::vector<const toml::table*> out;
  const toml::node* n = root.get(name);
  if (!n) return out;
  const toml::array* array = n->as_array();
  if (!array)
    throw SceneError(fmt::format("{}: '{}' must be an array of tables, written [[{}]], got {}",
                                 where(source, n->source()), name, name,
                                 scene_detail::describe_type(n->type())));
  for (const toml::node& element : *array) {
    const toml::table* t = element.as_table();
    if (!t)
      throw SceneError(fmt::format("{}: each '{}' entry must be a table, written [[{}]], got {}",
                                   where(source, element.source()), name, name,
                                   scene_detail::describe_type(element.type())));
    out.push_back(t);
  }
  return out;
}

const toml::table* single_table(const toml::table& root, std::string_view name,
                                const std::string& source) {
  const toml::node* n = root.get(name);
  if (!n) return nullptr;
  const toml::table* t = n->as_table();
  if (!t)
    throw SceneError(fmt::format("{}: '{}' must be a table, written [{}], got {}",
                                 where(source, n->source()), name, name,
                                 scene_detail::describe_type(n->type())));
  return t;
}

void reject_unknown_top_level(const toml::table& root, const std::string& source) {
  static constexpr std::string_view kKnown[] = {"simulation", "output", "material",
                                                "triangle",   "body",   "generate"};
  const toml::key* first = nullptr;
  for (const auto& [key, value] : root) {
    bool known = false;
    for (std::string_view k : kKnown) known = known || key.str() == k;
    if (!known && (!first || scene_detail::precedes(key.source().begin, first->source().begin)))
      first = &key;
  }
  if (first)
    throw SceneError(
        fmt::format("{}: unknown top-level table or key '{}' (expected [simulation], [output], "
                    "[[material]], [[triangle]], [[body]], [[generate]])",
                    where(source, first->source()), first->str()));
}

/// The body of one triangle, `triangles[index]` (the last one by default).
BodySpec lone_body(const std::vector<TriangleSpec>& triangles, std::size_t index) {
  const TriangleSpec& t = triangles[index];
  return {index, 1, t.velocity, t.angular_velocity, t.motion};
}
BodySpec lone_body(const std::vector<TriangleSpec>& triangles) {
  return lone_body(triangles, triangles.size() - 1);
}

}  // namespace

Scene parse_scene(std::string_view toml_text, std::string source_name) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source_name);
  } catch (const toml::parse_error& e) {
    throw SceneError(fmt::format("{}: TOML syntax error: {}", where(source_name, e.source()),
                                 e.description()));
  }
  const std::string& source = source_name;
  reject_unknown_top_level(root, source);

  Scene scene;
  const toml::table* simulation = single_table(root, "simulation", source);
  if (!simulation)
    throw SceneError(fmt::format("{}: missing required table [simulation] (it must set steps)",
                                 source));
  scene.simulation = scene_detail::parse_simulation(*simulation, source);
  if (const toml::table* output = single_table(root, "output", source))
    scene.output = scene_detail::parse_output(*output, source);

  const auto materials = blocks(root, "material", source);
  if (materials.empty())
    throw SceneError(fmt::format("{}: no [[material]] defined; at least one is required", source));
  for (std::size_t i = 0; i < materials.size(); ++i)
    scene.materials.push_back(
        scene_detail::parse_material(*materials[i], source, i + 1, scene.materials));

  // Ids: explicit [[triangle]]s and [[body]]s in file order (a body's members take
  // consecutive triangle ids), then each generator's output in file order.
  const auto triangles = blocks(root, "triangle", source);
  const auto bodies = blocks(root, "body", source);
  const auto generators = blocks(root, "generate", source);
  struct Explicit {
    const toml::table* table;
    bool body;
    std::size_t number;  // 1-based among its kind
  };
  std::vector<Explicit> in_file_order;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    in_file_order.push_back({triangles[i], false, i + 1});
  for (std::size_t i = 0; i < bodies.size(); ++i) in_file_order.push_back({bodies[i], true, i + 1});
  std::stable_sort(
      in_file_order.begin(), in_file_order.end(), [](const Explicit& a, const Explicit& b) {
        return scene_detail::precedes(a.table->source().begin, b.table->source().begin);
      });
  const bool with_bodies = !bodies.empty();
  scene.triangles.reserve(triangles.size());
  scene_detail::Provenance provenance;
  for (const Explicit& e : in_file_order) {
    const std::string at = where(source, e.table->source());
    if (e.body) {
      const BodySpec body = scene_detail::parse_body(
          *e.table, source, e.number, scene.bodies.size(), scene.materials, scene.triangles);
      for (std::size_t k = 0; k < body.count; ++k)
        provenance.explicit_origin.push_back(
            fmt::format("body id {}, [[body]] #{} at {}, its triangle {} of {}",
                        scene.bodies.size(), e.number, at, k + 1, body.count));
      scene.bodies.push_back(body);
      continue;
    }
    const std::size_t id = with_bodies ? scene.bodies.size() : scene.triangles.size();
    scene.triangles.push_back(
        scene_detail::parse_triangle(*e.table, source, e.number, id, scene.materials));
    provenance.explicit_origin.push_back(fmt::format("[[triangle]] #{} at {}", e.number, at));
    if (with_bodies) scene.bodies.push_back(lone_body(scene.triangles));
  }
  for (std::size_t i = 0; i < generators.size(); ++i) {
    const std::size_t first = scene.triangles.size();
    scene_detail::parse_generate(*generators[i], source, i + 1, scene.materials,
                                 scene.triangles);
    provenance.generators.push_back({first, scene.triangles.size() - first, i + 1,
                                     where(source, generators[i]->source())});
    if (scene.triangles.size() > kMaxGeneratedTriangles)
      throw SceneError(fmt::format(
          "{}: [[generate]] #{} brings the scene to {} triangles, more than the limit of {} "
          "(check units of region and size)",
          source, i + 1, scene.triangles.size(), kMaxGeneratedTriangles));
  }
  if (with_bodies)  // each generated triangle is a body of its own
    for (std::size_t i = scene.bodies.back().first + scene.bodies.back().count;
         i < scene.triangles.size(); ++i)
      scene.bodies.push_back(lone_body(scene.triangles, i));
  if (scene.triangles.empty())
    throw SceneError(fmt::format(
        "{}: the scene has no triangles; add [[triangle]] or [[generate]] blocks", source));

  scene.source = std::move(source_name);
  // A backstop for what the checks above should already have caught, and the one check
  // that needs every triangle: initial overlaps.
  scene_detail::validate_scene(scene, &provenance);
  return scene;
}

}  // namespace tridem
