#include "core/state_copy_fields.hpp"
#include "tridem/solver.hpp"

#include <utility>

namespace tridem {

void resize_copied_fields(Snapshot& s, std::size_t n, std::size_t bonds) {
  Snapshot::for_each_field([&](auto field) {
    for_each_array(s.column(field), [n](std::vector<double>& v, int) { v.resize(n); });
  });
  s.bond_damage.resize(bonds);
}

void hand_over_copied_fields(Snapshot& from, Snapshot& to) {
  to.step = from.step;
  to.time = from.time;
  // Swapped, not copied: `from` keeps `to`'s old arrays, of the same sizes, for the next copy.
  Snapshot::for_each_field([&](auto field) { std::swap(from.column(field), to.column(field)); });
  std::swap(from.bond_damage, to.bond_damage);
}

namespace {

/// The fallback: the solver's whole snapshot and energy, taken on the stepping thread.
class SnapshotCopy final : public StateCopy {
 public:
  explicit SnapshotCopy(const Solver& solver) : solver_(solver) {}
  void start() override {
    solver_.snapshot(snap_, false);
    budget_ = solver_.energy();
  }
  EnergyBudget finish(Snapshot& out) override {
    hand_over_copied_fields(snap_, out);
    return budget_;
  }

 private:
  const Solver& solver_;  ///< read in start() only
  Snapshot snap_;
  EnergyBudget budget_;
};

}  // namespace

std::unique_ptr<StateCopy> make_snapshot_copy(const Solver& solver) {
  return std::make_unique<SnapshotCopy>(solver);
}

}  // namespace tridem
