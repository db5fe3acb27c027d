#include "io/scene/size_distribution.hpp"

#include "io/scene/random_unit.hpp"

#include <algorithm>
#include <numbers>

namespace tridem::scene_detail {

std::vector<double> number_probabilities(const std::vector<SizeClass>& classes) {
  std::vector<double> p;
  double total = 0;
  for (const SizeClass& c : classes) {
    p.push_back(c.mass_fraction / (c.size * c.size));
    total += p.back();
  }
  for (double& x : p) x /= total;
  return p;
}

double draw_size(std::mt19937_64& rng, const SizeDistribution& d,
                 const std::vector<double>& cumulative) {
  const double u = unit_double(rng);
  if (d.classes.empty()) return d.min_size + (d.max_size - d.min_size) * u;
  // The first class whose cumulative probability exceeds u; the last one catches the
  // rounding of the sum.
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), u);
  const std::size_t k = std::min<std::size_t>(static_cast<std::size_t>(it - cumulative.begin()),
                                              d.classes.size() - 1);
  return d.classes[k].size;
}

double smallest_size(const SizeDistribution& d) {
  if (d.classes.empty()) return d.min_size;
  double s = d.classes.front().size;
  for (const SizeClass& c : d.classes) s = std::min(s, c.size);
  return s;
}

double largest_size(const SizeDistribution& d) {
  if (d.classes.empty()) return d.max_size;
  double s = d.classes.front().size;
  for (const SizeClass& c : d.classes) s = std::max(s, c.size);
  return s;
}

std::vector<double> draw_sizes(std::mt19937_64& rng, const SizeDistribution& d, std::size_t count,
                               double target_area, std::size_t cap) {
  std::vector<double> cumulative;
  if (!d.classes.empty()) {
    double sum = 0;
    for (double p : number_probabilities(d.classes)) cumulative.push_back(sum += p);
  }
  std::vector<double> sizes;
  double area = 0;
  while (sizes.size() < cap && (count > 0 ? sizes.size() < count : area < target_area)) {
    sizes.push_back(draw_size(rng, d, cumulative));
    area += std::numbers::pi * sizes.back() * sizes.back() / 4;
  }
  return sizes;
}

}  // namespace tridem::scene_detail
