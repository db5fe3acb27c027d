#pragma once
// Triangles read from a file ([[import]]): their vertices as written, and what the file
// says of their motion and grouping. parse_import turns them into TriangleSpecs and bodies.
#include "tridem/vec2.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace tridem::scene_detail {

struct ImportedParticles {
  std::vector<std::array<Vec2d, 3>> vertices;  ///< as in the file, either orientation
  std::vector<Vec2d> velocity;                 ///< of each triangle's centroid (zeros if absent)
  std::vector<double> angular_velocity;        ///< likewise
  /// Per triangle: the body it belongs to (triangles of one id become one body), or -1
  /// for a triangle on its own.
  std::vector<std::int64_t> body;
  /// Per triangle, for refusals: its line in a CSV file, its element tag in a mesh.
  std::vector<std::size_t> where;
  std::string where_name = "line";  ///< what `where` counts: "line" or "element"
};

/// A CSV of triangles (docs/scene-format.md, [[import]]): a header naming the columns,
/// x1,y1,x2,y2,x3,y3 required; vx, vy, omega, body optional; a run's final.csv columns
/// id, x, y, theta are accepted and not used. Throws SceneError naming the file and line.
ImportedParticles read_particle_csv(const std::filesystem::path& file);

/// The 3-node triangles of a 2D Gmsh mesh; those of the physical groups named in
/// `body_groups` become one body per group. Throws SceneError naming the file.
ImportedParticles read_gmsh_mesh(const std::filesystem::path& file,
                                 const std::vector<std::string>& body_groups);

/// A region for Gmsh to mesh ([[mesh]] kind = "disc", "rectangle" or "polygon").
struct MeshRegion {
  enum class Kind { Disc, Rectangle, Polygon } kind = Kind::Disc;
  Vec2d center{};     ///< disc
  double radius = 0;  ///< disc
  /// disc: the angle (rad) each of two flats at its top and bottom subtends at the centre
  /// (a flattened Brazilian disc, loaded over the flats); 0 = a full disc.
  double flat_angle = 0;
  Vec2d lo{}, hi{};   ///< rectangle's corners
  /// polygon: its outline, a simple polygon in either orientation (a notched beam's
  /// outline with its notch, for one)
  std::vector<Vec2d> polygon;
  double size = 0;    ///< target element size, m
};

/// The unstructured 3-node triangles Gmsh makes of the region (Frontal-Delaunay, one
/// thread, so the same mesh each time). Throws SceneError naming `what` (the block) when
/// Gmsh fails, or when this build has no Gmsh (TRIDEM_WITH_GMSH=OFF).
ImportedParticles mesh_region(const MeshRegion& region, const std::string& what);

}  // namespace tridem::scene_detail
