#include "restart_command.hpp"

#include <string_view>

namespace tridem::app {

namespace {

std::string shell_quoted(const std::string& arg) {
  constexpr std::string_view plain =
      "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%";
  if (!arg.empty() && arg.find_first_not_of(plain) == std::string::npos) return arg;
  std::string out = "'";
  for (char c : arg) {
    if (c == '\'') out.append("'\\''");
    else out.push_back(c);
  }
  out.push_back('\'');
  return out;
}

}  // namespace

std::string restart_command(const std::vector<std::string>& argv, const std::string& checkpoint) {
  std::string out;
  for (std::size_t i = 0; i < argv.size(); ++i) {
    if (argv[i] == "--restart") {
      ++i;  // and its value
      continue;
    }
    if (argv[i].rfind("--restart=", 0) == 0) continue;
    if (!out.empty()) out.push_back(' ');
    out.append(shell_quoted(argv[i]));
  }
  out.append(" --restart ");
  out.append(shell_quoted(checkpoint));
  return out;
}

}  // namespace tridem::app
