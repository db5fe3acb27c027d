// Valid scenes: every key lands in the right field, defaults, integers as reals, clockwise
// reordering and particle id order.
#include "core/particle_model.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "tridem/scene_io.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

const std::filesystem::path kScenes =
    std::filesystem::path(TRIDEM_SOURCE_DIR) / "tests/data/scenes";

void expect_same_vertices(const TriangleSpec& a, const TriangleSpec& b) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a.vertices[k].x, b.vertices[k].x);
    EXPECT_EQ(a.vertices[k].y, b.vertices[k].y);
  }
}

TEST(SceneParse, FullSceneGivesExpectedValues) {
  const Scene s = read_scene(kScenes / "full.toml");
  EXPECT_EQ(s.source, (kScenes / "full.toml").string());

  EXPECT_EQ(s.simulation.steps, 2000);
  ASSERT_TRUE(s.simulation.dt.has_value());
  EXPECT_DOUBLE_EQ(*s.simulation.dt, 1e-5);
  EXPECT_DOUBLE_EQ(s.simulation.safety, 0.5);
  EXPECT_DOUBLE_EQ(s.simulation.gravity.x, 0);
  EXPECT_DOUBLE_EQ(s.simulation.gravity.y, -9.81);
  EXPECT_EQ(s.simulation.backend, Backend::OpenMP);
  EXPECT_EQ(s.simulation.precision, Precision::Float);
  EXPECT_EQ(s.simulation.method, Method::SingleDomain);
  EXPECT_EQ(s.simulation.contact_test, ContactTest::DirectArea);
  EXPECT_FALSE(s.simulation.bbox_prefilter);
  EXPECT_EQ(s.simulation.decomposition.layout, DecompositionLayout::Grid);
  EXPECT_EQ(s.simulation.decomposition.rows, 3);
  EXPECT_EQ(s.simulation.decomposition.columns, 4);
  EXPECT_EQ(s.simulation.decomposition.capacity, 128);
  EXPECT_DOUBLE_EQ(s.simulation.local_damping, 0.2);
  EXPECT_DOUBLE_EQ(s.simulation.max_penetration, 0.6);
  EXPECT_TRUE(s.simulation.relax_overlaps);

  EXPECT_EQ(s.output.dir, "results");
  EXPECT_EQ(s.output.every, 100);
  EXPECT_FALSE(s.output.contacts);
  EXPECT_EQ(s.output.encoding, Encoding::Ascii);
  EXPECT_EQ(s.output.checkpoint_every, 500);
  EXPECT_EQ(s.output.energy_every, 20);
  ASSERT_EQ(s.output.measures.size(), 1u);
  EXPECT_EQ(s.output.measures[0].name, "core");
  ASSERT_TRUE(s.output.measures[0].region.has_value());
  EXPECT_EQ(s.output.measures[0].region->lo.y, 2);
  EXPECT_EQ(s.output.measures[0].region->hi.x, 5);
  EXPECT_EQ(s.output.measures[0].every, 40);
  EXPECT_EQ(s.output.measures[0].file_name(), "core.csv");

  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[0].name, "rock");
  EXPECT_DOUBLE_EQ(s.materials[0].density, 2500);
  EXPECT_DOUBLE_EQ(s.materials[0].penalty, 1e9);
  EXPECT_DOUBLE_EQ(s.materials[0].friction, 0.5);
  EXPECT_DOUBLE_EQ(s.materials[0].damping, 0.3);
  EXPECT_DOUBLE_EQ(s.materials[0].tangential_penalty, 2e8);
  EXPECT_EQ(s.materials[1].name, "steel");
  EXPECT_DOUBLE_EQ(s.materials[1].density, 7800);
  EXPECT_DOUBLE_EQ(s.materials[1].penalty, 2e11);
  EXPECT_DOUBLE_EQ(s.materials[1].friction, 0);
  EXPECT_DOUBLE_EQ(s.materials[1].damping, 0);
  EXPECT_DOUBLE_EQ(s.materials[1].tangential_penalty, 0.1 * 2e11);

  const LatticeSpec lattice{0, {0, 2}, {5, 5}, 1.0, 0.2, {0, -1}};
  RandomPackingSpec random;
  random.material = 1;
  random.region_min = {0, 6};
  random.region_max = {6, 10};
  random.size = 0.5;
  random.gap = 0.3;
  random.velocity = {0.5, 0};
  random.seed = 99;
  random.count = 10;
  random.irregularity = 0.4;
  const auto lattice_triangles = generate_lattice(lattice);
  const auto random_triangles = generate_random(random);
  ASSERT_EQ(s.triangles.size(), 3 + lattice_triangles.size() + 10);

  const TriangleSpec& wall = s.triangles[0];
  EXPECT_EQ(wall.material, 1);
  EXPECT_EQ(wall.motion, Motion::Fixed);
  const TriangleSpec& mover = s.triangles[1];
  EXPECT_EQ(mover.material, 0);
  EXPECT_EQ(mover.motion, Motion::Prescribed);
  EXPECT_DOUBLE_EQ(mover.velocity.x, 1);
  EXPECT_DOUBLE_EQ(mover.velocity.y, -2);
  EXPECT_DOUBLE_EQ(mover.angular_velocity, 3);
  EXPECT_EQ(s.triangles[2].motion, Motion::Free);
  EXPECT_DOUBLE_EQ(s.triangles[2].vertices[2].x, 4.5);

  for (std::size_t i = 0; i < lattice_triangles.size(); ++i) {
    const TriangleSpec& t = s.triangles[3 + i];
    expect_same_vertices(t, lattice_triangles[i]);
    EXPECT_EQ(t.material, 0);
    EXPECT_DOUBLE_EQ(t.velocity.y, -1);
  }
  for (std::size_t i = 0; i < random_triangles.size(); ++i) {
    const TriangleSpec& t = s.triangles[3 + lattice_triangles.size() + i];
    expect_same_vertices(t, random_triangles[i]);
    EXPECT_EQ(t.material, 1);
    EXPECT_DOUBLE_EQ(t.velocity.x, 0.5);
  }
}

