// SPDX-License-Identifier: MIT
// ddfcam: names of the simulation states that the workbench, ddfcam-cli and batch jobs record.
#pragma once

#include <ddfcam/planning/model/project.h>

#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief Name of the state that keeps the design heights, which error maps compare with.
inline constexpr const char* kDesignStateName = "design";

/// @brief "stock +<a> mm": the state after raising the part by a stock allowance of
/// @p allowanceMm, printed with up to 6 significant digits as "%g" does (0.02, 1e-05).
std::string allowanceStateName(double allowanceMm);

/// @brief "after <path>" for a grinding simulation, "Preston after <path>" for Preston removal:
/// the state after simulating the path named @p pathName.
std::string afterPathStateName(const std::string& pathName, bool preston = false);

/// @brief The state named kDesignStateName in @p states, or nullptr if there is none.
const SimulationState* designState(const std::vector<SimulationState>& states);

}  // namespace ddfcam::planning
