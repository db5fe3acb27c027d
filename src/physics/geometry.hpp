#pragma once
// Triangle geometry shared by every backend: signed area, poses, bounding boxes and the
// two overlap tests. The exact test is the separating-axis theorem (two convex polygons
// are disjoint iff the normal of some edge separates them); the paper's direct area
// method (a vertex of one inside the other) is kept as its baseline because it misses
// overlaps where edges cross with no vertex inside (docs/model.md, "Contact detection").
#include "tridem/hd.hpp"
#include "tridem/vec2.hpp"

namespace tridem::physics {

template <class Real>
struct Triangle {
  Vec2<Real> v[3];  ///< counter-clockwise
};

template <class Real>
struct Aabb {
  Vec2<Real> lo, hi;
};

/// Twice the signed area of (a, b, c): positive when counter-clockwise.
template <class Real>
TRIDEM_HD inline Real twice_signed_area(Vec2<Real> a, Vec2<Real> b, Vec2<Real> c) {
  return cross(b - a, c - a);
}

template <class Real>
TRIDEM_HD inline Real signed_area(const Triangle<Real>& t) {
  return Real(0.5) * twice_signed_area(t.v[0], t.v[1], t.v[2]);
}

template <class Real>
TRIDEM_HD inline Vec2<Real> centroid(const Triangle<Real>& t) {
  return (t.v[0] + t.v[1] + t.v[2]) / Real(3);
}

/// Vertices of a rigid triangle at pose (c, θ) from its body-frame offsets r.
template <class Real>
TRIDEM_HD inline Triangle<Real> place(Vec2<Real> c, Real theta, const Vec2<Real> r[3]) {
  const Real cs = math::cos(theta), sn = math::sin(theta);
  return {{c + rotate(r[0], cs, sn), c + rotate(r[1], cs, sn), c + rotate(r[2], cs, sn)}};
}

template <class Real>
TRIDEM_HD inline Aabb<Real> bounding_box(const Triangle<Real>& t) {
  Aabb<Real> b{t.v[0], t.v[0]};
  TRIDEM_UNROLL
  for (int k = 1; k < 3; ++k) {
    b.lo.x = t.v[k].x < b.lo.x ? t.v[k].x : b.lo.x;
    b.lo.y = t.v[k].y < b.lo.y ? t.v[k].y : b.lo.y;
    b.hi.x = t.v[k].x > b.hi.x ? t.v[k].x : b.hi.x;
    b.hi.y = t.v[k].y > b.hi.y ? t.v[k].y : b.hi.y;
  }
  return b;
}

/// The box test of every broad phase, the paper's pre-filter and the sub-domains' bands
/// (the one spelling of it). Touching boxes count as overlapping: the exact test decides.
template <class Real>
TRIDEM_HD inline bool boxes_overlap(const Aabb<Real>& a, const Aabb<Real>& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}

/// A box from the four columns a structure of arrays keeps it in.
template <class Real>
TRIDEM_HD inline Aabb<Real> box_of(Real lo_x, Real lo_y, Real hi_x, Real hi_y) {
  return {{lo_x, lo_y}, {hi_x, hi_y}};
}

/// True when an edge normal of `a` separates the two (touching counts as separated:
/// the overlap then has zero area and the contact force is zero).
template <class Real>
TRIDEM_HD inline bool edge_of_a_separates(const Triangle<Real>& a, const Triangle<Real>& b) {
  TRIDEM_UNROLL
  for (int e = 0; e < 3; ++e) {
    const Vec2<Real> p = a.v[e];
    const Vec2<Real> d = a.v[(e + 1) % 3] - p;
    // For a CCW triangle, cross(d, q - p) >= 0 on the inner side of edge e.
    bool all_outside = true;
    TRIDEM_UNROLL
    for (int k = 0; k < 3 && all_outside; ++k) all_outside = cross(d, b.v[k] - p) <= Real(0);
    if (all_outside) return true;
  }
  return false;
}

/// Exact overlap test by separating axes (six edge normals).
template <class Real>
TRIDEM_HD inline bool triangles_overlap(const Triangle<Real>& a, const Triangle<Real>& b) {
  return !edge_of_a_separates(a, b) && !edge_of_a_separates(b, a);
}

/// The separating-axis test as a distance: over the six edge normals, the shortest push
/// along one of them that separates the two triangles (how far the other triangle reaches
/// past that edge). <= 0 exactly when triangles_overlap is false (apart or touching).
/// `push` receives the unit direction in which b must move (or a the opposite way).
template <class Real>
TRIDEM_HD inline Real overlap_depth(const Triangle<Real>& a, const Triangle<Real>& b,
                                    Vec2<Real>& push) {
  Real best = Real(0);
  bool first = true;
  TRIDEM_UNROLL
  for (int role = 0; role < 2; ++role) {
    const Triangle<Real>& own = role == 0 ? a : b;
    const Triangle<Real>& other = role == 0 ? b : a;
    TRIDEM_UNROLL
    for (int e = 0; e < 3; ++e) {
      const Vec2<Real> p = own.v[e];
      const Vec2<Real> d = own.v[(e + 1) % 3] - p;
      Real reach = cross(d, other.v[0] - p);
      TRIDEM_UNROLL
      for (int k = 1; k < 3; ++k) {
        const Real r = cross(d, other.v[k] - p);
        reach = r > reach ? r : reach;
      }
      const Real length = norm(d);
      const Real depth = reach / length;
      if (first || depth < best) {
        best = depth;
        // Outward normal of a CCW edge; b leaves a along a's, and a leaves b along b's.
        const Vec2<Real> out{d.y / length, -d.x / length};
        push = role == 0 ? out : -out;
        first = false;
      }
    }
  }
  return best;
}

/// Point strictly inside a CCW triangle (the paper's Eq. (1) signs).
template <class Real>
TRIDEM_HD inline bool point_inside(const Triangle<Real>& t, Vec2<Real> p) {
  return twice_signed_area(t.v[0], t.v[1], p) > Real(0) &&
         twice_signed_area(t.v[1], t.v[2], p) > Real(0) &&
         twice_signed_area(t.v[2], t.v[0], p) > Real(0);
}

/// The paper's direct area method: some vertex of one triangle lies inside the other.
template <class Real>
TRIDEM_HD inline bool direct_area_overlap(const Triangle<Real>& a, const Triangle<Real>& b) {
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k)
    if (point_inside(b, a.v[k]) || point_inside(a, b.v[k])) return true;
  return false;
}

