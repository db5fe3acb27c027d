#pragma once
// A host copy of the state at one step, in double precision whatever the solver's real
// type: the one thing output writers and the renderer see. Solvers fill it only on output
// steps, so the state otherwise stays on its backend.
#include "tridem/particle_fields.hpp"
#include "tridem/scene.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

/// One contact between particles i and j at a frame: the total force that j exerts on i
/// (i receives +force, j receives −force) and the point where it acts.
struct ContactRecord {
  std::int64_t i = 0;
  std::int64_t j = 0;
  double fx = 0, fy = 0;
  double px = 0, py = 0;
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

  std::size_t size() const { return x.size(); }
  void resize(std::size_t n) {
    for_each_field([&](auto field) {
      for_each_array(column(field), [n](std::vector<double>& v, int) { v.resize(n); });
    });
    for (auto* v : {&x1, &y1, &x2, &y2, &x3, &y3, &mass, &inertia}) v->resize(n);
    material.resize(n);
    motion.resize(n);
  }
};

}  // namespace tridem
