// scene_fingerprint: FNV-1a over the bit patterns of what defines the particles. Generated
// triangles are reproducible (seeded), so a generated scene has a stable fingerprint too.
#include "tridem/checkpoint.hpp"

#include <bit>

namespace tridem {

namespace {

class Fnv1a {
 public:
  void add(std::uint64_t v) {
    for (int k = 0; k < 8; ++k) {
      hash_ ^= (v >> (8 * k)) & 0xFFu;
      hash_ *= 0x100000001B3ull;
    }
  }
  void add(double v) { add(std::bit_cast<std::uint64_t>(v)); }
  std::uint64_t value() const { return hash_; }

 private:
  std::uint64_t hash_ = 0xCBF29CE484222325ull;
};

}  // namespace

std::uint64_t scene_fingerprint(const Scene& scene) {
  Fnv1a h;
  h.add(std::uint64_t{scene.triangles.size()});
  for (const TriangleSpec& t : scene.triangles) {
    h.add(static_cast<std::uint64_t>(t.material));
    h.add(static_cast<std::uint64_t>(t.motion));
    for (const Vec2d& v : t.vertices) {
      h.add(v.x);
      h.add(v.y);
    }
    h.add(t.velocity.x);
    h.add(t.velocity.y);
    h.add(t.angular_velocity);
  }
  for (const Material& m : scene.materials) h.add(m.density);
  // Bodies of several triangles group the triangles: another grouping is another scene.
  // Added only when there are some, so every bodiless scene keeps its fingerprint.
  if (scene.has_bodies()) {
    h.add(std::uint64_t{scene.bodies.size()});
    for (const BodySpec& b : scene.bodies) {
      h.add(std::uint64_t{b.first});
      h.add(std::uint64_t{b.count});
      h.add(static_cast<std::uint64_t>(b.motion));
      h.add(b.velocity.x);
      h.add(b.velocity.y);
      h.add(b.angular_velocity);
    }
  }
  // Motion programs move walls: another program is another run. Added only when there are
  // some, so every scene without programs keeps its fingerprint.
  if (!scene.programs.empty()) {
    h.add(std::uint64_t{scene.programs.size()});
    // program + 1 in 64 bits: -1 (none) hashes as 0, as it always has.
    for (const TriangleSpec& t : scene.triangles)
      h.add(static_cast<std::uint64_t>(std::int64_t{t.program} + 1));
    for (const BodySpec& b : scene.bodies)
      h.add(static_cast<std::uint64_t>(std::int64_t{b.program} + 1));
    for (const MotionProgram& p : scene.programs) {
      h.add(static_cast<std::uint64_t>(p.kind));
      for (double v : {p.center.x, p.center.y, p.angular_velocity, p.direction.x, p.direction.y,
                       p.amplitude, p.frequency, p.phase, p.target_force, p.gain, p.max_speed})
        h.add(v);
      h.add(static_cast<std::uint64_t>(p.first_knot));
      h.add(static_cast<std::uint64_t>(p.knot_count));
      // A servo that follows a length (only then, so other programs keep their prints).
      if (p.length_walls[0] >= 0) {
        h.add(p.stress);
        h.add(static_cast<std::uint64_t>(p.length_walls[0]));
        h.add(static_cast<std::uint64_t>(p.length_walls[1]));
      }
    }
    for (const ProgramKnot& k : scene.program_knots)
      for (double v : {k.time, k.velocity.x, k.velocity.y, k.angular_velocity}) h.add(v);
  }
  // Bonds likewise (only when there are some): other bonds are another scene.
  if (!scene.bonds.empty()) {
    h.add(std::uint64_t{scene.bonds.size()});
    for (const BondSpec& b : scene.bonds) {
      h.add(std::uint64_t{b.a});
      h.add(std::uint64_t{b.b});
    }
  }
  return h.value();
}

}  // namespace tridem
