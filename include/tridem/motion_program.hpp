#pragma once
// A prescribed wall's motion program, as the scene gives it and the solvers run it
// (src/physics/motion_program.hpp evaluates it; docs/scene-format.md, "program").
// Plain data, so that a backend can copy the list to its device as it is.
//
// C++17: the CUDA sources include it.
#include "tridem/vec2.hpp"

#include <cstdint>

namespace tridem {

enum class ProgramKind : std::int32_t { Rotation = 0, Table = 1, Oscillation = 2, Servo = 3 };

/// One entry of a velocity table: from `time` on the velocity goes linearly to the next
/// entry's (held after the last one, and before the first one).
struct ProgramKnot {
  double time = 0;
  Vec2d velocity{};
  double angular_velocity = 0;
};

/// One wall's program, resolved for the run: `origin` is the wall's centroid at t = 0
/// (its angle is 0 then, as every particle's and body's).
struct MotionProgram {
  ProgramKind kind = ProgramKind::Rotation;
  Vec2d origin{};
  // Rotation: about `center` at `angular_velocity` (rad/s, counter-clockwise positive).
  Vec2d center{};
  double angular_velocity = 0;
  // Oscillation: origin + amplitude·(sin(2π·frequency·t + phase) − sin(phase))·direction.
  // Servo: the unit direction it moves along to press harder.
  Vec2d direction{};
  double amplitude = 0, frequency = 0, phase = 0;
  // Servo: velocity = clamp(gain·(target_force − F_n), −max_speed, max_speed)·direction,
  // F_n = −F·direction the normal force the grains push it back with (N per unit thickness).
  double target_force = 0, gain = 0, max_speed = 0;
  // Servo with `length_between`: the target is stress × the current gap between walls
  // length_walls[0] and [1] (body ids, the particle ids of a scene without bodies), measured
  // along length_axis (the unit vector across `direction`, from the first wall to the
  // second): the distance of their centroids along it less length_offset, the part of it
  // the two walls themselves fill (their reach past their centroids toward each other, from
  // the scene's poses: the walls only translate). target_force is unused then; -1: a fixed
  // target. core/particle_model fills axis and offset.
  double stress = 0;
  std::int32_t length_walls[2] = {-1, -1};
  Vec2d length_axis{};
  double length_offset = 0;
  // Table: its entries are ProgramTable::knots[first_knot, first_knot + knot_count).
  std::int32_t first_knot = 0, knot_count = 0;
};

}  // namespace tridem
