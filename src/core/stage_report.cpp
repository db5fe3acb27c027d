#include "core/stage_report.hpp"

#include <fmt/format.h>

namespace tridem {

const char* stage_name(Stage stage) {
  switch (stage) {
    case Stage::Geometry: return "geometry";
    case Stage::PairList: return "pair list";
    case Stage::PairForces: return "pair forces";
    case Stage::Gather: return "gather";
    case Stage::Check: return "check";
    case Stage::Integrate: return "integrate";
  }
  return "?";
}

double StageTimes::total() const {
  double sum = 0;
  for (double s : seconds) sum += s;
  return sum;
}

std::string stage_table(const StageTimes& t) {
  if (t.steps == 0) return {};
  if (t.timed_steps == 0)
    return fmt::format("time per stage: none of the {} steps was timed ({} times one step in "
                       "several, from the middle of the first few)\n",
                       t.steps, t.clock);
  const double total = t.total();
  std::string out = t.timed_steps > 0 && t.timed_steps < t.steps
                        ? fmt::format("time per stage ({} steps, {} of them timed, {}):\n", t.steps,
                                      t.timed_steps, t.clock)
                        : fmt::format("time per stage ({} steps, {}):\n", t.steps, t.clock);
  for (int k = 0; k < kStageCount; ++k) {
    const char* name = stage_name(static_cast<Stage>(k));
    if (t.fused_into[k] != k) {
      out += fmt::format("  {:<12} in {}\n", name, stage_name(static_cast<Stage>(t.fused_into[k])));
      continue;
    }
    out += fmt::format("  {:<12} {:10.4g} s {:5.1f} % {:10.3g} s/step\n", name, t.seconds[k],
                       total > 0 ? 100.0 * t.seconds[k] / total : 0.0,
                       t.seconds[k] / static_cast<double>(t.steps));
  }
  return out;
}

}  // namespace tridem
