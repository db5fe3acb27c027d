#include "io/output/frame_thread.hpp"
#include "io/output/output_writer.hpp"
#include "tridem/output.hpp"

#include <exception>
#include <future>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

namespace tridem {

namespace fs = std::filesystem;

struct OutputSet::Impl {
  fs::path dir;
  std::vector<std::unique_ptr<io::OutputWriter>> writers;
  /// Made at the first frame handed over; after `writers`, so that it stops first.
  std::optional<io::FrameThread> frames;

  /// Each writer has its own files and buffers, so for a large snapshot (a frame, or the
  /// final files: final.csv and bodies.csv are 3 GB of text at 10^7 triangles) they run
  /// side by side, the first writer on this thread: the serial parts of one (a grain's
  /// contact lists, zlib's close-up, the file's write) overlap the parallel loops of the
  /// others. A failure is thrown once all have returned.
  template <class Call>
  void each_writer(const Snapshot& s, Call call) {
    if (s.size() + s.contacts.size() < kSideBySide || writers.size() < 2) {
      for (auto& w : writers) call(*w);
      return;
    }
    std::vector<std::future<void>> others;
    for (std::size_t k = 1; k < writers.size(); ++k)
      others.push_back(std::async(std::launch::async, [&w = *writers[k], &call] { call(w); }));
    std::exception_ptr failure;
    try {
      call(*writers.front());
    } catch (...) {
      failure = std::current_exception();
    }
    for (std::future<void>& f : others) try {
        f.get();
      } catch (...) {
        if (!failure) failure = std::current_exception();
      }
    if (failure) std::rethrow_exception(failure);
  }
  void write_frame(const Snapshot& s) {
    each_writer(s, [&s](io::OutputWriter& w) { w.frame(s); });
  }
  /// Particles and contacts of a snapshot from which its writers run side by side.
  static constexpr std::size_t kSideBySide = std::size_t{1} << 16;
};

OutputSet::OutputSet(const OutputSettings& settings, fs::path dir, VtkFormat format,
                     const std::optional<ResumePoint>& resume)
    : impl_(std::make_unique<Impl>()) {
  io::make_directory(dir);
  impl_->dir = std::move(dir);
  const fs::path& where = impl_->dir;
  impl_->writers = io::make_writers(settings, where, format);
  // A run owns the tridem files of its directory: frames, their renderings and contact
  // files of an earlier run there would otherwise mix with the new ones (ParaView and
  // `tridem render` would show them). Each writer knows its own files; nothing else is
  // touched.
  for (auto& w : impl_->writers) w->start(resume);
  // An earlier blow-up's last_good.ckpt (the time loop's, not an output format) would
  // describe a failure this run did not have. checkpoint.ckpt stays: it may be what the
  // user means to restart from.
  std::error_code ec;
  if (!resume) fs::remove(where / "last_good.ckpt", ec);
}

OutputSet::~OutputSet() = default;
OutputSet::OutputSet(OutputSet&&) noexcept = default;
OutputSet& OutputSet::operator=(OutputSet&&) noexcept = default;

const fs::path& OutputSet::dir() const { return impl_->dir; }

void OutputSet::write_frame(const Snapshot& s) {
  finish_frames();
  impl_->write_frame(s);
}

void OutputSet::write_frame_beside(Snapshot& s, ContactCopy* contacts) {
  if (!impl_->frames)
    impl_->frames.emplace([impl = impl_.get()](const Snapshot& f) { impl->write_frame(f); });
  impl_->frames->submit(s, contacts);
}

void OutputSet::finish_frames() {
  if (impl_->frames) impl_->frames->wait();
}

void OutputSet::log(const Snapshot& s, Vec2d gravity, const EnergyBudget& budget) {
  const io::LogInputs in{gravity, budget};
  for (auto& w : impl_->writers) w->log(s, in);
}

void OutputSet::measure(const Snapshot& s, bool last_step) {
  for (auto& w : impl_->writers) w->measure(s, last_step);
}

void OutputSet::write_final(const Snapshot& s) {
  impl_->each_writer(s, [&s](io::OutputWriter& w) { w.final_state(s); });
}

}  // namespace tridem
