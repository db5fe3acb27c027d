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
                                                "triangle",   "body",   "generate",
                                                "import",     "mesh",   "measure"};
  const toml::key* first = nullptr;
  for (const auto& [key, value] : root) {
    bool known = false;
    for (std::string_view k : kKnown) known = known || key.str() == k;
    if (!known && (!first || scene_detail::precedes(key.source().begin, first->source().begin)))
      first = &key;
  }
  if (first)
    throw SceneError(fmt::format(
        "{}: unknown top-level table or key '{}' (expected [simulation], [output], "
        "[[material]], [[triangle]], [[body]], [[generate]], [[import]], [[mesh]], [[measure]])",
        where(source, first->source()), first->str()));
}

/// The body of the last triangle of `triangles`, alone.
BodySpec lone_body(const std::vector<TriangleSpec>& triangles) {
  const TriangleSpec& t = triangles.back();
  return {triangles.size() - 1, 1, t.velocity, t.angular_velocity, t.motion, t.program};
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
  const auto measures = blocks(root, "measure", source);
  for (std::size_t i = 0; i < measures.size(); ++i)
    scene.output.measures.push_back(
        scene_detail::parse_measure(*measures[i], source, i + 1, scene.output.measures));

  const auto materials = blocks(root, "material", source);
  if (materials.empty())
    throw SceneError(fmt::format("{}: no [[material]] defined; at least one is required", source));
  for (std::size_t i = 0; i < materials.size(); ++i)
    scene.materials.push_back(
        scene_detail::parse_material(*materials[i], source, i + 1, scene.materials));

  // Ids: explicit [[triangle]]s and [[body]]s in file order (a body's members take
  // consecutive triangle ids), then each generator's or import's output in file order.
  const auto triangles = blocks(root, "triangle", source);
  const auto bodies = blocks(root, "body", source);
  const auto generators = blocks(root, "generate", source);
  const auto imports = blocks(root, "import", source);
  const auto meshes = blocks(root, "mesh", source);
  struct Block {
    const toml::table* table;
    bool second_kind;    // [[body]] among the explicit ones, [[import]] among the rest
    std::size_t number;  // 1-based among its kind
    bool mesh = false;   // [[mesh]] among the rest
  };
  auto in_file_order = [](std::vector<Block> list) {
    std::stable_sort(list.begin(), list.end(), [](const Block& a, const Block& b) {
      return scene_detail::precedes(a.table->source().begin, b.table->source().begin);
    });
    return list;
  };
  std::vector<Block> explicit_blocks, made_blocks;
  for (std::size_t i = 0; i < triangles.size(); ++i)
    explicit_blocks.push_back({triangles[i], false, i + 1});
  for (std::size_t i = 0; i < bodies.size(); ++i)
    explicit_blocks.push_back({bodies[i], true, i + 1});
  for (std::size_t i = 0; i < generators.size(); ++i)
    made_blocks.push_back({generators[i], false, i + 1});
  for (std::size_t i = 0; i < imports.size(); ++i) made_blocks.push_back({imports[i], true, i + 1});
  for (std::size_t i = 0; i < meshes.size(); ++i)
    made_blocks.push_back({meshes[i], false, i + 1, true});
  // Bodies are kept for every scene while reading (a lone triangle is a body of one) and
  // dropped at the end when none has several members and no [[body]] was written.
  scene.triangles.reserve(triangles.size());
  scene_detail::Provenance provenance;
  for (const Block& e : in_file_order(std::move(explicit_blocks))) {
    const std::string at = where(source, e.table->source());
    if (e.second_kind) {
      const BodySpec body =
          scene_detail::parse_body(*e.table, source, e.number, scene.bodies.size(), scene.materials,
                                   scene.triangles, scene.programs, scene.program_knots);
      for (std::size_t k = 0; k < body.count; ++k)
        provenance.explicit_origin.push_back(
            fmt::format("body id {}, [[body]] #{} at {}, its triangle {} of {}",
                        scene.bodies.size(), e.number, at, k + 1, body.count));
      scene.bodies.push_back(body);
      continue;
    }
    scene.triangles.push_back(scene_detail::parse_triangle(*e.table, source, e.number,
                                                           scene.bodies.size(), scene.materials,
                                                           scene.programs, scene.program_knots));
    provenance.explicit_origin.push_back(fmt::format("[[triangle]] #{} at {}", e.number, at));
    scene.bodies.push_back(lone_body(scene.triangles));
  }
  for (const Block& e : in_file_order(std::move(made_blocks))) {
    const std::size_t first = scene.triangles.size();
    const char* section = e.mesh ? "[[mesh]]" : e.second_kind ? "[[import]]" : "[[generate]]";
    bool keep_overlaps = false;
    if (e.mesh)
      scene_detail::parse_mesh(*e.table, source, e.number, scene.materials, scene.triangles,
                               scene.bodies, scene.bonds);
    else if (e.second_kind)
      keep_overlaps = scene_detail::parse_import(*e.table, source, e.number, scene.materials,
                                                 scene.triangles, scene.bodies);
    else
      scene_detail::parse_generate(*e.table, source, e.number, scene.materials, scene.triangles,
                                   scene.bodies);
    provenance.generators.push_back({first, scene.triangles.size() - first, e.number,
                                     where(source, e.table->source()), section, keep_overlaps});
    if (scene.triangles.size() > kMaxGeneratedTriangles)
      throw SceneError(
          fmt::format("{}: {} #{} brings the scene to {} triangles, more than the limit of {} "
                      "(check units of region and size)",
                      source, section, e.number, scene.triangles.size(), kMaxGeneratedTriangles));
  }
  // Swapped out, not cleared: a large generated scene's lone bodies take 48 bytes a
  // triangle that clear() would keep for the rest of the run.
  if (bodies.empty() && !scene.has_bodies()) std::vector<BodySpec>().swap(scene.bodies);
  if (scene.triangles.empty())
    throw SceneError(fmt::format(
        "{}: the scene has no triangles; add [[triangle]], [[generate]] or [[import]] blocks",
        source));

  scene.source = std::move(source_name);
  // A backstop for what the checks above should already have caught, and the one check
  // that needs every triangle: initial overlaps.
  scene_detail::validate_scene(scene, &provenance);
  return scene;
}

}  // namespace tridem
