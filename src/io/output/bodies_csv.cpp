// bodies.csv: the state of every body at the last step. Without bodies of several
// triangles every triangle is a body of one member, and its row is the triangle's own.
#include "io/output/exact_number.hpp"
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "tridem/output.hpp"

namespace tridem {

void write_bodies_csv(const std::filesystem::path& file, const Snapshot& s) {
  io::check_snapshot(s, file.string());
  io::check_bodies(s, file.string());
  io::OutFile out(file);
  // Users' scripts index these columns by name; never reorder or rename them.
  out.write("id,x,y,theta,vx,vy,omega,mass,inertia,members\n");
  const auto row = [](fmt::memory_buffer& text, std::size_t b, double x, double y, double theta,
                      double vx, double vy, double omega, double mass, double inertia,
                      std::int64_t members) {
    fmt::format_to(fmt::appender(text), FMT_COMPILE("{},{},{},{},{},{},{},{},{},{}\n"), b,
                   io::Exact{x}, io::Exact{y}, io::Exact{theta}, io::Exact{vx}, io::Exact{vy},
                   io::Exact{omega}, io::Exact{mass}, io::Exact{inertia}, members);
  };
  if (s.member_body.empty()) {
    out.print_rows(s.size(), [&](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k)
        row(text, k, s.x[k], s.y[k], s.theta[k], s.vx[k], s.vy[k], s.omega[k], s.mass[k],
            s.inertia[k], 1);
    });
  } else {
    out.print_rows(s.body_count(),
                   [&](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
                     for (std::size_t b = first; b < last; ++b)
                       row(text, b, s.body_x[b], s.body_y[b], s.body_theta[b], s.body_vx[b],
                           s.body_vy[b], s.body_omega[b], s.body_mass[b], s.body_inertia[b],
                           s.body_first[b + 1] - s.body_first[b]);
                   });
  }
  out.close();
}

}  // namespace tridem
