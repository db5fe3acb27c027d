// [[generate]] kind = "polygons" and "triangles": the keys of random grains (shapes, size
// distribution, amount, placement), each checked here so that a refusal names its key,
// before anything is drawn.
#include "io/scene/generator_checks.hpp"
#include "io/scene/scene_sections.hpp"
#include "tridem/error.hpp"
#include "tridem/generate.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace tridem::scene_detail {
namespace {

constexpr std::string_view kRegionShape =
    "2 corners [[xmin, ymin], [xmax, ymax]] or a polygon [[x, y], ...] of at least 3 points";

// A value or a range [min, max] of one: a bare value v reads as [v, v].
template <class T>
std::pair<T, T> as_range(TableReader& r, std::string_view key, const std::vector<T>& v) {
  if (v.size() > 2)
    r.fail(key, fmt::format("expected a value or a range [min, max], got {} values", v.size()));
  const std::pair<T, T> range{v.front(), v.back()};
  if (!(range.first <= range.second))
    r.fail(key, fmt::format("range [{}, {}]: min must not exceed max", range.first, range.second));
  return range;
}

void read_shape(TableReader& r, bool triangles, GrainSpec& spec) {
  if (triangles) {
    if (r.has("sides")) r.fail("sides", "applies only to kind = \"polygons\" (triangles have 3)");
  } else {
    const auto sides = as_range(r, "sides", r.required(r.integers("sides"), "sides"));
    if (sides.first < 3 || sides.second > 64)
      r.fail("sides",
             fmt::format("must be within [3, 64], got [{}, {}]", sides.first, sides.second));
    spec.min_sides = static_cast<int>(sides.first);
    spec.max_sides = static_cast<int>(sides.second);
  }
  if (auto v = r.reals("aspect_ratio")) {
    const auto aspect = as_range(r, "aspect_ratio", *v);
    if (!(aspect.first >= 1))
      r.fail("aspect_ratio", fmt::format("must be >= 1 (length over width), got {}", aspect.first));
    spec.min_aspect = aspect.first;
    spec.max_aspect = aspect.second;
  }
  spec.angularity = r.real("angularity").value_or(0.0);
  if (!(spec.angularity >= 0 && spec.angularity < 1))
    r.fail("angularity", fmt::format("must be in [0, 1), got {}", spec.angularity));
}

void read_sizes(TableReader& r, GrainSpec& spec) {
  const auto size = r.reals("size");
  const auto sizes = r.reals("sizes");
  const auto fractions = r.reals("mass_fractions");
  if (size && sizes) r.fail("sizes", "give size (one size or a range) or sizes, not both");
  if (size) {
    if (fractions) r.fail("mass_fractions", "goes with sizes, not with size");
    const auto range = as_range(r, "size", *size);
    if (!(range.first > 0)) r.fail("size", fmt::format("must be > 0, got {}", range.first));
    spec.sizes.min_size = range.first;
    spec.sizes.max_size = range.second;
    return;
  }
  if (!sizes)
    r.fail_table("missing its sizes: give size = D, size = [min, max], or sizes = [...] with "
                 "mass_fractions = [...]");
  if (!fractions) r.fail("sizes", "needs mass_fractions = [...], one per size");
  if (fractions->size() != sizes->size())
    r.fail("mass_fractions",
           fmt::format("has {} values for {} sizes", fractions->size(), sizes->size()));
  double sum = 0;
  for (std::size_t k = 0; k < sizes->size(); ++k) {
    if (!((*sizes)[k] > 0))
      r.fail("sizes", fmt::format("size {} must be > 0, got {}", k + 1, (*sizes)[k]));
    if (!((*fractions)[k] > 0))
      r.fail("mass_fractions",
             fmt::format("fraction {} must be > 0, got {}", k + 1, (*fractions)[k]));
    sum += (*fractions)[k];
    spec.sizes.classes.push_back({(*sizes)[k], (*fractions)[k]});
  }
  if (std::abs(sum - 1) > 1e-6)
    r.fail("mass_fractions", fmt::format("must sum to 1, they sum to {}", sum));
}

// Which key a refusal about the amount names.
std::string_view read_amount(TableReader& r, GrainSpec& spec) {
  const auto count = r.integer("count");
  const auto fraction = r.real("packing_fraction");
  if (count && fraction) r.fail("packing_fraction", "give count or packing_fraction, not both");
  if (!count && !fraction)
    r.fail_table("missing how many grains: give count = N or packing_fraction = f");
  if (count) {
    if (*count <= 0) r.fail("count", fmt::format("must be > 0, got {}", *count));
    spec.count = static_cast<std::size_t>(*count);
    return "count";
  }
  if (!(*fraction > 0 && *fraction < 1))
    r.fail("packing_fraction", fmt::format("must be in (0, 1), got {}", *fraction));
  spec.packing_fraction = *fraction;
  return "packing_fraction";
}

}  // namespace

GeneratedGrains parse_generate_grains(TableReader& r, bool triangles,
                                      const std::vector<Material>& materials,
                                      std::size_t particles_before) {
  GrainSpec spec;
  spec.material = lookup_material(r, materials);
  spec.region = r.required(r.point_list("region", kRegionShape), "region");
  read_shape(r, triangles, spec);
  read_sizes(r, spec);
  const std::string_view amount = read_amount(r, spec);
  const std::int64_t seed = r.integer("seed").value_or(1);
  if (seed < 0) r.fail("seed", fmt::format("must be >= 0, got {}", seed));
  spec.seed = static_cast<std::uint64_t>(seed);
  const std::int64_t attempts = r.integer("max_attempts").value_or(10000);
  if (attempts < 1) r.fail("max_attempts", fmt::format("must be >= 1, got {}", attempts));
  spec.max_attempts = static_cast<std::size_t>(attempts);
  spec.velocity = r.vec2("velocity").value_or(Vec2d{});
  spec.numbering =
      r.choice_in<GrainNumbering>("numbering", kGrainNumberingNames).value_or(spec.numbering);
  r.reject_unknown_keys();

  // The region's own problems name 'region'; the rest of the spec was checked above.
  std::size_t most = 0;
  try {
    most = max_grain_triangles(spec);
  } catch (const SceneError& e) {
    r.fail("region", e.what());
  }
  if (most > kMaxGeneratedTriangles)
    r.fail(amount, fmt::format("could make up to {} triangles, more than the limit of {} "
                               "(check units of region and sizes)",
                               most, kMaxGeneratedTriangles));
  if (const std::string why = memory_shortfall(particles_before + most, available_memory_bytes());
      !why.empty())
    r.fail(amount, why);
  try {
    return generate_grains(spec);
  } catch (const SceneError& e) {
    r.fail(amount, e.what());
  }
}

}  // namespace tridem::scene_detail
