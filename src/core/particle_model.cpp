#include "core/particle_model.hpp"

#include "physics/geometry.hpp"
#include "physics/restitution.hpp"
#include "tridem/error.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <fmt/format.h>

namespace tridem {

namespace {

// Relative area below which a triangle is degenerate (also the scene reader's bound).
constexpr double kDegenerateArea = 1e-12;

void check_triangle(const Scene& scene, std::size_t id, const TriangleSpec& t) {
  auto fail = [&](const std::string& why) {
    throw SceneError(fmt::format("{}: particle id {}: {}", scene.source, id, why));
  };
  if (t.material < 0 || t.material >= static_cast<int>(scene.materials.size()))
    fail(fmt::format("material index {} does not exist", t.material));
  for (const auto& v : t.vertices)
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) fail("vertex is not a finite number");
  if (!std::isfinite(t.velocity.x) || !std::isfinite(t.velocity.y) ||
      !std::isfinite(t.angular_velocity))
    fail("velocity is not a finite number");
}

}  // namespace

ParticleModel build_particle_model(const Scene& scene) {
  if (scene.triangles.empty()) throw SceneError(scene.source + ": the scene has no triangle");
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
    check_triangle(scene, i, spec);
    physics::Triangle<double> t{{spec.vertices[0], spec.vertices[1], spec.vertices[2]}};
    double area = physics::signed_area(t);
    if (area < 0) {  // clockwise input: reorder
      std::swap(t.v[1], t.v[2]);
      area = -area;
    }
    const double edge = physics::longest_edge(t);
    if (!(area > kDegenerateArea * edge * edge))
      throw SceneError(fmt::format(
          "{}: particle id {}: triangle is degenerate (area {:g} <= {:g}*L^2, L = {:g})",
          scene.source, i, area, kDegenerateArea, edge));
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
  return m;
}

namespace {

/// physics::contact_law, with the calibration of each restitution done once per process:
/// solvers, the time-step estimate and scene descriptions all build the table, and the
/// calibration integrates an ODE some thousand times.
physics::ContactLaw<double> calibrated_law(double p, double pt, double mu, double e) {
  static std::mutex mutex;
  static std::map<double, physics::ContactLaw<double>> known;
  std::lock_guard<std::mutex> lock(mutex);
  auto it = known.find(e);
  if (it == known.end()) it = known.emplace(e, physics::contact_law(1, 1, 0, e)).first;
  physics::ContactLaw<double> law = it->second;
  law.penalty = p;
  law.tangential_penalty = pt;
  law.friction = mu;
  return law;
}

}  // namespace

bool walls_move(const ParticleModel& model) {
  for (std::size_t i = 0; i < model.size(); ++i)
    if (model.motion[i] != Motion::Free &&
        (model.velocity[i].x != 0 || model.velocity[i].y != 0 || model.angular_velocity[i] != 0))
      return true;
  return false;
}

double material_restitution(const Material& m) {
  return m.restitution ? *m.restitution : physics::restitution_of_damping_ratio(m.damping);
}

std::vector<physics::ContactLaw<double>> contact_law_table(const std::vector<Material>& mats) {
  const std::size_t n = mats.size();
  std::vector<physics::ContactLaw<double>> table(n * n);
  // Penalties combine as springs in series (harmonic mean: p for equal materials); the
  // smoother surface sets the friction; restitutions average, and the damping ratios are
  // calibrated for the pair's restitution (docs/model.md, "Damping").
  auto harmonic = [](double a, double b) { return 2.0 * a * b / (a + b); };
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (b < a) {
        table[a * n + b] = table[b * n + a];  // the law is symmetric; calibrate once
        continue;
      }
      table[a * n + b] = calibrated_law(
          harmonic(mats[a].penalty, mats[b].penalty),
          harmonic(mats[a].tangential_penalty, mats[b].tangential_penalty),
          std::min(mats[a].friction, mats[b].friction),
          0.5 * (material_restitution(mats[a]) + material_restitution(mats[b])));
    }
  return table;
}

}  // namespace tridem
