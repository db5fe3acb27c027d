#include "core/particle_model.hpp"

#include "io/scene/triangle_shape.hpp"
#include "physics/contact_laws.hpp"
#include "physics/geometry.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <cmath>
#include <fmt/format.h>

namespace tridem {

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
  }
  m.bodies = build_body_model(scene, m.centroid, m.mass, m.inertia, m.longest_edge);
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
