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

/// Damping ratios are tabulated at these load exponents n_eff (docs/model.md, "Damping").
constexpr int kDampingNodes = 3;  ///< n_eff = 1, 1.5, 2

/// Contact law of a pair of materials (mixing rules in docs/model.md). Built on the host by
/// physics::contact_law (restitution.hpp), which calibrates the damping ratios.
template <class Real>
struct ContactLaw {
  Real penalty;             ///< p, Pa
  Real tangential_penalty;  ///< p_t, Pa
  Real friction;            ///< μ
  /// ζ of the dashpot c = 2ζ√(m_eff·k) at n_eff = 1, 1.5, 2 (face … vertex contacts):
  /// the values that give the pair's restitution whatever the contact's shape.
  Real damping[kDampingNodes];
};

/// The law in another precision (solvers convert the double table once).
template <class To, class From>
inline ContactLaw<To> law_cast(const ContactLaw<From>& l) {
  ContactLaw<To> r{static_cast<To>(l.penalty), static_cast<To>(l.tangential_penalty),
                   static_cast<To>(l.friction), {}};
  for (int i = 0; i < kDampingNodes; ++i) r.damping[i] = static_cast<To>(l.damping[i]);
  return r;
}

}  // namespace tridem::physics
