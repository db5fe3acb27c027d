#include "omp_wait_policy.hpp"

#include <cstdlib>
#include <initializer_list>
#include <unistd.h>

namespace tridem::app {

void wait_passively_unless_told(char** argv) {
  for (const char* told : {"OMP_WAIT_POLICY", "GOMP_SPINCOUNT"})
    if (std::getenv(told) != nullptr) return;
  // An MPI launcher's rank keeps the environment it was given.
  for (const char* launcher : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    if (std::getenv(launcher) != nullptr) return;
  if (setenv("OMP_WAIT_POLICY", "passive", 0) != 0) return;
  execv("/proc/self/exe", argv);
  // Not restarted (no /proc): the runtime's default stays, and so does the run.
}

}  // namespace tridem::app
