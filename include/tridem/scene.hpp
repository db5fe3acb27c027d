#pragma once
// The validated description of a simulation, as read from a scene file (io/scene) or
// built in code by tests and benchmarks. Everything here is in SI units, double precision,
// per unit thickness (2D): densities in kg/m³ give masses in kg/m.
#include "tridem/motion_program.hpp"
#include "tridem/vec2.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace tridem {

enum class Backend { Auto, Cpu, OpenMP, Cuda };
enum class Precision { Double, Float };
/// The precision whose pairs compute in Real.
template <class Real>
inline constexpr Precision kPrecisionOf = sizeof(Real) == sizeof(float) ? Precision::Float
                                                                        : Precision::Double;
/// How the pairs that get a force are found. grid and all-pairs list every pair whose
/// boxes overlap and give the same physics; single-domain (the paper's single-core
/// baseline: every pair tested) and decomposition (the paper's sub-domains) list only the
/// pairs that pass the contact test (ContactTest).
enum class Method { Grid, AllPairs, SingleDomain, Decomposition };
/// The test the paper's methods use to decide which pairs get a force: the exact overlap
/// (separating axes; then they agree with grid) or the paper's direct area method (a
/// vertex of one triangle inside the other), which misses edge-crossing overlaps.
enum class ContactTest { Exact, DirectArea };
/// How the decomposition method cuts the domain: strips along x (the paper's 1D) or a
/// grid of rows × columns (2D).
enum class DecompositionLayout { Strips, Grid };

/// [simulation.decomposition]: read here, used only by method = decomposition.
struct DecompositionSettings {
  DecompositionLayout layout = DecompositionLayout::Strips;
  int rows = 0;        ///< 2D: initial sub-domain rows; 0 = chosen from the particle counts
  int columns = 0;     ///< 2D: initial sub-domain columns; 0 = chosen likewise
  int capacity = 256;  ///< most particles in a sub-domain, its overlap band included; >= 2
};

struct Material {
  std::string name;
  double density = 0;             ///< kg/m³
  double penalty = 0;             ///< normal penalty p, Pa
  double tangential_penalty = 0;  ///< friction spring p_t, Pa (reader default 0.1·p)
  double friction = 0;            ///< Coulomb μ
  /// Coefficient of restitution e in (0, 1] of an impact of two grains of this material,
  /// whatever the contact's shape; absent: set by `damping`.
  std::optional<double> restitution;
  double damping = 0;  ///< legacy: the face-contact damping ratio ζ in [0, 1) (e = exp(−πζ/√(1−ζ²)))
  /// Cohesive bonds of a bonded [[mesh]] (docs/fracture.md); 0 = not given (a material
  /// without them cannot be bonded).
  double young_modulus = 0;          ///< E, Pa: sets the bonds' stiffness
  double tensile_strength = 0;       ///< f_t, Pa
  double shear_strength = 0;         ///< cohesion c, Pa
  double friction_angle = 0;         ///< phi, degrees: shear strength c + sigma tan(phi)
  double fracture_energy = 0;        ///< G_I, J/m²
  double shear_fracture_energy = 0;  ///< G_II, J/m²

  /// True when every bond property is given (the reader refuses a partial set).
  bool bondable() const { return young_modulus > 0; }
};

/// How a triangle moves: by forces, not at all, or at a prescribed constant velocity.
enum class Motion : std::uint8_t { Free = 0, Fixed = 1, Prescribed = 2 };

struct TriangleSpec {
  int material = 0;                    ///< index into Scene::materials
  std::array<Vec2d, 3> vertices{};     ///< any orientation; the solver makes them CCW
  Vec2d velocity{};                    ///< of the centroid, m/s
  double angular_velocity = 0;         ///< rad/s, about the centroid
  Motion motion = Motion::Free;
  /// Prescribed only: index into Scene::programs of its motion program; -1 = none (it
  /// moves at its constant velocity).
  std::int32_t program = -1;
};

/// A rigid body of several triangles ([[body]]): its members are Scene::triangles
/// [first, first + count), which move as one (one mass, one inertia, one pose) and never
/// touch each other. The members' own velocity and motion are ignored; the body's apply.
struct BodySpec {
  std::size_t first = 0, count = 0;
  Vec2d velocity{};             ///< of the body's centroid, m/s
  double angular_velocity = 0;  ///< rad/s, about the body's centroid
  Motion motion = Motion::Free;
  std::int32_t program = -1;  ///< as TriangleSpec::program
};

