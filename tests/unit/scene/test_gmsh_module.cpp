// The Gmsh module (src/io/scene/gmsh_module_api.hpp): no program links libgmsh, the module
// loads when a mesh is needed, and a module that is missing or not one is refused with a
// message naming each place looked at.
#include "io/scene/gmsh_module_loader.hpp"
#include "tridem/error.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>
#include <link.h>

#include <fstream>
#include <string>
#include <vector>

namespace tridem::scene_detail {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;

std::string refusal(const std::vector<fs::path>& candidates) {
  try {
    load_gmsh_module(candidates, "[[mesh]] 1");
  } catch (const SceneError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no refusal";
  return {};
}

/// The DT_NEEDED entries of the running program (the test binary links tridem_core as
/// the tridem program does).
std::vector<std::string> needed_libraries() {
  std::vector<std::string> out;
  // The loader hands out addresses as integers: the casts to pointers cannot be avoided.
  // NOLINTBEGIN(performance-no-int-to-ptr)
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        auto& names = *static_cast<std::vector<std::string>*>(data);
        for (int k = 0; k < info->dlpi_phnum; ++k) {
          if (info->dlpi_phdr[k].p_type != PT_DYNAMIC) continue;
          const auto* dyn =
              reinterpret_cast<const ElfW(Dyn)*>(info->dlpi_addr + info->dlpi_phdr[k].p_vaddr);
          const char* strtab = nullptr;
          for (const ElfW(Dyn)* d = dyn; d->d_tag != DT_NULL; ++d)
            if (d->d_tag == DT_STRTAB) {
              // The loader relocates the table's addresses in place on x86-64; an
              // unrelocated one is an offset from the load address.
              const auto at = static_cast<ElfW(Addr)>(d->d_un.d_ptr);
              strtab =
                  reinterpret_cast<const char*>(at < info->dlpi_addr ? info->dlpi_addr + at : at);
            }
          for (const ElfW(Dyn)* d = dyn; strtab && d->d_tag != DT_NULL; ++d)
            if (d->d_tag == DT_NEEDED) names.emplace_back(strtab + d->d_un.d_val);
        }
        return 1;  // the first object is the program itself
      },
      &out);
  // NOLINTEND(performance-no-int-to-ptr)
  return out;
}

TEST(GmshModule, TheProgramDoesNotLinkGmsh) {
  const std::vector<std::string> needed = needed_libraries();
  ASSERT_FALSE(needed.empty()) << "the program's dynamic section was not read";
  bool has_libc = false;
  for (const std::string& name : needed) {
    EXPECT_EQ(name.find("gmsh"), std::string::npos) << name;
    has_libc = has_libc || name.find("libc.so") != std::string::npos;
  }
  EXPECT_TRUE(has_libc) << "the names read are not the program's libraries";
}

TEST(GmshModule, AMissingModuleIsRefusedNamingWhereItLooked) {
  const std::string message =
      refusal({"/nonexistent/a/libtridem_gmsh.so", "/nonexistent/b/libtridem_gmsh.so"});
  EXPECT_NE(message.find("[[mesh]] 1: this tridem cannot load its Gmsh module"), std::string::npos)
      << message;
  EXPECT_NE(message.find("/nonexistent/a/libtridem_gmsh.so: no such file"), std::string::npos)
      << message;
  EXPECT_NE(message.find("/nonexistent/b/libtridem_gmsh.so: no such file"), std::string::npos)
      << message;
  EXPECT_NE(message.find("TRIDEM_GMSH_MODULE"), std::string::npos) << message;
}

TEST(GmshModule, AFileThatIsNoLibraryIsRefusedWithTheLoadersReason) {
  test::TempDir dir;
  const fs::path fake = dir.path() / "libtridem_gmsh.so";
  std::ofstream(fake) << "not a shared library\n";
  const std::string message = refusal({fake});
  EXPECT_NE(message.find(fake.string() + ": "), std::string::npos) << message;
  EXPECT_EQ(message.find("no such file"), std::string::npos) << message;
}

TEST(GmshModule, ALibraryWithoutTheTableIsRefusedAsAnotherBuilds) {
  // libz is loaded by every tridem program (the frames' compression) and has no table.
  std::string libz;
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void* data) {
        const std::string name = info->dlpi_name ? info->dlpi_name : "";
        if (name.find("libz.so") != std::string::npos) *static_cast<std::string*>(data) = name;
        return 0;
      },
      &libz);
  ASSERT_FALSE(libz.empty()) << "libz is not loaded";
  const std::string message = refusal({libz});
  EXPECT_NE(message.find(libz + ": a Gmsh module of another build of tridem"), std::string::npos)
      << message;
}

#ifdef TRIDEM_HAS_GMSH
TEST(GmshModule, TheBuildsModuleIsFoundAndLoads) {
  const std::vector<fs::path> candidates = gmsh_module_candidates();
  ASSERT_FALSE(candidates.empty());
  const GmshModuleApi& api = load_gmsh_module(candidates, "this test");
  EXPECT_EQ(api.abi, kGmshModuleAbi);
  ImportedParticles out;
  std::string error;
  EXPECT_FALSE(api.read_mesh("/nonexistent.msh", {}, out, error));
  EXPECT_NE(error.find("/nonexistent.msh: cannot read the mesh: no such file"), std::string::npos)
      << error;
}
#endif

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem::scene_detail
