#pragma once
// Reading scenes from TOML files (format: docs/scene-format.md) and checking scenes built in
// code. Every refusal is a tridem::SceneError whose message names the file, the line:column
// where one is known, the table, the key and, for triangles, the particle id.
#include "tridem/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace tridem {

/// Reads, parses and validates a scene file. Throws SceneError if the file can't be read
/// or the scene is invalid.
Scene read_scene(const std::filesystem::path& file);

/// Parses and validates a scene from TOML text; `source_name` (usually the path) prefixes
/// every message and is stored in Scene::source. Explicit [[triangle]]s come first, in file
/// order, then the output of each [[generate]] in file order; clockwise triangles are
/// reordered to counter-clockwise.
Scene parse_scene(std::string_view toml_text, std::string source_name);

/// Checks a Scene however it was made: settings in range, materials valid and uniquely
/// named, at least one triangle, material indices in range, numbers finite, triangles not
/// degenerate, fixed triangles at rest. Changes nothing (clockwise triangles are accepted).
void validate_scene(const Scene& scene);

/// How messages name the scene: the file it came from, or "scene built in code".
std::string scene_label(const Scene& scene);

/// Settings a command line gives instead of the scene's: each replaces the [simulation]
/// or [output] key of the same name. Applied by apply_overrides alone, so that the scene
/// it returns is the one description of the run that everything after reads.
struct SceneOverrides {
  std::optional<std::string> out_dir;       ///< [output] dir
  std::optional<Backend> backend;           ///< [simulation] backend
  std::optional<std::int64_t> steps;        ///< [simulation] steps
  std::optional<Method> method;             ///< [simulation] method
  std::optional<ContactTest> contact_test;  ///< [simulation] contact_test
  std::optional<bool> bbox_prefilter;       ///< [simulation] bbox_prefilter
};

/// The scene with the overrides in place, its settings checked again as validate_scene
/// checks them (a method from the command line must fit the scene's contact test).
/// Throws SceneError naming the scene and the setting.
Scene apply_overrides(Scene scene, const SceneOverrides& overrides);

}  // namespace tridem
