// Writes the benchmark's dense_pile(n) (src/scenes/standard_scenes.cpp) as a scene that
// `tridem run` reads (bench/run_cli_vs_bench_on_device.sh; issue 12): DIR/grains.csv and
// DIR/walls.csv hold the vertices (17 digits: the same doubles), imported with their
// overlaps kept, since the pile starts with every lattice neighbour overlapping, which
// [[generate]] cannot express. Material, gravity, time-step rule and particle order are the
// pile's: the same triangles, numbered the same.
//   tridem_write_pile_scene N DIR [STEPS=3000] [EVERY=1000] [PRECISION=double]
#include "tridem/setting_names.hpp"
#include "tridem/standard_scenes.hpp"

#include <cstdio>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace {

std::FILE* open_for_writing(const std::filesystem::path& p) {
  std::FILE* f = std::fopen(p.c_str(), "w");
  if (!f) throw std::runtime_error("cannot write " + p.string());
  return f;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: %s N DIR [STEPS=3000] [EVERY=1000] [PRECISION=double]\n", argv[0]);
    return 2;
  }
  try {
    const tridem::Scene pile = tridem::dense_pile(std::stoul(argv[1]));
    const std::filesystem::path dir = argv[2];
    const long long steps = argc > 3 ? std::stoll(argv[3]) : 3000;
    const long long every = argc > 4 ? std::stoll(argv[4]) : 1000;
    const std::string precision = argc > 5 ? argv[5] : "double";
    if (!tridem::value_in(tridem::kPrecisionNames, precision))
      throw std::runtime_error("unknown precision " + precision);
    std::filesystem::create_directories(dir);

    // Grains, then walls, as dense_pile numbers them; both files imported with their
    // overlaps kept (a wall touches the outer grains, which the growth makes overlap a little).
    std::size_t grains = 0;
    for (const char* file : {"grains.csv", "walls.csv"}) {
      const bool walls = file[0] == 'w';
      std::FILE* csv = open_for_writing(dir / file);
      std::fprintf(csv, "x1,y1,x2,y2,x3,y3\n");
      for (const tridem::TriangleSpec& t : pile.triangles) {
        if ((t.motion == tridem::Motion::Free) == walls) continue;
        std::fprintf(csv, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", t.vertices[0].x, t.vertices[0].y,
                     t.vertices[1].x, t.vertices[1].y, t.vertices[2].x, t.vertices[2].y);
        if (!walls) ++grains;
      }
      std::fclose(csv);
    }

    const tridem::SimulationSettings& sim = pile.simulation;
    const tridem::Material& m = pile.materials.at(0);
    std::FILE* toml = open_for_writing(dir / "scene.toml");
    std::fprintf(toml,
                 "# dense_pile(%s) of the benchmark, %zu grains and %zu walls, written by "
                 "tridem_write_pile_scene\n"
                 "[simulation]\nsteps = %lld\nsafety = %.17g\ngravity = [%.17g, %.17g]\n"
                 "precision = \"%s\"\n\n"
                 "[output]\ndir = \"out\"\nevery = %lld\ncontacts = true\n\n"
                 "[[material]]\nname = \"%s\"\ndensity = %.17g\npenalty = %.17g\n"
                 "tangential_penalty = %.17g\nfriction = %.17g\nrestitution = %.17g\n",
                 argv[1], grains, pile.triangles.size() - grains, steps, sim.safety, sim.gravity.x,
                 sim.gravity.y, precision.c_str(), every, m.name.c_str(), m.density, m.penalty,
                 m.tangential_penalty, m.friction, m.restitution.value_or(1.0));
    std::fprintf(toml,
                 "\n[[import]]\nfile = \"grains.csv\"\nmaterial = \"%s\"\nkeep_overlaps = true\n"
                 "\n[[import]]\nfile = \"walls.csv\"\nmaterial = \"%s\"\nfixed = true\n"
                 "keep_overlaps = true\n",
                 m.name.c_str(), m.name.c_str());
    std::fclose(toml);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tridem_write_pile_scene: %s\n", e.what());
    return 1;
  }
  return 0;
}
