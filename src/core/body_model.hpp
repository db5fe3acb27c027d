#pragma once
// The rigid bodies of a scene with [[body]] blocks, built once in double precision from
// its triangles: one mass, the exact moment of inertia of the members about the body's
// centroid, the members' centroids in the body's frame. A lone triangle is a body of one
// member (and then its own centroid, mass and inertia, bit for bit).
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

struct BodyModel {
  std::vector<std::int64_t> first;  ///< members of body b: triangles [first[b], first[b+1])
  std::vector<Vec2d> centroid;
  std::vector<double> mass, inertia;  ///< per unit thickness, inertia about the centroid
  std::vector<double> half_size;      ///< the smallest member's half longest edge
  std::vector<Motion> motion;
  std::vector<Vec2d> velocity;
  std::vector<double> angular_velocity;
  std::vector<std::int32_t> program;  ///< index into ParticleModel::programs, -1 = none
  // Per triangle:
  std::vector<std::int32_t> body;    ///< the body it belongs to
  std::vector<Vec2d> member_offset;  ///< its centroid minus the body's, at theta = 0

  std::size_t size() const { return centroid.size(); }
  bool empty() const { return centroid.empty(); }
};

/// The bodies of `scene` from its triangles' centroids, areas, masses and inertias about
/// their own centroids (ParticleModel's columns); empty when the scene has no body of
/// several members.
BodyModel build_body_model(const Scene& scene, const std::vector<Vec2d>& centroid,
                           const std::vector<double>& mass, const std::vector<double>& inertia,
                           const std::vector<double>& longest_edge);

}  // namespace tridem