/// A cohesive bond between two triangles of a bonded [[mesh]] that share an edge
/// (physics/cohesive_bond.hpp): a < b, the edge's ends as in the scene (at the start).
struct BondSpec {
  std::size_t a = 0, b = 0;
  Vec2d p{}, q{};
};

/// One periodic direction of the cell: [lo, hi), of length hi − lo.
struct PeriodicRange {
  double lo = 0, hi = 0;
  double length() const { return hi - lo; }
};

/// Periodic boundaries (docs/scene-format.md, "Periodic boundaries"): a particle leaving
/// through one side enters at the other, and pairs see each other through the boundary.
/// With shear_rate != 0 (both directions periodic), Lees-Edwards boundaries: the images
/// one period above move at shear_rate · (y1 − y0) along x, shifted by that speed · t.
struct PeriodicCell {
  std::optional<PeriodicRange> x, y;
  double shear_rate = 0;  ///< 1/s; Lees-Edwards simple shear, d(vx)/dy; 0 = off
  bool any() const { return x.has_value() || y.has_value(); }
};

struct SimulationSettings {
  /// The run's length: `steps`, or, when `duration` > 0 (the key `time`), the steps that
  /// reach that simulated time once dt is known (steps_to_reach, core/time_step.hpp).
  std::int64_t steps = 0;
  double duration = 0;                 ///< [simulation] time, s; 0 = the run is `steps` long
  std::optional<double> dt;            ///< unset: dt = safety · dt_crit
  double safety = 0.1;                 ///< fraction of dt_crit used when dt is unset
  Vec2d gravity{};
  Backend backend = Backend::Auto;
  Precision precision = Precision::Double;
  Method method = Method::Grid;
  /// single-domain and decomposition only (other methods refuse a non-default value).
  ContactTest contact_test = ContactTest::Exact;
  /// single-domain and decomposition only: the paper's bounding-box test before the
  /// contact test. It changes no result, only the time spent.
  bool bbox_prefilter = true;
  DecompositionSettings decomposition;
  double local_damping = 0;            ///< Cundall's α in [0, 1); 0 = off
  /// Verlet skin of the CUDA pair list (and CPU MPI ranks', docs/scaling.md), per side of a
  /// box, as a fraction of the grid cell L: rebuilt only when a box leaves its grown copy.
  double skin = 0.05;
  /// Deepest overlap accepted, as φ of the deepest boundary point (0 at the edge, 1 at
  /// the centroid); deeper stops the run as a blow-up. 1 = off.
  double max_penetration = 0.8;
  /// Overlapping triangles in the scene are refused; true pushes them apart before the run
  /// instead, moving positions only (core/initial_overlaps.hpp).
  bool relax_overlaps = false;
  PeriodicCell periodic;  ///< periodic_x, periodic_y, shear_rate; none by default
};

/// How VTK XML arrays are stored: base64 inline (compact), text (greppable), or their raw
/// bytes after the XML in one <AppendedData encoding="raw"> block (VTK's appended format:
/// a quarter smaller than base64 and nothing to encode).
enum class Encoding { Binary, Ascii, Appended };
/// The type of the real-valued arrays of frames: 4 bytes (what a picture needs) or 8 (the
/// simulator's doubles, exactly). The time of a frame is always a double.
enum class VtkPrecision { Float32, Float64 };
/// Binary arrays compressed as VTK's vtkZLibDataCompressor does, or stored as they are, or
/// compressed as its vtkLZMADataCompressor does (some 27 % smaller than zlib in a dense
/// pile's frames, 3.6 times the writing time; ParaView 5.6 and later read it).
/// Text arrays are never compressed.
enum class VtkCompression { Zlib, None, Lzma };

/// Everything that decides how a VTK XML file's arrays are written.
struct VtkFormat {
  Encoding encoding = Encoding::Binary;
  VtkPrecision precision = VtkPrecision::Float32;
  VtkCompression compression = VtkCompression::Zlib;
  bool compressed() const {
    return encoding != Encoding::Ascii && compression != VtkCompression::None;
  }
};

/// The cell arrays of a frame (.vtu) that `[output] frame_arrays` chooses among: the real
/// fields, most of a frame's bytes. The geometry and `id`, `material`, `motion` and `body`
/// (a few bytes a triangle after compression) are always written.
enum class FrameArray : std::uint8_t {
  Velocity,
  AngularVelocity,
  Force,
  Torque,
  Stress,
  Pressure,
  Coordination,
  Count  ///< how many there are; not an array
};
/// The cell arrays of a contact network (.vtp) that `[output] contact_arrays` chooses
/// among; its lines (the pairs) are always written.
enum class ContactArray : std::uint8_t {
  Force,
  Magnitude,
  Normal,
  NormalForce,
  TangentialForce,
  Sliding,
  Depth,
  Count  ///< how many there are; not an array
};

