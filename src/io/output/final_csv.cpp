// final.csv: every triangle at the last step, and (the last column) the body it is in.
#include "io/output/exact_number.hpp"
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "tridem/output.hpp"

namespace tridem {

void write_final_csv(const std::filesystem::path& file, const Snapshot& s) {
  io::check_snapshot(s, file.string());
  io::check_bodies(s, file.string());
  io::OutFile out(file);
  // Users' scripts index these columns by name; never reorder or rename them (`body` came
  // with bodies of several triangles, issue 13: new columns go at the end).
  out.write("id,x,y,theta,vx,vy,omega,x1,y1,x2,y2,x3,y3,body\n");
  out.print_rows(s.size(), [&s](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
    for (std::size_t k = first; k < last; ++k)
      fmt::format_to(fmt::appender(text),
                     FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n"), k,
                     io::Exact{s.x[k]}, io::Exact{s.y[k]}, io::Exact{s.theta[k]},
                     io::Exact{s.vx[k]}, io::Exact{s.vy[k]}, io::Exact{s.omega[k]},
                     io::Exact{s.x1[k]}, io::Exact{s.y1[k]}, io::Exact{s.x2[k]}, io::Exact{s.y2[k]},
                     io::Exact{s.x3[k]}, io::Exact{s.y3[k]}, s.body_of(k));
  });
  out.close();
}

}  // namespace tridem
