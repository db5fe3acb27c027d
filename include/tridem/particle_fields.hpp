#pragma once
// The per-particle state, described once. Every place that holds, moves or counts a
// particle's data is generated from the lists below: CpuSolver's host vectors, the CUDA
// solver's device buffers and the ParticleArrays its kernels receive, Snapshot,
// SolverState, the checkpoint layout and its checks, and the memory estimate
// (core/memory_estimate.hpp). Adding a field is one line here plus its physics
// (ARCHITECTURE.md, "Adding a per-particle field"); per-body and per-bond state get lists
// of their own in the same form, as the contact history already has (pair_field).
//
// Each entry is F(member, name, Type, count, Role, initial, labels):
//   member   the solvers' name (CpuSolver's member_, ParticleArrays::member) and the tag
//            type particle_field::member that generic code passes around
//   name     the public name (Snapshot, SolverState, messages)
//   Type     double, Real (the solver's precision: pairs and forces), int, Motion, uint8_t
//   count    arrays per particle: 1, or 3 for a vertex coordinate, 4 energy sums
//   Role     FieldRole: what the solvers do with it
//   initial  its value at the start of a run: an expression of the ParticleModel m, the
//            particle i and the array k, expanded only inside the solvers
//   labels   nullptr, or count names for messages (otherwise name[k])
// The lists are in checkpoint order: format version 4 fixes the State fields, then the Sum
// fields (io/checkpoint/format.hpp asserts it).
//
// C++17: the CUDA sources include it.
#include "tridem/energy_budget.hpp"
#include "tridem/scene.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

