#pragma once
// What a pair interaction needs to know about one rigid triangle at the current step:
// gathered from the structure-of-arrays state into registers by each backend.
#include "physics/geometry.hpp"

namespace tridem::physics {

template <class Real>
struct Body {
  Triangle<Real> tri;   ///< current vertices, CCW
  Vec2<Real> c;         ///< centroid
  Vec2<Real> v;         ///< centroid velocity
  Real w;               ///< angular velocity
  Real area;
  Real mass;            ///< 0 marks a body moved by prescription (fixed or moving wall)
};

template <class Real>
TRIDEM_HD inline Vec2<Real> velocity_at(const Body<Real>& b, Vec2<Real> point) {
  return b.v + cross(b.w, point - b.c);
}

/// Contact law of a pair of materials (mixing rules in docs/model.md).
template <class Real>
struct ContactLaw {
  Real penalty;             ///< p, Pa
  Real tangential_penalty;  ///< p_t, Pa
  Real friction;            ///< μ
  Real damping;             ///< ζ
};

}  // namespace tridem::physics
