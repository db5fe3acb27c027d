#include "io/output/exact_number.hpp"
#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "tridem/output.hpp"

#include <fmt/compile.h>

namespace tridem {

void write_contacts_csv(const std::filesystem::path& file, const Snapshot& s) {
  io::check_contacts(s, file.string());
  io::OutFile out(file);
  // Columns after py were appended by issue 15 (the contact network's normal and
  // tangential parts); readers of the first six are unaffected.
  out.write("i,j,fx,fy,px,py,nx,ny,fn,ft,sliding,depth\n");
  // Some 1 kB of 17-digit text per triangle at 6 contacts each: formatted in blocks on the
  // OpenMP threads (OutFile::print_rows), byte for byte as one thread writes it.
  out.print_rows(
      s.contacts.size(), [&s](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
        for (std::size_t k = first; k < last; ++k) {
          const ContactRecord& c = s.contacts[k];
          fmt::format_to(fmt::appender(text), FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{},{}\n"),
                         c.i, c.j, io::Exact{c.fx}, io::Exact{c.fy}, io::Exact{c.px},
                         io::Exact{c.py}, io::Exact{c.nx}, io::Exact{c.ny},
                         io::Exact{c.normal_force()}, io::Exact{c.tangential_force()},
                         c.sliding ? 1 : 0, io::Exact{c.depth});
        }
      });
  out.close();
}

}  // namespace tridem
