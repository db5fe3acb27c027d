#pragma once
// Mixed precision: where the double state meets the compute precision Real (docs/model.md,
// "Precision"). Positions and angles are carried in double; every pair is computed in Real
// in a frame local to the pair, with its origin at the emitter's centroid, so that a float
// pair sees offsets of a few grain sizes (resolved to ~1e-7 of a grain) wherever the pair
// sits, instead of absolute coordinates (resolved to ~1e-7 of the distance to the origin).
// The rules here are the only place either backend turns state into pair geometry, so that
// the contact test of the paper's methods and pair_force see the very same triangles.
#include "physics/body.hpp"
#include "physics/geometry.hpp"

#include <float.h>
#include <cstdint>

namespace tridem::physics {

/// Offset of `c` from `origin`, subtracted in double and then rounded once to Real.
template <class Real>
TRIDEM_HD inline Vec2<Real> offset_from(Vec2d origin, Vec2d c) {
  return {static_cast<Real>(c.x - origin.x), static_cast<Real>(c.y - origin.y)};
}

/// A body's triangle in a frame whose origin lies at `centroid_offset` from its centroid:
/// the offset plus its vertices relative to its own centroid (`rel`, already rotated).
template <class Real>
TRIDEM_HD inline Triangle<Real> triangle_at(Vec2<Real> centroid_offset, const Vec2<Real> rel[3]) {
  return {{centroid_offset + rel[0], centroid_offset + rel[1], centroid_offset + rel[2]}};
}

/// The vertices of a body relative to its centroid at angle θ: the rotation's cosine and
/// sine in double (θ itself is double and may have grown large), the product in Real.
template <class Real>
TRIDEM_HD inline void rotated_offsets(double theta, const Vec2<Real> body_frame[3], Vec2<Real> rel[3]) {
  const Real c = static_cast<Real>(::cos(theta)), s = static_cast<Real>(::sin(theta));
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) rel[k] = rotate(body_frame[k], c, s);
}

/// Largest Real <= v and smallest Real >= v: the identity for double; for float, the
/// directed roundings (the device's own instructions, the same values on the host).
TRIDEM_HD inline double round_down(double v, double) { return v; }
TRIDEM_HD inline double round_up(double v, double) { return v; }
TRIDEM_HD inline float round_down(double v, float) {
#if defined(__CUDA_ARCH__)
  return __double2float_rd(v);
#else
  float f = static_cast<float>(v);
  if (static_cast<double>(f) > v) f = ::nextafterf(f, -FLT_MAX);
  return f;
#endif
}
TRIDEM_HD inline float round_up(double v, float) {
#if defined(__CUDA_ARCH__)
  return __double2float_ru(v);
#else
  float f = static_cast<float>(v);
  if (static_cast<double>(f) < v) f = ::nextafterf(f, FLT_MAX);
  return f;
#endif
}

/// The bounding box of a body at centroid c (double) with vertices `rel` about it, in
/// absolute coordinates rounded outward to Real and grown by a few units of Real's
/// rounding at the body's size. Pair geometry is exact only to that rounding (the offset
/// of the partner is rounded, then added to its vertices in Real), so a box that is not
/// grown could miss a pair whose local triangles overlap by that much; grown, the box
/// test never drops a pair the local test would pass. Boxes serve only the broad phase:
/// their absolute float coordinates may be coarse far from the origin (more candidates,
/// never fewer pairs).
template <class Real>
TRIDEM_HD inline Aabb<Real> outward_box(Vec2d c, const Vec2<Real> rel[3], Real half_size) {
  Real lx = rel[0].x, ly = rel[0].y, hx = lx, hy = ly;
  TRIDEM_UNROLL
  for (int k = 1; k < 3; ++k) {
    lx = rel[k].x < lx ? rel[k].x : lx;
    ly = rel[k].y < ly ? rel[k].y : ly;
    hx = rel[k].x > hx ? rel[k].x : hx;
    hy = rel[k].y > hy ? rel[k].y : hy;
  }
  const double eps = sizeof(Real) == 4 ? 1.1920928955078125e-07 : 2.220446049250313e-16;
  const double pad = 16.0 * eps * static_cast<double>(half_size);
  const Real tag = 0;
  return {{round_down(c.x + static_cast<double>(lx) - pad, tag),
           round_down(c.y + static_cast<double>(ly) - pad, tag)},
          {round_up(c.x + static_cast<double>(hx) + pad, tag),
           round_up(c.y + static_cast<double>(hy) + pad, tag)}};
}

/// The geometry stage of one body, on every backend: its vertices about its centroid at
/// angle θ (rotated_offsets) and its outward box.
template <class Real>
struct PlacedBody {
  Vec2<Real> rel[3];
  Aabb<Real> box;
};

template <class Real>
TRIDEM_HD inline PlacedBody<Real> place_body(Vec2d c, double theta, const Vec2<Real> body_frame[3],
                                             Real half_size) {
  PlacedBody<Real> b;
  rotated_offsets(theta, body_frame, b.rel);
  b.box = outward_box(c, b.rel, half_size);
  return b;
}

/// The three vertices (offsets or rotated offsets) of particle i from the three x and
/// three y columns a structure of arrays keeps them in: three host vectors or device
/// pointers (a std::array or a C array of them; tridem/particle_fields.hpp).
template <class Real, class Columns>
TRIDEM_HD inline void load_vertices(const Columns& x, const Columns& y, std::int64_t i,
                                    Vec2<Real> out[3]) {
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) out[k] = {x[k][i], y[k][i]};
}

template <class Real, class Columns>
TRIDEM_HD inline void store_vertices(Columns& x, Columns& y, std::int64_t i,
                                     const Vec2<Real> v[3]) {
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) {
    x[k][i] = v[k].x;
    y[k][i] = v[k].y;
  }
}

/// What pair_force needs of one body, in the pair's frame: its triangle and centroid at
/// `centroid_offset` from the frame's origin, its velocities rounded to Real.
template <class Real>
TRIDEM_HD inline Body<Real> body_at(Vec2<Real> centroid_offset, const Vec2<Real> rel[3],
                                    Vec2d v, double w, Real area, Real mass) {
  Body<Real> b;
  b.tri = triangle_at(centroid_offset, rel);
  b.c = centroid_offset;
  b.v = {static_cast<Real>(v.x), static_cast<Real>(v.y)};
  b.w = static_cast<Real>(w);
  b.area = area;
  b.mass = mass;
  return b;
}

}  // namespace tridem::physics
