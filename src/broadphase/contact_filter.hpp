#pragma once
// The per-pair decision of the paper's methods (single-domain, decomposition), on the host
// and the device alike: whether a pair (emitted by the rule of emitter_rule.hpp) passes the
// contact test, with or without the bounding-box pre-filter before it. Only the pairs that
// pass get a force computed.
#include "broadphase/emitter_rule.hpp"
#include "broadphase/periodic_grid.hpp"
#include "physics/local_frame.hpp"
#include "tridem/hd.hpp"
#include "tridem/scene.hpp"

namespace tridem {

/// [simulation] contact_test and bbox_prefilter, as the detection stage reads them.
struct ContactFilter {
  ContactTest test = ContactTest::Exact;
  bool bbox_prefilter = true;
};

/// The geometry a contact test reads, structure of arrays: vertices (counter-clockwise)
/// relative to their centroid, bounding boxes of the current step, and the centroids in
/// double (mixed precision: physics/local_frame.hpp).
template <class Real>
struct TriangleArrays {
  const Real* x[3];
  const Real* y[3];
  const Real *lo_x, *lo_y, *hi_x, *hi_y;
  const double *cx, *cy;

  TRIDEM_HD Vec2d centroid(int i) const { return {cx[i], cy[i]}; }
  /// Particle i's triangle in the frame whose origin is at `origin` (for a pair: the
  /// emitter's centroid), as pair_force sees it.
  TRIDEM_HD physics::Triangle<Real> triangle(int i, Vec2d origin) const {
    const Vec2<Real> rel[3] = {{x[0][i], y[0][i]}, {x[1][i], y[1][i]}, {x[2][i], y[2][i]}};
    return physics::triangle_at(physics::offset_from<Real>(origin, centroid(i)), rel);
  }
  /// Its nearest periodic image `im` in that frame (physics/periodic_frame.hpp).
  TRIDEM_HD physics::Triangle<Real> image_triangle(int i, Vec2d origin,
                                                   const physics::PeriodicImage& im) const {
    const Vec2<Real> rel[3] = {{x[0][i], y[0][i]}, {x[1][i], y[1][i]}, {x[2][i], y[2][i]}};
    return physics::triangle_at(physics::image_offset<Real>(origin, centroid(i), im), rel);
  }
  TRIDEM_HD physics::Aabb<Real> box(int i) const {
    return physics::box_of(lo_x[i], lo_y[i], hi_x[i], hi_y[i]);
  }
};

/// Whether a pair gets a force. The exact test is what pair_force itself checks first
/// (the same separating-axis arithmetic), so the pairs it drops would have given exact
/// zeros; the direct area test also drops overlaps with no vertex inside the other
/// triangle. The pre-filter drops only pairs whose boxes are apart, which no test passes.
template <class Real>
TRIDEM_HD inline bool passes_contact_test(const physics::Triangle<Real>& a,
                                          const physics::Aabb<Real>& box_a,
                                          const physics::Triangle<Real>& b,
                                          const physics::Aabb<Real>& box_b, ContactFilter f) {
  if (f.bbox_prefilter && !physics::boxes_overlap(box_a, box_b)) return false;
  return f.test == ContactTest::DirectArea ? physics::direct_area_overlap(a, b)
                                           : physics::triangles_overlap(a, b);
}

/// In a periodic cell: passes_contact_test with particle j of `g` at its nearest image seen
/// from `origin` (the emitter's centroid), the pre-filter's boxes through that image
/// (periodic_boxes_overlap), as pair_force then computes the pair (CpuSolver::image_body).
template <class Real>
TRIDEM_HD inline bool passes_periodic_contact_test(const physics::PeriodicFrame& frame,
                                                   Vec2d origin, const physics::Triangle<Real>& a,
                                                   const physics::Aabb<Real>& box_a,
                                                   const TriangleArrays<Real>& g, int j,
                                                   ContactFilter f) {
  const Vec2d cj = g.centroid(j);
  if (f.bbox_prefilter && !periodic_boxes_overlap(frame, origin, cj, box_a, g.box(j))) return false;
  const physics::Triangle<Real> b =
      g.image_triangle(j, origin, physics::nearest_image(frame, origin, cj));
  return f.test == ContactTest::DirectArea ? physics::direct_area_overlap(a, b)
                                           : physics::triangles_overlap(a, b);
}

}  // namespace tridem
