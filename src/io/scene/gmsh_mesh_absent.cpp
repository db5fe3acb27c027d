// A build configured with -DTRIDEM_WITH_GMSH=OFF has no Gmsh: a mesh is refused, saying so.
#include "io/scene/imported_particles.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

namespace tridem::scene_detail {

ImportedParticles read_gmsh_mesh(const std::filesystem::path& file,
                                 const std::vector<std::string>& /*body_groups*/) {
  throw SceneError(fmt::format("{}: this build of tridem reads no Gmsh meshes (configured with "
                               "-DTRIDEM_WITH_GMSH=OFF); rebuild with it ON (libgmsh-dev) or "
                               "export the mesh's triangles as a CSV",
                               file.string()));
}

ImportedParticles mesh_region(const MeshRegion& /*region*/, const std::string& what) {
  throw SceneError(fmt::format("{}: this build of tridem has no Gmsh to mesh it (configured "
                               "with -DTRIDEM_WITH_GMSH=OFF); rebuild with it ON (libgmsh-dev), "
                               "or import its triangles from a CSV with [[import]] (without "
                               "bonds)",
                               what));
}

}  // namespace tridem::scene_detail