namespace tridem {

/// What the solvers do with a field.
enum class FieldRole : std::uint8_t {
  Model,     ///< fixed for the run, built from the scene's ParticleModel
  State,     ///< advanced by the integrator, double in every precision; checkpointed, shown
  Force,     ///< recomputed every step from the state; shown; zero after a restart
  Sum,       ///< cumulative over the run; checkpointed (an empty array reads as zeros)
  Geometry,  ///< derived from model and state by each step's geometry stage
  Scratch,   ///< working memory of one stage
};

/// Roles a checkpoint (SolverState) stores, and roles a Snapshot shows.
constexpr bool is_checkpointed(FieldRole r) { return r == FieldRole::State || r == FieldRole::Sum; }
constexpr bool is_shown(FieldRole r) { return r == FieldRole::State || r == FieldRole::Force; }

// clang-format off
#define TRIDEM_MODEL_FIELDS(F)                                                               \
  /* body-frame vertex offsets about the centroid, counter-clockwise */                      \
  F(offset_x, offset_x, Real, 3, Model, static_cast<Real>(m.offsets[i][k].x), nullptr)       \
  F(offset_y, offset_y, Real, 3, Model, static_cast<Real>(m.offsets[i][k].y), nullptr)       \
  /* the integration is double in every precision; 0 for walls */                            \
  F(inv_mass, inv_mass, double, 1, Model,                                                    \
    m.motion[i] == Motion::Free ? 1.0 / m.mass[i] : 0.0, nullptr)                            \
  F(inv_inertia, inv_inertia, double, 1, Model,                                              \
    m.motion[i] == Motion::Free ? 1.0 / m.inertia[i] : 0.0, nullptr)                         \
  /* 0 for walls: a pair's effective mass */                                                 \
  F(mass, mass, Real, 1, Model,                                                              \
    m.motion[i] == Motion::Free ? static_cast<Real>(m.mass[i]) : Real(0), nullptr)           \
  F(area, area, Real, 1, Model, static_cast<Real>(m.area[i]), nullptr)                       \
  F(half_size, half_size, Real, 1, Model, static_cast<Real>(0.5 * m.longest_edge[i]), nullptr) \
  F(material, material, int, 1, Model, m.material[i], nullptr)                               \
  F(motion, motion, Motion, 1, Model, m.motion[i], nullptr)                                 \
  /* index of its motion program (physics/motion_program.hpp), -1 = none */                  \
  F(program, program, std::int32_t, 1, Model, m.program[i], nullptr)

#define TRIDEM_STATE_FIELDS(F)                                                               \
  F(x, x, double, 1, State, m.centroid[i].x, nullptr)                                        \
  F(y, y, double, 1, State, m.centroid[i].y, nullptr)                                        \
  F(theta, theta, double, 1, State, 0.0, nullptr)                                            \
  F(vx, vx, double, 1, State, m.velocity[i].x, nullptr)                                      \
  F(vy, vy, double, 1, State, m.velocity[i].y, nullptr)                                      \
  F(w, omega, double, 1, State, m.angular_velocity[i], nullptr)

/* the total contact force and torque of the last step */
#define TRIDEM_FORCE_FIELDS(F)                                                               \
  F(fx, fx, Real, 1, Force, Real(0), nullptr)                                                \
  F(fy, fy, Real, 1, Force, Real(0), nullptr)                                                \
  F(torque, torque, Real, 1, Force, Real(0), nullptr)

/* the energy budget's cumulative sums (EnergyAccumulator order), in double whatever Real
   is: they add small amounts to a growing total for the whole run */
#define TRIDEM_SUM_FIELDS(F)                                                                 \
  F(energy, energy, double, kEnergyAccumulators, Sum, 0.0, kEnergyAccumulatorNames)

/* vertices relative to the centroid, and the absolute bounding box */
#define TRIDEM_GEOMETRY_FIELDS(F)                                                            \
  F(rel_x, rel_x, Real, 3, Geometry, Real(0), nullptr)                                       \
  F(rel_y, rel_y, Real, 3, Geometry, Real(0), nullptr)                                       \
  F(lo_x, lo_x, Real, 1, Geometry, Real(0), nullptr)                                         \
  F(lo_y, lo_y, Real, 1, Geometry, Real(0), nullptr)                                         \
  F(hi_x, hi_x, Real, 1, Geometry, Real(0), nullptr)                                         \
  F(hi_y, hi_y, Real, 1, Geometry, Real(0), nullptr)

/// Every field both backends keep.
#define TRIDEM_PARTICLE_FIELDS(F)                                                            \
  TRIDEM_MODEL_FIELDS(F) TRIDEM_STATE_FIELDS(F) TRIDEM_FORCE_FIELDS(F) TRIDEM_SUM_FIELDS(F) \
  TRIDEM_GEOMETRY_FIELDS(F)

/* The CUDA solver's own: the free flag its kernels stage (1 for bodies moved by forces);
   the boxes of the last pair-list build, grown by the skin (until a grid build sets them
   they are the whole plane, so a single-domain solver, which never sets them, never asks
   for a rebuild); the elastic energy of each row, summed on the host at logging steps; a
   free particle's row energy of the step (RowEnergy: damping, friction, wall work), summed
   by the gather from the loads it reads and added by the integration if the step is
   written. */
#define TRIDEM_GPU_ONLY_FIELDS(F)                                                            \
  F(free, free, std::uint8_t, 1, Model, m.motion[i] == Motion::Free, nullptr)                \
  F(build_lo_x, build_lo_x, Real, 1, Geometry, std::numeric_limits<Real>::lowest(), nullptr) \
  F(build_lo_y, build_lo_y, Real, 1, Geometry, std::numeric_limits<Real>::lowest(), nullptr) \
  F(build_hi_x, build_hi_x, Real, 1, Geometry, std::numeric_limits<Real>::max(), nullptr)    \
  F(build_hi_y, build_hi_y, Real, 1, Geometry, std::numeric_limits<Real>::max(), nullptr)    \
  F(row_elastic, row_elastic, double, 1, Scratch, 0.0, nullptr)                             \
  F(row_step_energy, row_step_energy, double, 3, Scratch, 0.0, nullptr)

#define TRIDEM_GPU_PARTICLE_FIELDS(F) TRIDEM_PARTICLE_FIELDS(F) TRIDEM_GPU_ONLY_FIELDS(F)

/// What SolverState (a checkpoint) holds and what a Snapshot shows: is_checkpointed and
/// is_shown as lists.
#define TRIDEM_CHECKPOINTED_FIELDS(F) TRIDEM_STATE_FIELDS(F) TRIDEM_SUM_FIELDS(F)
#define TRIDEM_SHOWN_FIELDS(F) TRIDEM_STATE_FIELDS(F) TRIDEM_FORCE_FIELDS(F)
// clang-format on

/// The field descriptors: one tag type per field, carrying its role, count, names, element
/// type and initial value, so that generic code (`[](auto field) {...}`) can branch on them
/// at compile time.
namespace particle_field {

#define TRIDEM_FIELD_TAG(member_, name_, Type_, count_, Role_, initial_, labels_)            \
  struct member_ {                                                                           \
    static constexpr FieldRole role = FieldRole::Role_;                                      \
    static constexpr int count = count_;                                                     \
    static constexpr const char* name = #name_;                                              \
    template <class Real>                                                                    \
    using type = Type_;                                                                      \
    /** The value of array k of particle i at the start of a run. */                         \
    template <class Real, class Model>                                                       \
    static Type_ initial([[maybe_unused]] const Model& m, [[maybe_unused]] std::size_t i,    \
                         [[maybe_unused]] int k) {                                           \
      return initial_;                                                                       \
    }                                                                                        \
    static std::string label(int k) {                                                        \
      const char* const* labels = labels_;                                                   \
      if (labels) return labels[k];                                                          \
      return count_ == 1 ? std::string(#name_) : #name_ "[" + std::to_string(k) + "]";       \
    }                                                                                        \
  };
TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_FIELD_TAG)
// TRIDEM_FIELD_TAG stays defined: body_fields.hpp makes its tags with it.

}  // namespace particle_field

// Generators. Each expands one entry of a list inside a struct or function body.

/// The columns of a field in a storage whose one-array type is Column<T> (std::vector,
/// DeviceBuffer): Column<T>, or std::array of `count` of them.
template <template <class...> class Column, class T, int count>
using Columns = std::conditional_t<count == 1, Column<T>, std::array<Column<T>, count>>;

/// A view's pointer to a field (an array of `count` pointers): const for Model fields,
/// which no stage writes.
template <class Field, class Real>
using FieldPointer = std::conditional_t<Field::role == FieldRole::Model,
                                        const typename Field::template type<Real>*,
                                        typename Field::template type<Real>*>;
template <class Field, class Real>
using FieldPointers = std::conditional_t<Field::count == 1, FieldPointer<Field, Real>,
                                         FieldPointer<Field, Real>[Field::count]>;

template <class T>
struct is_std_array : std::false_type {};
template <class T, std::size_t N>
struct is_std_array<std::array<T, N>> : std::true_type {};

/// Calls g(array, k) for each of the `count` arrays of one field's columns (k = 0 for a
/// field of one array).
template <class Columns, class G>
void for_each_array(Columns& c, G&& g) {
  using Plain = std::remove_const_t<Columns>;
  if constexpr (std::is_array_v<Plain>) {
    for (int k = 0; k < static_cast<int>(std::extent_v<Plain>); ++k) g(c[k], k);
  } else if constexpr (is_std_array<Plain>::value) {
    for (int k = 0; k < static_cast<int>(std::tuple_size<Plain>::value); ++k) g(c[k], k);
  } else {
    g(c, 0);
  }
}

/// Array k of one field's columns (the columns themselves for a field of one array).
template <class T, std::size_t N>
T& array_at(std::array<T, N>& c, int k) {
  return c[static_cast<std::size_t>(k)];
}
template <class T, std::size_t N>
const T& array_at(const std::array<T, N>& c, int k) {
  return c[static_cast<std::size_t>(k)];
}
template <class Column>
Column& array_at(Column& c, int) {
  return c;
}

// Member declarations: storage of the solvers' member names (Column and Real in scope),
// storage suffixed by '_' (CpuSolver's members), public double columns (Snapshot,
// SolverState) and device views.
#define TRIDEM_DECLARE_COLUMNS(member_, name_, Type_, count_, Role_, initial_, labels_) \
  ::tridem::Columns<Column, Type_, count_> member_;
#define TRIDEM_DECLARE_MEMBER_COLUMNS(member_, name_, Type_, count_, Role_, initial_, labels_) \
  ::tridem::Columns<std::vector, Type_, count_> member_##_;
#define TRIDEM_DECLARE_PUBLIC_COLUMNS(member_, name_, Type_, count_, Role_, initial_, labels_) \
  ::tridem::Columns<std::vector, double, count_> name_;
#define TRIDEM_DECLARE_POINTERS(member_, name_, Type_, count_, Role_, initial_, labels_) \
  ::tridem::FieldPointers<::tridem::particle_field::member_, Real> member_;

// column(field): the columns of a field, by its tag, in each kind of storage.
#define TRIDEM_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, labels_) \
  auto& column(::tridem::particle_field::member_) { return member_; }                   \
  const auto& column(::tridem::particle_field::member_) const { return member_; }
#define TRIDEM_MEMBER_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, labels_) \
  auto& column(::tridem::particle_field::member_) { return member_##_; }                       \
  const auto& column(::tridem::particle_field::member_) const { return member_##_; }
#define TRIDEM_PUBLIC_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, labels_) \
  auto& column(::tridem::particle_field::member_) { return name_; }                            \
  const auto& column(::tridem::particle_field::member_) const { return name_; }

/// The members of a public struct of double columns for the fields of LIST (Snapshot,
/// SolverState): the columns under their public names, column(field), for_each_field(f)
/// in LIST's order, and the number of arrays per particle.
#define TRIDEM_PUBLIC_COLUMNS(LIST)                \
  LIST(TRIDEM_DECLARE_PUBLIC_COLUMNS)              \
  LIST(TRIDEM_PUBLIC_COLUMN_ACCESSOR)              \
  template <class F>                               \
  static void for_each_field(F&& f) {              \
    LIST(TRIDEM_VISIT_FIELD)                       \
  }                                                \
  static constexpr int kArraysPerParticle = 0 LIST(TRIDEM_PLUS_COUNT);

/// f(particle_field::member{}) for each entry.
#define TRIDEM_VISIT_FIELD(member_, name_, Type_, count_, Role_, initial_, labels_) \
  f(::tridem::particle_field::member_{});
/// + count, for counting arrays in a constant expression.
#define TRIDEM_PLUS_COUNT(member_, name_, Type_, count_, Role_, initial_, labels_) +count_

/// f(field) for every field both backends keep, for the Model fields among them, and for
/// every field of the CUDA solver.
template <class F>
void for_each_particle_field(F&& f) {
  TRIDEM_PARTICLE_FIELDS(TRIDEM_VISIT_FIELD)
}
template <class F>
void for_each_model_field(F&& f) {
  TRIDEM_MODEL_FIELDS(TRIDEM_VISIT_FIELD)
}
template <class F>
void for_each_gpu_particle_field(F&& f) {
  TRIDEM_GPU_PARTICLE_FIELDS(TRIDEM_VISIT_FIELD)
}

/// Bytes one particle takes in the fields f visits, for the solver precision Real.
template <class Real, class ForEach>
std::size_t bytes_per_particle(ForEach for_each) {
  std::size_t bytes = 0;
  for_each([&bytes](auto field) {
    using Field = decltype(field);
    bytes += Field::count * sizeof(typename Field::template type<Real>);
  });
  return bytes;
}

// The contact history a checkpoint carries, one entry per pair with history, in
// emitter-major, partner-ascending order: F(member, Type, count). A field of count > 1 is
// stored pair-major (std::array per pair), as the checkpoint file has it.
inline constexpr int kSlipsPerPair = 2;  ///< physics::kHistoryValues: u = √k_t·ξ (x, y)

// clang-format off
#define TRIDEM_PAIR_HISTORY_FIELDS(F) \
  F(pair_emitter, std::int32_t, 1)    \
  F(pair_partner, std::int32_t, 1)    \
  F(pair_slip, double, kSlipsPerPair)
// clang-format on

namespace pair_field {
#define TRIDEM_PAIR_FIELD_TAG(member_, Type_, count_) \
  struct member_ {                                    \
    static constexpr int count = count_;              \
    static constexpr const char* name = #member_;     \
    using type = Type_;                               \
  };
TRIDEM_PAIR_HISTORY_FIELDS(TRIDEM_PAIR_FIELD_TAG)
#undef TRIDEM_PAIR_FIELD_TAG
}  // namespace pair_field

/// One value per pair, or `count` of them together.
template <class T, int count>
using PairColumn = std::vector<std::conditional_t<count == 1, T, std::array<T, count>>>;

#define TRIDEM_DECLARE_PAIR_COLUMN(member_, Type_, count_) \
  ::tridem::PairColumn<Type_, count_> member_;
#define TRIDEM_PAIR_COLUMN_ACCESSOR(member_, Type_, count_)                  \
  auto& column(::tridem::pair_field::member_) { return member_; }             \
  const auto& column(::tridem::pair_field::member_) const { return member_; }
#define TRIDEM_VISIT_PAIR_FIELD(member_, Type_, count_) f(::tridem::pair_field::member_{});
#define TRIDEM_PAIR_BYTES(member_, Type_, count_) +count_ * sizeof(Type_)

template <class F>
void for_each_pair_history_field(F&& f) {
  TRIDEM_PAIR_HISTORY_FIELDS(TRIDEM_VISIT_PAIR_FIELD)
}

}  // namespace tridem
