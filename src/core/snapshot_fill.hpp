#pragma once
// Pieces of a Snapshot that every solver fills the same way from its own layout.
#include "physics/contact_force.hpp"
#include "physics/periodic_frame.hpp"
#include "tridem/snapshot.hpp"

#include <cstddef>
#include <cstdint>

namespace tridem {

template <class Real>
inline void set_vertices(Snapshot& out, std::size_t i, const physics::Triangle<Real>& t) {
  out.x1[i] = t.v[0].x;
  out.y1[i] = t.v[0].y;
  out.x2[i] = t.v[1].x;
  out.y2[i] = t.v[1].y;
  out.x3[i] = t.v[2].x;
  out.y3[i] = t.v[2].y;
}

/// The shown fields (State and Force) of host columns `from` (anything with column(field)
/// for them), in double.
template <class Columns>
inline void copy_shown_fields(Snapshot& out, const Columns& from) {
  Snapshot::for_each_field([&](auto field) {
    for_each_array(out.column(field), [&](std::vector<double>& to, int k) {
      const auto& values = array_at(from.column(field), k);
      const auto n = static_cast<std::ptrdiff_t>(to.size());
#pragma omp parallel for schedule(static) if (n > 65536)
      for (std::ptrdiff_t i = 0; i < n; ++i) to[i] = static_cast<double>(values[i]);
    });
  });
}

/// What a snapshot derives from the Model fields of `model` (anything with column(field)
/// for them) and the pose already in `out`: vertices, mass and inertia (1/(1/m), 0 for
/// walls), material and motion.
template <class Columns>
inline void fill_from_model(Snapshot& out, const Columns& model) {
  namespace pf = particle_field;
  const auto& ox = model.column(pf::offset_x{});
  const auto& oy = model.column(pf::offset_y{});
  const auto& inv_mass = model.column(pf::inv_mass{});
  const auto& inv_inertia = model.column(pf::inv_inertia{});
  // On the threads for large snapshots: a frame of 10^6 triangles is taken on the stepping
  // thread, which the GPU waits for meanwhile.
  const auto n = static_cast<std::ptrdiff_t>(out.size());
#pragma omp parallel for schedule(static) if (n > 65536)
  for (std::ptrdiff_t p = 0; p < n; ++p) {
    const auto i = static_cast<std::size_t>(p);
    const Vec2d off[3] = {{ox[0][i], oy[0][i]}, {ox[1][i], oy[1][i]}, {ox[2][i], oy[2][i]}};
    set_vertices(out, i, physics::place(Vec2d{out.x[i], out.y[i]}, out.theta[i], off));
    out.mass[i] = inv_mass[i] > 0 ? 1.0 / inv_mass[i] : 0.0;
    out.inertia[i] = inv_inertia[i] > 0 ? 1.0 / inv_inertia[i] : 0.0;
  }
  out.material.assign(model.column(pf::material{}).begin(), model.column(pf::material{}).end());
  out.motion.assign(model.column(pf::motion{}).begin(), model.column(pf::motion{}).end());
}

/// The body columns of a snapshot whose triangles are already in `out`, from storage
/// `from` with column(body_field) for the body and member fields (host vectors), for
/// `bodies` bodies; 0 (no body of several triangles) empties them.
template <class Columns>
inline void fill_bodies(Snapshot& out, const Columns& from, std::size_t bodies) {
  namespace bf = body_field;
  out.resize_bodies(bodies);
  if (bodies == 0) return;
  const auto& member_body = from.column(bf::member_body{});
  out.member_body.assign(member_body.begin(), member_body.end());
  Snapshot::for_each_body_column([&](auto field) {
    const auto& values = from.column(field);
    auto& to = out.column(field);
    for (std::size_t b = 0; b < bodies; ++b) to[b] = static_cast<double>(values[b]);
  });
  const auto& inv_mass = from.column(bf::body_inv_mass{});
  const auto& inv_inertia = from.column(bf::body_inv_inertia{});
  const auto& first = from.column(bf::body_first{});
  for (std::size_t b = 0; b < bodies; ++b) {
    out.body_mass[b] = inv_mass[b] > 0 ? 1.0 / inv_mass[b] : 0.0;
    out.body_inertia[b] = inv_inertia[b] > 0 ? 1.0 / inv_inertia[b] : 0.0;
    out.body_first[b] = first[b];
  }
  out.body_first[bodies] = from.column(bf::body_last{})[bodies - 1];
}

/// The contact record of touching pair (e, j) from its result. The pair's point is in its
/// frame, relative to the emitter's centroid (cx, cy): placed back in double here.
template <class Real>
inline ContactRecord contact_record(std::size_t e, std::size_t j, const physics::PairForce<Real>& r,
                                    const double* cx, const double* cy) {
  ContactRecord c;
  c.i = static_cast<std::int64_t>(e);
  c.j = static_cast<std::int64_t>(j);
  c.fx = r.force_a.x;
  c.fy = r.force_a.y;
  c.px = cx[e] + static_cast<double>(r.point.x);
  c.py = cy[e] + static_cast<double>(r.point.y);
  c.nx = r.normal.x;
  c.ny = r.normal.y;
  c.sliding = r.sliding;
  c.depth = r.depth;
  return c;
}

/// The touching pairs of a pair list (rows by emitter) as contact records, in slot order.
template <class Real, class Offset, class Partner>
inline void append_contacts(Snapshot& out, std::size_t n, const Offset* offset,
                            const Partner* partner, const physics::PairForce<Real>* result,
                            const double* cx, const double* cy) {
  for (std::size_t e = 0; e < n; ++e)
    for (auto s = offset[e]; s < offset[e + 1]; ++s)
      if (result[s].touching)
        out.contacts.push_back(
            contact_record(e, static_cast<std::size_t>(partner[s]), result[s], cx, cy));
}

/// Periodic boundaries: each contact's image translation of its partner j, by the rule the
/// pairs used (physics/periodic_frame.hpp), from the snapshot's positions.
inline void set_image_shifts(Snapshot& out, const physics::PeriodicFrame& frame, const double* cx,
                             const double* cy) {
  for (ContactRecord& c : out.contacts) {
    const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
    const physics::PeriodicImage im =
        physics::nearest_image(frame, Vec2d{cx[i], cy[i]}, Vec2d{cx[j], cy[j]});
    c.image_dx = im.shift.x;
    c.image_dy = im.shift.y;
  }
}

}  // namespace tridem
