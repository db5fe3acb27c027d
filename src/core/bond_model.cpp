#include "core/bond_model.hpp"

#include "physics/stability.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace tridem {

double bond_stiffness(double young_modulus, double centroid_distance) {
  return young_modulus / centroid_distance;
}

BondModel build_bond_model(const Scene& scene, const ParticleModel& model) {
  BondModel m;
  const std::size_t n = model.size();
  for (const Material& mat : scene.materials)
    m.strength.push_back(
        mat.bondable()
            ? physics::BondStrength<double>{mat.tensile_strength, mat.shear_strength,
                                            std::tan(mat.friction_angle * M_PI / 180.0),
                                            mat.fracture_energy, mat.shear_fracture_energy}
            : physics::BondStrength<double>{});
  std::vector<std::int32_t> count(n, 0);
  for (std::size_t k = 0; k < scene.bonds.size(); ++k) {
    const BondSpec& s = scene.bonds[k];
    // Triangles start at theta = 0 (particle_model): the body frame is the scene's frame
    // about the centroid.
    const Vec2d ca = model.centroid[s.a], cb = model.centroid[s.b];
    const Vec2d edge = s.q - s.p;
    const double length = norm(edge);
    Vec2d normal = perp(edge) / length;
    if (dot(normal, cb - ca) < 0) normal = -normal;
    // The centroids' distance across the edge: the sum of their distances to it.
    const double h = dot(cb - ca, normal);
    if (!(h > 1e-9 * length) || !(dot(s.p - ca, normal) > 0) || !(dot(cb - s.p, normal) > 0))
      throw SceneError(fmt::format("{}: bond #{} between particle ids {} and {}: the two "
                                   "triangles must lie on either side of their shared edge",
                                   scene_label(scene), k, s.a, s.b));
    const Material& mat = scene.materials[static_cast<std::size_t>(model.material[s.a])];
    physics::BondGeometry<double> g{};
    for (int p = 0; p < physics::kBondPoints; ++p) {
      const Vec2d at = s.p + edge * physics::bond_point_position(p);
      g.on_a[p] = at - ca;
      g.on_b[p] = at - cb;
    }
    g.normal = normal;
    g.length = length;
    g.stiffness = bond_stiffness(mat.young_modulus, h);
    m.a.push_back(static_cast<std::int32_t>(s.a));
    m.b.push_back(static_cast<std::int32_t>(s.b));
    m.geometry.push_back(g);
    m.material.push_back(model.material[s.a]);
    ++count[s.a];
    ++count[s.b];
  }
  if (m.size() == 0) return m;
  m.first.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) m.first[i + 1] = m.first[i] + count[i];
  m.partner.resize(static_cast<std::size_t>(m.first[n]));
  m.bond.resize(m.partner.size());
  std::vector<std::int32_t> next(m.first.begin(), m.first.end() - 1);
  // Bonds in ascending order, so each particle's list is ascending too.
  for (std::size_t k = 0; k < m.size(); ++k)
    for (const auto& [self, other] : {std::pair{m.a[k], m.b[k]}, std::pair{m.b[k], m.a[k]}}) {
      const auto slot = static_cast<std::size_t>(next[static_cast<std::size_t>(self)]++);
      m.partner[slot] = other;
      m.bond[slot] = static_cast<std::int32_t>(k);
    }
  return m;
}

double bond_time_step_limit(const ParticleModel& model, const BondModel& bonds, double local) {
  double limit = std::numeric_limits<double>::infinity();
  if (bonds.size() == 0) return limit;
  for (std::size_t i = 0; i < model.size(); ++i) {
    if (model.motion[i] != Motion::Free || bonds.first[i] == bonds.first[i + 1]) continue;
    physics::Sym3<double> springs;
    for (std::int32_t s = bonds.first[i]; s < bonds.first[i + 1]; ++s) {
      const auto k = static_cast<std::size_t>(bonds.bond[static_cast<std::size_t>(s)]);
      const physics::BondGeometry<double>& g = bonds.geometry[k];
      const bool is_a = bonds.a[k] == static_cast<std::int32_t>(i);
      // The edge's ends about this triangle's centroid; two free triangles share the
      // springs' stretch, so each is bounded with twice the springs (as for contacts).
      const Vec2d mid = (is_a ? g.on_a[0] + g.on_a[1] : g.on_b[0] + g.on_b[1]) * 0.5;
      const Vec2d along = perp(g.normal) * (0.5 * g.length);
      physics::add_edge_springs(springs, mid - along, mid + along, 2 * g.stiffness,
                                2 * g.stiffness);
    }
    const double lambda = local * physics::largest_mode(springs, model.mass[i], model.inertia[i]);
    limit = std::min(limit, physics::symplectic_euler_limit(lambda, 0.0));
  }
  return limit;
}

}  // namespace tridem
