#pragma once
// The mechanical model of each triangle, built once from a scene in double precision:
// body-frame vertex offsets, mass, inertia and sizes. Solvers copy it into their own real
// type and layout.
#include "core/body_model.hpp"
#include "physics/contact_laws.hpp"
#include "tridem/scene.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace tridem {

/// The ids by which a solver's messages (a blow-up, a too deep pair) name its particles and
/// bodies; empty: their index. A solver numbering the particles by place
/// (core/place_numbered_solver) runs on the scene's particles in another order and names
/// them by their scene ids.
struct ShownIds {
  std::vector<std::int64_t> particle, body;

  std::int64_t of_particle(std::int64_t i) const {
    return particle.empty() ? i : particle[static_cast<std::size_t>(i)];
  }
  std::int64_t of_body(std::int64_t b) const {
    return body.empty() ? b : body[static_cast<std::size_t>(b)];
  }
};

struct ParticleModel {
  std::vector<std::array<Vec2d, 3>> offsets;  ///< body-frame vertices about the centroid, CCW
  std::vector<Vec2d> centroid;
  std::vector<double> area, mass, inertia;    ///< per unit thickness
  std::vector<double> longest_edge, smallest_height;
  std::vector<int> material;
  std::vector<Motion> motion;
  std::vector<Vec2d> velocity;
  std::vector<double> angular_velocity;
  /// Index into `programs` of each triangle's motion program, -1 for none (a member of a
  /// body of several triangles: -1, its body's is BodyModel::program).
  std::vector<std::int32_t> program;
  /// The scene's programs with their origins (the wall's centroid at t = 0), and the
  /// velocity tables' entries: what every backend's integrator reads.
  std::vector<MotionProgram> programs;
  std::vector<ProgramKnot> program_knots;
  /// Bodies of several triangles; empty without them. A member's motion, velocity and
  /// angular velocity above are then its body's rigid motion at its centroid.
  BodyModel bodies;
  /// The ids by which messages name the particles and bodies (ShownIds).
  ShownIds shown_ids;

  std::size_t size() const { return centroid.size(); }
  /// f(a, b) for each per-particle array a above (shown_ids aside) and the same array b of
  /// `other` (a ParticleModel, const or not): a model's particles put in another order
  /// (core/place_numbered_solver) move in every one of them.
  template <class Other, class F>
  void for_each_particle_array(Other& other, F&& f) {
    f(offsets, other.offsets);
    f(centroid, other.centroid);
    f(area, other.area);
    f(mass, other.mass);
    f(inertia, other.inertia);
    f(longest_edge, other.longest_edge);
    f(smallest_height, other.smallest_height);
    f(material, other.material);
    f(motion, other.motion);
    f(velocity, other.velocity);
    f(angular_velocity, other.angular_velocity);
    f(program, other.program);
  }
};

/// Bytes of one particle's model (what the scene reader budgets for, and the memory
/// estimate counts).
inline constexpr std::size_t kParticleModelBytes =
    sizeof(std::array<Vec2d, 3>) + 2 * sizeof(Vec2d) + 6 * sizeof(double) + sizeof(int) +
    sizeof(Motion) + sizeof(std::int32_t);

/// True when some fixed or prescribed particle starts with a velocity or follows a motion
/// program, so that walls do work on the grains (the energy budget's wall work).
bool walls_move(const ParticleModel& model);

/// One byte per particle, 1 for a wall on a servo program (its law reads its whole load);
/// empty when no particle is one.
std::vector<std::uint8_t> servo_wall_mask(const ParticleModel& model);

/// Builds the model; throws SceneError for a scene without triangles, and one naming the
/// particle for a triangle validate_scene refuses (scene_detail::triangle_problem: a
/// degenerate shape, a non-finite value, a bad material index, a fixed one that moves).
ParticleModel build_particle_model(const Scene& scene);

/// The material's coefficient of restitution: `restitution`, or the one its legacy damping
/// ratio ζ stands for, exp(−πζ/√(1−ζ²)) (docs/scene-format.md).
double material_restitution(const Material& m);

/// Contact law for every ordered pair of materials, row-major (a·n + b).
std::vector<physics::LawParameters<double>> contact_law_table(const std::vector<Material>& m);

}  // namespace tridem
