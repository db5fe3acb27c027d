// The note of a large scene numbered far from where its grains lie: dense_pile's rows and
// the same grains along a Hilbert curve pass; the same grains numbered at random are told,
// above the size where it costs a run.
#include "core/numbering_note.hpp"
#include "core/space_filling_order.hpp"
#include "tridem/standard_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

namespace tridem {
namespace {
namespace TRIDEM_TEST_FILE {  // one per source in a unity batch (tests/CMakeLists.txt)

Scene shuffled(std::size_t n) {
  Scene s = dense_pile(n);  // the walls come last
  std::mt19937_64 random(5);
  std::shuffle(s.triangles.begin(), s.triangles.end() - 3, random);
  return s;
}

TEST(NumberingNote, RowsAndACurvePassAndARandomNumberingIsTold) {
  const ParticleModel rows = build_particle_model(dense_pile(100000));
  EXPECT_LT(consecutive_id_distance(rows), 2.0);
  EXPECT_LT(numbering_spread(rows), 0.02);
  EXPECT_EQ(numbering_note(rows, false), "");

  Scene curve = dense_pile(100000);
  number_by_place(curve.triangles, curve.triangles.size() - 3);  // the walls stay last
  const ParticleModel along = build_particle_model(curve);
  EXPECT_LT(consecutive_id_distance(along), 2.0);
  EXPECT_EQ(numbering_note(along, false), "");

  const ParticleModel random = build_particle_model(shuffled(100000));
  // About a third of the pile's ~450 grains across, in grains.
  EXPECT_GT(consecutive_id_distance(random), 100.0);
  EXPECT_NEAR(numbering_spread(random), 1.0, 0.05);  // random: as far as scrambled ids
  const std::string note = numbering_note(random, false);
  EXPECT_NE(note.find("numbered far from where they lie"), std::string::npos) << note;
  EXPECT_NE(note.find("numbering = \"space\""), std::string::npos) << note;
  EXPECT_NE(note.find("--particle-order at auto"), std::string::npos) << note;  // how it would
  // The solver numbering them by place says so, and not how to do it.
  const std::string told = numbering_note(random, true);
  EXPECT_NE(told.find("the solver keeps them numbered by place"), std::string::npos) << told;
  EXPECT_EQ(told.find("numbering = \"space\""), std::string::npos) << told;
}

TEST(NumberingNote, SmallScenesAreNotTold) {
  const ParticleModel random = build_particle_model(shuffled(20000));
  EXPECT_GT(consecutive_id_distance(random), kFarNumbering);
  EXPECT_NEAR(numbering_spread(random), 1.0, 0.05);  // whatever the scene's size
  EXPECT_EQ(numbering_note(random, false), "");
  EXPECT_EQ(numbering_note(random, true), "");
}

}  // namespace TRIDEM_TEST_FILE
}  // namespace
}  // namespace tridem
