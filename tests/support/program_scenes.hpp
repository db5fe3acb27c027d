#pragma once
// Scenes with motion programs and servo walls, shared by the validation, parity and restart
// tests.
#include "support/scene_builder.hpp"

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

}  // namespace tridem::test
