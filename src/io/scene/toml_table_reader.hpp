#pragma once
// Typed, checked access to one TOML table, with messages that point at the user's text.
// Every key a section asks about is remembered, so that afterwards anything else in the
// table can be refused as unknown: a misspelt key must not silently fall back to a default.
#include "tridem/vec2.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace tridem::scene_detail {

/// "file:line:col" where toml++ knows a position, else just "file".
std::string where(const std::string& source, const toml::source_region& region);

/// Whether `a` comes first in the file. toml++ iterates keys sorted, not in file order;
/// errors report the earliest offender because users fix files top to bottom.
inline bool precedes(const toml::source_position& a, const toml::source_position& b) {
  return a.line < b.line || (a.line == b.line && a.column < b.column);
}

class TableReader {
 public:
  /// `context` names the table in messages, e.g. "[[triangle]] #3 (particle id 2)".
  TableReader(const toml::table& table, const std::string& source, std::string context);

  /// The value under `key`, or nullptr if absent. Marks the key as known.
  const toml::node* node(std::string_view key);
  bool has(std::string_view key);

  // Typed getters: nullopt when the key is absent; SceneError on a wrong type or a
  // non-finite number. Integers are accepted as reals.
  std::optional<double> real(std::string_view key);
  std::optional<std::int64_t> integer(std::string_view key);
  std::optional<std::string> string(std::string_view key);
  std::optional<bool> boolean(std::string_view key);
  std::optional<Vec2d> vec2(std::string_view key);
  /// An array of exactly N [x, y] points, e.g. vertices (N = 3) or region (N = 2).
  template <std::size_t N>
  std::optional<std::array<Vec2d, N>> points(std::string_view key);

  /// A number, or an array of numbers: its elements (one for a bare number). Refused
  /// when empty.
  std::optional<std::vector<double>> reals(std::string_view key);
  /// An integer, or an array of integers, likewise.
  std::optional<std::vector<std::int64_t>> integers(std::string_view key);
  /// An array of any number of [x, y] points (`what` describes it in refusals).
  std::optional<std::vector<Vec2d>> point_list(std::string_view key, std::string_view what);

  /// The enumerator whose spelling equals the string under `key`, from a table of
  /// {spelling, value} (those of setting_names.hpp: one table per enumeration).
  template <class E, class Options>
  std::optional<E> choice_in(std::string_view key, const Options& options);
  /// An array of such spellings, each at most once (empty allowed): their enumerators, in
  /// the file's order.
  template <class E, class Options>
  std::optional<std::vector<E>> choices_in(std::string_view key, const Options& options);

  /// For a getter's result on a required key: the value, or a "missing required key" error.
  template <class T>
  T required(std::optional<T> value, std::string_view key) const {
    if (!value) fail_missing(key);
    return *std::move(value);
  }

  /// Refuses the value of `key` (or the table, if the key is absent) with `message`.
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  /// Refuses `at`, a node inside the value of `key` (an array element, say).
  [[noreturn]] void fail_at(const toml::node& at, std::string_view key,
                            std::string_view message) const;
  /// Refuses the whole table.
  [[noreturn]] void fail_table(std::string_view message) const;

  /// Refuses the first key (in file order) that no getter asked about.
  void reject_unknown_keys() const;

  const std::string& context() const { return context_; }
  const std::string& source() const { return source_; }

  /// The point [x, y] at `n`, an element of the value of `key` (`what` describes the
  /// expected value in refusals).
  Vec2d point_at(const toml::node& n, std::string_view key, std::string_view what) const;

 private:
  [[noreturn]] void fail_missing(std::string_view key) const;
  double number_at(const toml::node& n, std::string_view key) const;

  const toml::table& table_;
  const std::string& source_;
  std::string context_;
  std::vector<std::string> known_;
};

/// How a TOML type reads in a message: "a string", "an integer", ...
std::string_view describe_type(toml::node_type type);

template <std::size_t N>
std::optional<std::array<Vec2d, N>> TableReader::points(std::string_view key) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  const auto* array = n->as_array();
  const std::string shape = N == 3 ? "an array of 3 points [[x, y], [x, y], [x, y]]"
                                   : "an array of 2 corners [[xmin, ymin], [xmax, ymax]]";
  if (!array) fail(key, "expected " + shape + ", got " + std::string(describe_type(n->type())));
  if (array->size() != N)
    fail(key, "expected " + shape + ", got " + std::to_string(array->size()) + " element(s)");
  std::array<Vec2d, N> out{};
  for (std::size_t i = 0; i < N; ++i) out[i] = point_at(*array->get(i), key, shape);
  return out;
}

template <class E, class Options>
std::optional<E> TableReader::choice_in(std::string_view key, const Options& options) {
  const std::optional<std::string> text = string(key);
  if (!text) return std::nullopt;
  std::string allowed;
  for (const auto& [spelling, value] : options) {
    if (spelling == *text) return value;
    allowed += (allowed.empty() ? "\"" : ", \"") + std::string(spelling) + "\"";
  }
  fail(key, "unknown value \"" + *text + "\" (expected one of " + allowed + ")");
}

template <class E, class Options>
std::optional<std::vector<E>> TableReader::choices_in(std::string_view key,
                                                      const Options& options) {
  const toml::node* n = node(key);
  if (!n) return std::nullopt;
  std::string allowed;
  for (const auto& [spelling, value] : options)
    allowed += (allowed.empty() ? "\"" : ", \"") + std::string(spelling) + "\"";
  const auto* array = n->as_array();
  if (!array)
    fail(key, "expected an array of names (any of " + allowed + "), got " +
                  std::string(describe_type(n->type())));
  std::vector<E> out;
  for (const toml::node& element : *array) {
    const auto* text = element.as_string();
    if (!text)
      fail_at(element, key,
              "expected a name (a string), got " + std::string(describe_type(element.type())));
    const auto it = std::find_if(options.begin(), options.end(),
                                 [&](const auto& o) { return o.first == text->get(); });
    if (it == options.end())
      fail_at(element, key,
              "unknown name \"" + text->get() + "\" (expected any of " + allowed + ")");
    if (std::find(out.begin(), out.end(), it->second) != out.end())
      fail_at(element, key, "\"" + text->get() + "\" is listed twice");
    out.push_back(it->second);
  }
  return out;
}

}  // namespace tridem::scene_detail
