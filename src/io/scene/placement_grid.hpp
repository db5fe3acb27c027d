#pragma once
// The cell grid of random sequential addition: placed grains by the cell of their centre,
// as linked lists (head per cell, next per grain) so that inserting never allocates.
// Cells are at least the widest grain's diameter, so a grain can only touch grains whose
// centres are in the 3 × 3 cells about its own.
#include "tridem/vec2.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tridem::scene_detail {

class PlacementGrid {
 public:
  /// Over the box [lo, hi], cells of at least `min_cell`, for up to `grains` grains. The
  /// cells are widened so that there are no more of them than grains (a few grains in a
  /// huge region must not cost a huge grid).
  PlacementGrid(Vec2d lo, Vec2d hi, double min_cell, std::size_t grains) : lo_(lo) {
    const double w = hi.x - lo.x, h = hi.y - lo.y;
    const auto n = static_cast<double>(std::max<std::size_t>(grains, 1));
    // At most about 3n cells: (w/c + 1)(h/c + 1) <= n + w/c + h/c + 1 with c >= sqrt(wh/n),
    // and w/c, h/c <= n even for a sliver of a region.
    cell_ = std::max({min_cell, std::sqrt(w * h / n), w / n, h / n});
    nx_ = static_cast<std::int64_t>(w / cell_) + 1;
    ny_ = static_cast<std::int64_t>(h / cell_) + 1;
    head_.assign(static_cast<std::size_t>(nx_ * ny_), kNone);
    next_.reserve(grains);
  }

  /// Adds grain `id` (ids must be 0, 1, 2, ... in order) centred at `c`.
  void insert(std::size_t id, Vec2d c) {
    const std::size_t cell = index(column(c.x), row(c.y));
    next_.push_back(head_[cell]);
    head_[cell] = id;
  }

  /// Calls f(id) for every grain whose centre is in the 3 × 3 cells about `c`; stops and
  /// returns true as soon as f does.
  template <class F>
  bool any_near(Vec2d c, F f) const {
    const std::int64_t cx = column(c.x), cy = row(c.y);
    for (std::int64_t y = std::max<std::int64_t>(cy - 1, 0); y <= std::min(cy + 1, ny_ - 1); ++y)
      for (std::int64_t x = std::max<std::int64_t>(cx - 1, 0); x <= std::min(cx + 1, nx_ - 1); ++x)
        for (std::size_t id = head_[index(x, y)]; id != kNone; id = next_[id])
          if (f(id)) return true;
    return false;
  }

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::int64_t column(double x) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((x - lo_.x) / cell_)), 0,
                                    nx_ - 1);
  }
  std::int64_t row(double y) const {
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor((y - lo_.y) / cell_)), 0,
                                    ny_ - 1);
  }
  std::size_t index(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>(y * nx_ + x);
  }

  Vec2d lo_;
  double cell_ = 1;
  std::int64_t nx_ = 1, ny_ = 1;
  std::vector<std::size_t> head_, next_;
};

}  // namespace tridem::scene_detail
