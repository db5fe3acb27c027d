// Frame output benchmark (issue 12): bytes per triangle of a frame and its contact network
// on disk, and seconds per frame, for each VTK format, on dense_pile(n) after a given
// number of steps (the pile is densest at the start: about 6 touching pairs per triangle,
// fewer as it loosens). Also the time the time loop waits per frame when the frame is
// written beside the stepping (OutputSet::write_frame_beside) against writing it inline.
//   tridem_frame_bench [n=100000] [steps=2] [repetitions=3] [backend=openmp] [dir]
//                      [precision=double] [sections=all]
// Prints Markdown tables; bench/README.md says how to read them. sections=parts prints only
// where a default frame's time goes (its parts, and the writer's phases within them).
#include "io/output/vtk_frames.hpp"
#include "startup_environment.hpp"
#include "tridem/measurements.hpp"
#include "tridem/output.hpp"
#include "tridem/setting_names.hpp"
#include "tridem/solver.hpp"
#include "tridem/standard_scenes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using tridem::VtkFormat;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Case {
  const char* name;
  VtkFormat format;
  tridem::ArraySet<tridem::FrameArray> frame_arrays{};
  tridem::ArraySet<tridem::ContactArray> contact_arrays{};
};

/// The arrays of a lean frame: `frame` of the .vtu's real fields, `contact` of the .vtp's.
template <class E, class Names>
tridem::ArraySet<E> only(const Names& names, std::initializer_list<const char*> chosen) {
  auto set = tridem::ArraySet<E>::none();
  for (const char* name : chosen) set.add(tridem::value_in(names, name).value());
  return set;
}

}  // namespace

