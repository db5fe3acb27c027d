#include "startup_environment.hpp"

#include <cstdlib>
#include <unistd.h>

namespace tridem::app {

void restart_with_startup_environment(char** argv) {
  const auto changes = startup_environment_changes(std::getenv);
  if (changes.empty()) return;
  for (const auto& [name, value] : changes)
    if (setenv(name.c_str(), value.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);
  // Not restarted (no /proc): the libraries' defaults stay, and so does the run.
}

}  // namespace tridem::app
