#pragma once
// Particle generators, shared by scene files ([[generate]]) and by code (tests, benchmarks).
// All guarantee that no two generated triangles overlap, emit counter-clockwise vertices,
// and are deterministic: the same spec gives the same triangles on every platform (up to
// the last bits of the C library's sin/cos). Invalid specs, and specs that would make no
// triangle or more than kMaxGeneratedTriangles, throw SceneError.
#include "tridem/scene.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace tridem {

/// Hard upper limit on one generator's output, and on all generators of a scene together:
/// beyond it a scene is almost certainly a units mistake, and the memory (~100 bytes per
/// triangle) would not be there anyway.
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
// The fuzzer counts an input that takes over 10 s as a hang. Under its sanitizers a valid
// scene of a few thousand triangles around one large free triangle (a grid of coarse cells)
// takes that long, which is cost, not a hang; fuzz builds cap the scene so that a timeout
// means a real hang.
inline constexpr std::size_t kMaxGeneratedTriangles = 2'000;
#else
inline constexpr std::size_t kMaxGeneratedTriangles = 200'000'000;
#endif

/// Equilateral triangles of edge `size` on a triangular tiling (alternating up/down in
/// rows), spaced so that facing edges of neighbours are gap·size apart; every triangle lies
/// wholly inside [region_min, region_max]. Rows go bottom to top, left to right in a row.
struct LatticeSpec {
  int material = 0;
  Vec2d region_min{};
  Vec2d region_max{};
  double size = 0;     ///< edge length, > 0
  double gap = 0.1;    ///< separation of neighbours as a fraction of size, >= 0
  Vec2d velocity{};    ///< given to every triangle
};

/// Triangles of circumradius size/√3 (equilateral of edge `size` when irregularity = 0),
/// one per cell of a square grid of pitch 2R(1+gap), randomly rotated and shifted inside
/// their cell. Cells are filled bottom row first, left to right, up to `count`.
struct RandomPackingSpec {
  int material = 0;
  Vec2d region_min{};
  Vec2d region_max{};
  double size = 0;            ///< edge length of the undistorted triangle, > 0
  double gap = 0.1;           ///< >= 0; pitch 2R(1+gap), jitter up to R·gap/2 per axis
  Vec2d velocity{};
  std::uint64_t seed = 1;
  std::size_t count = 0;      ///< 0: one triangle per cell of the region
  double irregularity = 0;    ///< in [0, 1): 0 equilateral, towards 1 more distorted
};

/// One class of a size table: grains of `size` make up `mass_fraction` of the mass.
struct SizeClass {
  double size = 0;           ///< equal-area diameter, m, > 0
  double mass_fraction = 0;  ///< > 0; the fractions of a table sum to 1
};

/// Grain sizes. The size of a grain is the diameter of the circle of equal area,
/// d = 2·sqrt(A/π), so a grain's mass is ρ·π·d²/4 whatever its shape.
struct SizeDistribution {
  double min_size = 0;  ///< uniform by number in [min_size, max_size] (equal: one size)
  double max_size = 0;
  std::vector<SizeClass> classes;  ///< non-empty: this table instead of the range
};

/// How generated grains are numbered: in the order they were placed (largest first), or
/// along a space-filling curve through their centres, so that neighbours get nearby ids
/// (their data then lies close in memory: a GPU run of 10^6 triangles numbered at random
/// took over twice as long a step; docs/performance.md, "The particles' order").
enum class GrainNumbering { Placement, Space };

/// Random convex polygons (or triangles) placed by random sequential addition, without
/// overlap, wholly inside a rectangle or a simple polygon (docs/scene-format.md,
/// kind = "polygons" / "triangles"). Each polygon is one body of triangles (its
/// constrained Delaunay triangulation); a triangle is a body of one member.
struct GrainSpec {
  int material = 0;
  /// 2 points: the corners [min, max] of a rectangle; 3 or more: a simple polygon.
  std::vector<Vec2d> region;
  int min_sides = 3, max_sides = 3;       ///< sides drawn uniformly in [min, max], 3..64
  double min_aspect = 1, max_aspect = 1;  ///< aspect ratio drawn uniformly, >= 1
  double angularity = 0;                  ///< in [0, 1): spread of the vertex angles
  SizeDistribution sizes;
  std::size_t count = 0;        ///< grains to place; 0: use packing_fraction
  double packing_fraction = 0;  ///< in (0, 1): grains' total area / region area
  std::uint64_t seed = 1;
  std::size_t max_attempts = 10000;  ///< random positions tried per grain before giving up
  Vec2d velocity{};                  ///< given to every grain
  GrainNumbering numbering = GrainNumbering::Placement;  ///< the ids' order
};

/// The grains: triangles, and bodies over them (BodySpec::first indexes `triangles`).
struct GeneratedGrains {
  std::vector<TriangleSpec> triangles;
  std::vector<BodySpec> bodies;
};

/// Most triangles generate_grains(spec) can make (from the sizes and the amount asked
/// for, before drawing any), to size memory first; throws SceneError for an invalid spec.
std::size_t max_grain_triangles(const GrainSpec& spec);

/// Throws SceneError for an invalid spec, and when a grain finds no free place in
/// max_attempts tries (the message says how many were placed, and the packing fraction
/// reached). Grains are placed largest first; ids follow that order, or with
/// GrainNumbering::Space the Hilbert curve through the grains' placed centres (the same
/// grains either way).
GeneratedGrains generate_grains(const GrainSpec& spec);

/// How many triangles generate_lattice(spec) makes, without making them.
std::size_t count_lattice(const LatticeSpec& spec);
/// How many cells of the region can hold a triangle (count = 0 fills them all).
std::size_t count_random_cells(const RandomPackingSpec& spec);

std::vector<TriangleSpec> generate_lattice(const LatticeSpec& spec);
/// Throws SceneError if count exceeds count_random_cells(spec).
std::vector<TriangleSpec> generate_random(const RandomPackingSpec& spec);

}  // namespace tridem
