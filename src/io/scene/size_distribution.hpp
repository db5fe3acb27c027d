#pragma once
// Drawing the sizes of generated grains (docs/scene-format.md, "Sizes"): a uniform range
// by number, or a table of sizes with mass fractions. Sizes are equal-area diameters, so
// a grain's area is π·d²/4 whatever its shape and mass fractions are area fractions.
#include "tridem/generate.hpp"

#include <cstddef>
#include <random>
#include <vector>

namespace tridem::scene_detail {

/// The probability by number of each class of a table: mass fraction f over the mass of
/// one grain (∝ d²), normalised.
std::vector<double> number_probabilities(const std::vector<SizeClass>& classes);

/// One size, from one draw.
double draw_size(std::mt19937_64& rng, const SizeDistribution& d,
                 const std::vector<double>& cumulative);

/// The smallest size the distribution can give.
double smallest_size(const SizeDistribution& d);
/// The largest.
double largest_size(const SizeDistribution& d);

/// Sizes for `count` grains, or (count = 0) grains until their total area reaches
/// `target_area`, the last one included. `cap` bounds the count (the caller has refused a
/// target that needs more).
std::vector<double> draw_sizes(std::mt19937_64& rng, const SizeDistribution& d, std::size_t count,
                               double target_area, std::size_t cap);

}  // namespace tridem::scene_detail
