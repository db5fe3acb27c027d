#pragma once
// Checkpoint files: a SolverState on disk, so that a run can continue after a crash, a
// Ctrl-C or a blow-up (docs/reliability.md). The layout is in io/checkpoint/format.hpp.
// Writing goes to a temporary file that is synced and then renamed over the old one, so
// a checkpoint on disk is always a whole one; reading refuses, with a message naming the
// file, anything truncated, corrupt, of another version, scene or precision.
#include "tridem/scene.hpp"
#include "tridem/solver_state.hpp"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace tridem {

/// One setting that changes the physics, as a scene key and its value in text.
struct PhysicsSetting {
  std::string key;    ///< as a user finds it in the scene: "[simulation] method"
  std::string value;  ///< exact: reals in their shortest round-trip form
  bool operator==(const PhysicsSetting&) const = default;
};

/// What a checkpoint says about the run it belongs to, besides the state.
struct CheckpointMeta {
  Precision precision = Precision::Double;  ///< of the solver that wrote it
  std::uint64_t scene_hash = 0;              ///< scene_fingerprint() of its scene
  std::vector<PhysicsSetting> settings;      ///< physics_settings() of its run
};

struct Checkpoint {
  CheckpointMeta meta;
  SolverState state;
};

/// A hash of what defines the particles of a scene: their count, vertices, velocities,
/// motions and materials' densities, and, when some body has several triangles, how the
/// triangles are grouped into bodies and the bodies' velocities and motions. Contact
/// parameters, dt and outputs are left out, so that a run may go on with, say, a smaller
/// dt after a blow-up.
std::uint64_t scene_fingerprint(const Scene& scene);

/// The settings of `scene` (command-line overrides applied) that change its trajectory,
/// with the step `dt` the run uses: method and contact test, dt, gravity, damping, the
/// penetration limit and every material's contact parameters. Backend, skin, the
/// decomposition's layout and outputs change no result and are left out.
std::vector<PhysicsSetting> physics_settings(const Scene& scene, double dt);

/// Refuses (RunError naming the file, the key and both values) a restart whose settings
/// differ from those stored in the checkpoint.
void check_physics_settings(const std::vector<PhysicsSetting>& stored,
                            const std::vector<PhysicsSetting>& current,
                            const std::string& file);

/// The bytes of a checkpoint file, and back. decode_checkpoint checks the format (magic,
/// version, sizes, checksums) and the state (validate_solver_state) and throws
/// tridem::Error prefixed by `source` on any fault.
std::vector<std::uint8_t> encode_checkpoint(const Checkpoint& checkpoint);
Checkpoint decode_checkpoint(std::span<const std::uint8_t> bytes, const std::string& source);

/// Writes atomically: `file` is either left as it was or replaced by the whole new
/// checkpoint. Throws RunError naming the file on failure.
void write_checkpoint(const std::filesystem::path& file, const Checkpoint& checkpoint);

/// Reads and decodes a checkpoint file.
Checkpoint read_checkpoint(const std::filesystem::path& file);

/// Refuses (RunError naming the file) a checkpoint that does not belong to a run of
/// `scene` described by `run` (its precision and physics settings).
void check_checkpoint_fits(const Checkpoint& checkpoint, const std::filesystem::path& file,
                           const Scene& scene, const CheckpointMeta& run);

}  // namespace tridem
