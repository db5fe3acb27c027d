#pragma once
// How the enumerated settings are spelt, in scene files, on the command line, in messages
// and in a solver's description: one table each, so that a name means the same thing
// everywhere. Nothing else spells an enumerator: code that prints or reads one uses these.
#include "tridem/generate.hpp"
#include "tridem/render.hpp"
#include "tridem/scene.hpp"
#include "tridem/solver.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace tridem {

template <class E, std::size_t N>
using Spellings = std::array<std::pair<std::string_view, E>, N>;

inline constexpr Spellings<Backend, 4> kBackendNames{{{"auto", Backend::Auto},
                                                   {"cpu", Backend::Cpu},
                                                   {"openmp", Backend::OpenMP},
                                                   {"cuda", Backend::Cuda}}};

inline constexpr Spellings<Precision, 2> kPrecisionNames{
    {{"double", Precision::Double}, {"float", Precision::Float}}};

inline constexpr Spellings<Method, 4> kMethodNames{{{"grid", Method::Grid},
                                                 {"all-pairs", Method::AllPairs},
                                                 {"single-domain", Method::SingleDomain},
                                                 {"decomposition", Method::Decomposition}}};

inline constexpr Spellings<ContactTest, 2> kContactTestNames{
    {{"exact", ContactTest::Exact}, {"direct-area", ContactTest::DirectArea}}};

inline constexpr Spellings<GrainNumbering, 2> kGrainNumberingNames{
    {{"placement", GrainNumbering::Placement}, {"space", GrainNumbering::Space}}};

inline constexpr Spellings<ParticleOrder, 3> kParticleOrderNames{{{"auto", ParticleOrder::Auto},
                                                                  {"scene", ParticleOrder::Scene},
                                                                  {"place", ParticleOrder::Place}}};

inline constexpr Spellings<DecompositionLayout, 2> kLayoutNames{
    {{"1d", DecompositionLayout::Strips}, {"2d", DecompositionLayout::Grid}}};

inline constexpr Spellings<Encoding, 3> kEncodingNames{
    {{"binary", Encoding::Binary}, {"ascii", Encoding::Ascii}, {"appended", Encoding::Appended}}};

inline constexpr Spellings<VtkPrecision, 2> kVtkPrecisionNames{
    {{"float32", VtkPrecision::Float32}, {"double", VtkPrecision::Float64}}};

inline constexpr Spellings<VtkCompression, 3> kVtkCompressionNames{
    {{"zlib", VtkCompression::Zlib},
     {"none", VtkCompression::None},
     {"lzma", VtkCompression::Lzma}}};

/// `[output] frame_arrays`: the arrays' names in the .vtu.
inline constexpr Spellings<FrameArray, 7> kFrameArrayNames{
    {{"velocity", FrameArray::Velocity},
     {"angular_velocity", FrameArray::AngularVelocity},
     {"force", FrameArray::Force},
     {"torque", FrameArray::Torque},
     {"stress", FrameArray::Stress},
     {"pressure", FrameArray::Pressure},
     {"coordination", FrameArray::Coordination}}};

/// `[output] contact_arrays`: the arrays' names in the .vtp.
inline constexpr Spellings<ContactArray, 7> kContactArrayNames{
    {{"force", ContactArray::Force},
     {"magnitude", ContactArray::Magnitude},
     {"normal", ContactArray::Normal},
     {"normal_force", ContactArray::NormalForce},
     {"tangential_force", ContactArray::TangentialForce},
     {"sliding", ContactArray::Sliding},
     {"depth", ContactArray::Depth}}};

inline constexpr Spellings<Motion, 3> kMotionNames{
    {{"free", Motion::Free}, {"fixed", Motion::Fixed}, {"prescribed", Motion::Prescribed}}};

/// A wall's `program = { kind = ... }`.
inline constexpr Spellings<ProgramKind, 4> kProgramKindNames{
    {{"rotation", ProgramKind::Rotation},
     {"table", ProgramKind::Table},
     {"oscillation", ProgramKind::Oscillation},
     {"servo", ProgramKind::Servo}}};

/// tridem render --color.
inline constexpr Spellings<RenderOptions::ColorBy, 3> kColorByNames{
    {{"speed", RenderOptions::ColorBy::Speed},
     {"material", RenderOptions::ColorBy::Material},
     {"body", RenderOptions::ColorBy::Body}}};

/// The spelling of `value` in `table` (every enumerator has one).
template <class Table, class E>
constexpr std::string_view name_in(const Table& table, E value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "?";
}

/// The enumerator spelt `name`, or nothing.
template <class Table>
constexpr auto value_in(const Table& table, std::string_view name)
    -> std::optional<typename Table::value_type::second_type> {
  for (const auto& [spelling, v] : table)
    if (spelling == name) return v;
  return std::nullopt;
}

/// Every spelling of `table` in quotes, comma-separated: for messages and --help.
template <class Table>
std::string spellings_of(const Table& table) {
  std::string out;
  for (const auto& entry : table)
    out += (out.empty() ? "\"" : ", \"") + std::string(entry.first) + "\"";
  return out;
}

inline std::string_view backend_name(Backend b) { return name_in(kBackendNames, b); }
inline std::string_view precision_name(Precision p) { return name_in(kPrecisionNames, p); }
inline std::string_view method_name(Method m) { return name_in(kMethodNames, m); }
inline std::string_view contact_test_name(ContactTest t) { return name_in(kContactTestNames, t); }

/// The precision as a solver describes itself: float is the mixed mode, double state and
/// float pairs (docs/model.md, "Precision").
inline std::string precision_description(Precision p) {
  return std::string(precision_name(p)) + (p == Precision::Float ? " (double state)" : "");
}

/// The method with the settings that matter to it, for descriptions: "grid", or
/// "single-domain (contact test exact, bbox pre-filter on)".
inline std::string method_description(Method method, ContactTest test, bool bbox_prefilter) {
  std::string out(method_name(method));
  if (method == Method::SingleDomain || method == Method::Decomposition)
    out += " (contact test " + std::string(contact_test_name(test)) + ", bbox pre-filter " +
           (bbox_prefilter ? "on" : "off") + ")";
  return out;
}

/// Why the contact test and pre-filter settings cannot go with `method`, or nothing when
/// they can. They belong to the paper's methods; the others list every box-overlapping
/// pair, and silently ignoring a direct-area test there would give other physics than
/// the user asked for.
inline std::optional<std::string> method_settings_conflict(Method method, ContactTest test,
                                                           bool bbox_prefilter) {
  if (method == Method::SingleDomain || method == Method::Decomposition) return std::nullopt;
  const std::string paper = "used only by method \"single-domain\" or \"decomposition\"";
  if (test != ContactTest::Exact)
    return "contact_test = \"" + std::string(contact_test_name(test)) + "\" is " + paper +
           ", not \"" + std::string(method_name(method)) +
           "\" (which computes every pair whose boxes overlap): remove it or change the method";
  if (!bbox_prefilter)
    return "bbox_prefilter = false is " + paper + ", not \"" + std::string(method_name(method)) +
           "\" (whose broad phase is a bounding-box test): remove it or change the method";
  return std::nullopt;
}

}  // namespace tridem
