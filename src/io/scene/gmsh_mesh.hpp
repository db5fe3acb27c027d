#pragma once
// What the Gmsh module does with Gmsh (gmsh_mesh.cpp); tridem reaches it through
// GmshModuleApi (gmsh_module_api.hpp), never by linking it.
#include "io/scene/imported_particles.hpp"

namespace tridem::gmsh_module {

/// read_gmsh_mesh and mesh_region of imported_particles.hpp, done by Gmsh.
scene_detail::ImportedParticles read_mesh(const std::filesystem::path& file,
                                          const std::vector<std::string>& body_groups);
scene_detail::ImportedParticles mesh(const scene_detail::MeshRegion& region,
                                     const std::string& what);

}  // namespace tridem::gmsh_module
