// The `program = {...}` table of a prescribed [[triangle]] or [[body]]: a motion program
// (rotation about a point, a velocity table, an oscillation) or a servo. The physics of
// each is physics/motion_program.hpp; here only the keys and their refusals.
#include "io/scene/scene_sections.hpp"
#include "tridem/setting_names.hpp"

#include <climits>
#include <cmath>
#include <fmt/format.h>

namespace tridem::scene_detail {
namespace {

double positive(TableReader& r, std::string_view key, std::string_view what) {
  const double v = r.required(r.real(key), key);
  if (!(v > 0)) r.fail(key, fmt::format("{} must be > 0, got {}", what, v));
  return v;
}

// A direction as given (any length but zero), made a unit vector.
Vec2d unit_direction(TableReader& r) {
  const Vec2d d = r.required(r.vec2("direction"), "direction");
  const double length = std::hypot(d.x, d.y);
  if (!(length > 0)) r.fail("direction", "the direction must not be [0, 0]");
  return d / length;
}

void read_rotation(TableReader& r, MotionProgram& p) {
  p.center = r.required(r.vec2("center"), "center");
  p.angular_velocity = r.required(r.real("angular_velocity"), "angular_velocity");
}

void read_table(TableReader& r, MotionProgram& p, std::vector<ProgramKnot>& knots) {
  const std::vector<double> times = r.required(r.reals("times"), "times");
  const std::vector<Vec2d> velocities =
      r.required(r.point_list("velocities", "an array of [vx, vy]"), "velocities");
  const std::vector<double> angular = r.has("angular_velocities")
                                          ? *r.reals("angular_velocities")
                                          : std::vector<double>(times.size(), 0.0);
  if (velocities.size() != times.size())
    r.fail("velocities", fmt::format("{} velocities for {} times: give one [vx, vy] per time",
                                     velocities.size(), times.size()));
  if (angular.size() != times.size())
    r.fail("angular_velocities",
           fmt::format("{} angular velocities for {} times: give one per time", angular.size(),
                       times.size()));
  if (times[0] < 0) r.fail("times", fmt::format("times must be >= 0, got {}", times[0]));
  for (std::size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1]))
      r.fail("times", fmt::format("times must increase strictly: entry {} ({}) follows {}", k + 1,
                                  times[k], times[k - 1]));
  p.first_knot = static_cast<std::int32_t>(knots.size());
  p.knot_count = static_cast<std::int32_t>(times.size());
  for (std::size_t k = 0; k < times.size(); ++k)
    knots.push_back({times[k], velocities[k], angular[k]});
}

void read_oscillation(TableReader& r, MotionProgram& p) {
  p.amplitude = positive(r, "amplitude", "the amplitude");
  p.frequency = positive(r, "frequency", "the frequency (Hz)");
  p.direction = unit_direction(r);
  p.phase = r.real("phase").value_or(0.0);
}

// length_between = [A, B]: two body ids (particle ids without bodies), distinct and >= 0;
// whether they are walls of this scene, and their gap, is checked once the scene is whole
// (core/particle_model).
void read_length_between(TableReader& r, MotionProgram& p) {
  const std::vector<std::int64_t> ids = r.required(r.integers("length_between"), "length_between");
  if (ids.size() != 2)
    r.fail("length_between",
           fmt::format("expected two wall ids [A, B] (body ids; particle ids without bodies), "
                       "got {} values",
                       ids.size()));
  for (const std::int64_t id : ids)
    if (id < 0 || id > INT32_MAX)
      r.fail("length_between", fmt::format("{} is not a body id (ids count from 0)", id));
  if (ids[0] == ids[1])
    r.fail("length_between",
           fmt::format("names wall {} twice: give the two walls the length lies between", ids[0]));
  p.length_walls[0] = static_cast<std::int32_t>(ids[0]);
  p.length_walls[1] = static_cast<std::int32_t>(ids[1]);
}

void read_servo(TableReader& r, MotionProgram& p) {
  p.direction = unit_direction(r);
  const bool force = r.has("force");
  const bool stress = r.has("stress");
  if (force == stress)
    r.fail_table("a servo needs its target: give force = F (N per unit thickness) or stress = S "
                 "with length = L (Pa and m: F = S·L) or with length_between = [A, B] (the gap "
                 "between two walls, followed as they move), not both");
  if (force) {
    p.target_force = r.required(r.real("force"), "force");
    for (const char* key : {"length", "length_between"})
      if (r.has(key)) r.fail(key, fmt::format("{} goes with stress, not with force", key));
  } else if (r.has("length_between")) {
    if (r.has("length"))
      r.fail("length", "give length = L (a fixed length) or length_between = [A, B] (the gap "
                       "between two walls as they move), not both");
    p.stress = r.required(r.real("stress"), "stress");
    read_length_between(r, p);
  } else {
    p.target_force =
        r.required(r.real("stress"), "stress") * positive(r, "length", "the loaded length");
  }
  if (p.target_force < 0 || p.stress < 0)
    r.fail(force ? "force" : "stress",
           "the target must be >= 0 (a contact only pushes): reverse direction instead");
  p.gain = positive(r, "gain", "the gain (m/s per N)");
  p.max_speed = positive(r, "max_speed", "the maximum speed (m/s)");
}

}  // namespace

std::int32_t read_program(TableReader& wall, std::vector<MotionProgram>& programs,
                          std::vector<ProgramKnot>& knots) {
  const toml::node* node = wall.node("program");
  const toml::table* table = node ? node->as_table() : nullptr;
  if (!table)
    wall.fail("program", fmt::format("expected a table such as {{ kind = \"rotation\", center = "
                                     "[x, y], angular_velocity = w }}, got {}",
                                     node ? describe_type(node->type()) : "nothing"));
  TableReader r(*table, wall.source(), wall.context() + ", its program");
  MotionProgram p;
  p.kind = r.required(r.choice_in<ProgramKind>("kind", kProgramKindNames), "kind");
  switch (p.kind) {
    case ProgramKind::Rotation: read_rotation(r, p); break;
    case ProgramKind::Table: read_table(r, p, knots); break;
    case ProgramKind::Oscillation: read_oscillation(r, p); break;
    case ProgramKind::Servo: read_servo(r, p); break;
  }
  r.reject_unknown_keys();
  programs.push_back(p);
  return static_cast<std::int32_t>(programs.size() - 1);
}

}  // namespace tridem::scene_detail
