#include "io/output/snapshot_check.hpp"

#include "tridem/error.hpp"

#include <fmt/format.h>

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

void check_contacts(const Snapshot& s, std::string_view writing) {
  const auto n = static_cast<std::int64_t>(s.size());
  for (const ContactRecord& c : s.contacts)
    if (c.i < 0 || c.i >= n || c.j < 0 || c.j >= n)
      throw Error(fmt::format("cannot write {}: contact ({}, {}) at step {} names a particle "
                              "outside 0..{}",
                              writing, c.i, c.j, s.step, n - 1));
}

}  // namespace tridem::io
