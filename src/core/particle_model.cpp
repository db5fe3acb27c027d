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
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace tridem {
namespace {

// The walls a program moves and a servo's length_between names: the bodies when the scene
// has bodies, else the triangles (the same ids the scene format gives them).
struct Walls {
  std::size_t count;
  const std::vector<Motion>& motion;
  const std::vector<Vec2d>& centroid;
  const std::vector<double>& angular_velocity;
  const std::vector<std::int32_t>& program;
  const char* what;  // "body id" or "particle id"
};

// Why wall `id` cannot carry a servo's length (it must keep its angle: the gap is measured
// from centroids), or nothing.
std::optional<std::string> not_a_length_wall(const Walls& w, const Scene& scene, std::int32_t id) {
  if (static_cast<std::size_t>(id) >= w.count)
    return fmt::format("{} is no wall of this scene (it has {} {}s, 0 to {})", id, w.count, w.what,
                       w.count - 1);
  const auto i = static_cast<std::size_t>(id);
  if (w.motion[i] == Motion::Free)
    return fmt::format("{} {} is free: name walls (fixed or prescribed)", w.what, id);
  bool turns = w.motion[i] == Motion::Prescribed && w.angular_velocity[i] != 0;
  if (const std::int32_t k = w.program[i];
      k >= 0 && static_cast<std::size_t>(k) < scene.programs.size()) {
    const MotionProgram& p = scene.programs[static_cast<std::size_t>(k)];
    turns = p.kind == ProgramKind::Rotation;
    if (p.kind == ProgramKind::Table)
      for (std::int32_t j = 0; j < p.knot_count; ++j)
        if (const auto knot = static_cast<std::size_t>(p.first_knot) + static_cast<std::size_t>(j);
            knot < scene.program_knots.size() && scene.program_knots[knot].angular_velocity != 0)
          turns = true;
  }
  if (turns)
    return fmt::format("{} {} turns: the gap is measured from the walls' centroids, so name "
                       "walls that only translate",
                       w.what, id);
  return std::nullopt;
}

// The extent along `axis` of wall `id`'s triangles at t = 0: [lo, hi] of its vertices.
std::pair<double, double> extent_along(const ParticleModel& m, std::size_t id, Vec2d axis) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if ((m.bodies.empty() ? i : static_cast<std::size_t>(m.bodies.body[i])) != id) continue;
    for (const Vec2d& o : m.offsets[i]) {
      const double s = dot(m.centroid[i] + o, axis);
      lo = std::min(lo, s);
      hi = std::max(hi, s);
    }
  }
  return {lo, hi};
}

// Each servo with length_between gets the axis it measures along (across its direction,
// from its first wall to its second) and the offset from the walls' centroids to the gap
// between their facing sides; walls that are not walls of the scene, that turn, that are
// free, the servo's own wall, or a gap <= 0 are refused. Returns each program's target
// force at t = 0 (0 for the others).
std::vector<double> resolve_servo_lengths(const Scene& scene, ParticleModel& m, const Walls& w) {
  std::vector<double> targets(m.programs.size(), 0.0);
  for (std::size_t k = 0; k < m.programs.size(); ++k) {
    MotionProgram& p = m.programs[k];
    if (!physics::follows_length(p)) continue;
    const std::int32_t a = p.length_walls[0], b = p.length_walls[1];
    const std::string where = fmt::format("{}: the servo of program {}: length_between = [{}, {}]",
                                          scene_label(scene), k, a, b);
    for (const std::int32_t id : {a, b}) {
      if (auto why = not_a_length_wall(w, scene, id)) throw SceneError(where + ": " + *why);
      if (w.program[static_cast<std::size_t>(id)] == static_cast<std::int32_t>(k))
        throw SceneError(fmt::format("{}: {} {} is the servo's own wall: name the two walls "
                                     "the length lies between",
                                     where, w.what, id));
    }
    Vec2d axis{-p.direction.y, p.direction.x};
    const auto ua = static_cast<std::size_t>(a), ub = static_cast<std::size_t>(b);
    if (dot(w.centroid[ub] - w.centroid[ua], axis) < 0) axis = Vec2d{} - axis;
    const double gap = extent_along(m, ub, axis).first - extent_along(m, ua, axis).second;
    if (!(gap > 0))
      throw SceneError(fmt::format(
          "{}: the walls' gap across the servo's direction ({}, {}) is {} m at t = 0, not > 0: "
          "name two walls on either side of the sample, across the direction the servo moves",
          where, axis.x, axis.y, gap));
    p.length_axis = axis;
    p.length_offset = dot(w.centroid[ub] - w.centroid[ua], axis) - gap;
    targets[k] = physics::servo_target_of_length(p, gap);
  }
  return targets;
}

