#include "measure/grain_network.hpp"

#include "tridem/measurements.hpp"

#include <algorithm>
#include <cmath>

namespace tridem::measure {

double triangle_area(const Snapshot& s, std::size_t i) {
  return 0.5 * std::abs((s.x2[i] - s.x1[i]) * (s.y3[i] - s.y1[i]) -
                        (s.x3[i] - s.x1[i]) * (s.y2[i] - s.y1[i]));
}

Grains grains_of(const Snapshot& s) {
  const std::size_t n = s.body_count();
  Grains g;
  g.centroid.resize(n);
  g.area.assign(n, 0.0);
  g.free.assign(n, false);
  const bool bodies = !s.member_body.empty();
  for (std::size_t b = 0; b < n; ++b)
    g.centroid[b] = bodies ? Vec2d{s.body_x[b], s.body_y[b]} : Vec2d{s.x[b], s.y[b]};
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto b = static_cast<std::size_t>(s.body_of(i));
    g.area[b] += triangle_area(s, i);
    // Members share their body's motion.
    g.free[b] = s.motion[i] == Motion::Free;
  }
  return g;
}

std::vector<GrainContact> grain_contacts(const Snapshot& s) {
  struct Keyed {
    std::int64_t a, b;
    std::size_t record;
  };
  std::vector<Keyed> keyed;
  keyed.reserve(s.contacts.size());
  for (std::size_t k = 0; k < s.contacts.size(); ++k) {
    const ContactRecord& c = s.contacts[k];
    const std::int64_t a = s.body_of(static_cast<std::size_t>(c.i));
    const std::int64_t b = s.body_of(static_cast<std::size_t>(c.j));
    if (a != b) keyed.push_back({std::min(a, b), std::max(a, b), k});
  }
  std::sort(keyed.begin(), keyed.end(), [](const Keyed& l, const Keyed& r) {
    return l.a != r.a ? l.a < r.a : l.b != r.b ? l.b < r.b : l.record < r.record;
  });
  std::vector<GrainContact> out;
  for (std::size_t k = 0; k < keyed.size();) {
    GrainContact g{keyed[k].a, keyed[k].b, {}, 0.0};
    // The normal: the triangle contacts' normals weighted by their normal forces (a body
    // pressed face to face may touch its neighbour through a few small corner contacts
    // too, whose normals are tilted), or unweighted when none pushes.
    Vec2d weighted{}, plain{};
    for (; k < keyed.size() && keyed[k].a == g.a && keyed[k].b == g.b; ++k) {
      const ContactRecord& c = s.contacts[keyed[k].record];
      // The record's normal points from its i into its j; turned to point from a into b.
      const double sign = s.body_of(static_cast<std::size_t>(c.i)) == g.a ? 1.0 : -1.0;
      const Vec2d n = Vec2d{c.nx, c.ny} * sign;
      weighted += n * std::max(c.normal_force(), 0.0);
      plain += n;
      g.depth = std::max(g.depth, c.depth);
    }
    const double length = std::hypot(weighted.x, weighted.y),
                 plain_length = std::hypot(plain.x, plain.y);
    if (length > 0)
      g.normal = weighted / length;
    else if (plain_length > 0)
      g.normal = plain / plain_length;
    out.push_back(g);
  }
  return out;
}

Neighbours neighbours_of(std::size_t grains, const std::vector<GrainContact>& contacts) {
  Neighbours n;
  n.first.assign(grains + 1, 0);
  for (const GrainContact& c : contacts) {
    ++n.first[static_cast<std::size_t>(c.a) + 1];
    ++n.first[static_cast<std::size_t>(c.b) + 1];
  }
  for (std::size_t g = 0; g < grains; ++g) n.first[g + 1] += n.first[g];
  n.grain.resize(static_cast<std::size_t>(n.first[grains]));
  std::vector<std::int64_t> at(n.first.begin(), n.first.end() - 1);
  for (const GrainContact& c : contacts) {
    n.grain[static_cast<std::size_t>(at[static_cast<std::size_t>(c.a)]++)] = c.b;
    n.grain[static_cast<std::size_t>(at[static_cast<std::size_t>(c.b)]++)] = c.a;
  }
  return n;
}

std::vector<bool> rattlers_of(const Grains& grains, const Neighbours& neighbours) {
  const std::size_t n = grains.size();
  std::vector<std::int64_t> left(n);
  std::vector<bool> rattler(n, false);
  std::vector<std::size_t> pending;
  for (std::size_t g = 0; g < n; ++g) {
    left[g] = neighbours.first[g + 1] - neighbours.first[g];
    if (grains.free[g] && left[g] < 2) {
      rattler[g] = true;
      pending.push_back(g);
    }
  }
  // Each removal takes one contact from each neighbour still in the network.
  while (!pending.empty()) {
    const std::size_t g = pending.back();
    pending.pop_back();
    for (auto k = neighbours.first[g]; k < neighbours.first[g + 1]; ++k) {
      const auto h = static_cast<std::size_t>(neighbours.grain[static_cast<std::size_t>(k)]);
      if (rattler[h]) continue;
      if (--left[h] < 2 && grains.free[h]) {
        rattler[h] = true;
        pending.push_back(h);
      }
    }
  }
  return rattler;
}

}  // namespace tridem::measure

namespace tridem {

std::vector<bool> find_rattlers(const Snapshot& s) {
  const measure::Grains grains = measure::grains_of(s);
  return measure::rattlers_of(grains,
                              measure::neighbours_of(grains.size(), measure::grain_contacts(s)));
}

}  // namespace tridem
