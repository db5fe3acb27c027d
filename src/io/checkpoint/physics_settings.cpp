// physics_settings: the settings a checkpoint keeps so that a restart cannot silently go on
// with other physics. A setting belongs here when changing it changes the trajectory; the
// ones that only change speed or bookkeeping (backend, skin, decomposition layout, output)
// do not, so that a CPU checkpoint may continue on the GPU, for instance.
#include "core/particle_model.hpp"
#include "tridem/checkpoint.hpp"
#include "tridem/error.hpp"
#include "tridem/setting_names.hpp"

#include <fmt/format.h>
#include <optional>
#include <string>
#include <utility>

namespace tridem {

std::vector<PhysicsSetting> physics_settings(const Scene& scene, double dt) {
  const SimulationSettings& s = scene.simulation;
  // "{}" prints the shortest text that reads back to the same double, so equal text means
  // an equal value.
  std::vector<PhysicsSetting> out = {
      {"[simulation] method", std::string(method_name(s.method))},
      {"[simulation] contact_test", std::string(contact_test_name(s.contact_test))},
      {"[simulation] bbox_prefilter", s.bbox_prefilter ? "true" : "false"},
      {"[simulation] dt", fmt::format("{}", dt)},
      {"[simulation] gravity", fmt::format("[{}, {}]", s.gravity.x, s.gravity.y)},
      {"[simulation] local_damping", fmt::format("{}", s.local_damping)},
      {"[simulation] max_penetration", fmt::format("{}", s.max_penetration)},
  };
  // The periodic cell only where there is one: every other scene's settings are unchanged.
  // A resumed run must wrap, image and shear as the checkpointed one did.
  const PeriodicCell& cell = scene.simulation.periodic;
  if (cell.any()) {
    const auto range = [](const std::optional<PeriodicRange>& r) {
      return r ? fmt::format("[{}, {}]", r->lo, r->hi) : std::string("none");
    };
    out.push_back({"[simulation] periodic_x", range(cell.x)});
    out.push_back({"[simulation] periodic_y", range(cell.y)});
    out.push_back({"[simulation] shear_rate", fmt::format("{}", cell.shear_rate)});
  }
  for (const Material& m : scene.materials) {
    const std::string key = fmt::format("[[material]] \"{}\" ", m.name);
    out.push_back({key + "penalty", fmt::format("{}", m.penalty)});
    out.push_back({key + "tangential_penalty", fmt::format("{}", m.tangential_penalty)});
    out.push_back({key + "friction", fmt::format("{}", m.friction)});
    // The restitution the material gives, whether the scene says `restitution` or the
    // legacy `damping` (the contact law is built from this value alone).
    out.push_back({key + "restitution", fmt::format("{}", material_restitution(m))});
    // Bond properties only where given: the settings of every other scene are unchanged.
    if (m.bondable())
      for (const auto& [name, value] : {std::pair{"young_modulus", m.young_modulus},
                                        {"tensile_strength", m.tensile_strength},
                                        {"shear_strength", m.shear_strength},
                                        {"friction_angle", m.friction_angle},
                                        {"fracture_energy", m.fracture_energy},
                                        {"shear_fracture_energy", m.shear_fracture_energy}})
        out.push_back({key + name, fmt::format("{}", value)});
  }
  return out;
}

void check_physics_settings(const std::vector<PhysicsSetting>& stored,
                            const std::vector<PhysicsSetting>& current,
                            const std::string& file) {
  const auto find = [](const std::vector<PhysicsSetting>& list, const std::string& key) {
    for (const PhysicsSetting& s : list)
      if (s.key == key) return &s;
    return static_cast<const PhysicsSetting*>(nullptr);
  };
  const char* advice =
      "restart with the settings the checkpoint was written with (scene and command line), "
      "or start a new run";
  for (const PhysicsSetting& now : current) {
    const PhysicsSetting* then = find(stored, now.key);
    if (!then)
      throw RunError(fmt::format("{}: the checkpoint does not record {} (this run: {}); it "
                                 "was written by another tridem or for other materials; {}",
                                 file, now.key, now.value, advice));
    if (then->value != now.value)
      throw RunError(fmt::format("{}: the checkpoint was written with {} = {}, this run has "
                                 "{}; {}",
                                 file, now.key, then->value, now.value, advice));
  }
  for (const PhysicsSetting& then : stored)
    if (!find(current, then.key))
      throw RunError(fmt::format("{}: the checkpoint was written with {} = {}, which this "
                                 "run does not have; {}",
                                 file, then.key, then.value, advice));
}

}  // namespace tridem
