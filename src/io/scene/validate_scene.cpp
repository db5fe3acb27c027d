// Checks for scenes however they were made. A scene built in code has no line numbers, so
// messages name the scene's source (if any), the material or the particle id instead.
#include "core/initial_overlaps.hpp"
#include "io/scene/scene_sections.hpp"
#include "io/scene/triangle_shape.hpp"
#include "tridem/error.hpp"
#include "tridem/scene_io.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace tridem {
namespace {

bool finite(Vec2d v) { return std::isfinite(v.x) && std::isfinite(v.y); }

class Refuser {
 public:
  explicit Refuser(const Scene& scene) : prefix_(scene_label(scene)) {}
  [[noreturn]] void operator()(std::string_view what) const {
    throw SceneError(fmt::format("{}: {}", prefix_, what));
  }

 private:
  std::string prefix_;
};

void check_measures(const std::vector<MeasureSpec>& measures, const Refuser& refuse) {
  for (std::size_t k = 0; k < measures.size(); ++k) {
    const MeasureSpec& m = measures[k];
    const auto fail = [&](std::string_view key, const std::string& why) {
      refuse(fmt::format("[[measure]] #{} {}{}", k + 1, key.empty() ? "" : fmt::format("{} ", key),
                         why));
    };
    if (auto why = scene_detail::measure_name_problem(m.name)) fail("name", *why);
    if (m.region)
      if (auto why = scene_detail::measure_region_problem(*m.region)) fail("region", *why);
    if (m.every && *m.every < 0) fail("every", fmt::format("must be >= 0, got {}", *m.every));
    if (!m.file.empty())
      if (auto why = scene_detail::measure_file_problem(m.file)) fail("file", *why);
    const std::vector<MeasureSpec> earlier(measures.begin(), measures.begin() + k);
    if (auto why = scene_detail::measure_clash(m, earlier)) fail("", *why);
  }
}

void check_settings(const Scene& scene, const Refuser& refuse) {
  const SimulationSettings& s = scene.simulation;
  if (s.duration != 0) {
    if (!(std::isfinite(s.duration) && s.duration > 0))
      refuse(fmt::format("[simulation] time must be finite and > 0, got {}", s.duration));
  } else if (s.steps <= 0) {
    refuse(fmt::format("[simulation] steps must be > 0, got {}", s.steps));
  }
  if (s.dt && !(std::isfinite(*s.dt) && *s.dt > 0))
    refuse(fmt::format("[simulation] dt must be finite and > 0, got {}", *s.dt));
  if (!(s.safety > 0 && s.safety <= 1))
    refuse(fmt::format("[simulation] safety must be in (0, 1], got {}", s.safety));
  if (!finite(s.gravity)) refuse("[simulation] gravity must be finite");
  if (!(s.local_damping >= 0 && s.local_damping < 1))
    refuse(fmt::format("[simulation] local_damping must be in [0, 1), got {}", s.local_damping));
  if (!(s.max_penetration > 0 && s.max_penetration <= 1))
    refuse(fmt::format("[simulation] max_penetration must be in (0, 1], got {}",
                       s.max_penetration));
  if (scene.output.checkpoint_every < 0)
    refuse(fmt::format("[output] checkpoint_every must be >= 0, got {}",
                       scene.output.checkpoint_every));
  if (auto why = method_settings_conflict(s.method, s.contact_test, s.bbox_prefilter))
    refuse("[simulation] " + *why);
  const DecompositionSettings& d = s.decomposition;
  if (d.rows < 0 || d.columns < 0)
    refuse(fmt::format("[simulation.decomposition] rows and columns must be >= 0, got {} x {}",
                       d.rows, d.columns));
  if (d.layout == DecompositionLayout::Strips && (d.rows != 0 || d.columns != 0))
    refuse("[simulation.decomposition] rows and columns set the 2d layout, not layout = \"1d\"");
  if (d.capacity < 2)
    refuse(fmt::format("[simulation.decomposition] capacity must be >= 2, got {}", d.capacity));
  if (scene.output.every < 0)
    refuse(fmt::format("[output] every must be >= 0, got {}", scene.output.every));
  if (scene.output.energy_every && *scene.output.energy_every < 0)
    refuse(fmt::format("[output] energy_every must be >= 0, got {}", *scene.output.energy_every));
  if (scene.output.dir.empty()) refuse("[output] dir must not be empty");
  check_measures(scene.output.measures, refuse);
  std::string periodic_key;
  if (auto why = scene_detail::periodic_cell_problem(scene.simulation.periodic, periodic_key))
    refuse(fmt::format("[simulation] {} {}", periodic_key, *why));
}

void check_materials(const Scene& scene, const Refuser& refuse) {
  if (scene.materials.empty()) refuse("no material defined; at least one is required");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::string which = fmt::format("material #{} \"{}\"", i, m.name);
    if (m.name.empty()) refuse(fmt::format("material #{} has an empty name", i));
    for (std::size_t j = 0; j < i; ++j)
      if (scene.materials[j].name == m.name)
        refuse(fmt::format("{}: duplicate name (also material #{})", which, j));
    if (!(std::isfinite(m.density) && m.density > 0))
      refuse(fmt::format("{}: density must be finite and > 0, got {}", which, m.density));
    if (!(std::isfinite(m.penalty) && m.penalty > 0))
      refuse(fmt::format("{}: penalty must be finite and > 0, got {}", which, m.penalty));
    if (!(std::isfinite(m.tangential_penalty) && m.tangential_penalty > 0))
      refuse(fmt::format("{}: tangential_penalty must be finite and > 0, got {}", which,
                         m.tangential_penalty));
    if (!(std::isfinite(m.friction) && m.friction >= 0))
      refuse(fmt::format("{}: friction must be finite and >= 0, got {}", which, m.friction));
    if (!(m.damping >= 0 && m.damping < 1))
      refuse(fmt::format("{}: damping must be in [0, 1), got {}", which, m.damping));
    if (m.restitution && !(*m.restitution > 0 && *m.restitution <= 1))
      refuse(fmt::format("{}: restitution must be in (0, 1], got {}", which, *m.restitution));
    if (m.restitution && m.damping != 0)
      refuse(fmt::format("{}: give either restitution or damping, not both", which));
  }
}

