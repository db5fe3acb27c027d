// [[measure]]: a region whose averages (stress, packing fraction, coordination, fabric,
// overlaps) are logged to a CSV. The checks are shared with validate_scene, so that a
// scene built in code is refused for the same reasons as a file.
#include "io/scene/scene_sections.hpp"

#include <fmt/format.h>

#include <cmath>

namespace tridem::scene_detail {

namespace {

// Files of the output directory that tridem writes itself: a measure must not take them.
constexpr std::string_view kReservedFiles[] = {"energy.csv", "walls.csv",  "final.csv",
                                               "bodies.csv", "tridem.pvd", "contacts.pvd"};

bool name_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-';
}

}  // namespace

std::optional<std::string> measure_name_problem(std::string_view name) {
  if (name.empty()) return "must not be empty";
  for (char c : name)
    if (!name_character(c))
      return fmt::format("\"{}\" may hold only letters, digits, '_' and '-' (it names the file "
                         "measure_<name>.csv)",
                         name);
  return std::nullopt;
}

std::optional<std::string> measure_region_problem(const MeasureRegion& r) {
  if (!(std::isfinite(r.lo.x) && std::isfinite(r.lo.y) && std::isfinite(r.hi.x) &&
        std::isfinite(r.hi.y)))
    return "must have finite corners";
  if (!(r.lo.x < r.hi.x && r.lo.y < r.hi.y))
    return fmt::format("[[{}, {}], [{}, {}]] is empty: it needs xmin < xmax and ymin < ymax",
                       r.lo.x, r.lo.y, r.hi.x, r.hi.y);
  return std::nullopt;
}

std::optional<std::string> measure_file_problem(std::string_view file) {
  if (file.empty()) return "must not be empty (leave it out for measure_<name>.csv)";
  if (file.find('/') != std::string_view::npos || file.find('\\') != std::string_view::npos ||
      file == "." || file == "..")
    return fmt::format("\"{}\" must be a file name in the output directory, without folders", file);
  for (std::string_view reserved : kReservedFiles)
    if (file == reserved) return fmt::format("\"{}\" is a file tridem writes itself", file);
  return std::nullopt;
}

std::optional<std::string> measure_clash(const MeasureSpec& m,
                                         const std::vector<MeasureSpec>& earlier) {
  for (std::size_t k = 0; k < earlier.size(); ++k) {
    if (earlier[k].name == m.name)
      return fmt::format("name \"{}\" is already used by [[measure]] #{}", m.name, k + 1);
    if (earlier[k].file_name() == m.file_name())
      return fmt::format("file \"{}\" is already written by [[measure]] #{}", m.file_name(), k + 1);
  }
  return std::nullopt;
}

MeasureSpec parse_measure(const toml::table& table, const std::string& source, std::size_t number,
                          const std::vector<MeasureSpec>& earlier) {
  TableReader r(table, source, fmt::format("[[measure]] #{}", number));
  MeasureSpec m;
  m.name = r.required(r.string("name"), "name");
  if (auto why = measure_name_problem(m.name)) r.fail("name", *why);
  if (auto corners = r.points<2>("region")) {
    const MeasureRegion region{(*corners)[0], (*corners)[1]};
    if (auto why = measure_region_problem(region)) r.fail("region", *why);
    m.region = region;
  }
  if (auto every = r.integer("every")) {
    if (*every < 0)
      r.fail("every", fmt::format("must be >= 0 (steps between rows; 0 = the last step only), "
                                  "got {}",
                                  *every));
    m.every = *every;
  }
  if (auto file = r.string("file")) {
    if (auto why = measure_file_problem(*file)) r.fail("file", *why);
    m.file = *file;
  }
  r.reject_unknown_keys();
  if (auto why = measure_clash(m, earlier)) r.fail_table(*why);
  return m;
}

}  // namespace tridem::scene_detail
