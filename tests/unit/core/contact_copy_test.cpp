// Frames' contacts copied beside the steps (tridem/contact_copy.hpp, issue 12): what
// finish() appends is the contact network Solver::snapshot(s, true) gives at the step of
// start(), to the bit, though the solver has stepped on in between; and a run whose frames
// take their contacts that way writes the same files as one that takes them with the
// snapshot (the time loop's and the frame thread's part, on every backend).
#include "backends/cuda/cuda_backend.hpp"
#include "core/solver_factory.hpp"
#include "physics/pair_record.hpp"
#include "support/backend_test.hpp"
#include "support/forwarding_solver.hpp"
#include "support/gpu.hpp"
#include "support/periodic_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/snapshot_compare.hpp"
#include "tridem/run.hpp"
#include "tridem/standard_scenes.hpp"
#include "unit/io/io_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

namespace fs = std::filesystem;
using test::BackendTest;

/// The solver's own copy, or the snapshot fallback where it has none (the CPU solvers).
std::unique_ptr<ContactCopy> copy_of(const Solver& solver) {
  std::unique_ptr<ContactCopy> own = solver.make_contact_copy();
  return own ? std::move(own) : make_snapshot_contact_copy(solver);
}

/// A copy started now, finished `later` steps on into a contact-free snapshot of this
/// step, is the snapshot with contacts of this step.
void expect_contacts_of_this_step(Solver& solver, ContactCopy& copy, std::int64_t later) {
  Snapshot want;
  solver.snapshot(want, true);
  Snapshot got;
  solver.snapshot(got, false);
  ASSERT_TRUE(got.contacts.empty());
  copy.start();
  solver.advance(later);
  copy.finish(got);
  test::expect_identical(got, want);
  ASSERT_EQ(got.contacts.size(), want.contacts.size());
  for (std::size_t k = 0; k < got.contacts.size(); ++k) {
    EXPECT_TRUE(test::same_bits(got.contacts[k].image_dx, want.contacts[k].image_dx)) << k;
    EXPECT_TRUE(test::same_bits(got.contacts[k].image_dy, want.contacts[k].image_dy)) << k;
  }
}

class ContactCopyTest : public BackendTest {
 protected:
  void check_scene(const Scene& scene, std::int64_t before) {
    auto solver = test::solver_for(scene, GetParam());
    const std::unique_ptr<ContactCopy> copy = copy_of(*solver);
    // Step 0 (no contacts yet), then after `before` steps, twice with one copy.
    expect_contacts_of_this_step(*solver, *copy, 3);
    solver->advance(before);
    Snapshot now;
    solver->snapshot(now, true);
    EXPECT_GE(now.contacts.size(), 5u) << "the scene must be in contact to test anything";
    // The float precision's pairs are float32s, and the contacts CSV prints them as such.
    EXPECT_EQ(now.contact_precision, GetParam().precision);
    expect_contacts_of_this_step(*solver, *copy, 5);
    expect_contacts_of_this_step(*solver, *copy, 1);
  }
};

TEST_P(ContactCopyTest, IsTheSnapshotsContactsOfItsStep) {
  check_scene(test::jostling_pile(6, 4), 300);
}

TEST_P(ContactCopyTest, CarriesThePeriodicImages) { check_scene(test::periodic_pile(6, 4), 300); }

TEST(ContactCopy, FinishRefusesTheSnapshotOfAnotherStep) {
  Scene scene = test::jostling_pile(4, 3);
  scene.simulation.backend = Backend::Cpu;
  auto solver = make_solver(scene, {});
  const std::unique_ptr<ContactCopy> copy = make_snapshot_contact_copy(*solver);
  copy->start();
  solver->advance(2);
  Snapshot later;
  solver->snapshot(later, false);
  EXPECT_THROW(copy->finish(later), std::logic_error);
}

TRIDEM_INSTANTIATE_SOLVERS(ContactCopyTest);

/// The solver of a run, whose frames take their contacts with the snapshot (no copy) or
/// through a copy: its own, or the snapshot fallback where it has none. Counts the copies.
class CopyChoice final : public test::ForwardingSolver {
 public:
  CopyChoice(std::unique_ptr<Solver> solver, bool copies, int& started)
      : ForwardingSolver(std::move(solver)), copies_(copies), started_(started) {}

  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    if (!copies_) return nullptr;
    return std::make_unique<Counted>(copy_of(inner()), started_);
  }

 private:
  class Counted final : public ContactCopy {
   public:
    Counted(std::unique_ptr<ContactCopy> copy, int& started)
        : copy_(std::move(copy)), started_(started) {}
    void start() override {
      ++started_;
      copy_->start();
    }
    void finish(Snapshot& s) override { copy_->finish(s); }

   private:
    std::unique_ptr<ContactCopy> copy_;
    int& started_;
  };
  bool copies_;
  int& started_;
};

