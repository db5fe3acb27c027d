#pragma once
// What both benchmark programs need around Google Benchmark: their own --name=value flags
// (taken out of argv before benchmark::Initialize sees it) and the host's CPU model.
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>

#include "tridem/setting_names.hpp"

namespace tridem::bench {

/// Takes "--name=value" out of argv; returns the value or an empty string.
inline std::string take_flag(int& argc, char** argv, const std::string& name) {
  const std::string prefix = "--" + name + "=";
  std::string value;
  int out = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind(prefix, 0) == 0)
      value = arg.substr(prefix.size());
    else
      argv[out++] = argv[i];
  }
  argc = out;
  return value;
}

/// A number in [lo, hi], or exit 2 with a message naming the program and the flag.
inline double parse_number_in(const char* program, const std::string& flag, const std::string& text,
                              double lo, double hi, const char* wanted) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && v >= lo && v <= hi) return v;
  } catch (const std::exception&) {
  }
  std::cerr << program << ": --" << flag << " wants " << wanted << ", got '" << text << "'\n";
  std::exit(2);
}

/// A positive number, or exit 2 with a message naming the program and the flag.
inline double parse_number(const char* program, const std::string& flag, const std::string& text) {
  return parse_number_in(program, flag, text, std::nextafter(0.0, 1.0),
                         std::numeric_limits<double>::infinity(), "a positive number");
}

/// Takes "--name=spelling" out of argv into `value`, for a setting spelt in `table`
/// (tridem/setting_names.hpp); false, after a message naming the program, for a spelling
/// it does not know.
template <class Table, class E>
bool take_choice(const char* program, int& argc, char** argv, const std::string& name,
                 const Table& table, E& value) {
  const std::string text = take_flag(argc, argv, name);
  if (text.empty()) return true;
  const auto v = value_in(table, text);
  if (!v) {
    std::cerr << program << ": --" << name << " wants one of " << spellings_of(table) << "; got '"
              << text << "'\n";
    return false;
  }
  value = *v;
  return true;
}

inline std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) {
        auto model = line.substr(colon + 1);
        model.erase(0, model.find_first_not_of(" \t"));
        return model;
      }
    }
  return "unknown";
}

}  // namespace tridem::bench