/// Which of an enumeration's arrays a file carries, as one bit each: all by default.
template <class E>
struct ArraySet {
  std::uint32_t bits = (1u << static_cast<unsigned>(E::Count)) - 1u;
  static ArraySet none() { return ArraySet{0u}; }
  bool has(E e) const { return (bits >> static_cast<unsigned>(e) & 1u) != 0; }
  void add(E e) { bits |= 1u << static_cast<unsigned>(e); }
  // Spelt out: the CUDA sources that include this header are C++17.
  bool operator==(const ArraySet& o) const { return bits == o.bits; }
};

/// The region of a [[measure]]: an axis-aligned rectangle, lo < hi in both coordinates.
struct MeasureRegion {
  Vec2d lo{}, hi{};
  double area() const { return (hi.x - lo.x) * (hi.y - lo.y); }
  bool contains(Vec2d p) const { return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y; }
};

/// A [[measure]] table: averages over a region (docs/experiments.md, "Measurements")
/// logged to a CSV of the output directory, one row per logged step.
struct MeasureSpec {
  std::string name;                     ///< letters, digits, '_' and '-'; unique among the measures
  std::optional<MeasureRegion> region;  ///< absent: the whole domain (every free particle)
  /// Steps between rows (besides the last step); unset = [output] energy_every (its
  /// default included: log_every()); 0 = the last step only.
  std::optional<std::int64_t> every;
  std::string file;  ///< in the output directory; empty = measure_<name>.csv

  std::string file_name() const { return file.empty() ? "measure_" + name + ".csv" : file; }
};

struct OutputSettings {
  std::string dir = "out";
  std::int64_t every = 0;              ///< steps between frames; 0 = no frames
  bool contacts = true;                ///< write the contact network with each frame
  /// ... also as contacts/*.csv (text, 17 digits: most of a frame's bytes), besides .vtp
  bool contacts_csv = true;
  Encoding encoding = Encoding::Binary; ///< of the .vtu/.vtp frames
  VtkPrecision precision = VtkPrecision::Float32;     ///< of their real arrays
  VtkCompression compression = VtkCompression::Zlib;  ///< of their binary arrays
  /// The real fields the frames carry (`frame_arrays`; all by default). The grain's
  /// stress, pressure and coordination also need `contacts`.
  ArraySet<FrameArray> frame_arrays;
  ArraySet<ContactArray> contact_arrays;  ///< of the contact networks (`contact_arrays`)
  std::int64_t checkpoint_every = 0;   ///< steps between checkpoints; 0 = none
  /// Steps between rows of energy.csv and walls.csv (besides step 0 and the last step);
  /// unset = `every`, 0 = only those two.
  std::optional<std::int64_t> energy_every;

  std::int64_t log_every() const { return energy_every.value_or(every); }
  VtkFormat vtk_format() const { return {encoding, precision, compression}; }

  std::vector<MeasureSpec> measures;  ///< the [[measure]] tables, in file order
  std::int64_t measure_every(const MeasureSpec& m) const { return m.every.value_or(log_every()); }
};

struct Scene {
  std::string source;                  ///< file it came from, for messages
  SimulationSettings simulation;
  OutputSettings output;
  std::vector<Material> materials;
  std::vector<TriangleSpec> triangles; ///< explicit ones in file order, then generated
  /// Empty: every triangle is a body of its own (every scene without [[body]]). Otherwise
  /// one entry per body in id order ([[triangle]]s and [[body]]s in file order, then the
  /// generated triangles, one body each), covering `triangles` contiguously in order.
  std::vector<BodySpec> bodies;
  /// The walls' motion programs (`program = {...}` of a [[triangle]] or [[body]]), one per
  /// programmed wall, in the order of their walls; `origin` is filled by the particle
  /// model. The velocity tables' entries are `program_knots`.
  std::vector<MotionProgram> programs;
  std::vector<ProgramKnot> program_knots;
  /// Cohesive bonds (bonded [[mesh]]es), by ascending (a, b); empty for every other scene.
  std::vector<BondSpec> bonds;

  /// True when some body has more than one member.
  bool has_bodies() const {
    for (const BodySpec& b : bodies)
      if (b.count > 1) return true;
    return false;
  }
};

}  // namespace tridem
