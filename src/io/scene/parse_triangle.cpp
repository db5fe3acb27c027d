// [[triangle]] blocks: one explicit grain each.
#include "io/scene/scene_sections.hpp"
#include "io/scene/triangle_shape.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

namespace tridem::scene_detail {
namespace {

// `fixed` is the older, shorter spelling of `motion = "fixed"`; both may be given only if
// they agree, since a file saying both "fixed = true" and "prescribed" has a mistake in it.
Motion read_motion(TableReader& r) {
  const std::optional<bool> fixed = r.boolean("fixed");
  const std::optional<Motion> motion = r.choice_in<Motion>("motion", kMotionNames);
  if (fixed && motion && (*fixed != (*motion == Motion::Fixed)))
    r.fail("motion", fmt::format("conflicts with fixed = {}", *fixed ? "true" : "false"));
  if (motion) return *motion;
  return fixed.value_or(false) ? Motion::Fixed : Motion::Free;
}

}  // namespace

Movement read_movement(TableReader& r, std::string_view what, std::vector<MotionProgram>& programs,
                       std::vector<ProgramKnot>& knots) {
  Movement m;
  m.velocity = r.vec2("velocity").value_or(Vec2d{});
  m.angular_velocity = r.real("angular_velocity").value_or(0.0);
  m.motion = read_motion(r);
  if (m.motion == Motion::Fixed) {
    // A fixed grain with a velocity is contradictory; refusing beats guessing which was meant.
    if (m.velocity.x != 0 || m.velocity.y != 0)
      r.fail("velocity", fmt::format("a fixed {} can't have a velocity (use motion = "
                                     "\"prescribed\" for a moving wall)",
                                     what));
    if (m.angular_velocity != 0)
      r.fail("angular_velocity", fmt::format("a fixed {} can't have an angular velocity (use "
                                             "motion = \"prescribed\" for a moving wall)",
                                             what));
  }
  if (r.has("program")) {
    if (m.motion != Motion::Prescribed)
      r.fail("program", fmt::format("a motion program needs motion = \"prescribed\" (this {} "
                                    "is \"{}\")",
                                    what, m.motion == Motion::Fixed ? "fixed" : "free"));
    // The program sets the velocity at every instant; a second one would be ignored.
    if (r.has("velocity"))
      r.fail("velocity", fmt::format("a {} with a motion program takes its velocity from the "
                                     "program: remove velocity",
                                     what));
    if (r.has("angular_velocity"))
      r.fail("angular_velocity",
             fmt::format("a {} with a motion program takes its angular velocity from the "
                         "program: remove angular_velocity",
                         what));
    m.program = read_program(r, programs, knots);
  }
  return m;
}

TriangleSpec parse_triangle(const toml::table& table, const std::string& source, std::size_t number,
                            std::size_t id, const std::vector<Material>& materials,
                            std::vector<MotionProgram>& programs, std::vector<ProgramKnot>& knots) {
  TableReader r(table, source, fmt::format("[[triangle]] #{} (particle id {})", number, id));
  TriangleSpec t;
  t.material = lookup_material(r, materials);
  t.vertices = r.required(r.points<3>("vertices"), "vertices");
  if (auto problem = shape_problem(t.vertices)) r.fail("vertices", *problem);
  make_counter_clockwise(t.vertices);
  const Movement m = read_movement(r, "triangle", programs, knots);
  t.velocity = m.velocity;
  t.angular_velocity = m.angular_velocity;
  t.motion = m.motion;
  t.program = m.program;
  r.reject_unknown_keys();
  return t;
}

}  // namespace tridem::scene_detail
