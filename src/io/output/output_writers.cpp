// The output formats of a run, each an OutputWriter: what it writes, when, and which files
// of an output directory are its own.
#include "io/output/log_rows.hpp"
#include "io/output/output_writer.hpp"
#include "io/output/pvd_collection.hpp"
#include "io/output/resume_outputs.hpp"
#include "io/output/step_files.hpp"
#include "io/output/vtk_frames.hpp"
#include "tridem/error.hpp"

#include <fmt/format.h>

#include <functional>
#include <string>
#include <system_error>
#include <utility>

namespace tridem::io {

namespace fs = std::filesystem;

namespace {

/// A format of one file per frame.
struct StepFileFormat {
  StepFiles files;
  std::string_view extension;
  std::string_view collection;  ///< the .pvd listing the files, or empty for none
  /// Files derived from these (`tridem render`'s PNGs), cleaned up with them; or empty.
  std::string_view renderings;
};

/// The files of a StepFileFormat: written by `write`, or only cleaned up when it is empty
/// (a format the settings turn off still removes an earlier run's files).
class StepFileWriter final : public OutputWriter {
 public:
  using Write = std::function<void(const fs::path&, const Snapshot&)>;
  /// `only_with_bonds`: frames of scenes without cohesive bonds write no file.
  StepFileWriter(fs::path dir, StepFileFormat format, Write write, bool only_with_bonds = false)
      : dir_(std::move(dir)),
        format_(format),
        write_(std::move(write)),
        only_with_bonds_(only_with_bonds) {
    if (!format_.collection.empty()) collection_.emplace(dir_ / format_.collection);
  }

  void start(const std::optional<ResumePoint>& resume) override {
    const std::optional<std::int64_t> after =
        resume ? std::optional<std::int64_t>(resume->step) : std::nullopt;
    format_.files.remove(dir_, format_.extension, after);
    if (!format_.renderings.empty()) format_.files.remove(dir_, format_.renderings, after);
    if (!collection_) return;
    if (resume) {
      collection_->restore(resume->time);
    } else {
      std::error_code ec;
      fs::remove(collection_->file(), ec);
    }
  }

  void frame(const Snapshot& s) override {
    if (!write_ || (only_with_bonds_ && s.bond_a.empty())) return;
    // Made on first use so that a run without frames leaves no empty folders.
    if (!folder_made_) make_directory(dir_ / format_.files.folder);
    folder_made_ = true;
    const fs::path file = format_.files.path(dir_, s.step, format_.extension);
    write_(file, s);
    if (collection_) collection_->add(s.time, file);
  }

 private:
  fs::path dir_;
  StepFileFormat format_;
  Write write_;
  std::optional<PvdCollection> collection_;
  bool only_with_bonds_;
  bool folder_made_ = false;
};

/// A CSV file of rows added as the run goes, flushed each time so that a long run can be
/// watched and its rows survive a crash; a restarted run cuts it back to the checkpoint.
class CsvRows : public OutputWriter {
 public:
  /// `only_with_bonds`: the file is made at the first row of a scene with cohesive bonds
  /// (bonds.csv), and never for other scenes.
  CsvRows(fs::path file, std::string_view header, bool only_with_bonds = false)
      : file_(std::move(file)), header_(header), only_with_bonds_(only_with_bonds) {}

  void start(const std::optional<ResumePoint>& resume) override {
    std::error_code ec;
    if (resume && (!only_with_bonds_ || fs::exists(file_, ec))) {
      trim_log(file_, header_, resume->step);
      out_.emplace(file_, OutFile::Mode::Append);
      return;
    }
    if (only_with_bonds_) {
      fs::remove(file_, ec);
      return;
    }
    out_.emplace(file_);
    out_->write(header_);
    out_->flush();
  }

 protected:
  /// The file to add the rows of `s` to, or null when this scene gets no such file.
  OutFile* rows_for(const Snapshot& s) {
    if (only_with_bonds_ && s.bond_a.empty()) return nullptr;
    if (!out_) {
      out_.emplace(file_);
      out_->write(header_);
    }
    return &*out_;
  }

 private:
  fs::path file_;
  std::string_view header_;
  bool only_with_bonds_;
  std::optional<OutFile> out_;
};

/// A log with one block of rows per logging step (energy.csv, walls.csv, bonds.csv).
class CsvLog final : public CsvRows {
 public:
  using Rows = std::function<void(OutFile&, const Snapshot&, const LogInputs&)>;
  CsvLog(fs::path file, std::string_view header, Rows rows, bool only_with_bonds = false)
      : CsvRows(std::move(file), header, only_with_bonds), rows_(std::move(rows)) {}