int main(int argc, char** argv) {
  // The frame thread of `tridem run` runs with huge pages for its large blocks: without
  // them a 10^6 frame's grain stress took six times as long on a VM (its page faults).
  tridem::app::restart_with_startup_environment(argv);
  const std::size_t n = argc > 1 ? std::stoul(argv[1]) : 100000;
  const std::int64_t steps = argc > 2 ? std::stoll(argv[2]) : 2;
  const int reps = argc > 3 ? std::stoi(argv[3]) : 3;
  const std::string backend = argc > 4 ? argv[4] : "openmp";
  const fs::path dir =
      argc > 5 ? fs::path(argv[5]) : fs::temp_directory_path() / "tridem_frame_bench";
  const std::string precision = argc > 6 ? argv[6] : "double";
  const std::string sections = argc > 7 ? argv[7] : "all";
  if (sections != "all" && sections != "parts") {
    fmt::print(stderr, "sections must be all or parts, not '{}'\n", sections);
    return EXIT_FAILURE;
  }
  const bool all = sections == "all";
  fs::create_directories(dir);

  tridem::Scene scene = tridem::dense_pile(n);
  scene.simulation.backend = tridem::value_in(tridem::kBackendNames, backend).value();
  scene.simulation.precision = tridem::value_in(tridem::kPrecisionNames, precision).value();
  auto solver = tridem::make_solver(scene, {});
  solver->advance(steps);
  tridem::Snapshot s;
  solver->snapshot(s, true);
  const double tri = static_cast<double>(s.size());
  fmt::print(
      "dense_pile({}), {} precision: {} triangles after {} steps, {:.2f} contacts per triangle\n\n",
      n, precision, s.size(), steps, static_cast<double>(s.contacts.size()) / tri);

  using tridem::ContactArray, tridem::FrameArray;
  const auto motion = only<FrameArray>(tridem::kFrameArrayNames, {"velocity", "angular_velocity"});
  const auto force_depth = only<ContactArray>(tridem::kContactArrayNames, {"force", "depth"});
  const auto force = only<ContactArray>(tridem::kContactArrayNames, {"force"});
  const Case cases[] = {
      {"double, uncompressed (the former files)",
       {tridem::Encoding::Binary, tridem::VtkPrecision::Float64, tridem::VtkCompression::None}},
      {"float32, zlib (the default)", {}},
      {"float32, zlib, appended raw", {tridem::Encoding::Appended}},
      {"double, zlib",
       {tridem::Encoding::Binary, tridem::VtkPrecision::Float64, tridem::VtkCompression::Zlib}},
      {"float32, uncompressed",
       {tridem::Encoding::Binary, tridem::VtkPrecision::Float32, tridem::VtkCompression::None}},
      {"float32, lzma",
       {tridem::Encoding::Binary, tridem::VtkPrecision::Float32, tridem::VtkCompression::Lzma}},
      {"float32, lzma, appended raw",
       {tridem::Encoding::Appended, tridem::VtkPrecision::Float32, tridem::VtkCompression::Lzma}},
      // `[output] frame_arrays` and `contact_arrays`: motion and force chains only.
      {"float32, zlib, appended raw; velocity, angular_velocity; force, depth",
       {tridem::Encoding::Appended},
       motion,
       force_depth},
      {"float32, zlib, appended raw; velocity, angular_velocity; force",
       {tridem::Encoding::Appended},
       motion,
       force},
      {"float32, zlib; velocity, angular_velocity; force, depth", {}, motion, force_depth},
      {"float32, lzma, appended raw; velocity, angular_velocity; force, depth",
       {tridem::Encoding::Appended, tridem::VtkPrecision::Float32, tridem::VtkCompression::Lzma},
       motion,
       force_depth},
  };
  if (all)
    fmt::print("| format | frame B/tri | contacts .vtp B/tri | both B/tri | s per frame (both) |\n"
               "|---|---:|---:|---:|---:|\n");
  for (const Case& c : cases) {
    if (!all) break;
    tridem::io::VtkXmlWriter w(c.format);
    std::vector<double> times;
    for (int r = 0; r < reps; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      tridem::io::write_vtu_frame(w, dir / "frame.vtu", s, true, c.frame_arrays);
      tridem::io::write_contacts_vtp(w, dir / "contacts.vtp", s, c.contact_arrays);
      times.push_back(seconds_since(t0));
    }
    const double frame = static_cast<double>(fs::file_size(dir / "frame.vtu")) / tri;
    const double contacts = static_cast<double>(fs::file_size(dir / "contacts.vtp")) / tri;
    fmt::print("| {} | {:.1f} | {:.1f} | {:.1f} | {:.3f} |\n", c.name, frame, contacts,
               frame + contacts, median(times));
  }
  // Where a default frame's time goes (medians of `reps`), and the snapshot it is made
  // from (on the GPU: the download and conversion the stepping thread pays).
  {
    tridem::io::VtkXmlWriter w;
    const auto time = [&](auto&& part) {
      std::vector<double> t;
      for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        part();
        t.push_back(seconds_since(t0));
      }
      return median(t);
    };
    tridem::Snapshot again;
    const double state = time([&] { solver->snapshot(again, false); });
    const double snapshot = time([&] { solver->snapshot(again, true); });
    const double stress = time([&] { (void)tridem::grain_stress(s); });
    const double vtu_state = time([&] { tridem::io::write_vtu_frame(w, dir / "f.vtu", s, false); });
    // The writer's phases in each file (per file: summed over `reps`, divided by it).
    const auto phases = [&](const char* file) {
      const tridem::io::VtkXmlWriter::Seconds& p = w.seconds();
      const double r = reps;
      return fmt::format("| {} | {:.3f} | {:.3f} | {:.3f} | {:.3f} |\n", file, p.pack / r,
                         p.compress / r, p.encode / r, p.write / r);
    };
    w.reset_seconds();
    const double vtu = time([&] { tridem::io::write_vtu_frame(w, dir / "f.vtu", s, true); });
    const std::string vtu_phases = phases(".vtu with grain stress");
    w.reset_seconds();
    const double vtp = time([&] { tridem::io::write_contacts_vtp(w, dir / "c.vtp", s); });
    const std::string vtp_phases = phases("contacts .vtp");
    const double csv = time([&] { tridem::write_contacts_csv(dir / "contacts.csv", s); });
    fmt::print("\n| part (default format) | s |\n|---|---:|\n| snapshot without contacts | {:.3f} "
               "|\n| snapshot with contacts | {:.3f} |\n"
               "| grain stress | {:.3f} |\n| .vtu without grain stress | {:.3f} |\n"
               "| .vtu with it | {:.3f} |\n| contacts .vtp | {:.3f} |\n| contacts .csv | {:.3f} "
               "|\n",
               state, snapshot, stress, vtu_state, vtu, vtp, csv);
    fmt::print("\n| writer's phases, s a file | pack | compress | encode | write |\n"
               "|---|---:|---:|---:|---:|\n{}{}",
               vtu_phases, vtp_phases);
  }
  fmt::print("\ncontacts .csv (written with each frame while [output] contacts_csv is on): "
             "{:.1f} B/tri\n\n",
             static_cast<double>(fs::file_size(dir / "contacts.csv")) / tri);

  if (!all) return EXIT_SUCCESS;
  // What the time loop pays per frame (default format, contacts on): the OutputSet call
  // alone, inline or beside the stepping, with `steps` of stepping between frames.
  tridem::OutputSettings settings;
  settings.contacts_csv = false;
  fmt::print(
      "| output | loop waits per frame, s | stepping between frames, s |\n|---|---:|---:|\n");
  for (const bool beside : {false, true}) {
    tridem::OutputSet out(settings, dir / (beside ? "beside" : "inline"));
    std::vector<double> waits, stepping;
    tridem::Snapshot frame;
    for (int r = 0; r < reps; ++r) {
      solver->snapshot(frame, true);
      auto t0 = std::chrono::steady_clock::now();
      if (beside)
        out.write_frame_beside(frame);
      else
        out.write_frame(frame);
      waits.push_back(seconds_since(t0));
      t0 = std::chrono::steady_clock::now();
      solver->advance(1);
      stepping.push_back(seconds_since(t0));
    }
    auto t0 = std::chrono::steady_clock::now();
    out.finish_frames();
    waits.back() += seconds_since(t0);
    fmt::print("| {} | {:.3f} | {:.3f} |\n", beside ? "beside (output thread)" : "inline",
               median(waits), median(stepping));
  }
  return EXIT_SUCCESS;
}