TEST(SceneParse, OmittedKeysTakeDefaults) {
  const Scene s = read_scene(kScenes / "minimal.toml");
  EXPECT_EQ(s.simulation.steps, 10);
  EXPECT_FALSE(s.simulation.dt.has_value());
  EXPECT_DOUBLE_EQ(s.simulation.safety, 0.1);
  EXPECT_DOUBLE_EQ(s.simulation.gravity.x, 0);
  EXPECT_DOUBLE_EQ(s.simulation.gravity.y, 0);
  EXPECT_EQ(s.simulation.backend, Backend::Auto);
  EXPECT_EQ(s.simulation.precision, Precision::Double);
  EXPECT_EQ(s.simulation.method, Method::Grid);
  EXPECT_EQ(s.simulation.contact_test, ContactTest::Exact);
  EXPECT_TRUE(s.simulation.bbox_prefilter);
  EXPECT_EQ(s.simulation.decomposition.layout, DecompositionLayout::Strips);
  EXPECT_EQ(s.simulation.decomposition.rows, 0);
  EXPECT_EQ(s.simulation.decomposition.columns, 0);
  EXPECT_EQ(s.simulation.decomposition.capacity, 256);
  EXPECT_DOUBLE_EQ(s.simulation.local_damping, 0);
  EXPECT_DOUBLE_EQ(s.simulation.skin, 0.05);
  EXPECT_DOUBLE_EQ(s.simulation.max_penetration, 0.8);
  EXPECT_EQ(s.output.dir, "out");
  EXPECT_EQ(s.output.every, 0);
  EXPECT_TRUE(s.output.contacts);
  EXPECT_EQ(s.output.encoding, Encoding::Binary);
  EXPECT_EQ(s.output.checkpoint_every, 0);
  EXPECT_DOUBLE_EQ(s.materials[0].friction, 0);
  EXPECT_DOUBLE_EQ(s.materials[0].damping, 0);
  EXPECT_FALSE(s.materials[0].restitution.has_value());
  EXPECT_DOUBLE_EQ(material_restitution(s.materials[0]), 1.0);
  EXPECT_DOUBLE_EQ(s.materials[0].tangential_penalty, 1e6);
  ASSERT_EQ(s.triangles.size(), 1u);
  EXPECT_EQ(s.triangles[0].motion, Motion::Free);
  EXPECT_DOUBLE_EQ(s.triangles[0].angular_velocity, 0);
  EXPECT_DOUBLE_EQ(s.triangles[0].velocity.x, 0);
}

