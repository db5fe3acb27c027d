#pragma once
// Which sub-domains' overlap bands a particle joins, from the particle's side: the rule
// of the GPU's per-step bookkeeping (backends/cuda/assignment_kernels.cuh), written for
// host and device so that the host's tests can hold it against the host's own lists
// (Decomposition, which finds the same bands from the sub-domains' side).
#include "decomposition/domain_map.hpp"
#include "decomposition/periodic_images.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/hd.hpp"

#include <cstdint>

namespace tridem {

/// What the bookkeeping reads: the borders, the particles and, in a periodic cell, its frame
/// (device pointers on the GPU).
template <class Real>
struct AssignmentView {
  int n;
  int domains;
  DomainMap map;
  const std::uint8_t* small;
  const double *x, *y;  ///< centroids: double in every precision
  const Real *lo_x, *lo_y, *hi_x, *hi_y;
  /// In a periodic cell: its frame at this step, and the extent of every small box (the
  /// union of the hulls: extent_kernel). Null extent without a cell.
  physics::PeriodicFrame frame;
  const Hull<double>* extent;

  TRIDEM_HD std::int64_t cell_row(int i) const {
    return decomposition_cell(y[i], map.origin_y, map.cell);
  }
  TRIDEM_HD std::int64_t cell_column(int i) const {
    return decomposition_cell(x[i], map.origin_x, map.cell);
  }
};

/// Calls image(t, sx, sy, cell_row, cell_column) for each image (sx, sy) of particle i
/// that can bring its box onto some hull (those that move it onto the extent of them all,
/// widened by twice the largest margin a hull's test allows), numbered t = 0, 1, ... in
/// for_each_image's order, with the cell of its centroid moved there.
template <class Real, class Image>
TRIDEM_HD inline void visit_images(const AssignmentView<Real>& v, int i, Image&& image) {
  const Hull<double> e = *v.extent;
  if (e.lo_x > e.hi_x) return;
  const double m = 2 * image_margin(v.frame, e.lo_x, e.lo_y, e.hi_x, e.hi_y);
  const Hull<double> box{v.lo_x[i], v.lo_y[i], v.hi_x[i], v.hi_y[i]};
  int t = 0;
  for_each_image(v.frame, box, e.lo_x - m, e.lo_y - m, e.hi_x + m, e.hi_y + m,
                 [&](double sx, double sy) {
                   image(t++, sx, sy, decomposition_cell(v.y[i] + sy, v.map.origin_y, v.map.cell),
                         decomposition_cell(v.x[i] + sx, v.map.origin_x, v.map.cell));
                 });
}

/// Calls reached(k) once for every sub-domain whose hull particle i's box reaches: as
/// itself, ascending k, then in a periodic cell through its images (the host's
/// Decomposition::stage_images from the particle's side), each sub-domain at the first
/// way that reaches it, so that no sub-domain stages a particle twice.
template <class Real, class Reached>
TRIDEM_HD inline void visit_bands(const AssignmentView<Real>& v, const Hull<Real>* hull, int i,
                                  Reached&& reached) {
  const Real lx = v.lo_x[i], ly = v.lo_y[i], hx = v.hi_x[i], hy = v.hi_y[i];
  const std::int64_t row = v.cell_row(i), column = v.cell_column(i);
  v.map.visit_near(row, column, [&](int k) {
    if (box_reaches(lx, ly, hx, hy, hull[k])) reached(k);
  });
  if (v.extent == nullptr) return;
  visit_images(v, i, [&](int t, double sx, double sy, std::int64_t r, std::int64_t c) {
    v.map.visit_near(r, c, [&](int k) {
      if (!image_reaches(v.frame, hull[k], lx, ly, hx, hy, sx, sy)) return;
      if (v.map.near(row, column, k) && box_reaches(lx, ly, hx, hy, hull[k])) return;
      bool earlier = false;
      visit_images(v, i, [&](int t2, double sx2, double sy2, std::int64_t r2, std::int64_t c2) {
        earlier = earlier || (t2 < t && v.map.near(r2, c2, k) &&
                              image_reaches(v.frame, hull[k], lx, ly, hx, hy, sx2, sy2));
      });
      if (!earlier) reached(k);
    });
  });
}

}  // namespace tridem
