#pragma once
// The VTK files of a frame, written through a VtkXmlWriter that the run keeps, so that
// its buffers serve every frame (tridem/output.hpp has the same writers for one file).
#include "io/output/vtk_xml_writer.hpp"
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"

#include <filesystem>

namespace tridem::io {

void write_vtu_frame(VtkXmlWriter&, const std::filesystem::path& file, const Snapshot&,
                     bool grain_stress, ArraySet<FrameArray> arrays = {});
void write_contacts_vtp(VtkXmlWriter&, const std::filesystem::path& file, const Snapshot&,
                        ArraySet<ContactArray> arrays = {});
void write_bonds_vtp(VtkXmlWriter&, const std::filesystem::path& file, const Snapshot&);

}  // namespace tridem::io
