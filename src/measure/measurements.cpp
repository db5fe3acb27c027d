// Love-Weber stress, packing fraction, coordination, fabric and overlaps of a region
// (tridem/measurements.hpp; the formulas are in docs/experiments.md, "Measurements").
#include "tridem/measurements.hpp"

#include "broadphase/candidate_pairs.hpp"
#include "measure/grain_network.hpp"
#include "measure/region_clip.hpp"
#include "physics/periodic_frame.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tridem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Tensor {
  double xx = 0, xy = 0, yx = 0, yy = 0;
};

/// Each grain's triangle contacts in record order (a CSR built in two passes): for grain g,
/// ends[first[g] .. first[g + 1]) name the contact record and the grain at its other end.
/// A grain's sums over its own list are the serial loop's over all contacts, bit for bit,
/// and the grains can be summed on the threads: at 10^6 triangles and 6 contacts each, a
/// frame's grain stress took most of the frame on one core.
struct GrainContactLists {
  struct End {
    std::size_t record;
    std::size_t other;
  };
  std::vector<std::size_t> first;
  std::vector<End> ends;
};

GrainContactLists grain_contact_lists(const Snapshot& s, std::size_t grains) {
  const auto grain = [&s](std::int64_t i) {
    return static_cast<std::size_t>(s.body_of(static_cast<std::size_t>(i)));
  };
  GrainContactLists l;
  l.first.assign(grains + 1, 0);
  for (const ContactRecord& c : s.contacts) {
    const std::size_t a = grain(c.i), b = grain(c.j);
    if (a == b) continue;
    ++l.first[a + 1];
    ++l.first[b + 1];
  }
  for (std::size_t g = 0; g < grains; ++g) l.first[g + 1] += l.first[g];
  l.ends.resize(l.first[grains]);
  std::vector<std::size_t> at(l.first.begin(), l.first.end() - 1);
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    const std::size_t a = grain(s.contacts[k].i), b = grain(s.contacts[k].j);
    if (a == b) continue;
    l.ends[at[a]++] = {k, b};
    l.ends[at[b]++] = {k, a};
  }
  return l;
}

/// Σ_c f_i (x_c − x_p)_j of grain p over its triangle contacts: f on p, at x_c.
Tensor contact_moment(const Snapshot& s, const measure::Grains& grains,
                      const GrainContactLists& lists, std::size_t g) {
  Tensor m;
  for (std::size_t e = lists.first[g]; e < lists.first[g + 1]; ++e) {
    const ContactRecord& c = s.contacts[lists.ends[e].record];
    // i (in grain a) receives +f, j (in grain b) −f.
    const double sign =
        static_cast<std::size_t>(s.body_of(static_cast<std::size_t>(c.i))) == g ? 1.0 : -1.0;
    // j's grain is seen through its periodic image (0 without periodic boundaries).
    const double sx = sign < 0 ? c.image_dx : 0.0, sy = sign < 0 ? c.image_dy : 0.0;
    const double lx = c.px - (grains.centroid[g].x + sx), ly = c.py - (grains.centroid[g].y + sy);
    const double fx = sign * c.fx, fy = sign * c.fy;
    m.xx += fx * lx;
    m.xy += fx * ly;
    m.yx += fy * lx;
    m.yy += fy * ly;
  }
  return m;
}

/// contact_moment of every grain, on the OpenMP threads.
std::vector<Tensor> contact_moments(const Snapshot& s, const measure::Grains& grains,
                                    const GrainContactLists& lists) {
  std::vector<Tensor> m(grains.size());
  const auto count = static_cast<std::ptrdiff_t>(grains.size());
#pragma omp parallel for schedule(dynamic, 4096)
  for (std::ptrdiff_t g = 0; g < count; ++g)
    m[static_cast<std::size_t>(g)] = contact_moment(s, grains, lists, static_cast<std::size_t>(g));
  return m;
}

