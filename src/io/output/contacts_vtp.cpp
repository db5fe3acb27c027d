// The contact network as lines between the centroids of the two particles (the points are
// the particles' centroids, in id order), so ParaView
// can draw force chains (Tube filter, line width or colour by magnitude).
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_frames.hpp"
#include "tridem/output.hpp"

#include <cmath>
#include <cstdint>
#include <string>

namespace tridem {
namespace io {

namespace {

/// The active scalars and vectors ParaView colours by first, where the network has them.
std::string active_attributes(ArraySet<ContactArray> arrays) {
  const bool scalars = arrays.has(ContactArray::Magnitude),
             vectors = arrays.has(ContactArray::Force);
  return std::string(scalars ? "Scalars=\"magnitude\"" : "") + (scalars && vectors ? " " : "") +
         (vectors ? "Vectors=\"force\"" : "");
}

}  // namespace

void write_contacts_vtp(VtkXmlWriter& w, const std::filesystem::path& file, const Snapshot& s,
                        ArraySet<ContactArray> arrays) {
  check_snapshot(s, file.string());
  check_contacts(s, file.string());
  const std::vector<ContactRecord>& c = s.contacts;
  const std::size_t m = c.size();
  const auto planar = [&](auto a, auto b) {
    return [&c, a, b](std::size_t k) {
      const ContactRecord& r = c[k / 3];
      return k % 3 == 0 ? a(r) : k % 3 == 1 ? b(r) : 0.0;
    };
  };
  const auto each = [&c](auto value) { return [&c, value](std::size_t k) { return value(c[k]); }; };
  // Point p is the centroid of particle p, which every contact of p shares; segment k
  // joins those of its i and j.
  w.line_set_vtp(
      file, s.step, s.time, s.size(), [&](std::size_t p) { return s.x[p]; },
      [&](std::size_t p) { return s.y[p]; }, m, [&c](std::size_t k) { return c[k].i; },
      [&c](std::size_t k) { return c[k].j; }, active_attributes(arrays),
      [&](OutFile& out) {
        if (arrays.has(ContactArray::Force))
          w.reals(out, "force", 3, 3 * m,
                  planar([](const ContactRecord& r) { return r.fx; },
                         [](const ContactRecord& r) { return r.fy; }),
                  8);
        if (arrays.has(ContactArray::Magnitude))
          w.reals(out, "magnitude", 1, m,
                  each([](const ContactRecord& r) { return std::hypot(r.fx, r.fy); }), 8);
        if (arrays.has(ContactArray::Normal))
          w.reals(out, "normal", 3, 3 * m,
                  planar([](const ContactRecord& r) { return r.nx; },
                         [](const ContactRecord& r) { return r.ny; }),
                  8);
        if (arrays.has(ContactArray::NormalForce))
          w.reals(out, "normal_force", 1, m,
                  each([](const ContactRecord& r) { return r.normal_force(); }), 8);
        if (arrays.has(ContactArray::TangentialForce))
          w.reals(out, "tangential_force", 1, m,
                  each([](const ContactRecord& r) { return r.tangential_force(); }), 8);
        if (arrays.has(ContactArray::Sliding))
          w.integers<std::int32_t>(out, "sliding", 1, m,
                                   each([](const ContactRecord& r) { return r.sliding ? 1 : 0; }),
                                   8);
        if (arrays.has(ContactArray::Depth))
          w.reals(out, "depth", 1, m, each([](const ContactRecord& r) { return r.depth; }), 8);
      });
}

}  // namespace io

void write_contacts_vtp(const std::filesystem::path& file, const Snapshot& s, VtkFormat format,
                        ArraySet<ContactArray> arrays) {
  io::VtkXmlWriter w(format);
  io::write_contacts_vtp(w, file, s, arrays);
}

}  // namespace tridem
