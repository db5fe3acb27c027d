#pragma once
// Motion programs of prescribed walls (triangles and bodies): the pose and velocity of a
// wall as a function of time (a rotation about a point, a table of velocities, a sinusoidal
// oscillation), or of the contact force on it (a servo holding a target normal force: a
// fixed one, or stress × the current gap between two walls, computed once per step).
// Every backend advances a programmed wall with program_step; a program is data uploaded
// once (ProgramTable), evaluated from the time, so no backend sends anything per step.
//
// What the contact law sees: at the end of the step that reaches t_{n+1} = (n+1)·dt the
// wall's pose is the program's exact pose at t_{n+1} (a closed form of the time, never a
// sum of steps, so a rotation does not drift) and its velocity the program's velocity at
// that instant; the next step's contacts use both. A servo has no closed form: its velocity
// is set from the force of the step (the law below) and its pose advances by that velocity
// times dt, as symplectic Euler advances a free body.
//
// C++17: the CUDA sources include it.
#include "physics/integrate.hpp"
#include "tridem/hd.hpp"
#include "tridem/motion_program.hpp"
#include "tridem/vec2.hpp"

#include <cmath>
#include <cstdint>

namespace tridem::physics {

using tridem::MotionProgram;
using tridem::ProgramKind;
using tridem::ProgramKnot;

/// What the integrators read: every program, the knots of the tables and, when some servo
/// follows a length (length_between), each program's target force of the step, which the
/// backend fills before its Check stage with servo_targets_at (read at [k] only for those
/// servos; null when there are none).
struct ProgramTable {
  const MotionProgram* programs = nullptr;
  const ProgramKnot* knots = nullptr;
  const double* targets = nullptr;
};

/// Whether servo p's target force follows the gap between two walls (length_between).
TRIDEM_HD inline bool follows_length(const MotionProgram& p) {
  return p.kind == ProgramKind::Servo && p.length_walls[0] >= 0;
}

/// The gap between the two walls of p's length_between whose centroids are `first` and
/// `second` now, measured across p's direction (exact while they translate).
TRIDEM_HD inline double servo_length(const MotionProgram& p, Vec2d first, Vec2d second) {
  return dot(second - first, p.length_axis) - p.length_offset;
}

/// stress × length: the force that holds the stress over that length; 0 once the walls
/// have met (a contact only pushes).
TRIDEM_HD inline double servo_target_of_length(const MotionProgram& p, double length) {
  return length > 0 ? p.stress * length : 0.0;
}

/// The target force of program k, a servo that follows a length, for walls whose centroids
/// are (x[id], y[id]) (the particles' fields, or the bodies' in a scene with bodies): the
/// state at the start of the step, before anything is written, so that every thread of the
/// step and both of its readings of the law (the pose, then the velocity) see one target.
TRIDEM_HD inline double servo_target_at(const MotionProgram& p, const double* x, const double* y) {
  const std::int32_t a = p.length_walls[0], b = p.length_walls[1];
  return servo_target_of_length(p, servo_length(p, Vec2d{x[a], y[a]}, Vec2d{x[b], y[b]}));
}

/// The target force servo k holds at this step.
TRIDEM_HD inline double servo_target(const ProgramTable& table, std::int32_t k) {
  const MotionProgram& p = table.programs[k];
  return follows_length(p) ? table.targets[k] : p.target_force;
}

namespace program_detail {

/// A velocity table's velocity at t and the integral of it from 0 to t (the displacement
/// and the angle turned): segment by segment, each a trapezoid, so the position is exact
/// for piecewise-linear velocities up to rounding.
TRIDEM_HD inline void table_at(const ProgramKnot* k, int count, double t, Vec2d& velocity,
                               double& angular_velocity, Vec2d& displacement, double& angle) {
  // Before the first entry its velocity is held from t = 0.
  const double t0 = k[0].time < t ? k[0].time : t;
  displacement = k[0].velocity * t0;
  angle = k[0].angular_velocity * t0;
  velocity = k[0].velocity;
  angular_velocity = k[0].angular_velocity;
  for (int j = 0; j + 1 < count; ++j) {
    const ProgramKnot& a = k[j];
    const ProgramKnot& b = k[j + 1];
    if (!(t > a.time)) return;
    const double end = t < b.time ? t : b.time;
    const double s = (end - a.time) / (b.time - a.time);
    const Vec2d v_end = a.velocity + (b.velocity - a.velocity) * s;
    const double w_end = a.angular_velocity + (b.angular_velocity - a.angular_velocity) * s;
    const double h = 0.5 * (end - a.time);
    displacement += (a.velocity + v_end) * h;
    angle += (a.angular_velocity + w_end) * h;
    velocity = v_end;
    angular_velocity = w_end;
  }
  const ProgramKnot& last = k[count - 1];
  if (t > last.time) {
    displacement += last.velocity * (t - last.time);
    angle += last.angular_velocity * (t - last.time);
  }
}

}  // namespace program_detail

/// Pose (centroid, angle) and velocity at time t of a program that is a function of time
/// (every kind but Servo).
struct ProgramPose {
  Vec2d c;
  double theta;
  Vec2d v;
  double w;
};

TRIDEM_HD inline ProgramPose program_pose_at(const ProgramTable& table, const MotionProgram& p,
                                             double t) {
  ProgramPose out{p.origin, 0.0, {}, 0.0};
  switch (p.kind) {
    case ProgramKind::Rotation: {
      const double a = p.angular_velocity * t;
      const double c = cos(a), s = sin(a);
      const Vec2d r = p.origin - p.center;
      const Vec2d turned{c * r.x - s * r.y, s * r.x + c * r.y};
      out.c = p.center + turned;
      out.theta = a;
      out.v = Vec2d{-turned.y, turned.x} * p.angular_velocity;
      out.w = p.angular_velocity;
      break;
    }
    case ProgramKind::Table: {
      Vec2d d{};
      program_detail::table_at(table.knots + p.first_knot, p.knot_count, t, out.v, out.w, d,
                               out.theta);
      out.c = p.origin + d;
      break;
    }
    case ProgramKind::Oscillation: {
      const double two_pi_f = 6.283185307179586 * p.frequency;
      const double arg = two_pi_f * t + p.phase;
      out.c = p.origin + p.direction * (p.amplitude * (sin(arg) - sin(p.phase)));
      out.v = p.direction * (p.amplitude * two_pi_f * cos(arg));
      break;
    }
    case ProgramKind::Servo: break;  // no closed form: program_step
  }
  return out;
}

/// The servo law: the velocity along the servo's direction for the contact force `force`
/// on the wall and the target force `target` (servo_target).
TRIDEM_HD inline Vec2d servo_velocity(const MotionProgram& p, double target, Vec2d force) {
  const double pushed_back = -dot(force, p.direction);
  double speed = p.gain * (target - pushed_back);
  if (speed > p.max_speed) speed = p.max_speed;
  if (speed < -p.max_speed) speed = -p.max_speed;
  return p.direction * speed;
}

/// The velocity and angular velocity of a programmed wall at the end of the step that
/// reaches `t_new`, given the step's contact force on it (read only by a servo).
TRIDEM_HD inline void program_velocity(const ProgramTable& table, std::int32_t k, double t_new,
                                       Vec2d force, Vec2d& v, double& w) {
  const MotionProgram& p = table.programs[k];
  if (p.kind == ProgramKind::Servo) {
    v = servo_velocity(p, servo_target(table, k), force);
    w = 0;
    return;
  }
  const ProgramPose q = program_pose_at(table, p, t_new);
  v = q.v;
  w = q.w;
}

/// The step of programmed wall k from pose (c, theta) to the end of the step that reaches
/// `t_new`: exact pose and velocity for programs of time; for a servo, the law's velocity
/// and the position advanced by it (its angle kept).
template <class Pose>
TRIDEM_HD inline Pose program_step(const ProgramTable& table, std::int32_t k, Pose p, double t_new,
                                   double dt, Vec2d force) {
  const MotionProgram& prog = table.programs[k];
  if (prog.kind == ProgramKind::Servo) {
    p.v = servo_velocity(prog, servo_target(table, k), force);
    p.w = 0;
    p.c += p.v * dt;
    return p;
  }
  const ProgramPose q = program_pose_at(table, prog, t_new);
  p.c = q.c;
  p.theta = q.theta;
  p.v = q.v;
  p.w = q.w;
  return p;
}

/// The time at the end of step `step` (0-based) of length dt: a product, never a sum of
/// steps, so that programs see no accumulated rounding.
TRIDEM_HD inline double time_after_step(std::int64_t step, double dt) {
  return static_cast<double>(step + 1) * dt;
}

/// A body's pose after one step as every backend advances it: stepped_pose, or, for a wall
/// with a motion program (`program` >= 0), the program's step to `t_new` (the force, in the
/// pair precision, read by a servo only).
template <class Real>
TRIDEM_HD inline Pose<double> stepped_or_programmed_pose(const ProgramTable& table,
                                                         std::int32_t program, double t_new,
                                                         Pose<double> p, bool free, Vec2<Real> f,
                                                         Real torque, double inv_mass,
                                                         double inv_inertia, Vec2d g, double alpha,
                                                         double dt) {
  if (program < 0) return stepped_pose(p, free, f, torque, inv_mass, inv_inertia, g, alpha, dt);
  return program_step(table, program, p, t_new, dt,
                      Vec2d{static_cast<double>(f.x), static_cast<double>(f.y)});
}

}  // namespace tridem::physics