// Bonds (bonded [[mesh]]es, or a scene built in code): two distinct lone free triangles of
// a bondable material, ascending, sharing the bond's edge.
void check_bonds(const Scene& scene, const Refuser& refuse) {
  const std::size_t n = scene.triangles.size();
  for (std::size_t k = 0; k < scene.bonds.size(); ++k) {
    const BondSpec& bond = scene.bonds[k];
    if (!(bond.a < bond.b && bond.b < n))
      refuse(fmt::format("bond #{}: its triangles {} and {} must be ascending ids below {}", k,
                         bond.a, bond.b, n));
    if (k > 0 && !(scene.bonds[k - 1].a < bond.a ||
                   (scene.bonds[k - 1].a == bond.a && scene.bonds[k - 1].b < bond.b)))
      refuse(fmt::format("bond #{}: bonds must be sorted by (a, b) without repeats", k));
    for (std::size_t id : {bond.a, bond.b}) {
      const TriangleSpec& t = scene.triangles[id];
      const Material& m = scene.materials[static_cast<std::size_t>(t.material)];
      if (!m.bondable())
        refuse(fmt::format("bond #{}: particle id {} is of material \"{}\", which has no bond "
                           "properties (young_modulus, tensile_strength, ...)",
                           k, id, m.name));
      if (t.motion != Motion::Free)
        refuse(fmt::format("bond #{}: particle id {} is fixed or prescribed; bonds join free "
                           "triangles",
                           k, id));
    }
    if (scene.has_bodies())
      refuse("bonds and bodies of several triangles in one scene are not supported yet");
    if (!(norm(bond.q - bond.p) > 0)) refuse(fmt::format("bond #{}: its edge has zero length", k));
  }
}

