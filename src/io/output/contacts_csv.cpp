#include "io/output/out_file.hpp"
#include "io/output/snapshot_check.hpp"
#include "tridem/output.hpp"

#include <fmt/format.h>

namespace tridem {

void write_contacts_csv(const std::filesystem::path& file, const Snapshot& s) {
  io::check_contacts(s, file.string());
  io::OutFile out(file);
  out.write("i,j,fx,fy,px,py\n");
  for (const ContactRecord& c : s.contacts)
    out.print("{},{},{:.17g},{:.17g},{:.17g},{:.17g}\n", c.i, c.j, c.fx, c.fy, c.px, c.py);
  out.close();
}

}  // namespace tridem
