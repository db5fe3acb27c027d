#include "io/output/pvd_collection.hpp"

#include "io/output/out_file.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <algorithm>
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
