#pragma once
// The grains of a snapshot (bodies: a body of several triangles is one, a lone triangle
// another) and the contacts between them, which the measurements count and average over.
// Host code, run on logged steps only.
#include "tridem/snapshot.hpp"
#include "tridem/vec2.hpp"

#include <cstdint>
#include <vector>

namespace tridem::measure {

struct Grains {
  std::vector<Vec2d> centroid;  ///< the body's centroid (a lone triangle's own)
  std::vector<double> area;     ///< the sum of its triangles' areas
  std::vector<bool> free;       ///< false for fixed and prescribed grains: walls
  std::size_t size() const { return centroid.size(); }
};
Grains grains_of(const Snapshot& s);

/// The area of triangle i of a snapshot, from its vertices.
double triangle_area(const Snapshot& s, std::size_t i);

/// Two grains a < b that touch through one or more pairs of their triangles.
struct GrainContact {
  std::int64_t a = 0, b = 0;
  /// From a into b, unit: its triangle contacts' normals weighted by their normal forces.
  Vec2d normal{};
  double depth = 0;  ///< the deepest of its triangle contacts (the contact law's φ)
};

/// Every grain contact, in ascending (a, b) order, each once. Triangle contacts between
/// members of one body (which the solvers never make) are left out.
std::vector<GrainContact> grain_contacts(const Snapshot& s);

/// The grains each grain touches: neighbours of g are at [first[g], first[g + 1]).
struct Neighbours {
  std::vector<std::int64_t> first, grain;
};
Neighbours neighbours_of(std::size_t grains, const std::vector<GrainContact>& contacts);

/// Rattlers (tridem/measurements.hpp, find_rattlers) from the grains and their neighbours.
std::vector<bool> rattlers_of(const Grains& grains, const Neighbours& neighbours);

}  // namespace tridem::measure
