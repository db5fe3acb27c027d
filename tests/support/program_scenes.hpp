#pragma once
// Scenes with motion programs and servo walls, shared by the validation, parity and restart
// tests.
#include "support/lattice_scenes.hpp"
#include "support/scene_builder.hpp"

#include <algorithm>

namespace tridem::test {

/// jostling_pile(columns, rows) whose right wall is a servo pushing left to 50 N/m (gain
/// 2e-5 m/s/N, at most 0.1 m/s) and whose left wall oscillates (1 cm at 20 Hz along x).
inline Scene programmed_pile(int columns = 6, int rows = 4) {
  Scene s = jostling_pile(columns, rows);
  s.triangles[2].motion = Motion::Prescribed;
  s.triangles[2].program = 0;
  s.triangles[1].motion = Motion::Prescribed;
  s.triangles[1].program = 1;
  MotionProgram servo;
  servo.kind = ProgramKind::Servo;
  servo.direction = {-1, 0};
  servo.target_force = 50;
  servo.gain = 2e-5;
  servo.max_speed = 0.1;
  s.programs.push_back(servo);
  MotionProgram wiggle;
  wiggle.kind = ProgramKind::Oscillation;
  wiggle.amplitude = 0.01;
  wiggle.frequency = 20;
  wiggle.direction = {1, 0};
  s.programs.push_back(wiggle);
  return s;
}

/// The walls of servo_box: their particle ids, the lid's program and the servo's stress.
struct ServoBox {
  static constexpr std::size_t kFloor = 0, kLeft = 1, kRight = 2, kLid = 3;
  static constexpr double kHeight0 = 0.45;     ///< the lid's bottom above the floor at t = 0, m
  static constexpr double kStress = 5000;      ///< the side servo's stress, Pa
  static constexpr double kLidTravel = 0.07;   ///< how far the lid comes down, m (by 0.8 s)
  static constexpr double kLidCentroid = 0.3;  ///< the lid's centroid above its bottom, m
};

/// `rows` (5 by default) rows of lattice triangles (side 0.1 m, each shrunk to 0.95 about its
/// centroid: they start apart) under gravity in a box 0.6 m wide: the floor and the left wall
/// fixed, the right wall a servo pushing left at ServoBox::kStress, and a wide lid 0.45 m above the
/// floor (0.017 m above the grains) that comes down at 0.1 m/s, from 0.05 s to 0.8 s (its
/// velocity ramped over 0.05 s at each end), by 0.07 m: the sample's height shrinks by 16 %
/// and it spreads against the servo. With `follow`, the servo's length is the gap between
/// the floor and the lid (length_between = [floor, lid]); without, the fixed length of the
/// start, 0.45 m.
inline Scene servo_box(bool follow, int rows = 5) {
  Scene s = empty_scene(1e7, 2000, 0.2, 0);
  s.simulation.gravity = {0, -9.81};
  s.simulation.safety = 0.3;
  s.simulation.local_damping = 0.3;
  const double width = 0.6, top = 1.0, h0 = ServoBox::kHeight0;
  s.triangles.push_back(floor_triangle(-1, width + 2, 0));
  s.triangles.push_back(triangle({0, -0.1}, {0, top}, {-1, 0.45}, {}, Motion::Fixed));
  TriangleSpec right =
      triangle({width, top}, {width, -0.1}, {width + 1, 0.45}, {}, Motion::Prescribed);
  right.program = 0;
  s.triangles.push_back(right);
  const double t = ServoBox::kLidCentroid;  // a third of the lid's height
  TriangleSpec lid =
      triangle({-1, h0}, {width + 2, h0}, {0.5 * width, h0 + 3 * t}, {}, Motion::Prescribed);
  lid.program = 1;
  s.triangles.push_back(lid);
  MotionProgram servo;
  servo.kind = ProgramKind::Servo;
  servo.direction = {-1, 0};
  servo.gain = 1e-4;  // stable without dashpots; settles in about 0.1 s
  servo.max_speed = 0.1;
  if (follow) {
    servo.stress = ServoBox::kStress;
    servo.length_walls[0] = static_cast<std::int32_t>(ServoBox::kFloor);
    servo.length_walls[1] = static_cast<std::int32_t>(ServoBox::kLid);
  } else {
    servo.target_force = ServoBox::kStress * h0;
  }
  s.programs.push_back(servo);
  MotionProgram lid_motion;
  lid_motion.kind = ProgramKind::Table;
  lid_motion.first_knot = 0;
  lid_motion.knot_count = 4;
  // 0.1 m/s held from 0.1 s to 0.75 s, ramped over 0.05 s at each end: 0.07 m in all.
  s.program_knots = {
      {0.05, {0, 0}, 0}, {0.1, {0, -0.1}, 0}, {0.75, {0, -0.1}, 0}, {0.8, {0, 0}, 0}};
  s.programs.push_back(lid_motion);
  const double a = 0.1;
  for (int j = 0; j < rows; ++j)
    for (int k = -j; (j + k) * a / 2 + a <= width + 1e-9; ++k)
      s.triangles.push_back(lattice_triangle(k, j, a, 0.95));
  return s;
}

/// servo_box as bodies: each wall a body of one triangle (body ids 0 to 3, as the
/// particle ids), each pair of neighbours in the grains' order one rigid body of two (the last one
/// alone).
inline Scene servo_box_of_bodies(bool follow, int rows = 5) {
  Scene s = servo_box(follow, rows);
  for (std::size_t k = 0; k < 4; ++k) {
    BodySpec wall;
    wall.first = k;
    wall.count = 1;
    wall.motion = s.triangles[k].motion;
    wall.program = s.triangles[k].program;
    s.bodies.push_back(wall);
  }
  for (std::size_t first = 4; first < s.triangles.size(); first += 2) {
    BodySpec pair;
    pair.first = first;
    pair.count = std::min<std::size_t>(2, s.triangles.size() - first);
    s.bodies.push_back(pair);
  }
  return s;
}

}  // namespace tridem::test
