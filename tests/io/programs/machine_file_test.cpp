// SPDX-License-Identifier: MIT
// ddfcam: machine files: the shipped samples, round trips and the errors a user meets.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/machine_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

namespace ddfcam::io {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
const fs::path kMachines = fs::path(DDFCAM_SOURCE_DIR) / "resources" / "machines";

std::string errorOf(const std::string& text) {
  try {
    parseMachineFile(text, "m.json");
  } catch (const IoError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MachineFile, ShippedSamplesReadAndSayWhatTheyAre) {
  const MachineSetup haas = readMachineFile(kMachines / "haas-umc750.json");
  EXPECT_EQ(haas.kinematics.pair, planning::RotaryPair::BC);
  EXPECT_EQ(haas.kinematics.tiltDirection, -1.0);
  EXPECT_EQ(haas.kinematics.rotaryDirection, -1.0);
  EXPECT_TRUE(haas.tcpPositions);
  EXPECT_EQ(haas.tcpOnBlock, "G234 H{tool}");
  EXPECT_FALSE(haas.kinematics.rotaryLimited);
  EXPECT_EQ(haas.kinematics.tiltMinDeg, -35.0);
  // The generic samples are the machines of --dialect 5axis-ac and 5axis-bc.
  planning::TableKinematics ac;
  EXPECT_EQ(readMachineFile(kMachines / "table-ac.json").kinematics, ac);
  planning::TableKinematics bc;
  bc.pair = planning::RotaryPair::BC;
  const MachineSetup generic = readMachineFile(kMachines / "table-bc.json");
  EXPECT_EQ(generic.kinematics, bc);
  EXPECT_FALSE(generic.tcpPositions);
  int files = 0;
  for (const auto& entry : fs::directory_iterator(kMachines)) {
    SCOPED_TRACE(entry.path().string());
    EXPECT_FALSE(readMachineFile(entry.path()).name.empty());
    ++files;
  }
  EXPECT_GE(files, 3);
}

TEST(MachineFile, FormattedMachinesReadBackEqual) {
  MachineSetup m;
  m.name = "test \"machine\"";
  m.description = "line one\nline two";
  m.kinematics.pair = planning::RotaryPair::BC;
  m.kinematics.pivotMm = {1.25, -3.5, 1e-7};
  m.kinematics.rotaryOffsetMm = {0.1, 0.2, 0.3};
  m.kinematics.tiltMinDeg = -30.5;
  m.kinematics.tiltMaxDeg = 95.0;
  m.kinematics.rotaryLimited = true;
  m.kinematics.rotaryMinDeg = -200.0;
  m.kinematics.rotaryMaxDeg = 200.0;
  m.kinematics.tiltDirection = -1.0;
  m.kinematics.solution = planning::RotarySolution::NegativeTilt;
  m.tcpPositions = true;
  m.tcpOnBlock = "G43.4 H{tool}";
  m.tcpOffBlock = "G49";
  EXPECT_EQ(parseMachineFile(formatMachineFile(m), "round trip"), m);
  // An endless table has no C limits to keep: the file says null, the defaults come back.
  m.kinematics.rotaryLimited = false;
  m.kinematics.rotaryMinDeg = planning::TableKinematics{}.rotaryMinDeg;
  m.kinematics.rotaryMaxDeg = planning::TableKinematics{}.rotaryMaxDeg;
  m.kinematics.solution = planning::RotarySolution::PositiveTilt;
  EXPECT_EQ(parseMachineFile(formatMachineFile(m), "round trip"), m);
}

TEST(MachineFile, ErrorsNameTheFileAndWhatToChange) {
  EXPECT_THAT(errorOf("{"), HasSubstr("m.json: not valid JSON"));
  EXPECT_THAT(errorOf("[1]"), HasSubstr("m.json: a machine file is one JSON object"));
  EXPECT_THAT(errorOf("{}"), HasSubstr("\"name\" is required"));
  EXPECT_THAT(errorOf(R"({"name":"x","tilt_directoin":1})"),
              HasSubstr("unknown key \"tilt_directoin\""));
  EXPECT_THAT(errorOf(R"({"name":"x","tilt_direction":0.5})"),
              HasSubstr("\"tilt_direction\" must be 1 or -1"));
  EXPECT_THAT(errorOf(R"({"name":"x","rotary_axes":"AB"})"), HasSubstr("is not AC or BC"));
  EXPECT_THAT(errorOf(R"({"name":"x","pivot_mm":[1,2]})"),
              HasSubstr("\"pivot_mm\" must be an array of 3 numbers"));
  EXPECT_THAT(errorOf(R"({"name":"x","tilt_limits_deg":[30,-30]})"), HasSubstr("tilt limits"));
  EXPECT_THAT(errorOf(R"({"name":"x","solution":"closest"})"),
              HasSubstr("nearest, positive-tilt or negative-tilt"));
  EXPECT_THAT(errorOf(R"({"name":"x","positions":"tip"})"),
              HasSubstr("is not machine or tool-tip"));
  EXPECT_THROW(readMachineFile("no/such/machine.json"), IoError);
}

TEST(MachineFile, AppliedMachineSetsTheWriter) {
  const MachineSetup haas = readMachineFile(kMachines / "haas-umc750.json");
  GCodeWriteParams params;
  applyMachine(haas, params);
  EXPECT_EQ(params.mode, GCodeWriteParams::Mode::FiveAxis);
  EXPECT_EQ(params.kinematics, haas.kinematics);
  EXPECT_TRUE(params.tcpPositions);
  EXPECT_EQ(params.tcpOnBlock, haas.tcpOnBlock);
  EXPECT_EQ(params.machineName, haas.name);
}

}  // namespace
}  // namespace ddfcam::io
