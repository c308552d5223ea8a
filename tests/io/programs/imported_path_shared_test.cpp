// SPDX-License-Identifier: MIT
// ddfcam: placing a third-party path (the ROS-Industrial CRS sanding raster) on its part,
// simulating it and mapping the error.
#include <ddfcam/ddf/pseudo_normals.h>
#include <ddfcam/ddf/support_mesh.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/placement/imported_path.h>
#include <ddfcam/planning/simulation/path_simulation.h>
#include <ddfcam/planning/simulation/workpiece.h>

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
planning::ClProgram readCrsCsv() {
  std::ifstream in(kDir / "part_2_job_0_degrees.xyzijk.csv");
  EXPECT_TRUE(in.good());
  planning::ClProgram program;
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (line.empty() || line[0] == '#') continue;
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    planning::ClPoint p;
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

/// A sanding disc: a flat end of radius 12 mm whose face (the tip plane) is the pad.
planning::Tool sandingDisc() {
  return {.name = "sanding disc",
          .kind = planning::ToolKind::FlatEnd,
          .radiusMm = 12.0,
          .widthMm = 10.0};
}

TEST(ImportedPathShared, CrsSandingRasterLiesOnThePartAndGrindsOnlyAlongIt) {
  const ddf::DisplacementField part = crsPart();
  const planning::ClProgram program = readCrsCsv();
  ASSERT_EQ(program.points.size(), 98u);
  ASSERT_EQ(program.pathCount(), 7);
  const planning::Tool disc = sandingDisc();
  planning::PlaceProgramParams params;
  params.actualUnit = LengthUnit::Metre;
  const planning::ImportedPath placed = planning::placeProgram(program, disc, part, params);
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
  RecordProperty("max_contact_distance_mm", std::to_string(placed.maxAbsContactDistanceMm));
  std::cout << "CRS part_2: " << 98 - placed.pointsOffPart << " of 98 points on the part, |contact"
            << " distance| median " << median << " mm, max on part "
            << placed.maxOnPartContactDistanceMm.value_or(-1.0) << " mm, max " << distances.back()
            << " mm; axis along the part normal at " << alongNormal << " of 98\n";
  for (const planning::ClMessage& w : placed.warnings)
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

TEST(ImportedPathShared, CrsToolZAxisPointsOutOfThePartAndAutoReadsItAsToolAxis) {
  // Independent of the DDF: part_2.stl is closed with a positive signed volume, so its facets
  // wind outwards; each pose's z axis against the outward normal of the facet nearest to it.
  ddf::TriangleMesh mesh = readMesh(kDir / "part_2.stl");
  for (Vec3& v : mesh.vertices) v *= 1000.0;
  double volume = 0.0;
  std::vector<Vec3> centroids, normals;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    volume += a.dot(b.cross(c)) / 6.0;
    centroids.push_back((a + b + c) / 3.0);
    normals.push_back((b - a).cross(c - a).normalized());
  }
  EXPECT_GT(volume, 0.0);
  const planning::ClProgram program = readCrsCsv();
  int outwards = 0;
  for (const planning::ClPoint& p : program.points) {
    const Vec3 q = 1000.0 * p.positionMm;
    std::size_t nearest = 0;
    for (std::size_t f = 1; f < centroids.size(); ++f)
      if ((centroids[f] - q).squaredNorm() < (centroids[nearest] - q).squaredNorm()) nearest = f;
    if (p.axis->dot(normals[nearest]) > 0.9) ++outwards;
  }
  EXPECT_EQ(outwards, 98);  // the tool z axis is the outward normal: tip-to-holder, not approach

  const ddf::DisplacementField part = crsPart();
  const planning::Tool disc = sandingDisc();
  planning::PlaceProgramParams params;
  params.actualUnit = LengthUnit::Metre;
  params.vectorMeaning = planning::PathVectorMeaning::Auto;
  params.pointMeaning = planning::PathPointMeaning::Auto;
  const planning::ImportedPath detected = planning::placeProgram(program, disc, part, params);
  const planning::PathConvention& c = detected.convention;
  std::cout << "CRS part_2 auto: " << c.reason << "\n  " << detected.pointsOffPart
            << " of 98 off the part, max |contact distance| " << detected.maxAbsContactDistanceMm
            << " mm, on the part " << detected.maxOnPartContactDistanceMm.value_or(-1.0) << " mm, "
            << detected.gougingPoses << " gouging (deepest " << detected.maxGougeDepthMm
            << " mm)\n";
  EXPECT_EQ(c.vectors, planning::PathVectorMeaning::ToolAxis);
  EXPECT_TRUE(c.vectorsDetected);
  EXPECT_EQ(c.sampled, 98);
  EXPECT_GE(c.vectorsOut, 95);
  EXPECT_EQ(c.vectorsIn, 0);
  // A disc's tip touches: contacts and tips look alike, the CSV's tool points are kept.
  EXPECT_EQ(c.points, planning::ClPointKind::ToolReference);
  EXPECT_LT(std::abs(c.medianPointDistanceMm), 0.5);
  // Auto gives what the explicit tool-axis reading gives.
  const planning::ImportedPath axes =
      planning::placeProgram(program, disc, part, {.actualUnit = LengthUnit::Metre});
  ASSERT_EQ(axes.path.poses.size(), detected.path.poses.size());
  for (std::size_t i = 0; i < axes.path.poses.size(); ++i)
    EXPECT_TRUE(axes.path.poses[i].pose.isApprox(detected.path.poses[i].pose, 1e-12)) << i;
  // Read as approach directions the disc stands upside down in the part: every pose gouges.
  planning::PlaceProgramParams approach = params;
  approach.vectorMeaning = planning::PathVectorMeaning::ApproachDirection;
  const planning::ImportedPath wrong = planning::placeProgram(program, disc, part, approach);
  std::cout << "CRS part_2 as approach: " << wrong.gougingPoses << " gouging, max |contact "
            << "distance| " << wrong.maxAbsContactDistanceMm << " mm\n";
  EXPECT_EQ(wrong.gougingPoses, 98);
  // For the record: the disc tilted by the file's axes digs its rim in where the axis leaves
  // the part's normal; read as contacts, the rim touches at the point instead.
  planning::PlaceProgramParams contact = params;
  contact.pointMeaning = planning::PathPointMeaning::Contact;
  const planning::ImportedPath touching = planning::placeProgram(program, disc, part, contact);
  std::cout << "CRS part_2 as contacts: " << touching.gougingPoses << " gouging (deepest "
            << touching.maxGougeDepthMm << " mm), max |contact distance| "
            << touching.maxAbsContactDistanceMm << " mm\n";
  EXPECT_LE(touching.gougingPoses, detected.gougingPoses);
  const bool warned = std::any_of(wrong.warnings.begin(), wrong.warnings.end(), [](const auto& w) {
    return w.text.find("as tool axes (tip to holder) do") != std::string::npos;
  });
  EXPECT_TRUE(warned);
}

}  // namespace
}  // namespace ddfcam::io