void check_triangles(const Scene& scene, const Refuser& refuse) {
  if (scene.triangles.empty()) refuse("the scene has no triangles");
  // On the threads (a 10^7 scene, issue 12), refusing the lowest id at fault.
  const auto count = static_cast<std::ptrdiff_t>(scene.triangles.size());
  std::ptrdiff_t first_bad = count;
#pragma omp parallel for schedule(static) reduction(min : first_bad) if (count > 65536)
  for (std::ptrdiff_t id = 0; id < count; ++id)
    if (scene_detail::triangle_problem(scene.triangles[static_cast<std::size_t>(id)],
                                       scene.materials.size()))
      first_bad = std::min(first_bad, id);
  if (first_bad == count) return;
  const auto id = static_cast<std::size_t>(first_bad);
  refuse(fmt::format("particle id {}: {}", id,
                     *scene_detail::triangle_problem(scene.triangles[id], scene.materials.size())));
}

/// Overlapping triangles hold contact energy the scene did not mean to give them; refused
/// unless the scene asks for them to be pushed apart before the run (run_scene does it).
void check_overlaps(const Scene& scene, const Refuser& refuse,
                    const scene_detail::Provenance* provenance) {
  if (scene.simulation.relax_overlaps) return;
  std::optional<InitialOverlap> o;
  std::size_t kept = 0;  // triangles whose overlaps among themselves are kept
  if (provenance)
    for (const scene_detail::Provenance::Generated& g : provenance->generators)
      if (g.keep_overlaps) kept += g.count;
  if (kept == scene.triangles.size()) return;  // every pair kept (a run's final.csv, its walls)
  if (kept > 0) {
    // The first overlap not kept; the kept pairs are not even tested.
    o = first_initial_overlap_where(
        scene.triangles, scene.simulation.periodic,
        [&](std::size_t a, std::size_t b) { return !provenance->keeps_overlap(a, b); });
  } else {
    o = first_initial_overlap(scene.triangles, scene.simulation.periodic);
  }
  if (!o) return;
  auto describe = [&](std::size_t id) {
    return provenance ? provenance->describe(id) : fmt::format("particle id {}", id);
  };
  refuse(fmt::format("{} and {} overlap by {:.6g} m (the shortest push along an edge normal "
                     "that separates them; touching is allowed): their contact would start "
                     "with energy that the scene does not hold. Move them apart, or set "
                     "[simulation] relax_overlaps = true to push overlapping triangles apart "
                     "before the run{}",
                     describe(o->a), describe(o->b), o->depth,
                     provenance && provenance->in_import(o->a) && provenance->in_import(o->b)
                         ? " (or, if the file is a run's final.csv whose contacts overlap, "
                           "keep_overlaps = true in its [[import]] block to keep them)"
                         : ""));
}

}  // namespace

namespace scene_detail {

std::string Provenance::describe(std::size_t id) const {
  if (id < explicit_origin.size())
    return fmt::format("particle id {} ({})", id, explicit_origin[id]);
  for (const Generated& g : generators)
    if (id >= g.first && id < g.first + g.count)
      return fmt::format("particle id {} ({} #{} at {}, its triangle {} of {})", id, g.section,
                         g.number, g.where, id - g.first + 1, g.count);
  return fmt::format("particle id {}", id);
}

bool Provenance::in_import(std::size_t id) const {
  for (const Generated& g : generators)
    if (id >= g.first && id < g.first + g.count) return g.section == "[[import]]";
  return false;
}

bool Provenance::keeps_overlap(std::size_t a, std::size_t b) const {
  auto kept = [&](std::size_t id) {
    for (const Generated& g : generators)
      if (id >= g.first && id < g.first + g.count) return g.keep_overlaps;
    return false;
  };
  return kept(a) && kept(b);
}

void validate_settings(const Scene& scene) { check_settings(scene, Refuser(scene)); }

void validate_scene(const Scene& scene, const Provenance* provenance) {
  const Refuser refuse(scene);
  check_settings(scene, refuse);
  check_materials(scene, refuse);
  check_triangles(scene, refuse);
  check_bonds(scene, refuse);
  check_overlaps(scene, refuse, provenance);
}

}  // namespace scene_detail

void validate_scene(const Scene& scene) { scene_detail::validate_scene(scene, nullptr); }

std::string scene_label(const Scene& scene) {
  return scene.source.empty() ? std::string("scene built in code") : scene.source;
}

}  // namespace tridem
