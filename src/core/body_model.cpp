#include "core/body_model.hpp"

#include "tridem/error.hpp"

#include <algorithm>
#include <fmt/format.h>

namespace tridem {

BodyModel build_body_model(const Scene& scene, const std::vector<Vec2d>& centroid,
                           const std::vector<double>& mass, const std::vector<double>& inertia,
                           const std::vector<double>& longest_edge) {
  BodyModel b;
  if (!scene.has_bodies()) return b;
  const std::size_t n = scene.bodies.size();
  b.first.assign(n + 1, 0);
  b.centroid.resize(n);
  b.mass.resize(n);
  b.inertia.resize(n);
  b.half_size.resize(n);
  b.motion.resize(n);
  b.velocity.resize(n);
  b.angular_velocity.resize(n);
  b.program.assign(n, -1);
  b.body.assign(centroid.size(), -1);
  b.member_offset.resize(centroid.size());
  std::size_t expected_first = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const BodySpec& spec = scene.bodies[k];
    if (spec.first != expected_first || spec.count == 0 ||
        spec.first + spec.count > centroid.size())
      throw SceneError(fmt::format("{}: body id {}: its members [{}, {}) do not follow the "
                                   "previous body's within the {} triangles",
                                   scene.source, k, spec.first, spec.first + spec.count,
                                   centroid.size()));
    expected_first = spec.first + spec.count;
    b.first[k] = static_cast<std::int64_t>(spec.first);
    b.first[k + 1] = static_cast<std::int64_t>(expected_first);
    double m = 0;
    Vec2d moment{};
    double half = longest_edge[spec.first];
    for (std::size_t i = spec.first; i < expected_first; ++i) {
      m += mass[i];
      moment += centroid[i] * mass[i];
      half = std::min(half, longest_edge[i]);
    }
    // One member: its own centroid and inertia exactly, so that a lone triangle moves as
    // it does without bodies.
    const Vec2d c = spec.count == 1 ? centroid[spec.first] : moment / m;
    double inertia_c = 0;
    for (std::size_t i = spec.first; i < expected_first; ++i) {
      const Vec2d r = centroid[i] - c;
      b.member_offset[i] = r;
      b.body[i] = static_cast<std::int32_t>(k);
      inertia_c += inertia[i] + mass[i] * dot(r, r);  // parallel axes
    }
    b.centroid[k] = c;
    b.mass[k] = m;
    b.inertia[k] = inertia_c;
    b.half_size[k] = 0.5 * half;
    b.motion[k] = spec.motion;
    const bool fixed = spec.motion == Motion::Fixed;
    b.velocity[k] = fixed ? Vec2d{} : spec.velocity;
    b.angular_velocity[k] = fixed ? 0.0 : spec.angular_velocity;
    b.program[k] = spec.program;
  }
  if (expected_first != centroid.size())
    throw SceneError(fmt::format("{}: the bodies cover {} of the {} triangles", scene.source,
                                 expected_first, centroid.size()));
  return b;
}

}  // namespace tridem
