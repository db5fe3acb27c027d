#include "startup_environment.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace tridem::app {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

using Changes = std::vector<std::pair<std::string, std::string>>;

Changes changes_for(const std::map<std::string, std::string>& environment) {
  return startup_environment_changes([&](const char* name) -> const char* {
    const auto it = environment.find(name);
    return it == environment.end() ? nullptr : it->second.c_str();
  });
}

TEST(StartupEnvironment, AnEmptyEnvironmentGetsPassiveWaitsAndHugePages) {
  EXPECT_EQ(changes_for({}), (Changes{{"OMP_WAIT_POLICY", "passive"},
                                      {"GLIBC_TUNABLES", "glibc.malloc.hugetlb=1"}}));
}

TEST(StartupEnvironment, TheUsersTunablesAreKeptAndHugePagesAdded) {
  EXPECT_EQ(
      changes_for({{"OMP_WAIT_POLICY", "active"}, {"GLIBC_TUNABLES", "glibc.malloc.arena_max=2"}}),
      (Changes{{"GLIBC_TUNABLES", "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1"}}));
}

TEST(StartupEnvironment, TheUsersOwnHugePageSettingAndWaitPolicyChangeNothing) {
  EXPECT_TRUE(
      changes_for({{"GOMP_SPINCOUNT", "10000"}, {"GLIBC_TUNABLES", "glibc.malloc.hugetlb=0"}})
          .empty());
}

TEST(StartupEnvironment, AnMpiRankKeepsItsWaitPolicyButGetsHugePages) {
  for (const char* launcher : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK"})
    EXPECT_EQ(changes_for({{launcher, "2"}}),
              (Changes{{"GLIBC_TUNABLES", "glibc.malloc.hugetlb=1"}}))
        << launcher;
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::app
