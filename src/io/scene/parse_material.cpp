// [[material]] blocks and the by-name lookup that triangles and generators use.
#include "io/scene/scene_sections.hpp"

#include <fmt/format.h>

namespace tridem::scene_detail {
namespace {

// The cohesive bond keys (docs/fracture.md): all or none, so that a bonded [[mesh]] never
// runs on a default strength.
void read_bond_properties(TableReader& r, Material& m) {
  struct Key {
    const char* name;
    double* value;
    const char* unit;
    bool may_be_zero;
  };
  const Key keys[] = {{"young_modulus", &m.young_modulus, "Pa", false},
                      {"tensile_strength", &m.tensile_strength, "Pa", false},
                      {"shear_strength", &m.shear_strength, "Pa", false},
                      {"friction_angle", &m.friction_angle, "degrees", true},
                      {"fracture_energy", &m.fracture_energy, "J/m^2", false},
                      {"shear_fracture_energy", &m.shear_fracture_energy, "J/m^2", false}};
  const char* given = nullptr;
  const char* missing = nullptr;
  for (const Key& k : keys) {
    const std::optional<double> v = r.real(k.name);
    if (!v) {
      if (!missing) missing = k.name;
      continue;
    }
    if (!given) given = k.name;
    if (!(*v > 0 || (k.may_be_zero && *v == 0)))
      r.fail(k.name,
             fmt::format("must be {} ({}), got {}", k.may_be_zero ? ">= 0" : "> 0", k.unit, *v));
    *k.value = *v;
  }
  if (given && missing)
    r.fail(given, fmt::format("a bonded material needs all of young_modulus, tensile_strength, "
                              "shear_strength, friction_angle, fracture_energy and "
                              "shear_fracture_energy; {} is missing",
                              missing));
  if (m.friction_angle >= 90)
    r.fail("friction_angle", fmt::format("must be below 90 degrees, got {}", m.friction_angle));
}

}  // namespace

Material parse_material(const toml::table& table, const std::string& source, std::size_t number,
                        const std::vector<Material>& earlier) {
  TableReader r(table, source, fmt::format("[[material]] #{}", number));
  Material m;
  m.name = r.required(r.string("name"), "name");
  if (m.name.empty()) r.fail("name", "must not be empty");
  for (const Material& e : earlier)
    if (e.name == m.name) r.fail("name", fmt::format("duplicate material name \"{}\"", m.name));
  m.density = r.required(r.real("density"), "density");
  if (!(m.density > 0)) r.fail("density", fmt::format("must be > 0 (kg/m^3), got {}", m.density));
  m.penalty = r.required(r.real("penalty"), "penalty");
  if (!(m.penalty > 0)) r.fail("penalty", fmt::format("must be > 0 (Pa), got {}", m.penalty));
  m.friction = r.real("friction").value_or(0.0);
  if (!(m.friction >= 0)) r.fail("friction", fmt::format("must be >= 0, got {}", m.friction));
  // `restitution` is the input; `damping` (ζ) stays readable for older scenes. One of them.
  const std::optional<double> restitution = r.real("restitution");
  const std::optional<double> damping = r.real("damping");
  if (restitution && damping)
    r.fail("damping", "give either restitution or damping, not both (restitution replaces "
                      "damping; see docs/scene-format.md)");
  m.restitution = restitution;
  if (m.restitution && !(*m.restitution > 0 && *m.restitution <= 1))
    r.fail("restitution", fmt::format("must be in (0, 1], got {}", *m.restitution));
  m.damping = damping.value_or(0.0);
  if (!(m.damping >= 0 && m.damping < 1))
    r.fail("damping", fmt::format("must be in [0, 1), got {}", m.damping));
  m.tangential_penalty = r.real("tangential_penalty").value_or(0.1 * m.penalty);
  if (!(m.tangential_penalty > 0))
    r.fail("tangential_penalty", fmt::format("must be > 0 (Pa), got {}", m.tangential_penalty));
  read_bond_properties(r, m);
  r.reject_unknown_keys();
  return m;
}

int lookup_material(TableReader& reader, const std::vector<Material>& materials) {
  const std::string name = reader.required(reader.string("material"), "material");
  std::string known;
  for (std::size_t i = 0; i < materials.size(); ++i) {
    if (materials[i].name == name) return static_cast<int>(i);
    known += fmt::format("{}\"{}\"", known.empty() ? "" : ", ", materials[i].name);
  }
  reader.fail("material",
              fmt::format("unknown material \"{}\" (defined: {})", name, known));
}

}  // namespace tridem::scene_detail
