#pragma once
// The per-body state of scenes with bodies of several triangles, described once in the
// form of particle_fields.hpp (same entry F(member, name, Type, count, Role, initial,
// labels), same tags and generators), so that the CUDA buffers, snapshots and checkpoints
// can be generated from these lists as the per-particle ones are. `initial` reads the
// BodyModel m (core/body_model.hpp): body b = i in the body lists, triangle i in the
// member list. The solvers keep these columns only when the scene has bodies.
//
// C++17: the CUDA sources may include it.
#include "tridem/particle_fields.hpp"

#include <cstdint>
#include <vector>

namespace tridem {

// clang-format off
#define TRIDEM_BODY_MODEL_FIELDS(F)                                                          \
  F(body_first, first, std::int64_t, 1, Model, m.first[i], nullptr)                          \
  F(body_last, last, std::int64_t, 1, Model, m.first[i + 1], nullptr)                        \
  F(body_inv_mass, inv_mass, double, 1, Model,                                               \
    m.motion[i] == Motion::Free ? 1.0 / m.mass[i] : 0.0, nullptr)                            \
  F(body_inv_inertia, inv_inertia, double, 1, Model,                                         \
    m.motion[i] == Motion::Free ? 1.0 / m.inertia[i] : 0.0, nullptr)                         \
  F(body_half_size, half_size, double, 1, Model, m.half_size[i], nullptr)                    \
  F(body_motion, motion, Motion, 1, Model, m.motion[i], nullptr)                            \
  F(body_program, program, std::int32_t, 1, Model, m.program[i], nullptr)

#define TRIDEM_BODY_STATE_FIELDS(F)                                                          \
  F(body_x, x, double, 1, State, m.centroid[i].x, nullptr)                                   \
  F(body_y, y, double, 1, State, m.centroid[i].y, nullptr)                                   \
  F(body_theta, theta, double, 1, State, 0.0, nullptr)                                       \
  F(body_vx, vx, double, 1, State, m.velocity[i].x, nullptr)                                 \
  F(body_vy, vy, double, 1, State, m.velocity[i].y, nullptr)                                 \
  F(body_w, omega, double, 1, State, m.angular_velocity[i], nullptr)

/* the members' contact forces summed, and their torque about the body's centroid */
#define TRIDEM_BODY_FORCE_FIELDS(F)                                                          \
  F(body_fx, fx, double, 1, Force, 0.0, nullptr)                                             \
  F(body_fy, fy, double, 1, Force, 0.0, nullptr)                                             \
  F(body_torque, torque, double, 1, Force, 0.0, nullptr)

#define TRIDEM_BODY_FIELDS(F)                                                                \
  TRIDEM_BODY_MODEL_FIELDS(F) TRIDEM_BODY_STATE_FIELDS(F) TRIDEM_BODY_FORCE_FIELDS(F)

/* What a Snapshot shows of each body (State and Force), and what a checkpoint stores */
#define TRIDEM_BODY_SHOWN_FIELDS(F) TRIDEM_BODY_STATE_FIELDS(F) TRIDEM_BODY_FORCE_FIELDS(F)
#define TRIDEM_BODY_CHECKPOINTED_FIELDS(F) TRIDEM_BODY_STATE_FIELDS(F)

/* per triangle: its body and its centroid's offset from the body's at theta = 0 */
#define TRIDEM_MEMBER_FIELDS(F)                                                              \
  F(member_body, body, std::int32_t, 1, Model, m.body[i], nullptr)                           \
  F(member_dx, member_dx, double, 1, Model, m.member_offset[i].x, nullptr)                   \
  F(member_dy, member_dy, double, 1, Model, m.member_offset[i].y, nullptr)
// clang-format on

namespace body_field {
TRIDEM_BODY_FIELDS(TRIDEM_FIELD_TAG)
TRIDEM_MEMBER_FIELDS(TRIDEM_FIELD_TAG)
}  // namespace body_field

#define TRIDEM_BODY_MEMBER_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, \
                                           labels_)                                        \
  auto& column(::tridem::body_field::member_) { return member_##_; }                       \
  const auto& column(::tridem::body_field::member_) const { return member_##_; }
#define TRIDEM_VISIT_BODY_FIELD(member_, name_, Type_, count_, Role_, initial_, labels_) \
  f(::tridem::body_field::member_{});

/// column(field) by the body_field tag in a storage of the solvers' member names (the CUDA
/// solver's device buffers and the kernels' view), and that view's pointers (const for
/// Model fields).
#define TRIDEM_BODY_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, labels_) \
  auto& column(::tridem::body_field::member_) { return member_; }                            \
  const auto& column(::tridem::body_field::member_) const { return member_; }
#define TRIDEM_DECLARE_BODY_POINTERS(member_, name_, Type_, count_, Role_, initial_, labels_) \
  ::tridem::FieldPointers<::tridem::body_field::member_, double> member_;

/// The members of a public struct of per-body double columns for the fields of LIST
/// (Snapshot, SolverState): body_<name> (body_x, ..., body_omega, body_fx, ...), column(field)
/// by the body_field tag, and for_each_body_column(f) in LIST's order.
#define TRIDEM_DECLARE_BODY_PUBLIC_COLUMN(member_, name_, Type_, count_, Role_, initial_, labels_) \
  std::vector<double> body_##name_;
#define TRIDEM_BODY_PUBLIC_COLUMN_ACCESSOR(member_, name_, Type_, count_, Role_, initial_, \
                                           labels_)                                        \
  auto& column(::tridem::body_field::member_) { return body_##name_; }                     \
  const auto& column(::tridem::body_field::member_) const { return body_##name_; }
#define TRIDEM_BODY_PUBLIC_COLUMNS(LIST)    \
  LIST(TRIDEM_DECLARE_BODY_PUBLIC_COLUMN)   \
  LIST(TRIDEM_BODY_PUBLIC_COLUMN_ACCESSOR)  \
  template <class F>                        \
  static void for_each_body_column(F&& f) { \
    LIST(TRIDEM_VISIT_BODY_FIELD)           \
  }

/// f(field) for every per-body field, and for every per-member (per-triangle) field.
template <class F>
void for_each_body_field(F&& f) {
  TRIDEM_BODY_FIELDS(TRIDEM_VISIT_BODY_FIELD)
}
template <class F>
void for_each_member_field(F&& f) {
  TRIDEM_MEMBER_FIELDS(TRIDEM_VISIT_BODY_FIELD)
}

}  // namespace tridem
