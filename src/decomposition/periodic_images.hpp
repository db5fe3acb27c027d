#pragma once
// The decomposition's rules in a periodic cell, shared by the host bookkeeping
// (Decomposition::stage_images, add_image_bands) and the GPU's (assignment_kernels.cuh):
// which translations of the cell's images can bring a box onto a region, the rounding
// margin an image's box test allows, and that test itself. A sub-domain stages a
// particle whose box, moved to one of its images, reaches the sub-domain's hull, so that
// every pair through a boundary has its partner staged with its emitter.
#include "decomposition/domain_map.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/hd.hpp"

#include <cfloat>
#include <math.h>

namespace tridem {

/// The integers a with a * period in [lo, hi] (none when the range is empty).
struct PeriodRange {
  long long first, last;
};

TRIDEM_HD inline PeriodRange periods_within(double lo, double hi, double period) {
  const double first = ::ceil(lo / period), last = ::floor(hi / period);
  // A coordinate gone to infinity or NaN (a run the runaway check is about to stop) would
  // make the loops over these integers endless: none.
  if (!(::fabs(first) < 1e15 && ::fabs(last) < 1e15)) return {1, 0};
  return {static_cast<long long>(first), static_cast<long long>(last)};
}

/// Calls image(sx, sy) for each translation (a·lx + b·shift, b·ly) of the cell's images,
/// other than the identity, that moves some box of `extent` onto [lo_y, hi_y] along y
/// and, through its x range, onto [lo_x, hi_x]; in the order of b, then a.
template <class Image>
TRIDEM_HD void for_each_image(const physics::PeriodicFrame& f, const Hull<double>& extent,
                              double lo_x, double lo_y, double hi_x, double hi_y, Image&& image) {
  const PeriodRange rows =
      f.py ? periods_within(lo_y - extent.hi_y, hi_y - extent.lo_y, f.ly) : PeriodRange{0, 0};
  for (long long b = rows.first; b <= rows.last; ++b) {
    const double base = static_cast<double>(b) * f.shift;
    const PeriodRange columns =
        f.px ? periods_within(lo_x - extent.hi_x - base, hi_x - extent.lo_x - base, f.lx)
             : PeriodRange{0, 0};
    for (long long a = columns.first; a <= columns.last; ++a)
      if (a != 0 || b != 0)
        image(base + static_cast<double>(a) * f.lx, static_cast<double>(b) * f.ly);
  }
}

/// A margin of a few roundings of the cell and the coordinates: an image's box is a box
/// moved by a sum of periods, and the pair test that follows (passes_periodic_contact_test)
/// allows as much.
TRIDEM_HD inline double image_margin(const physics::PeriodicFrame& f, double a, double b, double c,
                                     double d) {
  return 16 * DBL_EPSILON *
         (::fabs(f.lx) + ::fabs(f.ly) + ::fabs(a) + ::fabs(b) + ::fabs(c) + ::fabs(d));
}

/// Whether box (lo, hi) moved by (sx, sy) reaches hull h within its margin: the box
/// against the hull moved back, so that host and device round alike. An empty hull
/// (lo above hi) is reached by nothing.
template <class Real>
TRIDEM_HD inline bool image_reaches(const physics::PeriodicFrame& f, const Hull<Real>& h, Real lo_x,
                                    Real lo_y, Real hi_x, Real hi_y, double sx, double sy) {
  if (h.lo_x > h.hi_x) return false;
  const double tol = image_margin(f, h.lo_x, h.lo_y, h.hi_x, h.hi_y);
  const double rlo_x = h.lo_x - tol - sx, rhi_x = h.hi_x + tol - sx;
  const double rlo_y = h.lo_y - tol - sy, rhi_y = h.hi_y + tol - sy;
  return lo_x <= rhi_x && hi_x >= rlo_x && lo_y <= rhi_y && hi_y >= rlo_y;
}

}  // namespace tridem
