#pragma once
// A double as the CSV outputs print it: the shortest text that reads back the same double
// (at most 17 significant digits; std::to_chars' shortest form, Ryu): 0.1 is "0.1", not
// %.17g's "0.10000000000000001". Shortest, it formats some 1.5 times faster than %.17g
// through to_chars (58 against 89 ns a number here; fmt's {:.17g} took 143): a 10^7-triangle run
// prints some 2x10^8 of them at its end, a 10^6-triangle frame 6x10^7 in its contacts (issue 12).
// Until 2026-12-06 the CSVs printed %.17g; the doubles read back are the same.
#include <charconv>
#include <fmt/compile.h>
#include <fmt/format.h>

namespace tridem::io {

/// A number printed as the shortest text that reads back the same number of its type.
template <class T>
struct Shortest {
  T value;
};

/// A double: at most 17 significant digits.
using Exact = Shortest<double>;

/// A number that is exactly a float32 (what the float precision's pairs computed), printed
/// with the fewest digits that read back the same float32 (at most 9 significant). Its
/// 17-digit double text would be twice as long, and its last eight digits would say nothing
/// the float32 holds.
using ExactFloat = Shortest<float>;

}  // namespace tridem::io

template <class T>
struct fmt::formatter<tridem::io::Shortest<T>> {
  constexpr auto parse(fmt::format_parse_context& ctx) { return ctx.begin(); }
  template <class Context>
  auto format(tridem::io::Shortest<T> e, Context& ctx) const {
    char text[32];  // 17 digits, sign, point, exponent: at most 24
    const std::to_chars_result r = std::to_chars(text, text + sizeof text, e.value);
    return std::copy(text, r.ptr, ctx.out());
  }
};
