#pragma once
// Bonded granite specimens of issue 14 (docs/fracture.md, "Validation"): a rectangle in
// uniaxial compression between two flat platens, and a beam in three-point bending on two
// supports under a loading nose. Shared by the validation tests and the docs' numbers.
#include "tridem/scene_io.hpp"
#include "tridem/snapshot.hpp"

#include <fmt/format.h>

#include <string>

namespace tridem::test {

/// The granite of the examples (E = 40 GPa, f_t = 8 MPa), `damping` Cundall's local
/// damping, `safety` the fraction of dt_crit, serial CPU.
/// G_I = 5 J/m^2, G_II = 25 J/m^2: the Brazilian disc's brittle granite (docs/fracture.md).
inline std::string bonded_granite_header(double damping, double safety) {
  return fmt::format(
      "[simulation]\nsteps = 1\nsafety = {}\nlocal_damping = {}\nbackend = \"cpu\"\n"
      "[[material]]\nname = \"granite\"\ndensity = 2650\npenalty = 5e10\nfriction = 0.6\n"
      "young_modulus = 40e9\ntensile_strength = 8e6\nshear_strength = 25e6\n"
      "friction_angle = 35\nfracture_energy = 5\nshear_fracture_energy = 25\n",
      safety, damping);
}

/// A `width` x `height` rectangle meshed at `size` on a fixed platen (id 0, flat top at
/// y = 0), pressed by a top platen (id 1, flat bottom at y = height) moving down at `speed`.
inline Scene compression_scene(double width, double height, double size, double speed) {
  const double w = width;
  const std::string toml =
      bonded_granite_header(0.2, 0.6) +
      fmt::format(
          "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{mw}, 0], [{w}, 0], [0, {mw}]]\n"
          "fixed = true\n"
          "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{mw}, {h}], [0, {hw}], [{w}, {h}]]\n"
          "motion = \"prescribed\"\nvelocity = [0, {v}]\n"
          "[[mesh]]\nkind = \"rectangle\"\nregion = [[{lo}, 0], [{hi}, {h}]]\nsize = {size}\n"
          "material = \"granite\"\nbonded = true\n",
          fmt::arg("w", w), fmt::arg("mw", -w), fmt::arg("h", height), fmt::arg("hw", height + w),
          fmt::arg("v", -speed), fmt::arg("lo", -0.5 * width), fmt::arg("hi", 0.5 * width),
          fmt::arg("size", size));
  return parse_scene(toml, "compression.toml");
}

/// A beam of `span` + overhangs (length 1.25 span) by `depth`, meshed at `size`, on two
/// fixed supports (ids 0, 1: flat tops at y = 0 of width depth / 2 centred on x = -+span/2)
/// under a loading nose (id 2: its flat bottom, as wide, at y = depth over x = 0) moving
/// down at `speed`, with local damping `damping`. Flat pads, not vertices: a vertex's
/// contact would crush the beam under it (the Brazilian disc's lesson).
inline Scene bending_scene(double span, double depth, double size, double speed, double damping) {
  const double s = 0.5 * span, b = 0.25 * depth;
  const std::string toml =
      bonded_granite_header(damping, 0.6) +
      fmt::format(
          "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{msb}, 0], [{ms}, {mb}], "
          "[{msb2}, 0]]\nfixed = true\n"
          "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{sb}, 0], [{s}, {mb}], "
          "[{sb2}, 0]]\nfixed = true\n"
          "[[triangle]]\nmaterial = \"granite\"\nvertices = [[{mb}, {d}], [{b}, {d}], [0, {db}]]\n"
          "motion = \"prescribed\"\nvelocity = [0, {v}]\n"
          "[[mesh]]\nkind = \"rectangle\"\nregion = [[{lo}, 0], [{hi}, {d}]]\nsize = {size}\n"
          "material = \"granite\"\nbonded = true\n",
          fmt::arg("s", s), fmt::arg("ms", -s), fmt::arg("b", b), fmt::arg("mb", -b),
          fmt::arg("msb", -s - b), fmt::arg("msb2", -s + b), fmt::arg("sb", s - b),
          fmt::arg("sb2", s + b), fmt::arg("d", depth), fmt::arg("db", depth + b),
          fmt::arg("v", -speed), fmt::arg("lo", -1.25 * s), fmt::arg("hi", 1.25 * s),
          fmt::arg("size", size));
  return parse_scene(toml, "three_point_bending.toml");
}

/// The mean y (or x) of the triangles, platens left out (ids below `first`), whose
/// centroid started inside [lo, hi] in x and [bottom, top] in y.
struct Band {
  double x0, x1, y0, y1;
};
inline Vec2d band_mean(const Snapshot& s, const Snapshot& start, std::size_t first, Band b) {
  Vec2d sum{};
  int n = 0;
  for (std::size_t i = first; i < s.size(); ++i)
    if (start.x[i] >= b.x0 && start.x[i] <= b.x1 && start.y[i] >= b.y0 && start.y[i] <= b.y1) {
      sum += Vec2d{s.x[i], s.y[i]};
      ++n;
    }
  return n > 0 ? sum / n : sum;
}

}  // namespace tridem::test
