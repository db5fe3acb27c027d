#pragma once
// One parser per kind of table in a scene file; parse_scene.cpp walks the document and
// calls them. Each refuses unknown keys in its own table.
#include "io/scene/toml_table_reader.hpp"
#include "tridem/generate.hpp"
#include "tridem/scene.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tridem::scene_detail {

SimulationSettings parse_simulation(const toml::table& table, const std::string& source);
/// periodic_x, periodic_y and shear_rate of [simulation] (parse_periodic.cpp).
PeriodicCell parse_periodic_cell(TableReader& r);
/// Why a periodic cell is refused (its ranges, its shear), naming the key in `key`;
/// shared by the reader and validate_scene.
std::optional<std::string> periodic_cell_problem(const PeriodicCell& cell, std::string& key);
OutputSettings parse_output(const toml::table& table, const std::string& source);

/// One [[measure]] block: `number` is its 1-based position among them, `earlier` those
/// before it (names and files must be unique).
MeasureSpec parse_measure(const toml::table& table, const std::string& source, std::size_t number,
                          const std::vector<MeasureSpec>& earlier);
/// The rules of a [[measure]], shared by its reader and validate_scene: why a name, a
/// region or a file is refused, or why it clashes with an earlier measure; nullopt if not.
std::optional<std::string> measure_name_problem(std::string_view name);
std::optional<std::string> measure_region_problem(const MeasureRegion& region);
std::optional<std::string> measure_file_problem(std::string_view file);
std::optional<std::string> measure_clash(const MeasureSpec& m,
                                         const std::vector<MeasureSpec>& earlier);

/// `number` is the 1-based position among the [[material]] blocks; `earlier` are those
/// before it (names must be unique).
Material parse_material(const toml::table& table, const std::string& source, std::size_t number,
                        const std::vector<Material>& earlier);

/// Reads the 'material' key of `reader`'s table and returns its index in `materials`.
int lookup_material(TableReader& reader, const std::vector<Material>& materials);

/// `number` is the 1-based position among the [[triangle]] blocks, `id` the particle id.
TriangleSpec parse_triangle(const toml::table& table, const std::string& source, std::size_t number,
                            std::size_t id, const std::vector<Material>& materials,
                            std::vector<MotionProgram>& programs, std::vector<ProgramKnot>& knots);

/// How a [[triangle]] or [[body]] moves: velocity, angular_velocity, fixed / motion.
struct Movement {
  Vec2d velocity{};
  double angular_velocity = 0;
  Motion motion = Motion::Free;
  std::int32_t program = -1;  ///< index into the scene's programs, -1 = none
};
/// Reads them from `reader`'s table; `what` ("triangle", "body") names it in refusals. A
/// `program` table is appended to `programs` (its table's entries to `knots`).
Movement read_movement(TableReader& reader, std::string_view what,
                       std::vector<MotionProgram>& programs, std::vector<ProgramKnot>& knots);
/// The `program = {...}` table of a prescribed wall (parse_program.cpp): appended to
/// `programs` and `knots`; returns its index.
std::int32_t read_program(TableReader& wall, std::vector<MotionProgram>& programs,
                          std::vector<ProgramKnot>& knots);

/// One [[body]] block: `number` is its 1-based position among them, `id` its body id.
/// Appends its members to `triangles` and returns the body (first = their first index).
BodySpec parse_body(const toml::table& table, const std::string& source, std::size_t number,
                    std::size_t id, const std::vector<Material>& materials,
                    std::vector<TriangleSpec>& triangles, std::vector<MotionProgram>& programs,
                    std::vector<ProgramKnot>& knots);

/// Appends the triangles of one [[generate]] block to `out` (whose size is the first id)
/// and its bodies to `bodies` (one per triangle, or one per grain of kind = "polygons").
void parse_generate(const toml::table& table, const std::string& source, std::size_t number,
                    const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                    std::vector<BodySpec>& bodies);

/// The keys of kind = "polygons" (or "triangles": `triangles`) read from `reader`, and the
/// grains they make; `particles_before` counts the scene's triangles so far (for the
/// memory check). Bodies index the returned triangles.
GeneratedGrains parse_generate_grains(TableReader& reader, bool triangles,
                                      const std::vector<Material>& materials,
                                      std::size_t particles_before);

/// One [[import]] block: the triangles (and bodies) of a CSV file or a Gmsh mesh, appended
/// like parse_generate's. Returns its keep_overlaps key: whether overlaps among imported
/// triangles are the state to keep (a run's final.csv) rather than a mistake to refuse.
bool parse_import(const toml::table& table, const std::string& source, std::size_t number,
                  const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                  std::vector<BodySpec>& bodies);

/// One [[mesh]] block: a disc or rectangle meshed by Gmsh, or a 2D .msh file, appended like
/// parse_generate's (one body per triangle); bonded = true appends to `bonds` a bond for
/// every two of its triangles that share an edge.
void parse_mesh(const toml::table& table, const std::string& source, std::size_t number,
                const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                std::vector<BodySpec>& bodies, std::vector<BondSpec>& bonds);

/// The bonds of triangles [first, end) of `triangles` that share an edge (the same two
/// end points exactly), sorted by (a, b).
std::vector<BondSpec> shared_edge_bonds(const std::vector<TriangleSpec>& triangles,
                                        std::size_t first);

/// Where each particle id of a scene file came from, so that a refusal about a pair of
/// particles (an initial overlap) says which blocks to edit.
struct Provenance {
  /// per explicit particle id: "[[triangle]] #2 at file:line:col" or
  /// "[[body]] #1 at file:line:col, its triangle 3 of 4"
  std::vector<std::string> explicit_origin;
  struct Generated {
    std::size_t first = 0, count = 0;  ///< ids [first, first + count)
    std::size_t number = 0;            ///< 1-based among the blocks of its section
    std::string where;
    std::string section = "[[generate]]";  ///< or "[[import]]", "[[mesh]]"
    bool keep_overlaps = false;            ///< an [[import]] with keep_overlaps = true
  };
  std::vector<Generated> generators;

  /// "particle id 12 ([[generate]] #1 at scene.toml:30:1, its triangle 3 of 200)"; ids of an
  /// [[import]] say "[[import]] #1".
  std::string describe(std::size_t id) const;

  /// Whether the overlap of `a` and `b` is kept: both come from [[import]]s with
  /// keep_overlaps = true.
  bool keeps_overlap(std::size_t a, std::size_t b) const;
  /// Whether particle `id` comes from an [[import]].
  bool in_import(std::size_t id) const;
};

/// The [simulation] and [output] checks of validate_scene alone.
void validate_settings(const Scene& scene);

/// validate_scene, naming where the particles of an overlapping pair come from.
void validate_scene(const Scene& scene, const Provenance* provenance);

}  // namespace tridem::scene_detail
