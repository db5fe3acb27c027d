#pragma once
// A solver that passes every call on to another: tests derive from it and override only
// what they watch or change (e.g. the contact copy a solver gives).
#include "tridem/solver.hpp"

#include <memory>
#include <utility>

namespace tridem::test {

class ForwardingSolver : public Solver {
 public:
  explicit ForwardingSolver(std::unique_ptr<Solver> inner) : inner_(std::move(inner)) {}

  void advance(std::int64_t steps) override { inner_->advance(steps); }
  void snapshot(Snapshot& out, bool with_contacts) const override {
    inner_->snapshot(out, with_contacts);
  }
  std::unique_ptr<ContactCopy> make_contact_copy() const override {
    return inner_->make_contact_copy();
  }
  void save_state(SolverState& out) const override { inner_->save_state(out); }
  void load_state(const SolverState& in) override { inner_->load_state(in); }
  EnergyBudget energy() const override { return inner_->energy(); }
  std::int64_t step() const override { return inner_->step(); }
  double time() const override { return inner_->time(); }
  double dt() const override { return inner_->dt(); }
  std::size_t size() const override { return inner_->size(); }
  std::string description() const override { return inner_->description(); }
  StageTimes stage_times() const override { return inner_->stage_times(); }
  void set_stage_timing(bool on) override { inner_->set_stage_timing(on); }
  std::string statistics() const override { return inner_->statistics(); }

 protected:
  const Solver& inner() const { return *inner_; }

 private:
  std::unique_ptr<Solver> inner_;
};

}  // namespace tridem::test
