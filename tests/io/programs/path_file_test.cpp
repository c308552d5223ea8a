// SPDX-License-Identifier: MIT
// Tests of the path-file dispatcher: format detection, reading by type, write -> read trips.
#include <ddfcam/error.h>
#include <ddfcam/io/programs/path_file.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "../io_test_support.h"

namespace ddfcam::io {
namespace {

using planning::MoveKind;
using test::ioErrorMessage;
using test::readBytes;
using test::ScratchDir;
using test::writeBytes;
using ::testing::HasSubstr;

TEST(PathFile, DetectsFormatsByExtensionAndContent) {
  const std::string apt = "$$ made by hand\nPARTNO TEST\nGOTO/1,2,3\nFINI\n";
  const std::string csv = "x,y,z\n1,2,3\n";
  const std::string yaml = "- paths:\n  - poses: []\n";
  const std::string ls = "/PROG A\n/MN\n";
  EXPECT_EQ(detectPathFormat("a.CSV", csv), PathFormat::Csv);
  EXPECT_EQ(detectPathFormat("a.txt", "1.5 2 3\n4 5 6\n"), PathFormat::Csv);
  EXPECT_EQ(detectPathFormat("a.txt", "path,point,tool_x_mm,tool_y_mm,tool_z_mm\n0,0,1,2,3\n"),
            PathFormat::Csv);
  EXPECT_EQ(detectPathFormat("a.txt", apt), PathFormat::Apt);
  EXPECT_EQ(detectPathFormat("a.txt", "TOOL PATH/FLOOR,TOOL,MILL\nGOTO/1,2,3\n"), PathFormat::Apt);
  EXPECT_EQ(detectPathFormat("a.txt", "just some notes\n"), std::nullopt);
  for (const char* name : {"a.apt", "a.cls", "a.cl", "a.ncl", "a.aptsource"})
    EXPECT_EQ(detectPathFormat(name, apt), PathFormat::Apt) << name;
  EXPECT_EQ(detectPathFormat("a.yaml", yaml), PathFormat::RosYaml);
  EXPECT_EQ(detectPathFormat("a.yml", "poses:\n  - position: {}\n"), PathFormat::RosYaml);
  EXPECT_EQ(detectPathFormat("a.yaml", "crs:\n  general: {}\n"), std::nullopt);
  EXPECT_EQ(detectPathFormat("a.ls", ls), PathFormat::FanucLs);
  EXPECT_EQ(detectPathFormat("a.ls", "hello\n"), std::nullopt);
  EXPECT_EQ(detectPathFormat("a.ls", "\xEF\xBB\xBF" + ls), PathFormat::FanucLs);
  for (const char* name : {"a.ngc", "a.nc", "a.gcode"})
    EXPECT_EQ(detectPathFormat(name, "G0 X0\n"), PathFormat::GCode) << name;
  // No or another extension: content decides.
  EXPECT_EQ(detectPathFormat("noext", apt), PathFormat::Apt);
  EXPECT_EQ(detectPathFormat("noext", ls), PathFormat::FanucLs);
  EXPECT_EQ(detectPathFormat("noext", yaml), PathFormat::RosYaml);
  EXPECT_EQ(detectPathFormat("a.dat", "1,2,3\n"), PathFormat::Csv);
  EXPECT_EQ(detectPathFormat("a.xml", "<?xml version=\"1.0\"?>\n<package/>\n"), std::nullopt);
  EXPECT_EQ(detectPathFormat("a.stl", "solid x\n facet normal 0 0 1\n"), std::nullopt);
  EXPECT_EQ(detectPathFormat("a.csv", std::string("1,2,3\n\0\x01", 8)), std::nullopt);
}

TEST(PathFile, ExtensionsOfEachFormatAreDetectedAsThatFormat) {
  const std::pair<PathFormat, std::string> cases[] = {{PathFormat::Csv, "1,2,3\n"},
                                                      {PathFormat::Apt, "PARTNO A\nGOTO/1,2,3\n"},
                                                      {PathFormat::GCode, "G0 X0\n"},
                                                      {PathFormat::RosYaml, "- paths: []\n"},
                                                      {PathFormat::FanucLs, "/PROG A\n"}};
  for (const auto& [format, head] : cases) {
    const auto extensions = pathFileExtensions(format);
    ASSERT_FALSE(extensions.empty());
    for (const std::string& ext : extensions)
      EXPECT_EQ(detectPathFormat("file" + ext, head), format) << pathFormatName(format) << ext;
  }
}

TEST(PathFile, ReadsEachFormatAndRejectsOthersClearly) {
  const ScratchDir dir;
  writeBytes(dir / "a.txt", "$$ hand\nPARTNO A\nUNITS/MM\nGOTO/1,2,3\nGOTO/4,5,6\nFINI\n");
  writeBytes(dir / "b.csv", "x,y,z\n1,2,3\n4,5,6\n7,8,9\n");
  writeBytes(dir / "c.yaml",
             "- paths:\n  - poses:\n    - position: {x: 1, y: 2, z: 3}\n"
             "      orientation: {x: 0, y: 0, z: 0, w: 1}\n");
  writeBytes(dir / "d.ls",
             "/PROG D\n/MN\n 1:L P[1] 10mm/sec FINE ;\n/POS\nP[1]{\n GP1:\n X = 1 mm, Y = 2 "
             "mm, Z = 3 mm, W = 0 deg, P = 0 deg, R = 0 deg\n};\n/END\n");
  EXPECT_EQ(readPathFile(dir / "a.txt").program.points.size(), 2u);
  EXPECT_EQ(readPathFile(dir / "b.csv").program.points.size(), 3u);
  // The format read comes back with the program, as detectPathFormat() finds it.
  for (const auto& [name, format] :
       {std::pair{"a.txt", PathFormat::Apt}, std::pair{"b.csv", PathFormat::Csv},
        std::pair{"c.yaml", PathFormat::RosYaml}, std::pair{"d.ls", PathFormat::FanucLs}}) {
    EXPECT_EQ(readPathFile(dir / name).format, format) << name;
    EXPECT_EQ(detectPathFormat(dir / name, readBytes(dir / name)), format) << name;
  }
  const planning::ClProgram yaml = readPathFile(dir / "c.yaml").program;
  ASSERT_EQ(yaml.points.size(), 1u);
  EXPECT_TRUE(yaml.points[0].positionMm.isApprox(ddf::Vec3(1000, 2000, 3000), 1e-12));
  EXPECT_EQ(yaml.partName, "c");
  const planning::ClProgram ls = readPathFile(dir / "d.ls").program;
  ASSERT_EQ(ls.points.size(), 1u);
  EXPECT_DOUBLE_EQ(ls.points[0].feedMmPerMin, 600.0);

  writeBytes(dir / "e.ngc", "G0 X0\nM30\n");
  EXPECT_THAT(ioErrorMessage([&] { readPathFile(dir / "e.ngc"); }),
              HasSubstr("G-code cannot be read"));
  writeBytes(dir / "f.yaml", "crs:\n  general: {}\n");
  writeBytes(dir / "g.xml", "<?xml version=\"1.0\"?>\n");
  for (const char* name : {"f.yaml", "g.xml"})
    EXPECT_EQ(ioErrorMessage([&] { readPathFile(dir / name); }),
              (dir / name).string() +
                  ": not a tool-path file (expected CSV, APT/CLDATA, ROS toolpath YAML or "
                  "FANUC .ls)");
  EXPECT_THAT(ioErrorMessage([&] { readPathFile(dir / "missing.csv"); }),
              HasSubstr("does not exist"));
  EXPECT_THAT(ioErrorMessage([&] { readPathFile(dir.path()); }), HasSubstr("directory"));
}

/// Two paths as APT numbers them (a rapid ends a path, the next cut starts one), 5-axis.
planning::ClProgram sampleProgram() {
  planning::ClProgram program;
  program.partName = "TRIP";
  const ddf::Vec3 positions[] = {{1.25, -2.5, 3.125},        {10.1234567, 20.7654321, -3.3},
                                 {-100.5, 0.0, 55.75},       {5, 5, 80},
                                 {0.001, -0.002, 12.345678}, {250.5, -125.25, 7.0}};
  const ddf::Vec3 axes[] = {{0, 0, 1}, {0.1, 0.2, 0.9},  {-0.3, 0.1, 0.8},
                            {0, 0, 1}, {0.5, -0.5, 0.7}, {0, 0.6, 0.8}};
  const MoveKind moves[] = {MoveKind::Cut,   MoveKind::Cut, MoveKind::Cut,
                            MoveKind::Rapid, MoveKind::Cut, MoveKind::Cut};
  const int paths[] = {0, 0, 0, 0, 1, 1};
  const int indices[] = {0, 1, 2, 3, 0, 1};
  for (int i = 0; i < 6; ++i) {
    planning::ClPoint p;
    p.path = paths[i];
    p.point = indices[i];
    p.positionMm = positions[i];
    p.axis = axes[i].normalized();
    p.move = moves[i];
    p.feedMmPerMin = moves[i] == MoveKind::Rapid ? 0.0 : (paths[i] == 0 ? 1200.0 : 450.0);
    program.points.push_back(p);
  }
  return program;
}

planning::Tool ballTool() {
  planning::Tool tool;
  tool.name = "ball R3";
  tool.kind = planning::ToolKind::BallEnd;
  tool.radiusMm = 3.0;
  tool.widthMm = 20.0;
  return tool;
}

void expectSameMoves(const planning::ClProgram& read, const planning::ClProgram& written,
                     double positionTol, double axisTol, double feedTol) {
  ASSERT_EQ(read.points.size(), written.points.size());
  for (std::size_t i = 0; i < written.points.size(); ++i) {
    const planning::ClPoint& a = read.points[i];
    const planning::ClPoint& b = written.points[i];
    EXPECT_EQ(a.path, b.path) << i;
    EXPECT_EQ(a.point, b.point) << i;
    EXPECT_EQ(a.move, b.move) << i;
    EXPECT_LE((a.positionMm - b.positionMm).cwiseAbs().maxCoeff(), positionTol) << i;
    ASSERT_TRUE(a.axis.has_value()) << i;
    EXPECT_LE((*a.axis - *b.axis).cwiseAbs().maxCoeff(), axisTol) << i;
    EXPECT_NEAR(a.feedMmPerMin, b.feedMmPerMin, feedTol) << i;
  }
}

TEST(PathFile, CsvRoundTripThroughTheDispatcher) {
  const ScratchDir dir;
  const planning::ClProgram program = sampleProgram();
  PathWriteParams params;
  params.format = PathFormat::Csv;
  writePathFile(program, ballTool(), dir / "trip.csv", params);
  // 6 decimals: positions within 5e-7 mm; axes re-normalised after rounding.
  expectSameMoves(readPathFile(dir / "trip.csv").program, program, 5e-7, 2e-6, 5e-7);
  params.csv.unit = LengthUnit::Metre;
  params.csv.decimals = 7;
  writePathFile(program, ballTool(), dir / "trip_m.txt", params);
  const planning::ClProgram metres = readPathFile(dir / "trip_m.txt").program;
  EXPECT_EQ(metres.sourceUnit, LengthUnit::Metre);
  expectSameMoves(metres, program, 5e-8 * 1000, 2e-7, 5e-8 * 1000);
}

TEST(PathFile, AptRoundTripThroughTheDispatcher) {
  const ScratchDir dir;
  const planning::ClProgram program = sampleProgram();
  PathWriteParams params;
  params.format = PathFormat::Apt;
  params.apt.coordinateDecimals = 5;
  params.apt.vectorDecimals = 8;
  writePathFile(program, ballTool(), dir / "trip.apt", params);
  const planning::ClProgram mm = readPathFile(dir / "trip.apt").program;
  expectSameMoves(mm, program, 5e-6, 1e-7, 5e-6);
  ASSERT_TRUE(mm.cutter.has_value());  // from the tool, the program had none
  EXPECT_DOUBLE_EQ(mm.cutter->diameterMm, 6.0);
  params.apt.unit = LengthUnit::Inch;
  params.apt.coordinateDecimals = 6;
  params.apt.feedUnitFirst = true;
  writePathFile(program, ballTool(), dir / "trip_in.cls", params);
  const planning::ClProgram inch = readPathFile(dir / "trip_in.cls").program;
  EXPECT_EQ(inch.sourceUnit, LengthUnit::Inch);
  expectSameMoves(inch, program, 5e-7 * 25.4, 1e-7, 5e-7 * 25.4);
}

TEST(PathFile, WritesGCodeButDoesNotReadIt) {
  const ScratchDir dir;
  planning::ClProgram program = sampleProgram();
  for (planning::ClPoint& p : program.points) p.axis = ddf::Vec3::UnitZ();
  PathWriteParams params;
  params.format = PathFormat::GCode;
  writePathFile(program, ballTool(), dir / "trip.ngc", params);
  const std::string text = test::readBytes(dir / "trip.ngc");
  EXPECT_THAT(text, HasSubstr("G1"));
  EXPECT_THAT(text, HasSubstr("M30"));
  EXPECT_THAT(ioErrorMessage([&] { readPathFile(dir / "trip.ngc"); }),
              HasSubstr("G-code cannot be read"));
  for (const PathFormat format : {PathFormat::RosYaml, PathFormat::FanucLs}) {
    params.format = format;
    EXPECT_THROW(writePathFile(program, ballTool(), dir / "x", params), InvalidInput);
  }
}

}  // namespace
}  // namespace ddfcam::io
