#pragma once
// Host columns of the per-particle fields (tridem/particle_fields.hpp) and of the per-body
// ones (tridem/body_fields.hpp), and how both backends start them from a ParticleModel.
#include "core/particle_model.hpp"
#include "tridem/body_fields.hpp"
#include "tridem/particle_fields.hpp"

#include <vector>

namespace tridem {

/// Array k of `field` for every particle of the model, at its initial value, into `out`
/// (m.size() values); on the OpenMP threads for large models (a 10^7 run's set-up fills
/// some forty such arrays).
template <class Real, class Field>
void fill_initial_column(Field, const ParticleModel& m, int k,
                         typename Field::template type<Real>* out) {
  const auto n = static_cast<std::ptrdiff_t>(m.size());
#pragma omp parallel for schedule(static) if (n > 65536)
  for (std::ptrdiff_t i = 0; i < n; ++i)
    out[i] = Field::template initial<Real>(m, static_cast<std::size_t>(i), k);
}

/// Array k of `field` for every particle of the model, at its initial value.
template <class Real, class Field>
std::vector<typename Field::template type<Real>> initial_column(Field field, const ParticleModel& m,
                                                                int k) {
  std::vector<typename Field::template type<Real>> v(m.size());
  fill_initial_column<Real>(field, m, k, v.data());
  return v;
}

/// A per-body field (`count` = the bodies) or per-member one (`count` = the triangles) of
/// the bodies' model, at its initial value.
template <class Field>
std::vector<typename Field::template type<double>> initial_body_column(Field, const BodyModel& m,
                                                                       std::size_t count) {
  std::vector<typename Field::template type<double>> v(count);
  for (std::size_t i = 0; i < count; ++i) v[i] = Field::template initial<double>(m, i, 0);
  return v;
}

/// The per-body and per-member fields on the host (the CUDA solver's copy for snapshots).
struct BodyColumns {
  template <class T>
  using Column = std::vector<T>;
  TRIDEM_BODY_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_MEMBER_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_BODY_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)
  TRIDEM_MEMBER_FIELDS(TRIDEM_BODY_COLUMN_ACCESSOR)
};

/// The Model fields on the host: what the CUDA solver keeps there for snapshots.
template <class Real>
struct ModelColumns {
  template <class T>
  using Column = std::vector<T>;
  TRIDEM_MODEL_FIELDS(TRIDEM_DECLARE_COLUMNS)
  TRIDEM_MODEL_FIELDS(TRIDEM_COLUMN_ACCESSOR)

  explicit ModelColumns(const ParticleModel& m) {
    for_each_model_field([&](auto field) {
      for_each_array(column(field), [&](auto& v, int k) { v = initial_column<Real>(field, m, k); });
    });
  }
};

}  // namespace tridem
