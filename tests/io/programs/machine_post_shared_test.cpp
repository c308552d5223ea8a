// SPDX-License-Identifier: MIT
// ddfcam: 5-axis G-code of NX's variable-axis CLSF against NX's own Haas UMC-750 post of the
// same file (shared/data/paths/mech491-nx-clsf), and the tool axis of every written move
// against the axis in force in the APT text, read here by a scan of its own.
#include <ddfcam/io/programs/machine_file.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/planning/placement/cutter_tool.h>
#include <ddfcam/planning/placement/machine_kinematics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

namespace fs = std::filesystem;
const fs::path kDir = fs::path(DDFCAM_SHARED_DATA_DIR) / "paths" / "mech491-nx-clsf";
const fs::path kMachines = fs::path(DDFCAM_SOURCE_DIR) / "resources" / "machines";
constexpr double kDeg = std::numbers::pi / 180.0;

/// Modal X Y Z B C after every block that moves X, Y or Z, skipping machine-coordinate
/// (G53) and home (G28) blocks: the programmed points of a post's output.
std::vector<std::map<char, double>> programmedMoves(const std::string& text) {
  std::vector<std::map<char, double>> moves;
  std::map<char, double> state{{'X', 0}, {'Y', 0}, {'Z', 0}, {'B', 0}, {'C', 0}};
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '(' || line[0] == '%') continue;
    if (line.find("G53") != std::string::npos || line.find("G28") != std::string::npos) continue;
    std::istringstream words(line.substr(0, line.find('(')));
    bool moved = false;
    for (std::string w; words >> w;) {
      if (w.size() < 2 || std::string("XYZBC").find(w[0]) == std::string::npos) continue;
      state[w[0]] = std::stod(w.substr(1));
      moved = moved || w[0] == 'X' || w[0] == 'Y' || w[0] == 'Z';
    }
    if (moved) moves.push_back(state);
  }
  return moves;
}

/// Point and tool axis in force of every GOTO of the APT text: a 6-value GOTO sets the axis,
/// a 3-value one keeps it (NX CLSF; no MULTAX/OFF in these files).
struct AptMove {
  ddf::Vec3 point;
  ddf::Vec3 axis;
};
std::vector<AptMove> aptMoves(const std::string& text) {
  std::vector<AptMove> moves;
  ddf::Vec3 axis = ddf::Vec3::UnitZ();
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("GOTO/", 0) != 0) continue;
    std::vector<double> v;
    std::istringstream values(line.substr(5));
    for (std::string item; std::getline(values, item, ',');) v.push_back(std::stod(item));
    if (v.size() == 6) axis = ddf::Vec3(v[3], v[4], v[5]).normalized();
    moves.push_back({{v[0], v[1], v[2]}, axis});
  }
  return moves;
}

/// Haas UMC convention written out: axis = (sin B cos C, sin B sin C, cos B).
ddf::Vec3 haasAxis(double bDeg, double cDeg) {
  return {std::sin(bDeg * kDeg) * std::cos(cDeg * kDeg),
          std::sin(bDeg * kDeg) * std::sin(cDeg * kDeg), std::cos(bDeg * kDeg)};
}

/// Our G-code of the CLSF for @p params, as programmed moves without the two safe-plane
/// rapids at the start and the retract at the end.
std::vector<std::map<char, double>> ourMoves(const GCodeWriteParams& params) {
  const planning::ClProgram program = readPathFile(kDir / "APT_Variable_Axis.txt").program;
  PathWriteParams write;
  write.format = PathFormat::GCode;
  write.gcode = params;
  write.gcode.unit = LengthUnit::Inch;
  write.gcode.angleDecimals = 4;
  const fs::path out = fs::temp_directory_path() / "ddfcam_machine_post_shared.ngc";
  writePathFile(program, planning::toolFromCutter(*program.cutter, program.toolName), out, write);
  std::vector<std::map<char, double>> moves = programmedMoves(test::readBytes(out));
  fs::remove(out);
  EXPECT_EQ(moves.size(), program.points.size() + 3);
  return {moves.begin() + 2, moves.end() - 1};
}

#define SKIP_WITHOUT_SHARED_DATA() \
  if (!fs::exists(kDir)) GTEST_SKIP() << "shared data not found at " << kDir

TEST(MachinePostShared, HaasMachineFileReproducesNxsHaasPost) {
  SKIP_WITHOUT_SHARED_DATA();
  GCodeWriteParams params;
  applyMachine(readMachineFile(kMachines / "haas-umc750.json"), params);
  const std::vector<std::map<char, double>> ours = ourMoves(params);
  const std::vector<std::map<char, double>> post =
      programmedMoves(test::readBytes(kDir / "PostProcessed_Variable_Axis.txt"));
  ASSERT_EQ(ours.size(), 348u);
  ASSERT_EQ(post.size(), ours.size());
  double worstAngle = 0.0, worstXyz = 0.0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    for (const char a : {'B', 'C'}) {
      EXPECT_NEAR(ours[i].at(a), post[i].at(a), 1e-3) << "move " << i << " " << a;
      worstAngle = std::max(worstAngle, std::abs(ours[i].at(a) - post[i].at(a)));
    }
    // G234 TCPC: X Y Z are the CL points, which the post writes with 4 decimals too.
    for (const char a : {'X', 'Y', 'Z'}) {
      EXPECT_NEAR(ours[i].at(a), post[i].at(a), 1.01e-4) << "move " << i << " " << a;
      worstXyz = std::max(worstXyz, std::abs(ours[i].at(a) - post[i].at(a)));
    }
  }
  RecordProperty("worst_angle_deg", std::to_string(worstAngle));
  RecordProperty("worst_xyz_in", std::to_string(worstXyz));
}

TEST(MachinePostShared, EveryWrittenMoveHasTheAxisInForce) {
  SKIP_WITHOUT_SHARED_DATA();
  const std::vector<AptMove> apt = aptMoves(test::readBytes(kDir / "APT_Variable_Axis.txt"));
  ASSERT_EQ(apt.size(), 348u);
  int tiltedThreeValue = 0;  // moves whose axis comes from an earlier GOTO and is tilted
  for (const AptMove& m : apt) tiltedThreeValue += m.axis.z() < 1.0 - 1e-9;
  EXPECT_GT(tiltedThreeValue, 300);
  // The Haas machine (directions -1, TCP) and the generic right-handed B/C table.
  GCodeWriteParams haas;
  applyMachine(readMachineFile(kMachines / "haas-umc750.json"), haas);
  GCodeWriteParams generic;
  generic.mode = GCodeWriteParams::Mode::FiveAxis;
  generic.kinematics.pair = planning::RotaryPair::BC;
  for (const GCodeWriteParams& params : {haas, generic}) {
    const std::vector<std::map<char, double>> ours = ourMoves(params);
    ASSERT_EQ(ours.size(), apt.size());
    for (std::size_t i = 0; i < apt.size(); ++i) {
      const planning::MachinePose pose{
          25.4 * ddf::Vec3(ours[i].at('X'), ours[i].at('Y'), ours[i].at('Z')), ours[i].at('B'),
          ours[i].at('C')};
      const ddf::Vec3 axis = params.tcpPositions
                                 ? haasAxis(pose.tiltDeg, pose.rotaryDeg)
                                 : planning::forwardKinematics(params.kinematics, pose).axis;
      // B and C have 4 decimals: 1e-4 deg is 1.7e-6 rad.
      EXPECT_LT((axis - apt[i].axis).norm(), 1e-5) << "move " << i;
    }
  }
}

}  // namespace
}  // namespace ddfcam::io