/// Area of the intersection of two counter-clockwise triangles (Sutherland-Hodgman: a
/// clipped by b's three edges), computed about `origin` so that large coordinates cancel
/// before the products. Continuous in the vertices, collinear and shared edges included.
template <class Real>
TRIDEM_HD inline Real overlap_area(const Triangle<Real>& a, const Triangle<Real>& b,
                                   Vec2<Real> origin) {
  // A triangle clipped by three half-planes has at most six vertices.
  Vec2<Real> poly[2][6];
  int count = 3;
  TRIDEM_UNROLL
  for (int k = 0; k < 3; ++k) poly[0][k] = a.v[k] - origin;
  int from = 0;
  TRIDEM_UNROLL
  for (int e = 0; e < 3; ++e) {
    const Vec2<Real> p0 = b.v[e] - origin, d = b.v[(e + 1) % 3] - b.v[e];
    const Vec2<Real>* in = poly[from];
    Vec2<Real>* out = poly[1 - from];
    int kept = 0;
    for (int k = 0; k < count; ++k) {
      const Vec2<Real> p = in[k], q = in[(k + 1) % count];
      const Real fp = cross(d, p - p0), fq = cross(d, q - p0);
      if (fp >= Real(0) && kept < 6) out[kept++] = p;
      if (((fp >= Real(0)) != (fq >= Real(0))) && kept < 6) {
        const Real t = fp / (fp - fq);
        out[kept++] = p + (q - p) * t;
      }
    }
    count = kept;
    from = 1 - from;
    if (count < 3) return Real(0);
  }
  Real twice = 0;
  for (int k = 0; k < count; ++k) twice += cross(poly[from][k], poly[from][(k + 1) % count]);
  return twice > Real(0) ? Real(0.5) * twice : Real(0);
}

/// Narrows [t0, t1] to where f0 + t·fd >= 0 (a signed area along a segment, linear in t);
/// false when nothing of positive length is left. Three of these clip a segment to a
/// triangle.
template <class Real>
TRIDEM_HD inline bool clip_to_half_plane(Real f0, Real fd, Real& t0, Real& t1) {
  if (fd == Real(0)) return f0 >= Real(0) && t1 > t0;
  const Real t = math::divide(-f0, fd);
  if (fd > Real(0))
    t0 = math::max(t, t0);
  else
    t1 = math::min(t, t1);
  return t1 > t0;
}

/// clip_to_half_plane for an area f0 + t·fd whose zero, -f0/fd, is already known: the
/// same result, so that a ray shared by two sub-triangles is divided by once.
template <class Real>
TRIDEM_HD inline bool clip_at_crossing(Real f0, Real fd, Real crossing, Real& t0, Real& t1) {
  if (fd == Real(0)) return f0 >= Real(0) && t1 > t0;
  if (fd > Real(0)) t0 = crossing > t0 ? crossing : t0;
  else t1 = crossing < t1 ? crossing : t1;
  return t1 > t0;
}

/// Length of the longest edge.
template <class Real>
TRIDEM_HD inline Real longest_edge(const Triangle<Real>& t) {
  Real l = Real(0);
  TRIDEM_UNROLL
  for (int e = 0; e < 3; ++e) {
    const Real le = norm(t.v[(e + 1) % 3] - t.v[e]);
    l = le > l ? le : l;
  }
  return l;
}

/// A triangle is degenerate when its area <= kDegenerateAreaFactor · L², L its longest
/// edge: scale-free, so it holds for grains of any size, and far above rounding noise of a
/// true sliver while far below any triangle a user would mean to draw.
inline constexpr double kDegenerateAreaFactor = 1e-12;

/// The one degeneracy rule (the scene reader and the particle model both ask it), for
/// either orientation. Written as a negated ">" so that a NaN from overflowing
/// coordinates counts as degenerate too.
TRIDEM_HD inline bool is_degenerate(double area, double longest_edge_squared) {
  return !(area > kDegenerateAreaFactor * longest_edge_squared);
}

/// Smallest height: twice the area over the longest edge.
template <class Real>
TRIDEM_HD inline Real smallest_height(const Triangle<Real>& t) {
  return Real(2) * signed_area(t) / longest_edge(t);
}

}  // namespace tridem::physics
