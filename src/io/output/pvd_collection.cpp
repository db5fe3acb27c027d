#include "io/output/pvd_collection.hpp"

#include "io/output/atomic_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <fstream>

namespace tridem::io {

PvdCollection::PvdCollection(std::filesystem::path file) : file_(std::move(file)) {}

void PvdCollection::add(double time, const std::filesystem::path& dataset) {
  std::string relative = dataset.lexically_relative(file_.parent_path()).generic_string();
  if (relative.empty()) relative = dataset.generic_string();
  const auto same = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const Entry& e) { return e.file == relative; });
  if (same != entries_.end())
    same->time = time;
  else
    entries_.push_back({time, std::move(relative)});
  rewrite();
}

void PvdCollection::restore(double max_time) {
  std::ifstream in(file_);
  if (!in) return;
  std::string line;
  // Reads back exactly what rewrite() writes: one DataSet per line.
  while (std::getline(in, line)) {
    const std::size_t t = line.find("timestep=\""), f = line.find("file=\"");
    if (t == std::string::npos || f == std::string::npos) continue;
    const std::size_t f_end = line.find('"', f + 6);
    if (f_end == std::string::npos) continue;
    const double time = std::strtod(line.c_str() + t + 10, nullptr);
    if (time <= max_time) entries_.push_back({time, line.substr(f + 6, f_end - f - 6)});
  }
  rewrite();
}

void PvdCollection::rewrite() const {
  fmt::memory_buffer text;
  auto out = fmt::appender(text);
  fmt::format_to(out, "<?xml version=\"1.0\"?>\n"
                      "<VTKFile type=\"Collection\" version=\"0.1\">\n"
                      "  <Collection>\n");
  for (const Entry& e : entries_)
    fmt::format_to(out, "    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n",
                   e.time, e.file);
  fmt::format_to(out, "  </Collection>\n</VTKFile>\n");
  write_file_atomically(file_, {reinterpret_cast<const std::uint8_t*>(text.data()), text.size()});
}

}  // namespace tridem::io
