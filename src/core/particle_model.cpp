#include "core/particle_model.hpp"

#include "io/scene/triangle_shape.hpp"
#include "physics/contact_laws.hpp"
#include "physics/geometry.hpp"
#include "physics/motion_program.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace tridem {
namespace {

// Each programmed wall (a triangle, or a body when the scene has bodies) gets its origin,
// the centroid it starts from, and the program's velocity at t = 0; a program of no wall,
// of two walls, of a wall that is not prescribed or out of range is refused (a scene built
// in code may not have been through the reader).
void resolve_programs(const Scene& scene, ParticleModel& m) {
  m.programs = scene.programs;
  m.program_knots = scene.program_knots;
  std::vector<int> users(scene.programs.size(), 0);
  auto resolve = [&](std::int32_t k, Motion motion, Vec2d centroid, Vec2d& velocity,
                     double& angular_velocity, const std::string& wall) {
    if (k < 0) return;
    if (static_cast<std::size_t>(k) >= scene.programs.size() || motion != Motion::Prescribed)
      throw SceneError(fmt::format("{}: {}: program {} {}", scene_label(scene), wall, k,
                                   motion != Motion::Prescribed ? "on a wall that is not prescribed"
                                                                : "out of range"));
    MotionProgram& p = m.programs[static_cast<std::size_t>(k)];
    if (p.kind == ProgramKind::Table &&
        (p.knot_count < 1 || p.first_knot < 0 ||
         static_cast<std::size_t>(p.first_knot + p.knot_count) > scene.program_knots.size()))
      throw SceneError(fmt::format("{}: {}: its velocity table's entries are out of range",
                                   scene_label(scene), wall));
    if (++users[static_cast<std::size_t>(k)] > 1)
      throw SceneError(fmt::format("{}: {}: program {} already moves another wall",
                                   scene_label(scene), wall, k));
    p.origin = centroid;
    const physics::ProgramTable table{m.programs.data(), m.program_knots.data()};
    physics::program_velocity(table, k, 0.0, Vec2d{}, velocity, angular_velocity);
  };
  if (m.bodies.empty()) {
    for (std::size_t i = 0; i < m.size(); ++i)
      resolve(m.program[i], m.motion[i], m.centroid[i], m.velocity[i], m.angular_velocity[i],
              fmt::format("particle id {}", i));
    return;
  }
  std::fill(m.program.begin(), m.program.end(), -1);  // the bodies carry them
  BodyModel& b = m.bodies;
  for (std::size_t k = 0; k < b.size(); ++k)
    resolve(b.program[k], b.motion[k], b.centroid[k], b.velocity[k], b.angular_velocity[k],
            fmt::format("body id {}", k));
}

}  // namespace

ParticleModel build_particle_model(const Scene& scene) {
  if (scene.triangles.empty())
    throw SceneError(scene_label(scene) + ": the scene has no triangles");
  ParticleModel m;
  const std::size_t n = scene.triangles.size();
  m.offsets.resize(n);
  m.centroid.resize(n);
  m.area.resize(n);
  m.mass.resize(n);
  m.inertia.resize(n);
  m.longest_edge.resize(n);
  m.smallest_height.resize(n);
  m.material.resize(n);
  m.motion.resize(n);
  m.velocity.resize(n);
  m.angular_velocity.resize(n);
  m.program.assign(n, -1);
  for (std::size_t i = 0; i < n; ++i) {
    const TriangleSpec& spec = scene.triangles[i];
    // The scene reader's rules: a scene built in code may not have been through it.
    if (auto problem = scene_detail::triangle_problem(spec, scene.materials.size()))
      throw SceneError(fmt::format("{}: particle id {}: {}", scene_label(scene), i, *problem));
    physics::Triangle<double> t{{spec.vertices[0], spec.vertices[1], spec.vertices[2]}};
    double area = physics::signed_area(t);
    if (area < 0) {  // clockwise input: reorder
      std::swap(t.v[1], t.v[2]);
      area = -area;
    }
    const double edge = physics::longest_edge(t);
    const Vec2d c = physics::centroid(t);
    double sum_r2 = 0;
    for (int k = 0; k < 3; ++k) {
      m.offsets[i][k] = t.v[k] - c;
      sum_r2 += dot(m.offsets[i][k], m.offsets[i][k]);
    }
    const double density = scene.materials[spec.material].density;
    m.centroid[i] = c;
    m.area[i] = area;
    m.mass[i] = density * area;
    m.inertia[i] = m.mass[i] * sum_r2 / 12.0;  // uniform lamina about its centroid
    m.longest_edge[i] = edge;
    m.smallest_height[i] = 2.0 * area / edge;
    m.material[i] = spec.material;
    m.motion[i] = spec.motion;
    const bool fixed = spec.motion == Motion::Fixed;
    m.velocity[i] = fixed ? Vec2d{} : spec.velocity;
    m.angular_velocity[i] = fixed ? 0.0 : spec.angular_velocity;
    m.program[i] = spec.program;
  }
  m.bodies = build_body_model(scene, m.centroid, m.mass, m.inertia, m.longest_edge);
  resolve_programs(scene, m);
  for (std::size_t i = 0; i < m.bodies.body.size(); ++i) {
    const auto b = static_cast<std::size_t>(m.bodies.body[i]);
    m.motion[i] = m.bodies.motion[b];
    m.velocity[i] =
        m.bodies.velocity[b] + cross(m.bodies.angular_velocity[b], m.bodies.member_offset[i]);
    m.angular_velocity[i] = m.bodies.angular_velocity[b];
  }
  return m;
}

bool walls_move(const ParticleModel& model) {
  if (!model.programs.empty()) return true;
  for (std::size_t i = 0; i < model.size(); ++i)
    if (model.motion[i] != Motion::Free &&
        (model.velocity[i].x != 0 || model.velocity[i].y != 0 || model.angular_velocity[i] != 0))
      return true;
  return false;
}

double material_restitution(const Material& m) {
  return physics::material_restitution(m.restitution, m.damping);
}

std::vector<physics::LawParameters<double>> contact_law_table(const std::vector<Material>& mats) {
  const std::size_t n = mats.size();
  std::vector<physics::LawParameters<double>> table(n * n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b)
      table[a * n + b] = b < a ? table[b * n + a]  // the law is symmetric: mix once
                               : physics::SceneContactLaw::parameters(mats[a], mats[b]);
  return table;
}

}  // namespace tridem
