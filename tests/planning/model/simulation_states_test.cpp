// SPDX-License-Identifier: MIT
// Tests of the simulation state names against the names users see in the workbench.
#include <ddfcam/planning/model/simulation_states.h>

#include <gtest/gtest.h>

namespace ddfcam::planning {
namespace {

TEST(SimulationStates, NamesReadAsInTheWorkbench) {
  EXPECT_EQ(allowanceStateName(0.02), "stock +0.02 mm");
  EXPECT_EQ(allowanceStateName(1.0), "stock +1 mm");
  EXPECT_EQ(allowanceStateName(0.1234567), "stock +0.123457 mm");
  EXPECT_EQ(afterPathStateName("roll pass 1"), "after roll pass 1");
  EXPECT_EQ(afterPathStateName("roll pass 1", true), "Preston after roll pass 1");
}

TEST(SimulationStates, DesignStateIsFoundByName) {
  std::vector<SimulationState> states = {{"stock", {1.0f}}, {"after p", {2.0f}}};
  EXPECT_EQ(designState(states), nullptr);
  states.push_back({kDesignStateName, {3.0f}});
  ASSERT_NE(designState(states), nullptr);
  EXPECT_EQ(designState(states)->heights, std::vector<float>{3.0f});
}

}  // namespace
}  // namespace ddfcam::planning
