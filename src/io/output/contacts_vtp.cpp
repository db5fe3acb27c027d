// The contact network as lines between the centroids of the two particles, so ParaView
// can draw force chains (Tube filter, line width or colour by magnitude).
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "io/output/vtk_xml_writer.hpp"
#include "tridem/output.hpp"

#include <cmath>
#include <cstdint>
#include <vector>

namespace tridem {

void write_contacts_vtp(const std::filesystem::path& file, const Snapshot& s,
                        Encoding encoding) {
  io::check_snapshot(s, file.string());
  io::check_contacts(s, file.string());
  const std::size_t m = s.contacts.size();

  std::vector<double> points(6 * m), force(3 * m), magnitude(m), normal(3 * m), fn(m), ft(m),
      depth(m);
  std::vector<std::int32_t> sliding(m);
  for (std::size_t k = 0; k < m; ++k) {
    const ContactRecord& c = s.contacts[k];
    const auto i = static_cast<std::size_t>(c.i), j = static_cast<std::size_t>(c.j);
    points[6 * k] = s.x[i];
    points[6 * k + 1] = s.y[i];
    points[6 * k + 3] = s.x[j];
    points[6 * k + 4] = s.y[j];
    force[3 * k] = c.fx;
    force[3 * k + 1] = c.fy;
    magnitude[k] = std::hypot(c.fx, c.fy);
    normal[3 * k] = c.nx;
    normal[3 * k + 1] = c.ny;
    fn[k] = c.normal_force();
    ft[k] = c.tangential_force();
    sliding[k] = c.sliding ? 1 : 0;
    depth[k] = c.depth;
  }
  io::write_line_set_vtp(
      file, s.step, s.time, points, "Scalars=\"magnitude\" Vectors=\"force\"", encoding,
      [&](io::OutFile& out) {
        io::write_data_array<double>(out, "force", force, 3, encoding, 8);
        io::write_data_array<double>(out, "magnitude", magnitude, 1, encoding, 8);
        io::write_data_array<double>(out, "normal", normal, 3, encoding, 8);
        io::write_data_array<double>(out, "normal_force", fn, 1, encoding, 8);
        io::write_data_array<double>(out, "tangential_force", ft, 1, encoding, 8);
        io::write_data_array<std::int32_t>(out, "sliding", sliding, 1, encoding, 8);
        io::write_data_array<double>(out, "depth", depth, 1, encoding, 8);
      });
}

}  // namespace tridem