// Each programmed wall (a triangle, or a body when the scene has bodies) gets its origin,
// the centroid it starts from, and the program's velocity at t = 0; a program of no wall,
// of two walls, of a wall that is not prescribed or out of range is refused (a scene built
// in code may not have been through the reader).
void resolve_programs(const Scene& scene, ParticleModel& m) {
  m.programs = scene.programs;
  m.program_knots = scene.program_knots;
  const bool bodies = !m.bodies.empty();
  const Walls walls =
      bodies ? Walls{m.bodies.size(),           m.bodies.motion,  m.bodies.centroid,
                     m.bodies.angular_velocity, m.bodies.program, "body id"}
             : Walls{m.size(), m.motion, m.centroid, m.angular_velocity, m.program, "particle id"};
  const std::vector<double> targets = resolve_servo_lengths(scene, m, walls);
  std::vector<int> users(scene.programs.size(), 0);
  // `label()` names the wall in a refusal: made only then (a string for each of 10^7
  // particles, most of them with no program, was a second of a large set-up).
  auto resolve = [&](std::int32_t k, Motion motion, Vec2d centroid, Vec2d& velocity,
                     double& angular_velocity, auto label) {
    if (k < 0) return;
    const std::string wall = label();
    if (static_cast<std::size_t>(k) >= scene.programs.size() || motion != Motion::Prescribed)
      throw SceneError(fmt::format("{}: {}: program {} {}", scene_label(scene), wall, k,
                                   motion != Motion::Prescribed ? "on a wall that is not prescribed"
                                                                : "out of range"));
    MotionProgram& p = m.programs[static_cast<std::size_t>(k)];
    if (p.kind == ProgramKind::Table &&
        (p.knot_count < 1 || p.first_knot < 0 ||
         static_cast<std::size_t>(p.first_knot) + static_cast<std::size_t>(p.knot_count) >
             scene.program_knots.size()))
      throw SceneError(fmt::format("{}: {}: its velocity table's entries are out of range",
                                   scene_label(scene), wall));
    if (++users[static_cast<std::size_t>(k)] > 1)
      throw SceneError(fmt::format("{}: {}: program {} already moves another wall",
                                   scene_label(scene), wall, k));
    p.origin = centroid;
    const physics::ProgramTable table{m.programs.data(), m.program_knots.data(), targets.data()};
    physics::program_velocity(table, k, 0.0, Vec2d{}, velocity, angular_velocity);
  };
  if (m.bodies.empty()) {
    for (std::size_t i = 0; i < m.size(); ++i)
      resolve(m.program[i], m.motion[i], m.centroid[i], m.velocity[i], m.angular_velocity[i],
              [i] { return fmt::format("particle id {}", i); });
    return;
  }
  std::fill(m.program.begin(), m.program.end(), -1);  // the bodies carry them
  BodyModel& b = m.bodies;
  for (std::size_t k = 0; k < b.size(); ++k)
    resolve(b.program[k], b.motion[k], b.centroid[k], b.velocity[k], b.angular_velocity[k],
            [k] { return fmt::format("body id {}", k); });
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
  // On the threads (a 10^7 set-up, issue 12); a refusal names the lowest id at fault, as
  // one thread in order would.
  const auto count = static_cast<std::ptrdiff_t>(n);
  std::ptrdiff_t first_bad = count;
#pragma omp parallel for schedule(static) reduction(min : first_bad) if (count > 65536)
  for (std::ptrdiff_t signed_i = 0; signed_i < count; ++signed_i) {
    const auto i = static_cast<std::size_t>(signed_i);
    const TriangleSpec& spec = scene.triangles[i];
    // The scene reader's rules: a scene built in code may not have been through it.
    if (scene_detail::triangle_problem(spec, scene.materials.size())) {
      first_bad = std::min(first_bad, signed_i);
      continue;
    }
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
  if (first_bad < count) {
    const auto i = static_cast<std::size_t>(first_bad);
    throw SceneError(
        fmt::format("{}: particle id {}: {}", scene_label(scene), i,
                    *scene_detail::triangle_problem(scene.triangles[i], scene.materials.size())));
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

std::vector<std::uint8_t> servo_wall_mask(const ParticleModel& model) {
  std::vector<std::uint8_t> mask;
  for (std::size_t i = 0; i < model.size(); ++i) {
    const std::int32_t k = model.program[i];
    if (k < 0 || model.programs[static_cast<std::size_t>(k)].kind != ProgramKind::Servo) continue;
    mask.resize(model.size(), 0);
    mask[i] = 1;
  }
  return mask;
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
