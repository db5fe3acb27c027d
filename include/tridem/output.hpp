#pragma once
// Everything a run writes to disk. Every writer takes the double-precision Snapshot, so
// none of this depends on the solver's real type or backend. docs/output-format.md is
// the users' description of the files; keep the two in step.
#include "tridem/contact_copy.hpp"
#include "tridem/energy_budget.hpp"
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace tridem {

/// Conserved quantities of the free particles at one step, and the energy budget. Fixed
/// and prescribed particles are excluded: their motion is imposed, so they would only hide
/// what the solver does (what moving walls put in is `wall_work`).
struct EnergyRow {
  std::int64_t step = 0;
  double time = 0;
  double kinetic = 0;     ///< J/m
  double momentum_x = 0;  ///< kg/s (per unit thickness)
  double momentum_y = 0;
  double angular_momentum = 0;  ///< about the origin, kg·m/s
  double potential = 0;         ///< gravitational, −Σ m g·c (zero at the origin), J/m
  EnergyBudget budget;          ///< from Solver::energy()
  /// kinetic + potential + elastic + the three dissipations − wall_work: constant up to
  /// the time discretisation.
  double total() const;
};

/// The row of a snapshot under gravity `g`, with the solver's budget.
EnergyRow compute_energy(const Snapshot&, Vec2d gravity = {}, const EnergyBudget& budget = {});

/// Frame and contact file names carry the step padded to 9 digits so that they sort.
std::string frame_file_name(std::int64_t step);     ///< frame_000000042.vtu
std::string contacts_file_stem(std::int64_t step);  ///< contacts_000000042
/// The frame of the highest step in an output directory (frames/frame_<step>.vtu), or none.
std::optional<std::filesystem::path> last_frame_file(const std::filesystem::path& dir);

// Single-file writers. OutputSet calls them; tools and tests may call them alone. All
// throw RunError naming the path and the system's reason when the file cannot be written.
void write_final_csv(const std::filesystem::path& file, const Snapshot&);
/// bodies.csv: one row per body (Snapshot::body_count()), in body-id order; without bodies
/// of several triangles, one per triangle, from the triangle columns.
void write_bodies_csv(const std::filesystem::path& file, const Snapshot&);
/// `grain_stress`: the per-grain stress, pressure and coordination arrays, from the
/// snapshot's contacts (a run writes them when [output] contacts is on: the contacts then
/// come with every frame).
/// The VTK files take the format of their arrays (VtkFormat: binary, Float32, zlib by
/// default; the scene's `[output] vtk_encoding`, `vtk_precision`, `vtk_compression`).
/// `arrays`: the real fields it carries (`[output] frame_arrays`; all by default).
void write_vtu_frame(const std::filesystem::path& file, const Snapshot&, VtkFormat = {},
                     bool grain_stress = true, ArraySet<FrameArray> arrays = {});
void write_contacts_csv(const std::filesystem::path& file, const Snapshot&);
/// `arrays`: the cell arrays it carries (`[output] contact_arrays`; all by default).
void write_contacts_vtp(const std::filesystem::path& file, const Snapshot&, VtkFormat = {},
                        ArraySet<ContactArray> arrays = {});
/// bonds/bonds_<step>.vtp: the cohesive bonds as lines along their shared edges, with
/// cell data damage (0 to 1), broken (0 or 1) and the two triangles' ids a, b.
void write_bonds_vtp(const std::filesystem::path& file, const Snapshot&, VtkFormat = {});

/// Reads back a frame written by write_vtu_frame, in any VtkFormat (and the Float64
/// uncompressed frames written before issue 12). Recovers step, time,
/// vertices, centroids (vertex mean), velocities, forces, torques, material and motion, in
/// id order, and each triangle's body (member_body and body_first, when some body has
/// several triangles; frames written before bodies have no `body` array and read as
/// bodiless). theta, mass and inertia are not stored in frames and come back as 0; the
/// other per-body columns and contacts are left empty. The real fields a frame was written
/// without (`[output] frame_arrays`) read as 0; `arrays`, when given, receives those it
/// holds. Throws Error on a file it cannot read or that is not such a frame.
Snapshot read_vtu_frame(const std::filesystem::path& file, ArraySet<FrameArray>* arrays = nullptr);

/// Whether a [[measure]] writing every `every` steps has a row at `step`: at the positive
/// multiples of `every` (every > 0) and at the run's last step; never at step 0, before
/// any contact force has been computed.
inline bool measure_due(std::int64_t every, std::int64_t step, bool last_step) {
  return step > 0 && (last_step || (every > 0 && step % every == 0));
}

/// Where a restarted run takes over the outputs of the run it continues.
struct ResumePoint {
  std::int64_t step = 0;
  double time = 0;
};

/// The files of one run, under one directory (each format an io::OutputWriter, listed in
/// io/output/output_writers.cpp):
///   energy.csv, walls.csv          one block of rows per log() call, flushed each time
///   frames/frame_<step>.vtu        one per write_frame(), listed in tridem.pvd
///   contacts/contacts_<step>.csv   and .vtp, with each frame when settings.contacts,
///                                  the .vtp files listed in contacts.pvd
///   measure_<name>.csv             a row per measure() call due for that [[measure]]
///   final.csv, bodies.csv          from write_final()
/// Frames go through write_frame, or beside the caller through write_frame_beside.
/// The .pvd collections are replaced atomically after every frame, so they stay valid
/// if the run dies. Every failure to create or write throws RunError.
/// A fresh set removes the tridem files of an earlier run in `dir`; a resumed one keeps
/// them up to the resume point and removes what came after (rows, frames, entries).
class OutputSet {
 public:
  OutputSet(const OutputSettings&, std::filesystem::path dir, VtkFormat = {},
            const std::optional<ResumePoint>& resume = std::nullopt);
  ~OutputSet();
  OutputSet(OutputSet&&) noexcept;
  OutputSet& operator=(OutputSet&&) noexcept;

  void write_frame(const Snapshot&);
  /// The same files as write_frame, written by the set's output thread while the caller
  /// goes on (io/output/frame_thread.hpp): waits for the previous frame, then takes the
  /// contents of `s` by swap (`s` is left with an earlier frame's buffer, for the next
  /// Solver::snapshot to overwrite). The other calls may run while a frame is written: the
  /// frames' writers share nothing with the logs'. A failure surfaces as the RunError it
  /// was, thrown by the next write_frame_beside, write_frame or finish_frames. With
  /// `contacts` (started at `s`'s step, its buffers not in use), the output thread first
  /// appends the contacts it copies to `s`'s contents (tridem/contact_copy.hpp).
  void write_frame_beside(Snapshot& s, ContactCopy* contacts = nullptr);
  /// Waits for the frame in flight; throws its failure, if any.
  void finish_frames();
  /// One row of energy.csv (with the solver's budget under gravity g) and walls.csv.
  void log(const Snapshot&, Vec2d gravity = {}, const EnergyBudget& budget = {});
  void write_final(const Snapshot&);
  /// A row of each [[measure]] due at the snapshot's step (measure_due); the snapshot
  /// must hold the contacts. `last_step`: the run's last step.
  void measure(const Snapshot&, bool last_step);

  const std::filesystem::path& dir() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tridem
