// [[generate]] blocks. Each key is range-checked here, before the generator runs, so that a
// refusal names the key; the generators repeat the checks for callers that use them directly.
#include "io/scene/generator_checks.hpp"
#include "io/scene/scene_sections.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"

#include <fmt/format.h>

#include <array>
#include <string_view>
#include <utility>

namespace tridem::scene_detail {
namespace {

enum class Kind { Lattice, Random, Polygons, Triangles };
constexpr std::array<std::pair<std::string_view, Kind>, 4> kKindNames{
    {{"lattice", Kind::Lattice},
     {"random", Kind::Random},
     {"polygons", Kind::Polygons},
     {"triangles", Kind::Triangles}}};

struct Common {
  int material;
  Vec2d region_min, region_max;
  double size, gap;
  Vec2d velocity;
};

Common read_common(TableReader& r, const std::vector<Material>& materials) {
  Common c{};
  c.material = lookup_material(r, materials);
  const auto region = r.required(r.points<2>("region"), "region");
  c.region_min = region[0];
  c.region_max = region[1];
  if (!(c.region_max.x > c.region_min.x && c.region_max.y > c.region_min.y))
    r.fail("region", fmt::format("max corner ({}, {}) must exceed min corner ({}, {}) in x and y",
                                 c.region_max.x, c.region_max.y, c.region_min.x, c.region_min.y));
  c.size = r.required(r.real("size"), "size");
  if (!(c.size > 0)) r.fail("size", fmt::format("must be > 0, got {}", c.size));
  c.gap = r.real("gap").value_or(0.1);
  if (!(c.gap >= 0)) r.fail("gap", fmt::format("must be >= 0, got {}", c.gap));
  c.velocity = r.vec2("velocity").value_or(Vec2d{});
  return c;
}

// Zero or too many triangles are reported against size, the usual culprit (a region in
// metres with a size in millimetres, or the reverse).
void check_count(TableReader& r, std::size_t n) {
  if (n == 0)
    r.fail("size", "the region holds no whole triangle of this size and gap: enlarge region "
                   "or reduce size/gap");
  if (n > kMaxGeneratedTriangles)
    r.fail("size", fmt::format("would generate {} triangles, more than the limit of {} "
                               "(check units of region and size)",
                               n, kMaxGeneratedTriangles));
}

LatticeSpec read_lattice(TableReader& r, const Common& c) {
  for (const char* key : {"seed", "count", "irregularity"})
    if (r.has(key)) r.fail(key, "applies only to kind = \"random\"");
  const LatticeSpec spec{c.material, c.region_min, c.region_max, c.size, c.gap, c.velocity};
  check_count(r, count_lattice(spec));
  return spec;
}

RandomPackingSpec read_random(TableReader& r, const Common& c) {
  RandomPackingSpec spec{};
  spec.material = c.material;
  spec.region_min = c.region_min;
  spec.region_max = c.region_max;
  spec.size = c.size;
  spec.gap = c.gap;
  spec.velocity = c.velocity;
  const std::int64_t seed = r.integer("seed").value_or(1);
  if (seed < 0) r.fail("seed", fmt::format("must be >= 0, got {}", seed));
  spec.seed = static_cast<std::uint64_t>(seed);
  const std::int64_t count = r.integer("count").value_or(0);
  if (count < 0) r.fail("count", fmt::format("must be >= 0 (0 = fill the region), got {}", count));
  spec.count = static_cast<std::size_t>(count);
  spec.irregularity = r.real("irregularity").value_or(0.0);
  if (!(spec.irregularity >= 0 && spec.irregularity < 1))
    r.fail("irregularity", fmt::format("must be in [0, 1), got {}", spec.irregularity));
  const std::size_t cells = count_random_cells(spec);
  if (spec.count > cells)
    r.fail("count", fmt::format("asks for {} triangles but the region holds only {} at this "
                                "size and gap",
                                spec.count, cells));
  check_count(r, spec.count > 0 ? spec.count : cells);
  return spec;
}

// The checks above should leave the generator nothing to refuse; should one slip through,
// its message still gets the file position and block number.
template <class Make>
std::vector<TriangleSpec> generate_here(const TableReader& r, Make make) {
  try {
    return make();
  } catch (const SceneError& e) {
    r.fail_table(e.what());
  }
}

}  // namespace

void parse_generate(const toml::table& table, const std::string& source, std::size_t number,
                    const std::vector<Material>& materials, std::vector<TriangleSpec>& out,
                    std::vector<BodySpec>& bodies) {
  TableReader r(table, source,
                fmt::format("[[generate]] #{} (particle ids from {})", number, out.size()));
  const Kind kind = r.required(r.choice_in<Kind>("kind", kKindNames), "kind");
  if (kind == Kind::Polygons || kind == Kind::Triangles) {
    GeneratedGrains grains =
        parse_generate_grains(r, kind == Kind::Triangles, materials, out.size());
    for (BodySpec& b : grains.bodies) {
      b.first += out.size();
      bodies.push_back(b);
    }
    out.insert(out.end(), grains.triangles.begin(), grains.triangles.end());
    return;
  }
  const Common common = read_common(r, materials);
  // Read everything and refuse unknown keys before generating: a typo should not cost the
  // time of generating a million triangles first.
  std::vector<TriangleSpec> made;
  // Nor should it cost the machine: a count that cannot be held is refused before a byte
  // of it is made.
  auto check_memory = [&](std::size_t count) {
    if (const std::string why = memory_shortfall(out.size() + count, available_memory_bytes());
        !why.empty())
      r.fail("size", why);
  };
  if (kind == Kind::Lattice) {
    const LatticeSpec spec = read_lattice(r, common);
    r.reject_unknown_keys();
    check_memory(count_lattice(spec));
    made = generate_here(r, [&] { return generate_lattice(spec); });
  } else {
    const RandomPackingSpec spec = read_random(r, common);
    r.reject_unknown_keys();
    check_memory(spec.count > 0 ? spec.count : count_random_cells(spec));
    made = generate_here(r, [&] { return generate_random(spec); });
  }
  // Each triangle of these kinds is a body of its own (on the threads: a 10^7 lattice).
  const std::size_t first_body = bodies.size();
  bodies.resize(first_body + made.size());
  const auto count = static_cast<std::ptrdiff_t>(made.size());
#pragma omp parallel for schedule(static) if (count > 65536)
  for (std::ptrdiff_t signed_k = 0; signed_k < count; ++signed_k) {
    const auto k = static_cast<std::size_t>(signed_k);
    bodies[first_body + k] = {out.size() + k, 1, made[k].velocity, made[k].angular_velocity,
                              made[k].motion};
  }
  if (out.empty()) {
    out = std::move(made);
  } else {
    out.insert(out.end(), made.begin(), made.end());
  }
}

}  // namespace tridem::scene_detail
