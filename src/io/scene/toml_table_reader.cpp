#include "io/scene/toml_table_reader.hpp"

#include "tridem/error.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tridem::scene_detail {

std::string where(const std::string& source, const toml::source_region& region) {
  if (region.begin.line == 0) return source;  // toml++ uses line 0 for "no position"
  return fmt::format("{}:{}:{}", source, region.begin.line, region.begin.column);
}

std::string_view describe_type(toml::node_type type) {
  switch (type) {
    case toml::node_type::table: return "a table";
    case toml::node_type::array: return "an array";
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a floating-point number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::date: return "a date";
    case toml::node_type::time: return "a time";
    case toml::node_type::date_time: return "a date-time";
    case toml::node_type::none: break;
  }
  return "nothing";
}

TableReader::TableReader(const toml::table& table, const std::string& source,
                         std::string context)
    : table_(table), source_(source), context_(std::move(context)) {}

const toml::node* TableReader::node(std::string_view key) {
  if (std::find(known_.begin(), known_.end(), key) == known_.end()) known_.emplace_back(key);
  return table_.get(key);
}

bool TableReader::has(std::string_view key) { return node(key) != nullptr; }

double TableReader::number_at(const toml::node& n, std::string_view key) const {
  if (const auto* i = n.as_integer()) return static_cast<double>(i->get());
  const auto* f = n.as_floating_point();
  if (!f) fail_at(n, key, fmt::format("expected a number, got {}", describe_type(n.type())));
  if (!std::isfinite(f->get()))
    fail_at(n, key, fmt::format("number must be finite, got {}", f->get()));
  return f->get();
}

std::optional<double> TableReader::real(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return number_at(*n, key);
}

std::optional<std::int64_t> TableReader::integer(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* i = n->as_integer();
  if (!i) fail(key, fmt::format("expected an integer, got {}", describe_type(n->type())));
  return i->get();
}

std::optional<std::string> TableReader::string(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* s = n->as_string();
  if (!s) fail(key, fmt::format("expected a string, got {}", describe_type(n->type())));
  return s->get();
}

std::optional<bool> TableReader::boolean(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* b = n->as_boolean();
  if (!b) fail(key, fmt::format("expected true or false, got {}", describe_type(n->type())));
  return b->get();
}

std::optional<std::vector<double>> TableReader::reals(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* array = n->as_array();
  if (!array) return std::vector<double>{number_at(*n, key)};
  if (array->empty()) fail(key, "expected a number or an array of numbers, got an empty array");
  std::vector<double> out;
  for (const toml::node& element : *array) out.push_back(number_at(element, key));
  return out;
}

std::optional<std::vector<std::int64_t>> TableReader::integers(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  auto integer_at = [&](const toml::node& e) {
    const auto* i = e.as_integer();
    if (!i) fail_at(e, key, fmt::format("expected an integer, got {}", describe_type(e.type())));
    return i->get();
  };
  const auto* array = n->as_array();
  if (!array) return std::vector<std::int64_t>{integer_at(*n)};
  if (array->empty()) fail(key, "expected an integer or an array of integers, got an empty array");
  std::vector<std::int64_t> out;
  for (const toml::node& element : *array) out.push_back(integer_at(element));
  return out;
}

std::optional<std::vector<Vec2d>> TableReader::point_list(std::string_view key,
                                                          std::string_view what) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* array = n->as_array();
  if (!array) fail(key, fmt::format("expected {}, got {}", what, describe_type(n->type())));
  std::vector<Vec2d> out;
  for (const toml::node& element : *array) out.push_back(point_at(element, key, what));
  return out;
}

Vec2d TableReader::point_at(const toml::node& n, std::string_view key,
                            std::string_view what) const {
  const auto* pair = n.as_array();
  if (!pair || pair->size() != 2)
    fail_at(n, key, fmt::format("expected {}; this element is not a pair [x, y]", what));
  return {number_at(*pair->get(0), key), number_at(*pair->get(1), key)};
}

std::optional<Vec2d> TableReader::vec2(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  return point_at(*n, key, "a pair of numbers [x, y]");
}

void TableReader::fail(std::string_view key, std::string_view message) const {
  const toml::node* n = table_.get(key);
  if (n) fail_at(*n, key, message);
  throw SceneError(
      fmt::format("{}: {}: key '{}': {}", where(source_, table_.source()), context_, key, message));
}

void TableReader::fail_at(const toml::node& at, std::string_view key,
                          std::string_view message) const {
  throw SceneError(
      fmt::format("{}: {}: key '{}': {}", where(source_, at.source()), context_, key, message));
}

void TableReader::fail_table(std::string_view message) const {
  throw SceneError(fmt::format("{}: {}: {}", where(source_, table_.source()), context_, message));
}

void TableReader::fail_missing(std::string_view key) const {
  fail_table(fmt::format("missing required key '{}'", key));
}

void TableReader::reject_unknown_keys() const {
  const toml::key* first = nullptr;
  for (const auto& [k, v] : table_) {
    if (std::find(known_.begin(), known_.end(), k.str()) != known_.end()) continue;
    if (!first || precedes(k.source().begin, first->source().begin)) first = &k;
  }
  if (!first) return;
  std::string expected;
  for (const std::string& k : known_) expected += (expected.empty() ? "" : ", ") + k;
  throw SceneError(fmt::format("{}: {}: unknown key '{}' (expected one of: {})",
                               where(source_, first->source()), context_, first->str(),
                               expected));
}

}  // namespace tridem::scene_detail
