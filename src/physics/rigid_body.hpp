#pragma once
// Bodies of several triangles: how a member follows its body, and how its contact loads
// become the body's. Every backend calls these, once per member and per body.
#include "physics/integrate.hpp"
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

#include <cstdint>
#include <math.h>

namespace tridem::physics {

/// A member's pose from its body's: the body's angle and angular velocity, the centroid
/// and velocity of the rigid motion at the member's centroid (offset from the body's
/// centroid at theta = 0).
TRIDEM_HD inline Pose<double> member_pose(const Pose<double>& body, Vec2d offset) {
  const Vec2d r = rotate(offset, ::cos(body.theta), ::sin(body.theta));
  return {body.c + r, body.theta, body.v + cross(body.w, r), body.w};
}

/// Adds a member's contact force and torque (about the member's own centroid) to its
/// body's sums: the same force, and the torque about the body's centroid, `arm` being the
/// member's centroid minus the body's. Summed in double, members in ascending order.
template <class Real>
TRIDEM_HD inline void add_member_load(Vec2d& f, double& torque, Vec2<Real> member_f,
                                      Real member_torque, Vec2d arm) {
  const Vec2d fd{static_cast<double>(member_f.x), static_cast<double>(member_f.y)};
  f += fd;
  torque += static_cast<double>(member_torque) + cross(arm, fd);
}

/// Members of one body never touch: the pair filter every finder's pairs go through.
TRIDEM_HD inline bool same_body(const std::int32_t* body, std::int64_t a, std::int64_t b) {
  return body != nullptr && body[a] == body[b];
}

}  // namespace tridem::physics
