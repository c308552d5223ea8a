// SPDX-License-Identifier: MIT
// ddfcam: names of the simulation states that the workbench, ddfcam-cli and batch jobs record.
#include <ddfcam/planning/model/simulation_states.h>

#include <algorithm>
#include <cstdio>

namespace ddfcam::planning {

std::string allowanceStateName(double allowanceMm) {
  char number[32];
  std::snprintf(number, sizeof number, "%g", allowanceMm);
  return std::string("stock +") + number + " mm";
}

std::string afterPathStateName(const std::string& pathName, bool preston) {
  return (preston ? "Preston after " : "after ") + pathName;
}

const SimulationState* designState(const std::vector<SimulationState>& states) {
  const auto it = std::ranges::find_if(
      states, [](const SimulationState& s) { return s.name == kDesignStateName; });
  return it != states.end() ? &*it : nullptr;
}

}  // namespace ddfcam::planning