/// The bounding box of the free triangles' vertices (the whole domain's region), or an
/// empty one at the origin when there is none.
MeasureRegion free_bounding_box(const Snapshot& s) {
  MeasureRegion box{
      {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()},
      {-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()}};
  bool any = false;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.motion[i] != Motion::Free) continue;
    any = true;
    for (const auto& [x, y] :
         {std::pair{s.x1[i], s.y1[i]}, std::pair{s.x2[i], s.y2[i]}, std::pair{s.x3[i], s.y3[i]}}) {
      box.lo = {std::min(box.lo.x, x), std::min(box.lo.y, y)};
      box.hi = {std::max(box.hi.x, x), std::max(box.hi.y, y)};
    }
  }
  return any ? box : MeasureRegion{};
}

double ratio(double num, double den) { return den > 0 ? num / den : kNaN; }

/// The area of triangle i inside `region`, its periodic images' included: a grain wraps
/// by its centroid (a body by its own), so a triangle across a side of the cell has the
/// rest of its area in the cell through the image one period over (with Lees-Edwards, the
/// images above and below shifted by the frame's offset). Images one and two periods away
/// along x (two: the shifted rows), one along y: a triangle is under a quarter of a period
/// (core/periodic_checks), so no farther image reaches the cell's neighbourhood.
double area_inside_with_images(const Snapshot& s, std::size_t i, const MeasureRegion& region,
                               const physics::PeriodicFrame& frame) {
  const std::array<Vec2d, 3> t{Vec2d{s.x1[i], s.y1[i]}, Vec2d{s.x2[i], s.y2[i]},
                               Vec2d{s.x3[i], s.y3[i]}};
  const int ky = frame.py ? 1 : 0, kx = frame.px ? 2 : 0;
  double area = 0;
  for (int k = -ky; k <= ky; ++k)
    for (int m = -kx; m <= kx; ++m) {
      const Vec2d shift{m * frame.lx + k * frame.shift, k * frame.ly};
      const std::array<Vec2d, 3> image{t[0] + shift, t[1] + shift, t[2] + shift};
      // Most images are far from the region: their box does not meet it.
      const double lo_x = std::min({image[0].x, image[1].x, image[2].x});
      const double hi_x = std::max({image[0].x, image[1].x, image[2].x});
      const double lo_y = std::min({image[0].y, image[1].y, image[2].y});
      const double hi_y = std::max({image[0].y, image[1].y, image[2].y});
      if (hi_x <= region.lo.x || lo_x >= region.hi.x || hi_y <= region.lo.y || lo_y >= region.hi.y)
        continue;
      area += measure::area_inside(image, region);
    }
  return area;
}

}  // namespace

