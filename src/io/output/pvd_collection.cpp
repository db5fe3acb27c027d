#include "io/output/pvd_collection.hpp"

#include "io/output/out_file.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <system_error>

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
  std::filesystem::path temporary = file_;
  temporary += ".tmp";
  OutFile out(temporary);
  out.write("<?xml version=\"1.0\"?>\n"
            "<VTKFile type=\"Collection\" version=\"0.1\">\n"
            "  <Collection>\n");
  for (const Entry& e : entries_)
    out.print("    <DataSet timestep=\"{:.17g}\" group=\"\" part=\"0\" file=\"{}\"/>\n", e.time,
              e.file);
  out.write("  </Collection>\n</VTKFile>\n");
  out.close();
  std::error_code ec;
  std::filesystem::rename(temporary, file_, ec);
  if (ec)
    throw RunError(fmt::format("cannot replace '{}': {}", file_.string(), ec.message()));
}

}  // namespace tridem::io
