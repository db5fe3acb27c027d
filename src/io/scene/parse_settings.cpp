// [simulation] and [output]. Defaults come from the structs in scene.hpp so that a scene
// built in code and one read from a file agree on them.
#include "io/scene/scene_sections.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>

#include <climits>
#include <cmath>

namespace tridem::scene_detail {

namespace {

/// An integer key of [simulation.decomposition] in [lo, INT_MAX], or `fallback`.
int bounded_int(TableReader& r, std::string_view key, int lo, int fallback,
                std::string_view meaning) {
  const auto v = r.integer(key);
  if (!v) return fallback;
  if (*v < lo || *v > INT_MAX)
    r.fail(key, fmt::format("must be an integer in [{}, {}] ({}), got {}", lo, INT_MAX, meaning,
                            *v));
  return static_cast<int>(*v);
}

/// [simulation.decomposition]: how method = "decomposition" cuts the domain.
DecompositionSettings parse_decomposition(const toml::node& node, TableReader& parent,
                                          const std::string& source) {
  const toml::table* table = node.as_table();
  if (!table)
    parent.fail("decomposition", fmt::format("must be a table, written [simulation.decomposition], "
                                             "got {}",
                                             describe_type(node.type())));
  TableReader r(*table, source, "[simulation.decomposition]");
  DecompositionSettings d;
  d.layout = r.choice_in<DecompositionLayout>("layout", kLayoutNames).value_or(d.layout);
  d.rows = bounded_int(r, "rows", 0, d.rows, "0 = chosen from the particle counts");
  d.columns = bounded_int(r, "columns", 0, d.columns, "0 = chosen from the particle counts");
  if (d.layout == DecompositionLayout::Strips && (d.rows != 0 || d.columns != 0))
    r.fail(d.rows != 0 ? "rows" : "columns",
           "sets the 2d layout; layout = \"1d\" chooses its strips from the particle counts "
           "(set layout = \"2d\" or remove the key)");
  d.capacity = bounded_int(r, "capacity", 2, d.capacity,
                           "most particles in a sub-domain, its overlap band included");
  r.reject_unknown_keys();
  return d;
}

}  // namespace

SimulationSettings parse_simulation(const toml::table& table, const std::string& source) {
  TableReader r(table, source, "[simulation]");
  SimulationSettings s;
  const auto steps = r.integer("steps");
  const auto duration = r.real("time");
  if (steps && duration) r.fail("time", "and steps both set the run's length: give one of them");
  if (!steps && !duration)
    r.fail_table("missing required key 'steps' (the number of steps; or give time, the "
                 "simulated seconds)");
  if (steps) {
    s.steps = *steps;
    if (s.steps <= 0) r.fail("steps", fmt::format("must be > 0, got {}", s.steps));
  } else {
    s.duration = *duration;
    if (!(std::isfinite(s.duration) && s.duration > 0))
      r.fail("time", fmt::format("must be finite and > 0 (simulated seconds), got {}", s.duration));
  }
  if (auto dt = r.real("dt")) {
    if (!(*dt > 0)) r.fail("dt", fmt::format("must be > 0, got {} (omit dt for automatic)", *dt));
    s.dt = *dt;
  }
  s.safety = r.real("safety").value_or(s.safety);
  if (!(s.safety > 0 && s.safety <= 1))
    r.fail("safety", fmt::format("must be in (0, 1], got {}", s.safety));
  s.gravity = r.vec2("gravity").value_or(s.gravity);
  s.backend = r.choice_in<Backend>("backend", kBackendNames).value_or(s.backend);
  s.precision = r.choice_in<Precision>("precision", kPrecisionNames).value_or(s.precision);
  s.method = r.choice_in<Method>("method", kMethodNames).value_or(s.method);
  s.contact_test =
      r.choice_in<ContactTest>("contact_test", kContactTestNames).value_or(s.contact_test);
  s.bbox_prefilter = r.boolean("bbox_prefilter").value_or(s.bbox_prefilter);
  if (auto why = method_settings_conflict(s.method, s.contact_test, s.bbox_prefilter))
    r.fail(s.contact_test != ContactTest::Exact ? "contact_test" : "bbox_prefilter", *why);
  if (const toml::node* d = r.node("decomposition"))
    s.decomposition = parse_decomposition(*d, r, source);
  s.local_damping = r.real("local_damping").value_or(s.local_damping);
  if (!(s.local_damping >= 0 && s.local_damping < 1))
    r.fail("local_damping", fmt::format("must be in [0, 1), got {}", s.local_damping));
  s.skin = r.real("skin").value_or(s.skin);
  if (!(s.skin >= 0 && s.skin <= 1))
    r.fail("skin", fmt::format("must be in [0, 1] (a fraction of the grid cell), got {}", s.skin));
  s.max_penetration = r.real("max_penetration").value_or(s.max_penetration);
  if (!(s.max_penetration > 0 && s.max_penetration <= 1))
    r.fail("max_penetration",
           fmt::format("must be in (0, 1] (1 = no check), got {}", s.max_penetration));
  s.relax_overlaps = r.boolean("relax_overlaps").value_or(s.relax_overlaps);
  s.periodic = parse_periodic_cell(r);
  r.reject_unknown_keys();
  return s;
}

OutputSettings parse_output(const toml::table& table, const std::string& source) {
  TableReader r(table, source, "[output]");
  OutputSettings o;
  o.dir = r.string("dir").value_or(o.dir);
  if (o.dir.empty()) r.fail("dir", "must not be empty (use \".\" for the current folder)");
  o.every = r.integer("every").value_or(o.every);
  if (o.every < 0) r.fail("every", fmt::format("must be >= 0 (0 = no frames), got {}", o.every));
  o.contacts = r.boolean("contacts").value_or(o.contacts);
  o.contacts_csv = r.boolean("contacts_csv").value_or(o.contacts_csv);
  o.checkpoint_every = r.integer("checkpoint_every").value_or(o.checkpoint_every);
  if (o.checkpoint_every < 0)
    r.fail("checkpoint_every",
           fmt::format("must be >= 0 (0 = no periodic checkpoints), got {}", o.checkpoint_every));
  if (auto e = r.integer("energy_every")) {
    if (*e < 0)
      r.fail("energy_every",
             fmt::format("must be >= 0 (0 = only step 0 and the last step), got {}", *e));
    o.energy_every = *e;
  }
  o.encoding = r.choice_in<Encoding>("vtk_encoding", kEncodingNames).value_or(o.encoding);
  o.precision =
      r.choice_in<VtkPrecision>("vtk_precision", kVtkPrecisionNames).value_or(o.precision);
  o.compression =
      r.choice_in<VtkCompression>("vtk_compression", kVtkCompressionNames).value_or(o.compression);
  if (auto names = r.choices_in<FrameArray>("frame_arrays", kFrameArrayNames)) {
    o.frame_arrays = ArraySet<FrameArray>::none();
    for (FrameArray a : *names) {
      // The grain's sums come from the frame's contacts, which only `contacts` downloads.
      const bool of_contacts =
          a == FrameArray::Stress || a == FrameArray::Pressure || a == FrameArray::Coordination;
      if (of_contacts && !o.contacts)
        r.fail("frame_arrays",
               fmt::format("\"{}\" is computed from each frame's contacts: it needs contacts "
                           "= true",
                           name_in(kFrameArrayNames, a)));
      o.frame_arrays.add(a);
    }
  }
  if (auto names = r.choices_in<ContactArray>("contact_arrays", kContactArrayNames)) {
    o.contact_arrays = ArraySet<ContactArray>::none();
    for (ContactArray a : *names) o.contact_arrays.add(a);
  }
  r.reject_unknown_keys();
  return o;
}

}  // namespace tridem::scene_detail