  void log(const Snapshot& s, const LogInputs& in) override {
    OutFile* out = rows_for(s);
    if (out == nullptr) return;
    rows_(*out, s, in);
    out->flush();
  }

 private:
  Rows rows_;
};

/// A [[measure]]'s file: a row of measure_region() at each of its steps.
class MeasureLog final : public CsvRows {
 public:
  MeasureLog(const fs::path& dir, MeasureSpec spec, std::int64_t every)
      : CsvRows(dir / spec.file_name(), kMeasureHeader), spec_(std::move(spec)), every_(every) {}

  void measure(const Snapshot& s, bool last_step) override {
    if (!measure_due(every_, s.step, last_step)) return;
    OutFile& out = *rows_for(s);
    write_measure_row(out, measure_region(s, spec_.region));
    out.flush();
  }

 private:
  MeasureSpec spec_;
  std::int64_t every_;
};

/// A file of the state the run ends (or stops) with: final.csv, bodies.csv.
class FinalCsv final : public OutputWriter {
 public:
  using Write = void (*)(const fs::path&, const Snapshot&);
  FinalCsv(fs::path file, Write write) : file_(std::move(file)), write_(write) {}
  void start(const std::optional<ResumePoint>& resume) override {
    // A restarted run keeps the file until it writes its own.
    std::error_code ec;
    if (!resume) fs::remove(file_, ec);
  }
  void final_state(const Snapshot& s) override { write_(file_, s); }

 private:
  fs::path file_;
  Write write_;
};

}  // namespace

std::vector<std::unique_ptr<OutputWriter>> make_writers(const OutputSettings& settings,
                                                        const fs::path& dir, VtkFormat format) {
  using Write = StepFileWriter::Write;
  std::vector<std::unique_ptr<OutputWriter>> w;
  w.push_back(std::make_unique<StepFileWriter>(
      dir, StepFileFormat{kFrameFiles, ".vtu", "tridem.pvd", ".png"},
      // Each VTK format keeps its own writer, whose buffers then serve every frame.
      [w = VtkXmlWriter(format), contacts = settings.contacts,
       arrays = settings.frame_arrays](const fs::path& f, const Snapshot& s) mutable {
        write_vtu_frame(w, f, s, contacts, arrays);
      }));
  const bool contacts = settings.contacts;
  w.push_back(std::make_unique<StepFileWriter>(
      dir, StepFileFormat{kContactFiles, ".csv", {}, {}},
      contacts && settings.contacts_csv ? Write(write_contacts_csv) : Write()));
  w.push_back(std::make_unique<StepFileWriter>(
      dir, StepFileFormat{kContactFiles, ".vtp", "contacts.pvd", {}},
      contacts ? Write([w = VtkXmlWriter(format), arrays = settings.contact_arrays](
                           const fs::path& f, const Snapshot& s) mutable {
        write_contacts_vtp(w, f, s, arrays);
      })
               : Write()));
  w.push_back(std::make_unique<CsvLog>(
      dir / "energy.csv", kEnergyHeader, [](OutFile& out, const Snapshot& s, const LogInputs& in) {
        write_energy_row(out, compute_energy(s, in.gravity, in.budget));
      }));
  w.push_back(std::make_unique<CsvLog>(
      dir / "walls.csv", kWallsHeader,
      [](OutFile& out, const Snapshot& s, const LogInputs&) { write_wall_rows(out, s); }));
  // Cohesive bonds (docs/fracture.md): only for scenes that have some.
  w.push_back(std::make_unique<StepFileWriter>(
      dir, StepFileFormat{kBondFiles, ".vtp", "bonds.pvd", {}},
      [w = VtkXmlWriter(format)](const fs::path& f, const Snapshot& s) mutable {
        write_bonds_vtp(w, f, s);
      },
      true));
  w.push_back(std::make_unique<CsvLog>(
      dir / "bonds.csv", kBondsHeader,
      [](OutFile& out, const Snapshot& s, const LogInputs& in) {
        write_bond_row(out, s, in.budget.dissipated_fracture);
      },
      true));
  for (const MeasureSpec& m : settings.measures)
    w.push_back(std::make_unique<MeasureLog>(dir, m, settings.measure_every(m)));
  w.push_back(std::make_unique<FinalCsv>(dir / "final.csv", write_final_csv));
  w.push_back(std::make_unique<FinalCsv>(dir / "bodies.csv", write_bodies_csv));
  return w;
}

void make_directory(const fs::path& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  // An existing regular file of that name is not always reported as an error.
  if (!ec && !fs::is_directory(dir, ec) && !ec)
    ec = std::make_error_code(std::errc::not_a_directory);
  if (ec)
    throw RunError(
        fmt::format("cannot create output directory '{}': {}", dir.string(), ec.message()));
}

}  // namespace tridem::io
