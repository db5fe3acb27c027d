#pragma once
// The table through which tridem calls its Gmsh module (libtridem_gmsh.so), loaded only
// when a scene reads or makes a mesh. Linking libgmsh into every program made each start
// pay for its ~90 shared libraries (OpenCASCADE, FLTK, X11): 0.15-0.2 s per process, once
// per test of the suite and per `tridem` call. Errors cross as text, never as exceptions.
#include "io/scene/imported_particles.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace tridem::scene_detail {

/// Bumped whenever the table or the types it passes change, so that a module of another
/// build of tridem is refused instead of called.
inline constexpr int kGmshModuleAbi = 2;  // 2: MeshRegion::polygon
inline constexpr const char* kGmshModuleEntry = "tridem_gmsh_module";
inline constexpr const char* kGmshModuleFile = "libtridem_gmsh.so";

struct GmshModuleApi {
  int abi;
  /// Each fills `out` and returns true, or returns false with the message in `error`.
  bool (*read_mesh)(const std::filesystem::path& file, const std::vector<std::string>& groups,
                    ImportedParticles& out, std::string& error);
  bool (*mesh_region)(const MeshRegion& region, const std::string& what, ImportedParticles& out,
                      std::string& error);
};

using GmshModuleEntry = const GmshModuleApi* (*)();

}  // namespace tridem::scene_detail
