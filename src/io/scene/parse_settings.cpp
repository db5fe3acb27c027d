// [simulation] and [output]. Defaults come from the structs in scene.hpp so that a scene
// built in code and one read from a file agree on them.
#include "io/scene/scene_sections.hpp"

#include <fmt/format.h>

namespace tridem::scene_detail {

SimulationSettings parse_simulation(const toml::table& table, const std::string& source) {
  TableReader r(table, source, "[simulation]");
  SimulationSettings s;
  s.steps = r.required(r.integer("steps"), "steps");
  if (s.steps <= 0) r.fail("steps", fmt::format("must be > 0, got {}", s.steps));
  if (auto dt = r.real("dt")) {
    if (!(*dt > 0)) r.fail("dt", fmt::format("must be > 0, got {} (omit dt for automatic)", *dt));
    s.dt = *dt;
  }
  s.safety = r.real("safety").value_or(s.safety);
  if (!(s.safety > 0 && s.safety <= 1))
    r.fail("safety", fmt::format("must be in (0, 1], got {}", s.safety));
  s.gravity = r.vec2("gravity").value_or(s.gravity);
  s.backend = r.choice<Backend>("backend", {{"auto", Backend::Auto},
                                            {"cpu", Backend::Cpu},
                                            {"openmp", Backend::OpenMP},
                                            {"cuda", Backend::Cuda}})
                  .value_or(s.backend);
  s.precision =
      r.choice<Precision>("precision", {{"double", Precision::Double}, {"float", Precision::Float}})
          .value_or(s.precision);
  s.method = r.choice<Method>("method", {{"grid", Method::Grid}, {"all-pairs", Method::AllPairs}})
                 .value_or(s.method);
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
  o.checkpoint_every = r.integer("checkpoint_every").value_or(o.checkpoint_every);
  if (o.checkpoint_every < 0)
    r.fail("checkpoint_every",
           fmt::format("must be >= 0 (0 = no periodic checkpoints), got {}", o.checkpoint_every));
  o.encoding = r.choice<Encoding>("vtk_encoding",
                                  {{"binary", Encoding::Binary}, {"ascii", Encoding::Ascii}})
                   .value_or(o.encoding);
  r.reject_unknown_keys();
  return o;
}

}  // namespace tridem::scene_detail
