// SPDX-License-Identifier: MIT
// ddfcam-cli simulate places a CSV with normals as the workbench's import does
// (planning::placeProgram): the same poses off the part, contact distances and gouges.
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/programs/path_file.h>
#include <ddfcam/io/programs/tool_path_csv.h>
#include <ddfcam/planning/placement/imported_path.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cli_simulate_support.h"

namespace ddfcam::io {
namespace {

using test::cli;
using test::CliRun;
using test::jsonNumber;

TEST(CliSimulate, CsvWithNormalsIsPlacedAsTheWorkbenchPlacesIt) {
  test::ScratchDir dir;
  writeDdf(test::plate(), dir / "part.ddf");
  // A roll pass along x at y = 10 from x = 10 to 26 every 0.5 mm: it leaves the 20 mm plate
  // at x = 20, its contacts on z = 0 with the normal +z.
  planning::ClProgram table = test::straightPass(0.5);
  for (planning::ClPoint& row : table.points) row.positionMm.x() += 8.0;
  writeToolPathCsv(table, dir / "edge.csv");
  const CliRun run = cli(dir, "simulate",
                         {(dir / "part.ddf").string(), "--paths", (dir / "edge.csv").string(), "-o",
                          (dir / "out.ddf").string(), "--report", (dir / "r.json").string(),
                          "--radius", "5", "--width", "4"});
  ASSERT_EQ(run.exitCode, 0) << run.err;
  const std::string json = test::readBytes(dir / "r.json");

  // Oracle 1, geometry: past the edge the roll's centre (x, 10, 5) is sqrt((x - 20)^2 + R^2)
  // from the plate's edge, so the gap is that minus R, > 2 mm (the off-part limit) for
  // x - 20 > sqrt(24): x = 25, 25.5 and 26 (contacts farther than 2 mm off the plate start
  // at x = 22.5).
  const double radius = 5.0;
  int offPart = 0;
  for (const planning::ClPoint& row : table.points) {
    const double past = std::max(0.0, row.positionMm.x() - 20.0);
    offPart += std::hypot(past, radius) - radius > 2.0 ? 1 : 0;
  }
  ASSERT_EQ(offPart, 3);
  EXPECT_EQ(jsonNumber(json, "points_off_part"), offPart) << json;
  EXPECT_NEAR(jsonNumber(json, "max_contact_distance_mm"), std::hypot(6.0, radius) - radius, 1e-3)
      << json;

  // Oracle 2, the workbench: File > Import tool path places the file with placeProgram() and
  // the dialog's defaults (the file's unit, no transform, vectors and points detected).
  const PathFile file = readPathFile(dir / "edge.csv");
  planning::Tool roll;
  roll.radiusMm = radius;
  roll.widthMm = 4.0;
  planning::PlaceProgramParams gui;
  gui.actualUnit = file.program.sourceUnit;
  const planning::ImportedPath placed =
      planning::placeProgram(file.program, roll, test::plate(), gui);
  EXPECT_EQ(jsonNumber(json, "poses_placed"), static_cast<double>(placed.path.poses.size()));
  EXPECT_EQ(jsonNumber(json, "points_off_part"), placed.pointsOffPart) << json;
  EXPECT_DOUBLE_EQ(jsonNumber(json, "max_contact_distance_mm"), placed.maxAbsContactDistanceMm);
  ASSERT_TRUE(placed.maxOnPartContactDistanceMm.has_value());
  EXPECT_DOUBLE_EQ(jsonNumber(json, "max_contact_distance_on_part_mm"),
                   *placed.maxOnPartContactDistanceMm);
  EXPECT_EQ(jsonNumber(json, "gouging_poses"), placed.gougingPoses) << json;
  EXPECT_DOUBLE_EQ(jsonNumber(json, "max_gouge_depth_mm"), placed.maxGougeDepthMm);
}

}  // namespace
}  // namespace ddfcam::io
