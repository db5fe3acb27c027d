#pragma once
// A host copy of the state at one step, in double precision whatever the solver's real
// type: the one thing output writers and the renderer see. Solvers fill it only on output
// steps, so the state otherwise stays on its backend.
#include "tridem/body_fields.hpp"
#include "tridem/particle_fields.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

/// One contact between particles i and j at a frame: the total force that j exerts on i
/// (i receives +force, j receives −force) and the point where it acts; its unit normal
/// (nx, ny) from i into j, so that force = −normal_force()·n + tangential_force()·t with
/// t = (−ny, nx); whether the Coulomb cap held it (sliding); and its penetration depth
/// (the contact law's φ: 0 at an edge, 1 at a centroid).
struct ContactRecord {
  std::int64_t i = 0;
  std::int64_t j = 0;
  double fx = 0, fy = 0;
  double px = 0, py = 0;
  double nx = 0, ny = 0;
  bool sliding = false;
  double depth = 0;
  /// Periodic boundaries: the translation of j's image that i touches (j's centroid plus
  /// it is the centroid seen from the contact); 0 without periodic boundaries.
  double image_dx = 0, image_dy = 0;

  /// > 0 when the contact pushes i and j apart (damping can make it slightly negative).
  double normal_force() const { return -(fx * nx + fy * ny); }
  /// Along t = (−ny, nx), the normal turned by +90°.
  double tangential_force() const { return -fx * ny + fy * nx; }
};

/// Structure of arrays, one entry per particle in id order: the shown fields of
/// tridem/particle_fields.hpp (State and Force: centroid, angle, velocities, the total
/// contact force and torque of the step) in double, and what output derives from the model.
struct Snapshot {
  std::int64_t step = 0;
  double time = 0;
  /// x, y, theta, vx, vy, omega, fx, fy, torque; column(field), for_each_field(f),
  /// kArraysPerParticle.
  TRIDEM_PUBLIC_COLUMNS(TRIDEM_SHOWN_FIELDS)
  std::vector<double> x1, y1, x2, y2, x3, y3;  ///< current vertices, counter-clockwise
  std::vector<double> mass, inertia;
  std::vector<int> material;
  std::vector<Motion> motion;
  std::vector<ContactRecord> contacts;    ///< filled when contacts are requested
  /// What the contacts' fx, fy, nx, ny and depth are: Float when the solver's pairs are
  /// float (the float precision's mixed mode), so each is exactly a float32 and the
  /// contacts CSV prints it as one (the fewest digits that read back the same float32).
  Precision contact_precision = Precision::Double;
  /// The run's periodic cell (none without periodic boundaries): a grain across its sides
  /// is in the cell partly through its images, which the measurements count (measure/).
  PeriodicCell periodic;

  // Bodies of several triangles (tridem/body_fields.hpp). All EMPTY when the scene has no
  // body of several triangles: every triangle is then its own body, of id its triangle id.
  std::vector<std::int32_t> member_body;  ///< per triangle: its body (Scene::bodies order)
  /// Per body: body_x, body_y, body_theta, body_vx, body_vy, body_omega (the centroid's
  /// pose and velocities), body_fx, body_fy, body_torque (the members' contact load of the
  /// step, torque about the body's centroid); column(body_field::...).
  TRIDEM_BODY_PUBLIC_COLUMNS(TRIDEM_BODY_SHOWN_FIELDS)
  std::vector<double> body_mass, body_inertia;  ///< 0 for fixed and prescribed bodies
  /// n_bodies + 1 offsets: the members of body b are triangles [first[b], first[b+1]).
  std::vector<std::int64_t> body_first;

  // Cohesive bonds (docs/fracture.md), in Scene::bonds order; all EMPTY without bonds.
  std::vector<std::int32_t> bond_a, bond_b;  ///< the two triangles
  std::vector<double> bond_damage;           ///< the mean of its points' damage, 0 to 1
  std::vector<std::uint8_t> bond_broken;     ///< 1 once every point is fully damaged
  /// The shared edge's two ends as triangle a carries them now (the crack's faces).
  std::vector<double> bond_x0, bond_y0, bond_x1, bond_y1;

  std::size_t body_count() const { return member_body.empty() ? size() : body_first.size() - 1; }
  std::int64_t body_of(std::size_t i) const {
    return member_body.empty() ? static_cast<std::int64_t>(i) : member_body[i];
  }

  std::size_t size() const { return x.size(); }
  /// Sizes every per-particle array for n particles (src/core/snapshot_resize.cpp).
  void resize(std::size_t n);
  /// f(a, b) for each per-particle array a of this snapshot and the same array b of
  /// `other` (a Snapshot, const or not): the shown fields, the vertices, mass, inertia,
  /// material and motion. resize() and the solver that numbers particles by place
  /// (core/place_numbered_solver) go through it, so that an array added here is sized and
  /// mapped to the scene's ids with the rest.
  template <class Other, class F>
  void for_each_particle_array(Other& other, F&& f) {
    for_each_field([&](auto field) {
      for_each_array(column(field),
                     [&](auto& a, int k) { f(a, array_at(other.column(field), k)); });
    });
    f(x1, other.x1);
    f(y1, other.y1);
    f(x2, other.x2);
    f(y2, other.y2);
    f(x3, other.x3);
    f(y3, other.y3);
    f(mass, other.mass);
    f(inertia, other.inertia);
    f(material, other.material);
    f(motion, other.motion);
  }
  /// Sizes the body columns for `bodies` bodies of the size() triangles; 0 empties them.
  void resize_bodies(std::size_t bodies) {
    const std::size_t members = bodies > 0 ? size() : 0;
    member_body.resize(members);
    for_each_body_column([&](auto field) { column(field).resize(bodies); });
    body_mass.resize(bodies);
    body_inertia.resize(bodies);
    body_first.resize(bodies > 0 ? bodies + 1 : 0);
  }
};

}  // namespace tridem
