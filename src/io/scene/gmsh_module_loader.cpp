// read_gmsh_mesh and mesh_region for tridem_core: the Gmsh module, dlopen'ed on first use
// (gmsh_module_api.hpp says why Gmsh is not linked).
#include "io/scene/gmsh_module_loader.hpp"

#include "tridem/error.hpp"

#include <dlfcn.h>
#include <fmt/format.h>

#include <cstdlib>
#include <mutex>

namespace tridem::scene_detail {
namespace fs = std::filesystem;

std::vector<fs::path> gmsh_module_candidates() {
  if (const char* path = std::getenv("TRIDEM_GMSH_MODULE"); path && *path) return {path};
  std::vector<fs::path> out;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) out.push_back(exe.parent_path().parent_path() / "lib" / "tridem" / kGmshModuleFile);
#ifdef TRIDEM_GMSH_MODULE_BUILD_PATH
  out.emplace_back(TRIDEM_GMSH_MODULE_BUILD_PATH);
#endif
  return out;
}

const GmshModuleApi& load_gmsh_module(const std::vector<fs::path>& candidates,
                                      const std::string& what) {
  std::string tried;
  for (const fs::path& file : candidates) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) {
      tried += fmt::format("\n  {}: no such file", file.string());
      continue;
    }
    // Never closed: Gmsh's global state lives as long as the program.
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      tried += fmt::format("\n  {}: {}", file.string(), dlerror());
      continue;
    }
    const auto entry = reinterpret_cast<GmshModuleEntry>(dlsym(handle, kGmshModuleEntry));
    const GmshModuleApi* api = entry ? entry() : nullptr;
    if (!api || api->abi != kGmshModuleAbi) {
      tried += fmt::format("\n  {}: a Gmsh module of another build of tridem (ABI {}, this "
                           "tridem needs {})",
                           file.string(), api ? api->abi : -1, kGmshModuleAbi);
      continue;
    }
    return *api;
  }
  throw SceneError(fmt::format("{}: this tridem cannot load its Gmsh module ({}), which reads "
                               "and makes meshes; looked for it at:{}\nReinstall tridem (cmake "
                               "--install puts it in lib/tridem/), point TRIDEM_GMSH_MODULE at "
                               "it, or import the triangles from a CSV",
                               what, kGmshModuleFile, tried));
}

namespace {

const GmshModuleApi& gmsh_module(const std::string& what) {
  // Loaded once; a failed load is retried (and reported) by the next scene that needs it.
  static std::mutex mutex;
  static const GmshModuleApi* api = nullptr;
  const std::lock_guard lock(mutex);
  if (!api) api = &load_gmsh_module(gmsh_module_candidates(), what);
  return *api;
}

ImportedParticles checked(bool ok, ImportedParticles&& out, const std::string& error) {
  if (!ok) throw SceneError(error);
  return std::move(out);
}

}  // namespace

ImportedParticles read_gmsh_mesh(const fs::path& file, const std::vector<std::string>& groups) {
  const GmshModuleApi& api = gmsh_module(file.string());
  ImportedParticles out;
  std::string error;
  const bool ok = api.read_mesh(file, groups, out, error);
  return checked(ok, std::move(out), error);
}

ImportedParticles mesh_region(const MeshRegion& region, const std::string& what) {
  const GmshModuleApi& api = gmsh_module(what);
  ImportedParticles out;
  std::string error;
  const bool ok = api.mesh_region(region, what, out, error);
  return checked(ok, std::move(out), error);
}

}  // namespace tridem::scene_detail
