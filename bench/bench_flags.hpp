#pragma once
// What both benchmark programs need around Google Benchmark: their own --name=value flags
// (taken out of argv before benchmark::Initialize sees it) and the host's CPU model.
#include <cstddef>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <string>

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

/// A positive number, or exit 2 with a message naming the program and the flag.
inline double parse_number(const char* program, const std::string& flag, const std::string& text) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used == text.size() && v > 0) return v;
  } catch (const std::exception&) {
  }
  std::cerr << program << ": --" << flag << " wants a positive number, got '" << text << "'\n";
  std::exit(2);
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
