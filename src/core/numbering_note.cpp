#include "core/numbering_note.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

namespace tridem {

double consecutive_id_distance(const ParticleModel& model) {
  const auto n = static_cast<std::int64_t>(model.size());
  double size = 0, distance = 0;
  std::int64_t free = 0, steps = 0;
#pragma omp parallel for schedule(static) reduction(+ : size, distance, free, steps) if (n > 65536)
  for (std::int64_t i = 0; i < n; ++i) {
    if (model.motion[i] != Motion::Free) continue;
    size += std::sqrt(model.area[i]);
    ++free;
    if (i + 1 < n && model.motion[i + 1] == Motion::Free) {
      distance += norm(model.centroid[i + 1] - model.centroid[i]);
      ++steps;
    }
  }
  if (steps == 0 || size <= 0) return 0;
  return (distance / static_cast<double>(steps)) / (size / static_cast<double>(free));
}

double numbering_spread(const ParticleModel& model) {
  const auto n = static_cast<std::int64_t>(model.size());
  double distance = 0;
  std::int64_t pairs = 0;
#pragma omp parallel for schedule(static) reduction(+ : distance, pairs) if (n > 65536)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto j = static_cast<std::int64_t>((static_cast<std::uint64_t>(i) * 2654435761ULL) %
                                             static_cast<std::uint64_t>(n));
    if (j == i || model.motion[i] != Motion::Free || model.motion[j] != Motion::Free) continue;
    distance += norm(model.centroid[j] - model.centroid[i]);
    ++pairs;
  }
  if (pairs == 0 || distance <= 0) return 0;
  double size = 0;
  std::int64_t free = 0;
  for (std::int64_t i = 0; i < n; ++i)
    if (model.motion[i] == Motion::Free) {
      size += std::sqrt(model.area[i]);
      ++free;
    }
  // consecutive_id_distance is in grain sizes; so is the scrambled pairs' mean here.
  const double scrambled =
      distance / static_cast<double>(pairs) / (size / static_cast<double>(free));
  return consecutive_id_distance(model) / scrambled;
}

std::string numbering_note(const ParticleModel& model) {
  if (model.size() < kLargeNumbering) return {};
  const double apart = consecutive_id_distance(model);
  if (!(apart > kFarNumbering)) return {};
  return fmt::format(
      "note: the particles are numbered far from where they lie (ids i and i + 1 are {:.0f} "
      "grain sizes apart on average): a pair's two grains then lie far apart in memory, and "
      "a large run steps at up to half the rate of the same grains numbered by place "
      "(docs/performance.md, \"The particles' order\"); list them by place in the scene, or "
      "give generated grains numbering = \"space\"\n",
      apart);
}

}  // namespace tridem