constexpr const char* kHead = R"(
[simulation]
steps = 5
[[material]]
name = "m"
density = 1000
penalty = 1e6
)";

TEST(SceneParse, RestitutionIsReadAndDampingMapsToIt) {
  const Scene s = parse_scene(std::string(kHead) + "restitution = 0.6\n" + R"(
[[material]]
name = "old"
density = 1000
penalty = 1e6
damping = 0.2
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
)",
                              "r.toml");
  ASSERT_TRUE(s.materials[0].restitution.has_value());
  EXPECT_DOUBLE_EQ(*s.materials[0].restitution, 0.6);
  EXPECT_DOUBLE_EQ(material_restitution(s.materials[0]), 0.6);
  // ζ = 0.2 stands for the face restitution it gave: exp(−0.2π/√0.96) = 0.5266.
  EXPECT_NEAR(material_restitution(s.materials[1]), 0.52662, 1e-5);
}

TEST(SceneParse, FrameFormatKeysAreRead) {
  const std::string triangle = R"(
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
)";
  const Scene s = parse_scene(std::string(kHead) + triangle + R"(
[output]
every = 10
contacts_csv = false
vtk_encoding = "appended"
vtk_precision = "double"
vtk_compression = "none"
)",
                              "formats.toml");
  EXPECT_FALSE(s.output.contacts_csv);
  EXPECT_EQ(s.output.encoding, Encoding::Appended);
  EXPECT_EQ(s.output.precision, VtkPrecision::Float64);
  EXPECT_EQ(s.output.compression, VtkCompression::None);
  EXPECT_EQ(parse_scene(std::string(kHead) + triangle + "[output]\nvtk_compression = \"lzma\"\n",
                        "lzma.toml")
                .output.compression,
            VtkCompression::Lzma);
  try {
    parse_scene(std::string(kHead) + triangle + "[output]\nvtk_encoding = \"raw\"\n", "bad.toml");
    ADD_FAILURE() << "accepted vtk_encoding = \"raw\"";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("appended"), std::string::npos)
        << "the message names the choices: " << e.what();
  }
}

TEST(SceneParse, FrameAndContactArraysAreRead) {
  const std::string triangle = R"(
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
)";
  const Scene all = parse_scene(std::string(kHead) + triangle, "all.toml");
  EXPECT_EQ(all.output.frame_arrays, ArraySet<FrameArray>{});
  EXPECT_TRUE(all.output.contact_arrays.has(ContactArray::Sliding));
  const Scene s = parse_scene(std::string(kHead) + triangle + R"(
[output]
frame_arrays = ["velocity", "stress"]
contact_arrays = []
)",
                              "lean.toml");
  for (const FrameArray a : {FrameArray::Velocity, FrameArray::Stress})
    EXPECT_TRUE(s.output.frame_arrays.has(a));
  for (const FrameArray a : {FrameArray::AngularVelocity, FrameArray::Force, FrameArray::Torque,
                             FrameArray::Pressure, FrameArray::Coordination})
    EXPECT_FALSE(s.output.frame_arrays.has(a));
  EXPECT_EQ(s.output.contact_arrays, ArraySet<ContactArray>::none());
}

