#pragma once
// A run of other rounding on the CPU: the serial solver of the scene moved by an offset,
// seen moved back. Nothing in a scene without periodic boundaries depends on where it is
// (programs give velocities, servos forces, contacts differences of coordinates), so the
// two runs are the same physics; but every coordinate rounds otherwise, as a GPU's fused
// multiply-adds round otherwise. It stands in for the GPU where the comparisons of the
// unstable parity tests (support/program_compare.hpp, support/bond_compare.hpp) are
// checked on the CPU: they must let it pass, and fail a wrong solver.
#include "tridem/scene.hpp"
#include "tridem/snapshot.hpp"
#include "tridem/solver.hpp"
#include "tridem/solver_state.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace tridem::test {

/// `s` moved by `offset`: its triangles and its bonds' edges (a scene without periodic
/// boundaries or rotation programs, whose centre would move too).
inline Scene shifted_scene(Scene s, Vec2d offset) {
  EXPECT_FALSE(s.simulation.periodic.any()) << "a periodic cell is not moved";
  for (const MotionProgram& p : s.programs)
    EXPECT_NE(p.kind, ProgramKind::Rotation) << "a rotation's centre is not moved";
  for (TriangleSpec& t : s.triangles)
    for (Vec2d& v : t.vertices) v = v + offset;
  for (BondSpec& b : s.bonds) {
    b.p = b.p + offset;
    b.q = b.q + offset;
  }
  return s;
}

/// A solver of shifted_scene(scene, offset) showing its positions moved back.
class ShiftedSolver : public Solver {
 public:
  ShiftedSolver(std::unique_ptr<Solver> moved, Vec2d offset)
      : moved_(std::move(moved)), offset_(offset) {}

  void advance(std::int64_t steps) override { moved_->advance(steps); }
  void snapshot(Snapshot& out, bool with_contacts) const override {
    moved_->snapshot(out, with_contacts);
    back(out.x, offset_.x);
    back(out.y, offset_.y);
    for (auto* v : {&out.x1, &out.x2, &out.x3, &out.body_x, &out.bond_x0, &out.bond_x1})
      back(*v, offset_.x);
    for (auto* v : {&out.y1, &out.y2, &out.y3, &out.body_y, &out.bond_y0, &out.bond_y1})
      back(*v, offset_.y);
    for (ContactRecord& c : out.contacts) {
      c.px -= offset_.x;
      c.py -= offset_.y;
    }
  }
  void save_state(SolverState& out) const override {
    moved_->save_state(out);
    back(out.x, offset_.x);
    back(out.y, offset_.y);
    back(out.body_x, offset_.x);
    back(out.body_y, offset_.y);
  }
  void load_state(const SolverState&) override { ADD_FAILURE() << "not for restarts"; }
  EnergyBudget energy() const override { return moved_->energy(); }
  std::int64_t step() const override { return moved_->step(); }
  double time() const override { return moved_->time(); }
  double dt() const override { return moved_->dt(); }
  std::size_t size() const override { return moved_->size(); }
  std::string description() const override { return moved_->description() + ", moved"; }
  StageTimes stage_times() const override { return moved_->stage_times(); }
  void set_stage_timing(bool on) override { moved_->set_stage_timing(on); }

 private:
  static void back(std::vector<double>& v, double by) {
    for (double& e : v) e -= by;
  }
  std::unique_ptr<Solver> moved_;
  Vec2d offset_;
};

}  // namespace tridem::test
