#include "io/output/snapshot_check.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tridem::io {

void check_snapshot(const Snapshot& s, std::string_view writing) {
  const std::size_t n = s.size();
  const std::size_t sizes[] = {s.y.size(),  s.theta.size(), s.vx.size(),     s.vy.size(),
                               s.omega.size(), s.fx.size(), s.fy.size(),     s.torque.size(),
                               s.x1.size(), s.y1.size(),    s.x2.size(),     s.y2.size(),
                               s.x3.size(), s.y3.size(),    s.mass.size(),   s.inertia.size(),
                               s.material.size(), s.motion.size()};
  for (const std::size_t size : sizes)
    if (size != n)
      throw Error(fmt::format("cannot write {}: inconsistent snapshot at step {} ({} "
                              "particles but an array of {})",
                              writing, s.step, n, size));
}

void check_bodies(const Snapshot& s, std::string_view writing, bool members_only) {
  const auto bad = [&](std::string_view why) {
    throw Error(fmt::format("cannot write {}: inconsistent bodies in the snapshot at step {}: {}",
                            writing, s.step, why));
  };
  const std::size_t n = s.size();
  if (s.member_body.empty()) {
    if (!s.body_first.empty() || !s.body_mass.empty() || !s.body_x.empty())
      bad("body columns without member_body");
    return;
  }
  if (s.member_body.size() != n)
    bad(fmt::format("{} triangles but member_body has {}", n, s.member_body.size()));
  if (s.body_first.size() < 2) bad("body_first has no body");
  const std::size_t bodies = s.body_first.size() - 1;
  if (s.body_first.front() != 0 || s.body_first.back() != static_cast<std::int64_t>(n))
    bad(fmt::format("body_first runs from {} to {}, not 0 to {}", s.body_first.front(),
                    s.body_first.back(), n));
  for (std::size_t b = 0; b < bodies; ++b) {
    if (s.body_first[b] >= s.body_first[b + 1]) bad(fmt::format("body {} has no member", b));
    for (auto i = s.body_first[b]; i < s.body_first[b + 1]; ++i)
      if (s.member_body[static_cast<std::size_t>(i)] != static_cast<std::int32_t>(b))
        bad(fmt::format("triangle {} is in body {}'s range but says body {}", i, b,
                        s.member_body[static_cast<std::size_t>(i)]));
  }
  const std::size_t expected = members_only ? 0 : bodies;
  bool sizes_ok = s.body_mass.size() == expected && s.body_inertia.size() == expected;
  Snapshot::for_each_body_column(
      [&](auto field) { sizes_ok = sizes_ok && s.column(field).size() == expected; });
  if (!sizes_ok) bad(fmt::format("a per-body column does not have {} entries", expected));
}

void check_contacts(const Snapshot& s, std::string_view writing) {
  const auto n = static_cast<std::int64_t>(s.size());
  // Float contacts are printed as float32s: a double among them would lose its digits.
  const bool float32 = s.contact_precision == Precision::Float;
  const auto not_float32 = [](double v) {
    return static_cast<double>(static_cast<float>(v)) != v && !std::isnan(v);
  };
  for (const ContactRecord& c : s.contacts) {
    if (c.i < 0 || c.i >= n || c.j < 0 || c.j >= n)
      throw Error(fmt::format("cannot write {}: contact ({}, {}) at step {} names a particle "
                              "outside 0..{}",
                              writing, c.i, c.j, s.step, n - 1));
    if (float32 && (not_float32(c.fx) || not_float32(c.fy) || not_float32(c.nx) ||
                    not_float32(c.ny) || not_float32(c.depth)))
      throw Error(fmt::format("cannot write {}: contact ({}, {}) at step {} is of float "
                              "precision, but its force, normal or depth is not a float32",
                              writing, c.i, c.j, s.step));
  }
}

}  // namespace tridem::io
