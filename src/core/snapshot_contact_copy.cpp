#include "tridem/contact_copy.hpp"
#include "tridem/solver.hpp"

#include <stdexcept>

namespace tridem {

namespace {

class SnapshotContactCopy final : public ContactCopy {
 public:
  explicit SnapshotContactCopy(const Solver& solver) : solver_(solver) {}
  void start() override { solver_.snapshot(snap_, true); }
  void finish(Snapshot& s) override {
    if (s.step != snap_.step)
      throw std::logic_error("ContactCopy::finish: not the snapshot of the step started");
    s.contact_precision = snap_.contact_precision;
    s.contacts.insert(s.contacts.end(), snap_.contacts.begin(), snap_.contacts.end());
  }

 private:
  const Solver& solver_;  ///< read in start() only
  Snapshot snap_;
};

}  // namespace

std::unique_ptr<ContactCopy> make_snapshot_contact_copy(const Solver& solver) {
  return std::make_unique<SnapshotContactCopy>(solver);
}

}  // namespace tridem
