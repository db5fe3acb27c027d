#pragma once
// The environment the tridem program runs in (issue 12). Two settings are read by
// libraries as they load, before main() (a setting made in main() is too late, and one
// made by an ELF pre-initialiser is undone by the C library's own start-up), so the
// program starts itself again, once, with them in its environment:
//
// - OMP_WAIT_POLICY=passive: a thread that reaches a barrier early sleeps instead of
//   spinning. libgomp's default spins some 300 000 times first (milliseconds), and when
//   other programs share the cores that spinning takes the core from the very thread it
//   waits for: on 2 busy cores the bundled example's OpenMP steps took 24-40 times the
//   serial solver's with the default, 0.5-1.5 times with passive waits (medians;
//   docs/performance.md, "OpenMP on shared cores"). A user's own OMP_WAIT_POLICY or
//   GOMP_SPINCOUNT is left as it is, as is an MPI rank's.
// - glibc.malloc.hugetlb=1 added to GLIBC_TUNABLES (glibc 2.35 and later; older ones
//   ignore it): the C library asks the kernel for transparent huge pages for its large
//   blocks (madvise), so that the set-up's and the outputs' arrays of a large scene are
//   touched 2 MiB at a time rather than 4 KiB: a page fault each, which led the profile
//   of a 10^7-triangle set-up (docs/performance.md, "Set-up and final outputs of a large
//   run"). Left as it is when GLIBC_TUNABLES already names glibc.malloc.hugetlb; kernels
//   whose huge pages are off ignore the advice.
//
// A program linking the library (make_solver) keeps its own environment.

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tridem::app {

/// The variables to set (name, value) for an environment read by `get` (getenv's
/// signature): empty when nothing is to change.
template <class Get>
std::vector<std::pair<std::string, std::string>> startup_environment_changes(Get get) {
  std::vector<std::pair<std::string, std::string>> changes;
  const bool told = get("OMP_WAIT_POLICY") != nullptr || get("GOMP_SPINCOUNT") != nullptr;
  // An MPI launcher's rank keeps the wait policy it was given.
  const bool rank = get("OMPI_COMM_WORLD_SIZE") != nullptr || get("PMI_SIZE") != nullptr ||
                    get("PMIX_RANK") != nullptr;
  if (!told && !rank) changes.emplace_back("OMP_WAIT_POLICY", "passive");
  const char* tunables = get("GLIBC_TUNABLES");
  const std::string given = tunables != nullptr ? tunables : "";
  if (given.find("glibc.malloc.hugetlb") == std::string::npos)
    changes.emplace_back("GLIBC_TUNABLES", given.empty() ? "glibc.malloc.hugetlb=1"
                                                         : given + ":glibc.malloc.hugetlb=1");
  return changes;
}

/// Call first in main(): returns when nothing is to change or the restart failed.
void restart_with_startup_environment(char** argv);

}  // namespace tridem::app
