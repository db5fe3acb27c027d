// Checkpoints on disk: atomic writing, whole-file reading, and the check that a
// checkpoint belongs to the run about to continue from it.
#include "io/output/atomic_file.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fmt/format.h>

namespace tridem {

void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint) {
  io::write_file_atomically(file, encode_checkpoint(checkpoint));
}

void Solver::save_checkpoint(const std::filesystem::path& file, const CheckpointMeta& meta,
                             Checkpoint& scratch) const {
  save_state(scratch.state);
  scratch.meta = meta;
  write_checkpoint(file, scratch);
}

Checkpoint read_checkpoint(const std::filesystem::path& file) {
  std::FILE* in = std::fopen(file.c_str(), "rb");
  if (!in)
    throw RunError(fmt::format("cannot read checkpoint '{}': {}", file.string(),
                               std::strerror(errno)));
  std::vector<std::uint8_t> bytes;
  std::uint8_t buffer[1 << 16];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, in)) > 0)
    bytes.insert(bytes.end(), buffer, buffer + got);
  const bool failed = std::ferror(in) != 0;
  std::fclose(in);
  if (failed) throw RunError(fmt::format("cannot read checkpoint '{}'", file.string()));
  return decode_checkpoint(bytes, file.string());
}

void check_checkpoint_fits(const Checkpoint& c, const std::filesystem::path& file,
                           const Scene& scene, const CheckpointMeta& run) {
  const Precision precision = run.precision;
  const std::string name = file.string();
  if (c.state.size() != scene.triangles.size())
    throw RunError(fmt::format("{}: checkpoint of {} particles, but scene '{}' has {}: it "
                               "belongs to another scene",
                               name, c.state.size(), scene.source, scene.triangles.size()));
  if (c.meta.scene_hash != scene_fingerprint(scene))
    throw RunError(fmt::format("{}: checkpoint of another scene: the particles of '{}' "
                               "(vertices, velocities, motions or densities) differ from "
                               "those the checkpoint was written for",
                               name, scene.source));
  if (c.meta.precision != precision) {
    throw RunError(fmt::format("{}: checkpoint written by a {} solver; this run is {} (set "
                               "[simulation] precision = \"{}\" to continue it exactly)",
                               name, precision_name(c.meta.precision), precision_name(precision),
                               precision_name(c.meta.precision)));
  }
  check_physics_settings(c.meta.settings, run.settings, name);
}

}  // namespace tridem
