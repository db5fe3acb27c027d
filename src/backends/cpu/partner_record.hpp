#pragma once
// What a pair reads of its partner, packed into one record per particle (issue 12).
//
// The particle fields are columns (structure of arrays), which the stages that walk the
// particles in order stream well; a pair reads some fifteen of them at its partner's index,
// which lies anywhere when the particles are not numbered by where they are (a scene poured
// or imported rather than generated row by row, or mixed by a long flow): fifteen cache
// misses a pair. The Geometry stage copies those fields into this record as it places each
// particle, and the pair stage reads the record instead: the same values, so the same bits,
// in two or three cache lines (docs/performance.md, "The particles' order").
#include "physics/body.hpp"
#include "physics/local_frame.hpp"

#include <cstdint>

namespace tridem {

template <class Real>
struct PartnerRecord {
  double x, y;                  ///< centroid (the pair frame's offsets and periodic images)
  double vx, vy, w;             ///< velocities
  Real rel_x[3], rel_y[3];      ///< vertices about the centroid (Geometry's placement)
  Real lo_x, lo_y, hi_x, hi_y;  ///< bounding box (a kept list's overlap test)
  Real area, mass;
  std::int32_t material;

  /// The particle as pair_force sees it, centroid at `offset` in the pair's frame, moving
  /// with `v`: body_at of the columns, value for value.
  physics::Body<Real> body(Vec2<Real> offset, Vec2d v) const {
    const Vec2<Real> rel[3] = {{rel_x[0], rel_y[0]}, {rel_x[1], rel_y[1]}, {rel_x[2], rel_y[2]}};
    return physics::body_at(offset, rel, v, w, area, mass);
  }
};

}  // namespace tridem