TEST(SceneParse, IntegersAcceptedWhereRealsExpected) {
  const Scene s = parse_scene(std::string(kHead) + R"(
[[triangle]]
material = "m"
vertices = [[0, 0], [2, 0], [0, 3]]
velocity = [4, 5]
angular_velocity = 6
[[generate]]
kind = "random"
material = "m"
region = [[0, 10], [20, 30]]
size = 2
gap = 1
irregularity = 0
)",
                              "ints.toml");
  EXPECT_DOUBLE_EQ(s.materials[0].density, 1000);
  EXPECT_DOUBLE_EQ(s.triangles[0].vertices[2].y, 3);
  EXPECT_DOUBLE_EQ(s.triangles[0].velocity.y, 5);
  EXPECT_DOUBLE_EQ(s.triangles[0].angular_velocity, 6);
  EXPECT_GT(s.triangles.size(), 1u);
}

TEST(SceneParse, ClockwiseVerticesAreReorderedCounterClockwise) {
  const Scene s = parse_scene(std::string(kHead) + R"(
[[triangle]]
material = "m"
vertices = [[0, 0], [0, 1], [1, 0]]
[[triangle]]
material = "m"
vertices = [[2, 0], [3, 0], [2, 1]]
)",
                              "cw.toml");
  for (const TriangleSpec& t : s.triangles)
    EXPECT_GT(cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]), 0);
  // The clockwise one keeps its first vertex and the same vertex set.
  EXPECT_DOUBLE_EQ(s.triangles[0].vertices[0].x, 0);
  EXPECT_DOUBLE_EQ(s.triangles[0].vertices[1].x, 1);
  EXPECT_DOUBLE_EQ(s.triangles[0].vertices[2].y, 1);
  // An already counter-clockwise one is left exactly as written.
  EXPECT_DOUBLE_EQ(s.triangles[1].vertices[1].x, 3);
}

TEST(SceneParse, IdsAreExplicitTrianglesThenGeneratedInFileOrder) {
  // Generators written before the triangles, and two of them: ids still put every explicit
  // triangle first, then generator 1's output, then generator 2's.
  const Scene s = parse_scene(std::string(kHead) + R"(
[[generate]]
kind = "lattice"
material = "m"
region = [[100, 0], [103, 2]]
size = 1
[[triangle]]
material = "m"
vertices = [[-10, 0], [-9, 0], [-10, 1]]
[[generate]]
kind = "random"
material = "m"
region = [[200, 0], [203, 3]]
size = 1
count = 2
[[triangle]]
material = "m"
vertices = [[-20, 0], [-19, 0], [-20, 1]]
)",
                              "ids.toml");
  ASSERT_GE(s.triangles.size(), 5u);
  EXPECT_DOUBLE_EQ(s.triangles[0].vertices[0].x, -10);
  EXPECT_DOUBLE_EQ(s.triangles[1].vertices[0].x, -20);
  const std::size_t n = s.triangles.size();
  for (std::size_t i = 2; i < n - 2; ++i) EXPECT_GE(s.triangles[i].vertices[0].x, 100);
  for (std::size_t i = 2; i < n - 2; ++i) EXPECT_LT(s.triangles[i].vertices[0].x, 200);
  EXPECT_GE(s.triangles[n - 2].vertices[0].x, 199);
  EXPECT_GE(s.triangles[n - 1].vertices[0].x, 199);
}

TEST(SceneParse, FixedTrueWithMotionFixedIsAccepted) {
  const Scene s = parse_scene(std::string(kHead) + R"(
[[triangle]]
material = "m"
vertices = [[0, 0], [1, 0], [0, 1]]
fixed = true
motion = "fixed"
velocity = [0, 0]
[[triangle]]
material = "m"
vertices = [[2, 0], [3, 0], [2, 1]]
fixed = false
motion = "prescribed"
velocity = [1, 0]
)",
                              "fixed.toml");
  EXPECT_EQ(s.triangles[0].motion, Motion::Fixed);
  EXPECT_EQ(s.triangles[1].motion, Motion::Prescribed);
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
