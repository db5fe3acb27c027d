// The Gmsh module's one exported symbol: the table of its functions. Every exception
// stops here and crosses to tridem as its message.
#include "io/scene/gmsh_mesh.hpp"
#include "io/scene/gmsh_module_api.hpp"

#include <exception>

namespace tridem::gmsh_module {
namespace {

template <class Work>
bool reporting_errors(std::string& error, Work&& work) {
  try {
    work();
    return true;
  } catch (const std::exception& e) {
    error = e.what();
  } catch (...) {
    error = "the Gmsh module failed without a message";
  }
  return false;
}

bool read_mesh_entry(const std::filesystem::path& file, const std::vector<std::string>& groups,
                     scene_detail::ImportedParticles& out, std::string& error) {
  return reporting_errors(error, [&] { out = read_mesh(file, groups); });
}

bool mesh_region_entry(const scene_detail::MeshRegion& region, const std::string& what,
                       scene_detail::ImportedParticles& out, std::string& error) {
  return reporting_errors(error, [&] { out = mesh(region, what); });
}

constexpr scene_detail::GmshModuleApi kApi{scene_detail::kGmshModuleAbi, read_mesh_entry,
                                           mesh_region_entry};

}  // namespace
}  // namespace tridem::gmsh_module

extern "C" __attribute__((visibility("default"))) const tridem::scene_detail::GmshModuleApi*
tridem_gmsh_module() {
  return &tridem::gmsh_module::kApi;
}
