#pragma once
// The cohesive bonds of a scene (Scene::bonds) as the solvers keep them, built once on the
// host in double: each bond's points on its two triangles, normal, length and stiffness
// (physics/cohesive_bond.hpp), the strengths of each material, and each particle's list of
// bonds (at most three, in ascending bond order: the order its bond loads are summed in).
#include "core/particle_model.hpp"
#include "physics/cohesive_bond.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

struct BondModel {
  std::vector<std::int32_t> a, b;  ///< the two triangles, a < b
  std::vector<physics::BondGeometry<double>> geometry;
  std::vector<std::int32_t> material;                   ///< a's material (one per mesh)
  std::vector<physics::BondStrength<double>> strength;  ///< per material (zeros if not bondable)
  // Per particle i: its bonds are slots [first[i], first[i + 1]) of partner and bond.
  std::vector<std::int32_t> first, partner, bond;

  std::size_t size() const { return a.size(); }
};

/// The stiffness k = E / h of a bond whose triangles' centroids lie h apart across the
/// edge (docs/fracture.md, "Stiffness"): the springs that give a mesh of rigid triangles
/// the material's Young's modulus.
double bond_stiffness(double young_modulus, double centroid_distance);

/// The bonds of `scene` (empty without bonds). Throws SceneError for a bond whose
/// triangles do not lie on both sides of its edge.
BondModel build_bond_model(const Scene& scene, const ParticleModel& model);

/// The stability limit of the bonds alone: the smallest over bonded free triangles of the
/// symplectic Euler limit of the triangle on its bonds' springs (doubled: two free
/// triangles share a spring's stretch, as time_step.cpp bounds contacts), with
/// Cundall's factor `local` (1 + alpha). Infinite without bonds.
double bond_time_step_limit(const ParticleModel& model, const BondModel& bonds, double local);

}  // namespace tridem
