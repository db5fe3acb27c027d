#include "core/numbering_note.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace tridem {

namespace {

/// The mean distance between the centroids of free particles i and partner(i), over the
/// i whose partner is another free particle; 0 without one.
template <class Partner>
double mean_distance(const ParticleModel& model, Partner partner) {
  const auto n = static_cast<std::int64_t>(model.size());
  double distance = 0;
  std::int64_t pairs = 0;
#pragma omp parallel for schedule(static) reduction(+ : distance, pairs) if (n > 65536)
  for (std::int64_t i = 0; i < n; ++i) {
    const std::int64_t j = partner(i, n);
    if (j == i || j >= n || model.motion[i] != Motion::Free || model.motion[j] != Motion::Free)
      continue;
    distance += norm(model.centroid[j] - model.centroid[i]);
    ++pairs;
  }
  return pairs > 0 ? distance / static_cast<double>(pairs) : 0.0;
}

double consecutive_mean(const ParticleModel& model) {
  return mean_distance(model, [](std::int64_t i, std::int64_t) { return i + 1; });
}

}  // namespace

double free_grain_size(const ParticleModel& model) {
  const auto n = static_cast<std::int64_t>(model.size());
  double size = 0;
  std::int64_t free = 0;
#pragma omp parallel for schedule(static) reduction(+ : size, free) if (n > 65536)
  for (std::int64_t i = 0; i < n; ++i)
    if (model.motion[i] == Motion::Free) {
      size += std::sqrt(model.area[i]);
      ++free;
    }
  return free > 0 ? size / static_cast<double>(free) : 0.0;
}

double consecutive_id_distance(const ParticleModel& model) {
  const double size = free_grain_size(model);
  return size > 0 ? consecutive_mean(model) / size : 0.0;
}

double numbering_spread(const ParticleModel& model) {
  const double scrambled = mean_distance(model, [](std::int64_t i, std::int64_t n) {
    return static_cast<std::int64_t>((static_cast<std::uint64_t>(i) * 2654435761ULL) %
                                     static_cast<std::uint64_t>(n));
  });
  return scrambled > 0 ? consecutive_mean(model) / scrambled : 0.0;
}

std::string numbering_note(const ParticleModel& model, bool by_place) {
  if (model.size() < kLargeNumbering) return {};
  const double apart = consecutive_id_distance(model);
  if (!(apart > kFarNumbering)) return {};
  if (by_place)
    return fmt::format(
        "note: the particles are numbered far from where they lie (ids i and i + 1 are {:.0f} "
        "grain sizes apart on average): the solver keeps them numbered by place, which steps "
        "such a scene at up to twice the rate, and every output names them by the scene's "
        "ids (docs/performance.md, \"The particles' order\"; --particle-order scene keeps "
        "the scene's order)\n",
        apart);
  return fmt::format(
      "note: the particles are numbered far from where they lie (ids i and i + 1 are {:.0f} "
      "grain sizes apart on average): a pair's two grains then lie far apart in memory, and "
      "a large run steps at up to half the rate of the same grains numbered by place "
      "(docs/performance.md, \"The particles' order\"); list them by place in the scene, or "
      "give generated grains numbering = \"space\", or leave the solver's --particle-order at "
      "auto, which numbers them by place itself in a run of one rank\n",
      apart);
}

}  // namespace tridem
