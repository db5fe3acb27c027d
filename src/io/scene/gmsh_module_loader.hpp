#pragma once
// Finding and loading the Gmsh module (gmsh_module_api.hpp) the first time a scene needs it.
#include "io/scene/gmsh_module_api.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace tridem::scene_detail {

/// Where the module is looked for, in order: $TRIDEM_GMSH_MODULE alone when it is set;
/// otherwise lib/tridem/ beside the program's directory (an installed tridem, the device
/// bundle), then the build tree's copy.
std::vector<std::filesystem::path> gmsh_module_candidates();

/// The first candidate that loads as a module of this build's ABI, or SceneError naming
/// each candidate and why it was not taken. `what` names what needed Gmsh.
const GmshModuleApi& load_gmsh_module(const std::vector<std::filesystem::path>& candidates,
                                      const std::string& what);

}  // namespace tridem::scene_detail
