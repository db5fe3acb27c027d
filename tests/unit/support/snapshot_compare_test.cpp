// The bit-for-bit comparator of support/snapshot_compare.hpp sees a one-ulp change in any
// field of a snapshot, a sign of zero, and any field of any contact record: a field it
// skipped would let every parity test built on it pass on a wrong result.
#include "support/snapshot_compare.hpp"

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Snapshot three_particles() {
  Snapshot s;
  s.step = 12;
  s.time = 0.5;
  s.resize(3);
  double value = 1.25;
  for (auto* v : {&s.x, &s.y, &s.theta, &s.vx, &s.vy, &s.omega, &s.fx, &s.fy, &s.torque,
                  &s.x1, &s.y1, &s.x2, &s.y2, &s.x3, &s.y3, &s.mass, &s.inertia})
    for (double& e : *v) e = (value += 0.5);
  s.material = {0, 1, 0};
  s.motion = {Motion::Free, Motion::Free, Motion::Fixed};
  s.contacts = {{0, 1, 3.5, -2.5, 0.25, 0.75}, {1, 2, -1.5, 4.5, 1.25, -0.5}};
  return s;
}

double next_up(double v) { return std::nextafter(v, std::numeric_limits<double>::infinity()); }

/// The comparison of three_particles() with a copy spoiled by `spoil` fails, naming `what`.
void expect_seen(const std::function<void(Snapshot&)>& spoil, const std::string& what) {
  const Snapshot a = three_particles();
  Snapshot b = a;
  spoil(b);
  SCOPED_TRACE(what);
  EXPECT_NONFATAL_FAILURE(test::expect_identical(a, b), what);
}

TEST(SnapshotCompare, PassesIdenticalSnapshots) {
  test::expect_identical(three_particles(), three_particles());
}

TEST(SnapshotCompare, SeesOneUlpInEveryPerParticleField) {
  const struct {
    const char* name;
    std::vector<double> Snapshot::*values;
  } fields[] = {{"x", &Snapshot::x},   {"y", &Snapshot::y},   {"theta", &Snapshot::theta},
                {"vx", &Snapshot::vx}, {"vy", &Snapshot::vy}, {"omega", &Snapshot::omega},
                {"fx", &Snapshot::fx}, {"fy", &Snapshot::fy}, {"torque", &Snapshot::torque},
                {"x1", &Snapshot::x1}, {"y1", &Snapshot::y1}, {"x2", &Snapshot::x2},
                {"y2", &Snapshot::y2}, {"x3", &Snapshot::x3}, {"y3", &Snapshot::y3},
                {"mass", &Snapshot::mass}, {"inertia", &Snapshot::inertia}};
  for (const auto& f : fields)
    expect_seen([&](Snapshot& s) { (s.*f.values)[2] = next_up((s.*f.values)[2]); },
                std::string(f.name) + " of particle 2 differs");
  expect_seen([](Snapshot& s) { s.material[1] = 2; }, "material of particle 1 differs");
  expect_seen([](Snapshot& s) { s.motion[0] = Motion::Prescribed; }, "motion of particle 0");
}

TEST(SnapshotCompare, SeesTheSignOfZero) {
  Snapshot a = three_particles(), b = a;
  a.fy[1] = 0.0;
  b.fy[1] = -0.0;
  EXPECT_NONFATAL_FAILURE(test::expect_identical(a, b), "fy of particle 1 differs");
}

TEST(SnapshotCompare, SeesStepAndTime) {
  expect_seen([](Snapshot& s) { s.step += 1; }, "step");
  expect_seen([](Snapshot& s) { s.time = next_up(s.time); }, "time");
}

TEST(SnapshotCompare, SeesEveryFieldOfEveryContactRecord) {
  for (int k = 0; k < 2; ++k) {
    const std::string record = "contact record " + std::to_string(k) + " differs";
    expect_seen([k](Snapshot& s) { s.contacts[k].i += 1; }, record);
    expect_seen([k](Snapshot& s) { s.contacts[k].j += 1; }, record);
    expect_seen([k](Snapshot& s) { s.contacts[k].fx = next_up(s.contacts[k].fx); }, record);
    expect_seen([k](Snapshot& s) { s.contacts[k].fy = next_up(s.contacts[k].fy); }, record);
    expect_seen([k](Snapshot& s) { s.contacts[k].px = next_up(s.contacts[k].px); }, record);
    expect_seen([k](Snapshot& s) { s.contacts[k].py = next_up(s.contacts[k].py); }, record);
  }
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
