#pragma once
// Periodic boundaries and Lees-Edwards shear (docs/scene-format.md, "Periodic boundaries"):
// the rules every backend applies, in one place. A pair sees its partner's nearest image
// (the minimum-image convention), and a free particle leaving the cell is put back in at
// the other side. Both are exact for a pair when no two touching particles are farther
// apart than half a period, which core/periodic_checks refuses scenes against.
//
// Lees-Edwards: the image of the cell one period above (y + Ly) is shifted along x by
// shift = γ̇·Ly·t (mod Lx) and moves faster along x by γ̇·Ly; a particle crossing the top
// re-enters at the bottom shifted back by shift and slowed by γ̇·Ly. Without shear the
// shift and the speed are 0 and the rules reduce to plain periodic ones.
#include "physics/integrate.hpp"
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

#include <math.h>

namespace tridem::physics {

/// The periodic cell at one instant: which directions are periodic, the cell, and the
/// Lees-Edwards offset and speed of the image one period above.
struct PeriodicFrame {
  bool px = false, py = false;
  double x0 = 0, lx = 0, y0 = 0, ly = 0;
  double shift = 0;           ///< x offset of the image one period above, in [0, lx)
  double shear_velocity = 0;  ///< x velocity of that image relative to the cell: γ̇·Ly
};

/// The frame of the cell at time t, for a shear rate γ̇ (0 = plain periodic).
TRIDEM_HD inline PeriodicFrame periodic_frame_at(bool px, double x0, double lx, bool py, double y0,
                                                 double ly, double shear_rate, double t) {
  PeriodicFrame f;
  f.px = px;
  f.py = py;
  f.x0 = x0;
  f.lx = lx;
  f.y0 = y0;
  f.ly = ly;
  if (shear_rate != 0 && px && py) {
    f.shear_velocity = shear_rate * ly;
    f.shift = ::fmod(f.shear_velocity * t, lx);
    if (f.shift < 0) f.shift += lx;
  }
  return f;
}

/// How partner c is seen from `origin`: the translation of its nearest image, and the
/// x velocity that image adds (Lees-Edwards).
struct PeriodicImage {
  Vec2d shift{};
  double dvx = 0;
};

TRIDEM_HD inline PeriodicImage nearest_image(const PeriodicFrame& f, Vec2d origin, Vec2d c) {
  PeriodicImage im;
  double dx = c.x - origin.x;
  if (f.py) {
    const double k = ::floor((c.y - origin.y) / f.ly + 0.5);
    im.shift.y = -k * f.ly;
    im.shift.x = -k * f.shift;
    im.dvx = -k * f.shear_velocity;
    dx += im.shift.x;
  }
  if (f.px) im.shift.x -= f.lx * ::floor(dx / f.lx + 0.5);
  return im;
}

/// The offset of partner c's nearest image from `origin`, subtracted in double and then
/// rounded once to Real (offset_from of local_frame.hpp when the image is c itself).
template <class Real>
TRIDEM_HD inline Vec2<Real> image_offset(Vec2d origin, Vec2d c, const PeriodicImage& im) {
  return {static_cast<Real>((c.x - origin.x) + im.shift.x),
          static_cast<Real>((c.y - origin.y) + im.shift.y)};
}

/// Puts a free body's pose back into the cell: across y (with the Lees-Edwards shift and
/// speed), then across x. The pose's angle and angular velocity never change.
TRIDEM_HD inline void wrap_into_cell(const PeriodicFrame& f, Pose<double>& p) {
  if (f.py) {
    const double k = ::floor((p.c.y - f.y0) / f.ly);
    if (k != 0) {
      p.c.y -= k * f.ly;
      p.c.x -= k * f.shift;
      p.v.x -= k * f.shear_velocity;
    }
  }
  if (f.px) {
    const double k = ::floor((p.c.x - f.x0) / f.lx);
    if (k != 0) p.c.x -= k * f.lx;
  }
}

/// The boundary's work on the grains (docs/experiments.md, "Energy"). A pair that meets
/// its partner's Lees-Edwards image sees it move faster by im.dvx: the power the pair's
/// force puts into the grains exceeds what its springs and dashpots account for by the
/// force on the particle that sees the image times that speed.
TRIDEM_HD inline double image_power(const PeriodicImage& im, double force_on_origin_x) {
  return force_on_origin_x * im.dvx;
}

/// And a wrap puts a body of mass m elsewhere, at another speed across a Lees-Edwards
/// boundary: the kinetic and gravitational (g) energy it gains, 0 when it did not wrap.
TRIDEM_HD inline double wrap_energy(const Pose<double>& before, const Pose<double>& after,
                                    double mass, Vec2d g) {
  return 0.5 * mass * (dot(after.v, after.v) - dot(before.v, before.v)) -
         mass * dot(g, after.c - before.c);
}

/// Puts a free body of inverse mass `inv_mass` back into the cell (wrap_into_cell) and
/// returns what that gave it (wrap_energy), which the caller books as the boundary's work.
TRIDEM_HD inline double wrap_with_work(const PeriodicFrame& f, Pose<double>& p, double inv_mass,
                                       Vec2d g) {
  const Pose<double> before = p;
  wrap_into_cell(f, p);
  return wrap_energy(before, p, 1.0 / inv_mass, g);
}

/// The cell coordinate of `v` along a periodic direction of n cells of size `cell` from
/// `origin`: its column (or row) modulo n, and how many periods it lies past the cell
/// (`wraps`, negative below it).
TRIDEM_HD inline long long periodic_cell_of(double v, double origin, double cell, long long n,
                                            long long& wraps) {
  const auto raw = static_cast<long long>(::floor((v - origin) / cell));
  wraps = raw >= 0 ? raw / n : -((-raw + n - 1) / n);
  return raw - wraps * n;
}

}  // namespace tridem::physics