class ContactCopyRunTest : public BackendTest {
 protected:
  /// The files of `scene` run with or without copies; `started`: the copies started.
  std::map<std::string, std::string> run(Scene scene, const fs::path& dir, bool copies,
                                         int& started) {
    scene = GetParam().applied_to(scene);
    scene.output.dir = dir.string();
    RunOptions o;
    o.progress = false;
    o.log = std::fopen("/dev/null", "w");
    o.make_solver = [&](const Scene& s, const ParticleModel& m, const TimeStep& ts,
                        const SolverConfig& c) -> std::unique_ptr<Solver> {
      return std::make_unique<CopyChoice>(make_solver(s, m, ts, c), copies, started);
    };
    run_scene(scene, o);
    std::fclose(o.log);
    return test::files_under(dir, ".ckpt");
  }
};

// Frames every 50 steps with the contact files, a log every 25, and a measure every 100:
// the measures' steps take their contacts with the snapshot (they need them at once), the
// other frames through the copy; the files are the same either way.
TEST_P(ContactCopyRunTest, WritesTheFilesOfContactsTakenWithTheSnapshot) {
  test::TempDir dir;
  Scene scene = test::jostling_pile(6, 4);
  scene.simulation.steps = 400;
  scene.output.every = 50;
  scene.output.energy_every = 25;
  scene.output.contacts = true;
  scene.output.contacts_csv = true;
  MeasureSpec m;
  m.name = "all";
  m.every = 100;
  scene.output.measures.push_back(m);
  int with_snapshot = 0, beside = 0;
  const auto want = run(scene, dir.path() / "with_snapshot", false, with_snapshot);
  const auto got = run(scene, dir.path() / "beside", true, beside);
  EXPECT_EQ(with_snapshot, 0);
  EXPECT_EQ(beside, 5) << "frames at 0, 50, 150, 250, 350 (measures at 100, 200, 300, 400)";
  ASSERT_EQ(got.size(), want.size());
  EXPECT_GT(std::count_if(want.begin(), want.end(),
                          [](const auto& f) { return f.first.find(".vtp") != std::string::npos; }),
            8);
  for (const auto& [name, text] : want) {
    const auto it = got.find(name);
    ASSERT_NE(it, got.end()) << name;
    EXPECT_TRUE(it->second == text) << name << " differs";
  }
}

TRIDEM_INSTANTIATE_SOLVERS(ContactCopyRunTest);

// The CUDA solver compacts and downloads a frame's contact network a window of rows at a
// time (SolverConfig::gpu_contact_rows_per_copy, backends/cuda/touching_pairs.cuh): the
// same records whatever the window, through the snapshot and through the copy beside the
// steps, and the frame's GPU scratch is about a window, not a row for every contact (at
// 10^8 triangles that was 24 GB beside the solver's arrays).
TEST(GpuContactWindows, SameContactsInScratchOfOneWindow) {
  TRIDEM_SKIP_WITHOUT_GPU();
  for (Precision p : {Precision::Double, Precision::Float}) {
    SCOPED_TRACE(precision_name(p));
    Scene scene = dense_pile(200000);
    scene.simulation.backend = Backend::Cuda;
    scene.simulation.precision = p;
    SolverConfig windows;
    windows.gpu_contact_rows_per_copy = 997;
    auto whole = make_solver(scene, {});
    auto small = make_solver(scene, windows);
    whole->advance(20);
    small->advance(20);
    Snapshot want, got;
    cuda_stream_pool_peak(0, true);
    whole->snapshot(want, true);
    const std::size_t whole_peak = cuda_stream_pool_peak(0, true);
    small->snapshot(got, true);
    const std::size_t window_peak = cuda_stream_pool_peak(0);
    ASSERT_GT(want.contacts.size(), 100u * 997) << "many windows, a few rows in the last";
    test::expect_identical(got, want);
    const std::size_t row_bytes = p == Precision::Float ? sizeof(physics::TouchingPair<float>)
                                                        : sizeof(physics::TouchingPair<double>);
    EXPECT_GE(whole_peak, want.contacts.size() * row_bytes);
    EXPECT_LT(window_peak, whole_peak / 2);
    // Beside the steps: copies started at this step, finished after more steps into the
    // contact-free snapshots of this step.
    Snapshot want_beside, got_beside;
    whole->snapshot(want_beside, false);
    small->snapshot(got_beside, false);
    const std::unique_ptr<ContactCopy> whole_copy = whole->make_contact_copy();
    const std::unique_ptr<ContactCopy> small_copy = small->make_contact_copy();
    ASSERT_TRUE(whole_copy && small_copy);
    whole_copy->start();
    small_copy->start();
    whole->advance(3);
    small->advance(3);
    whole_copy->finish(want_beside);
    small_copy->finish(got_beside);
    test::expect_identical(want_beside, want);
    test::expect_identical(got_beside, want);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
