// The live view's copy of a CPU solver's state (tridem/state_copy.hpp): start() copies the
// shown arrays and the bonds' damage into this object's own, in double, and sums the
// energy (a pass over four arrays); no vertices, masses or bodies, which a snapshot also
// derives. finish() hands the arrays over without copying them again.
#include "backends/cpu/cpu_solver.hpp"
#include "core/snapshot_fill.hpp"
#include "core/state_copy_fields.hpp"

namespace tridem {

namespace {

template <class Real>
class CpuStateCopy final : public StateCopy {
 public:
  explicit CpuStateCopy(const CpuSolver<Real>& solver) : solver_(solver) {}

  void start() override {
    // A no-op but for the first copy and after finish() handed the arrays to a snapshot
    // of other sizes (it swaps them).
    resize_copied_fields(copy_, solver_.size(), solver_.bonds());
    copy_.step = solver_.step();
    copy_.time = solver_.time();
    copy_shown_fields(copy_, solver_);
    const HostBondColumns<Real>& bonds = solver_.bond_columns();
    for (std::size_t k = 0; k < bonds.size(); ++k)
      copy_.bond_damage[k] = mean_bond_damage(bonds.damage.data(), k);
    budget_ = solver_.energy();
  }

  EnergyBudget finish(Snapshot& out) override {
    hand_over_copied_fields(copy_, out);
    return budget_;
  }

 private:
  const CpuSolver<Real>& solver_;  ///< read in start() only
  Snapshot copy_;                  ///< its copied fields only
  EnergyBudget budget_;
};

}  // namespace

template <class Real>
std::unique_ptr<StateCopy> CpuSolver<Real>::make_state_copy() const {
  return std::make_unique<CpuStateCopy<Real>>(*this);
}

template std::unique_ptr<StateCopy> CpuSolver<float>::make_state_copy() const;
template std::unique_ptr<StateCopy> CpuSolver<double>::make_state_copy() const;

}  // namespace tridem
