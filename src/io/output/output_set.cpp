#include "io/output/log_rows.hpp"
#include "io/output/out_file.hpp"
#include "io/output/pvd_collection.hpp"
#include "io/output/resume_outputs.hpp"
#include "tridem/error.hpp"
#include "tridem/output.hpp"

#include <fmt/format.h>

#include <system_error>

namespace tridem {
namespace {

namespace fs = std::filesystem;

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  // An existing regular file of that name is not always reported as an error.
  if (!ec && !fs::is_directory(dir, ec) && !ec)
    ec = std::make_error_code(std::errc::not_a_directory);
  if (ec)
    throw RunError(fmt::format("cannot create output directory '{}': {}", dir.string(),
                               ec.message()));
}

/// A run owns the tridem files of its directory: frames, their renderings and contact files
/// of an earlier run there would otherwise mix with the new ones (ParaView and `tridem
/// render` would show them), and an earlier blow-up's last_good.ckpt would describe a
/// failure this run did not have. Only files with tridem's own names are removed; nothing
/// else is touched (checkpoint.ckpt stays: it may be what the user means to restart from).
void remove_earlier_run(const fs::path& dir) {
  auto remove_matching = [](const fs::path& folder, std::string_view prefix) {
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return;
    for (const auto& entry : fs::directory_iterator(folder, ec)) {
      const std::string name = entry.path().filename().string();
      const std::string ext = entry.path().extension().string();
      if (name.starts_with(prefix) &&
          (ext == ".vtu" || ext == ".vtp" || ext == ".csv" || ext == ".png"))
        fs::remove(entry.path(), ec);
    }
  };
  remove_matching(dir / "frames", "frame_");
  remove_matching(dir / "contacts", "contacts_");
  std::error_code ec;
  for (const char* name : {"tridem.pvd", "contacts.pvd", "final.csv", "last_good.ckpt"})
    fs::remove(dir / name, ec);
}

io::OutFile open_log(const fs::path& file, std::string_view header,
                     const std::optional<ResumePoint>& resume) {
  if (resume) {
    io::trim_log(file, header, resume->step);
    return io::OutFile(file, io::OutFile::Mode::Append);
  }
  io::OutFile out(file);
  out.write(header);
  out.flush();
  return out;
}

io::PvdCollection open_collection(const fs::path& file, const std::optional<ResumePoint>& resume) {
  io::PvdCollection collection(file);
  if (resume) collection.restore(resume->time);
  return collection;
}

}  // namespace

struct OutputSet::Impl {
  OutputSettings settings;
  fs::path dir;
  Encoding encoding;
  io::OutFile energy;
  io::OutFile walls;
  io::PvdCollection frames;
  io::PvdCollection contacts;
  bool subfolders_made = false;
};

OutputSet::OutputSet(const OutputSettings& settings, fs::path dir, Encoding encoding,
                     const std::optional<ResumePoint>& resume) {
  make_directory(dir);
  if (resume)
    io::remove_frames_after(dir, resume->step);
  else
    remove_earlier_run(dir);
  impl_ = std::make_unique<Impl>(Impl{settings, dir, encoding,
                                      open_log(dir / "energy.csv", io::kEnergyHeader, resume),
                                      open_log(dir / "walls.csv", io::kWallsHeader, resume),
                                      open_collection(dir / "tridem.pvd", resume),
                                      open_collection(dir / "contacts.pvd", resume)});
}

OutputSet::~OutputSet() = default;
OutputSet::OutputSet(OutputSet&&) noexcept = default;
OutputSet& OutputSet::operator=(OutputSet&&) noexcept = default;

const fs::path& OutputSet::dir() const { return impl_->dir; }

void OutputSet::write_frame(const Snapshot& s) {
  Impl& o = *impl_;
  // Made on first use so that a run without frames leaves no empty folders.
  if (!o.subfolders_made) {
    make_directory(o.dir / "frames");
    if (o.settings.contacts) make_directory(o.dir / "contacts");
    o.subfolders_made = true;
  }
  const fs::path frame = o.dir / "frames" / frame_file_name(s.step);
  write_vtu_frame(frame, s, o.encoding);
  o.frames.add(s.time, frame);

  if (o.settings.contacts) {
    const fs::path stem = o.dir / "contacts" / contacts_file_stem(s.step);
    fs::path csv = stem, vtp = stem;
    csv += ".csv";
    vtp += ".vtp";
    write_contacts_csv(csv, s);
    write_contacts_vtp(vtp, s, o.encoding);
    o.contacts.add(s.time, vtp);
  }
}

void OutputSet::log(const Snapshot& s, Vec2d gravity, const EnergyBudget& budget) {
  Impl& o = *impl_;
  io::write_energy_row(o.energy, compute_energy(s, gravity, budget));
  io::write_wall_rows(o.walls, s);
  // Flushed every time so that a long run can be watched, and survives a crash.
  o.energy.flush();
  o.walls.flush();
}

void OutputSet::write_final(const Snapshot& s) { write_final_csv(impl_->dir / "final.csv", s); }

}  // namespace tridem
