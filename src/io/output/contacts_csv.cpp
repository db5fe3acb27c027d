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
  // Some 1 kB of text per triangle at 6 contacts each: formatted in blocks on the
  // OpenMP threads (OutFile::print_rows), byte for byte as one thread writes it.
  const auto rows = [&s](auto number) {
    return [&s, number](fmt::memory_buffer& text, std::size_t first, std::size_t last) {
      for (std::size_t k = first; k < last; ++k) {
        const ContactRecord& c = s.contacts[k];
        fmt::format_to(fmt::appender(text), FMT_COMPILE("{},{},{},{},{},{},{},{},{},{},{},{}\n"),
                       c.i, c.j, number(c.fx), number(c.fy), io::Exact{c.px}, io::Exact{c.py},
                       number(c.nx), number(c.ny), io::Exact{c.normal_force()},
                       io::Exact{c.tangential_force()}, c.sliding ? 1 : 0, number(c.depth));
      }
    };
  };
  // In float precision the pairs' numbers are float32s: as such they take half the text
  // and half the time (the CSV of a 10^6-triangle frame lagged the steps, issue 12). The
  // point (centroid plus a float offset) and the normal and tangential split are doubles.
  if (s.contact_precision == Precision::Float)
    out.print_rows(s.contacts.size(),
                   rows([](double v) { return io::ExactFloat{static_cast<float>(v)}; }));
  else
    out.print_rows(s.contacts.size(), rows([](double v) { return io::Exact{v}; }));
  out.close();
}

}  // namespace tridem