Measurement measure_region(const Snapshot& s, const std::optional<MeasureRegion>& region) {
  const measure::Grains grains = measure::grains_of(s);
  const std::vector<measure::GrainContact> contacts = measure::grain_contacts(s);
  const measure::Neighbours neighbours = measure::neighbours_of(grains.size(), contacts);
  const std::vector<bool> rattler = measure::rattlers_of(grains, neighbours);

  Measurement out;
  out.step = s.step;
  out.time = s.time;
  const MeasureRegion where = region ? *region : free_bounding_box(s);
  out.area = where.area();

  // The grains measured: free, with their centroid inside (every free grain without a
  // region: the bounding box holds them all).
  std::vector<bool> inside(grains.size(), false);
  for (std::size_t g = 0; g < grains.size(); ++g)
    inside[g] = grains.free[g] && (!region || region->contains(grains.centroid[g]));

  const std::vector<Tensor> moment =
      contact_moments(s, grains, grain_contact_lists(s, grains.size()));
  Tensor sum;
  std::int64_t grain_contact_ends = 0, mechanical_ends = 0, mechanical_grains = 0;
  for (std::size_t g = 0; g < grains.size(); ++g) {
    if (!inside[g]) continue;
    ++out.particles;
    sum.xx += moment[g].xx;
    sum.xy += moment[g].xy;
    sum.yx += moment[g].yx;
    sum.yy += moment[g].yy;
    grain_contact_ends += neighbours.first[g + 1] - neighbours.first[g];
    if (rattler[g]) {
      ++out.rattlers;
      continue;
    }
    ++mechanical_grains;
    for (auto k = neighbours.first[g]; k < neighbours.first[g + 1]; ++k)
      if (!rattler[static_cast<std::size_t>(neighbours.grain[static_cast<std::size_t>(k)])])
        ++mechanical_ends;
  }
  // Compression positive: a pressed grain's contact forces point into it, against the
  // branch vectors.
  const double inv_area = out.area > 0 ? 1.0 / out.area : kNaN;
  out.sxx = -sum.xx * inv_area;
  out.sxy = -sum.xy * inv_area;
  out.syx = -sum.yx * inv_area;
  out.syy = -sum.yy * inv_area;
  out.pressure = 0.5 * (out.sxx + out.syy);
  out.deviatoric = std::hypot(0.5 * (out.sxx - out.syy), 0.5 * (out.sxy + out.syx));

  // Without periodic boundaries the frame has no image but the triangle itself.
  const physics::PeriodicFrame frame = periodic_frame_of(s.periodic, s.time);
  double solid = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.motion[i] != Motion::Free) continue;
    solid += region ? area_inside_with_images(s, i, *region, frame) : measure::triangle_area(s, i);
  }
  out.packing_fraction = ratio(solid, out.area);
  out.coordination =
      ratio(static_cast<double>(grain_contact_ends), static_cast<double>(out.particles));
  out.mechanical_coordination =
      ratio(static_cast<double>(mechanical_ends), static_cast<double>(mechanical_grains));

  // Fabric over the contacts of the grains inside, each contact once per grain inside
  // (n n does not depend on the normal's sign); overlaps over the contacts, each once.
  Tensor fabric;
  double depth_sum = 0;
  for (const measure::GrainContact& c : contacts) {
    const int ends =
        int(inside[static_cast<std::size_t>(c.a)]) + int(inside[static_cast<std::size_t>(c.b)]);
    if (ends == 0) continue;
    fabric.xx += ends * c.normal.x * c.normal.x;
    fabric.xy += ends * c.normal.x * c.normal.y;
    fabric.yy += ends * c.normal.y * c.normal.y;
    ++out.contacts;
    depth_sum += c.depth;
    out.max_overlap = std::max(out.max_overlap, c.depth);
  }
  const auto ends = static_cast<double>(grain_contact_ends);
  out.fabric_xx = ratio(fabric.xx, ends);
  out.fabric_xy = ratio(fabric.xy, ends);
  out.fabric_yy = ratio(fabric.yy, ends);
  out.mean_overlap = ratio(depth_sum, static_cast<double>(out.contacts));
  if (out.contacts == 0) out.max_overlap = kNaN;
  return out;
}

GrainStress grain_stress(const Snapshot& s) {
  const measure::Grains grains = measure::grains_of(s);
  const std::size_t n = grains.size();
  const GrainContactLists lists = grain_contact_lists(s, n);
  GrainStress out;
  for (auto* v : {&out.sxx, &out.sxy, &out.syx, &out.syy}) v->resize(n);
  out.coordination.resize(n);
  const auto grains_count = static_cast<std::ptrdiff_t>(n);
#pragma omp parallel
  {
    std::vector<std::size_t> others;
#pragma omp for schedule(dynamic, 4096)
    for (std::ptrdiff_t p = 0; p < grains_count; ++p) {
      const auto g = static_cast<std::size_t>(p);
      const Tensor m = contact_moment(s, grains, lists, g);
      // The coordination: the distinct grains at the other ends.
      others.clear();
      for (std::size_t e = lists.first[g]; e < lists.first[g + 1]; ++e)
        others.push_back(lists.ends[e].other);
      std::sort(others.begin(), others.end());
      const auto distinct = std::unique(others.begin(), others.end()) - others.begin();
      const double scale = grains.area[g] > 0 ? -1.0 / grains.area[g] : 0.0;
      out.sxx[g] = scale * m.xx;
      out.sxy[g] = scale * m.xy;
      out.syx[g] = scale * m.yx;
      out.syy[g] = scale * m.yy;
      out.coordination[g] = static_cast<std::int32_t>(distinct);
    }
  }
  return out;
}

}  // namespace tridem
