// SPDX-License-Identifier: MIT
// ddfcam: placing a third-party path (the ROS-Industrial CRS sanding raster) on its part,
// simulating it and mapping the error.
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/io/imported_path.h>
#include <ddfcam/io/mesh_io.h>
#include <ddfcam/planning/error_map.h>
#include <ddfcam/planning/path_simulation.h>
#include <ddfcam/planning/workpiece.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ddfcam::io {
namespace {

using ddf::Vec3;

const std::filesystem::path kDir =
    std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "paths" / "crs-robotic-sanding";

/// The derived CSV (path_index,x,y,z,i,j,k in metres after a '#' comment line), read here
/// with a few lines of its own so the test does not depend on the CSV reader. Numbers are
/// kept in metres in a program that claims millimetres: placeProgram's actualUnit rescales.
ClProgram readCrsCsv() {
  std::ifstream in(kDir / "part_2_job_0_degrees.xyzijk.csv");
  EXPECT_TRUE(in.good());
  ClProgram program;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    ClPoint p;
    Vec3 axis;
    fields >> p.path >> p.positionMm.x() >> p.positionMm.y() >> p.positionMm.z() >> axis.x() >>
        axis.y() >> axis.z();
    EXPECT_FALSE(fields.fail()) << "line " << lineNo;
    p.axis = axis.normalized();
    p.point = program.points.empty() || program.points.back().path != p.path
                  ? 0
                  : program.points.back().point + 1;
    p.sourceLine = lineNo;
    program.points.push_back(p);
  }
  return program;
}

/// The part as a DDF the way convertMeshToDdf() builds it (the mesh as support, repaired
/// pseudo-normals as directions, heights 0 on the support itself), but with a uniform 1 mm
/// crust instead of the per-face length choice, which takes seconds on these 26,568 facets.
ddf::DisplacementField crsPart() {
  ddf::TriangleMesh mesh = readMesh(kDir / "part_2.stl");
  for (Vec3& v : mesh.vertices) v *= 1000.0;  // the STL is in metres
  ddf::SupportMesh support = ddf::makeSupportMesh(mesh.vertices, mesh.triangles);
  std::vector<Vec3> vectors = ddf::pseudoNormals(support).normals;
  return ddf::DisplacementField(std::move(support), std::move(vectors), 3);
}

TEST(ImportedPathShared, CrsSandingRasterLiesOnThePartAndGrindsOnlyAlongIt) {
  const ddf::DisplacementField part = crsPart();
  const ClProgram program = readCrsCsv();
  ASSERT_EQ(program.points.size(), 98u);
  ASSERT_EQ(program.pathCount(), 7);
  // A sanding disc: a flat end of radius 12 mm whose face (the tip plane) is the pad.
  const planning::Tool disc{.name = "sanding disc",
                            .kind = planning::ToolKind::FlatEnd,
                            .radiusMm = 12.0,
                            .widthMm = 10.0};
  PlaceProgramParams params;
  params.actualUnit = LengthUnit::Metre;
  const ImportedPath placed = placeProgram(program, disc, part, params);
  ASSERT_EQ(placed.path.poses.size(), 98u);
  EXPECT_EQ(placed.path.passStarts.size(), 7u);

  // The file's axis points away from the part: along the part's own normal at the contact.
  int alongNormal = 0;
  for (std::size_t i = 0; i < placed.normals.size(); ++i)
    if ((placed.path.poses[i].pose.linear() * Vec3::UnitZ()).dot(placed.normals[i]) > 0.9)
      ++alongNormal;
  EXPECT_GE(alongNormal, 95);

  std::vector<double> distances = placed.contactDistancesMm;
  for (double& d : distances) d = std::abs(d);
  std::sort(distances.begin(), distances.end());
  const double median = distances[distances.size() / 2];
  RecordProperty("points_on_part", 98 - placed.pointsOffPart);
  RecordProperty("median_contact_distance_mm", std::to_string(median));
  RecordProperty("max_contact_distance_mm", std::to_string(placed.maxContactDistanceMm));
  std::cout << "CRS part_2: " << 98 - placed.pointsOffPart << " of 98 points on the part, |contact"
            << " distance| median " << median << " mm, max on part " << placed.maxContactDistanceMm
            << " mm, max " << distances.back() << " mm; axis along the part normal at "
            << alongNormal << " of 98\n";
  for (const ClMessage& w : placed.warnings)
    std::cout << "  line " << w.line << ": " << w.text << "\n";
  EXPECT_GE(98 - placed.pointsOffPart, 90);  // a raster ON the part
  EXPECT_LT(median, 2.0);

  // Simulate on a workpiece with allowance: material goes only where the disc was.
  const double allowanceMm = 0.05;
  const ddf::DisplacementField stock = planning::workpieceWithAllowance(part, allowanceMm);
  ddf::DisplacementField ground = stock;
  planning::simulatePath(ground, disc, placed.path);
  std::size_t removed = 0, outside = 0;
  for (int f = 0; f < ground.faceCount(); ++f)
    for (int i = 0; i < ground.resolution(); ++i)
      for (int k = 0; i + k < ground.resolution(); ++k) {
        if (ground.height(f, i, k) >= stock.height(f, i, k)) continue;
        ++removed;
        // Independent check: the lowered point lies inside the cutter at some pose.
        const Vec3 q = ground.surfacePoint(f, i, k);
        const bool inside =
            std::any_of(placed.path.poses.begin(), placed.path.poses.end(), [&](const auto& p) {
              const Vec3 local = p.pose.inverse() * q;
              return local.head<2>().norm() <= disc.radiusMm + 1e-3 && local.z() >= -1e-3 &&
                     local.z() <= disc.widthMm + 1e-3;
            });
        if (!inside) ++outside;
      }
  EXPECT_GT(removed, 0u);
  EXPECT_EQ(outside, 0u);

  const planning::ScalarField deviation = planning::deviationMap(ground, part);
  const planning::ErrorStatistics stats =
      planning::errorStatistics(deviation, part, {.lowerMm = -0.01, .upperMm = 0.01});
  // Untouched stock keeps its allowance (up to the two normal estimates of workpiece and error
  // map, which differ across the coarse raster's sharp edges); the disc takes it off where it
  // went and digs in where the planner's poses reach below the STL.
  std::size_t untouched = 0, atAllowance = 0;
  for (std::size_t i = 0; i < deviation.values.size(); ++i) {
    if (ground.allHeights()[i] < stock.allHeights()[i] || !std::isfinite(deviation.values[i]))
      continue;
    ++untouched;
    if (std::abs(deviation.values[i] - allowanceMm) < 0.1 * allowanceMm) ++atAllowance;
  }
  std::cout << "CRS part_2 error map: " << atAllowance << " of " << untouched
            << " untouched heights within 10 % of the allowance; " << removed
            << " heights lowered, deviation min " << stats.minMm << " max " << stats.maxMm
            << " mm, material left " << stats.materialLeftPercent << " %, in tolerance "
            << stats.inTolerancePercent << " %, overcut " << stats.overcutPercent << " %\n";
  EXPECT_GT(double(atAllowance), 0.95 * double(untouched));
  EXPECT_LT(stats.minMm, 0.0);
  EXPECT_GT(stats.materialLeftPercent, 50.0);  // a sparse raster of a 12 mm disc on 1.2 m
}

}  // namespace
}  // namespace ddfcam::io
