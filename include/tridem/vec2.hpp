#pragma once
// A 2D vector usable on host and device. Kept in the public headers because scene
// descriptions and the physics share it; it is a plain aggregate so that arrays of it
// are trivially copyable to a GPU.
#include "tridem/hd.hpp"

#include <cmath>

namespace tridem {

template <class Real>
struct Vec2 {
  Real x{0};
  Real y{0};

  TRIDEM_HD constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  TRIDEM_HD constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  TRIDEM_HD constexpr Vec2 operator-() const { return {-x, -y}; }
  TRIDEM_HD constexpr Vec2 operator*(Real s) const { return {x * s, y * s}; }
  TRIDEM_HD constexpr Vec2 operator/(Real s) const { return {x / s, y / s}; }
  TRIDEM_HD constexpr Vec2& operator+=(Vec2 o) { x += o.x; y += o.y; return *this; }
  TRIDEM_HD constexpr Vec2& operator-=(Vec2 o) { x -= o.x; y -= o.y; return *this; }
};

template <class Real>
TRIDEM_HD constexpr Vec2<Real> operator*(Real s, Vec2<Real> v) { return {s * v.x, s * v.y}; }
template <class Real>
TRIDEM_HD constexpr Real dot(Vec2<Real> a, Vec2<Real> b) { return a.x * b.x + a.y * b.y; }
/// z-component of the 3D cross product.
template <class Real>
TRIDEM_HD constexpr Real cross(Vec2<Real> a, Vec2<Real> b) { return a.x * b.y - a.y * b.x; }
/// ω × r for a scalar angular velocity ω about z.
template <class Real>
TRIDEM_HD constexpr Vec2<Real> cross(Real w, Vec2<Real> r) { return {-w * r.y, w * r.x}; }
/// Rotates v by +90°.
template <class Real>
TRIDEM_HD constexpr Vec2<Real> perp(Vec2<Real> v) { return {-v.y, v.x}; }
template <class Real>
TRIDEM_HD inline Real norm(Vec2<Real> v) { return math::sqrt(dot(v, v)); }
template <class Real>
TRIDEM_HD inline Vec2<Real> rotate(Vec2<Real> v, Real c, Real s) {
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

using Vec2d = Vec2<double>;

}  // namespace tridem
