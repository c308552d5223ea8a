// SPDX-License-Identifier: MIT
// ddfcam: tests of what placeProgram() takes a program's vectors and points for (tool axis,
// approach direction, surface normal; contact or tool reference point), detected from the part
// and warned about, on a sphere whose contacts and normals are known exactly.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/imported_path.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kSphereMm = 30.0;

const ddf::GeneratedSurface& sphere() {
  static const ddf::GeneratedSurface part =
      ddf::spherePart({.radiusMm = kSphereMm, .subdivisions = 3, .m = 9});
  return part;
}

/// Outward unit normal of the sphere at polar angle 40 deg and azimuth @p phiDeg.
Vec3 direction(double phiDeg) {
  const double theta = 40.0 * std::numbers::pi / 180.0, phi = phiDeg * std::numbers::pi / 180.0;
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}

/// A robot pass along the 40 deg latitude, azimuth 0..90 deg every 3 deg: positions on the
/// sphere raised by @p liftMm along the normal, vectors = @p sign times the outward normal
/// (-1: pointing into the part, as a robot's approach direction does). Headerless robot CSVs
/// are read as tool reference points; @p kind says otherwise.
ClProgram robotPass(double sign, double liftMm = 0.0,
                    ClPointKind kind = ClPointKind::ToolReference) {
  ClProgram program;
  program.pointKind = kind;
  for (int i = 0; i <= 30; ++i) {
    const Vec3 u = direction(3.0 * i);
    ClPoint p;
    p.point = i;
    p.positionMm = (kSphereMm + liftMm) * u;
    p.axis = sign * u;
    p.feedMmPerMin = 600.0;
    p.sourceLine = i + 1;
    program.points.push_back(p);
  }
  return program;
}

bool mentions(const std::vector<ClMessage>& warnings, const std::string& text) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const ClMessage& m) { return m.text.find(text) != std::string::npos; });
}

const Tool kBall{.kind = ToolKind::BallEnd, .radiusMm = 3.0, .widthMm = 10.0};
const Tool kRoll{.kind = ToolKind::CylinderRoll, .radiusMm = 5.0, .widthMm = 10.0, .segments = 64};

TEST(ImportedPathConvention, ApproachDirectionsPutTheBallOnTheSurface) {
  const ClProgram program = robotPass(-1.0);
  for (const PathVectorMeaning meaning :
       {PathVectorMeaning::ApproachDirection, PathVectorMeaning::Auto}) {
    const ImportedPath placed =
        placeProgram(program, kBall, sphere().ddf, {.vectorMeaning = meaning});
    ASSERT_EQ(placed.path.poses.size(), program.points.size());
    for (std::size_t i = 0; i < placed.path.poses.size(); ++i) {
      const auto& pose = placed.path.poses[i].pose;
      // Independent: the ball centre (tool frame (0, 0, R)) lies R outside the exact sphere.
      const Vec3 centre = pose * Vec3(0, 0, kBall.radiusMm);
      EXPECT_NEAR(centre.norm() - kSphereMm - kBall.radiusMm, 0.0, 1e-9) << i;
      EXPECT_GT((pose.linear() * Vec3::UnitZ()).dot(direction(3.0 * i)), 1.0 - 1e-12) << i;
      // The raster mesh is within its chord error of the sphere.
      EXPECT_NEAR(placed.contactDistancesMm[i], 0.0, 0.05) << i;
    }
    EXPECT_EQ(placed.gougingPoses, 0);
    EXPECT_EQ(placed.pointsOffPart, 0);
    EXPECT_LT(placed.maxAbsContactDistanceMm, 0.05);
    ASSERT_TRUE(placed.maxOnPartContactDistanceMm.has_value());
    EXPECT_DOUBLE_EQ(*placed.maxOnPartContactDistanceMm, placed.maxAbsContactDistanceMm);
    EXPECT_TRUE(placed.warnings.empty()) << placed.warnings.front().text;
    EXPECT_EQ(placed.convention.vectors, PathVectorMeaning::ApproachDirection);
    EXPECT_EQ(placed.convention.points, ClPointKind::ToolReference);
  }
}

TEST(ImportedPathConvention, AutoDetectsApproachAndSaysWhy) {
  const ImportedPath placed = placeProgram(
      robotPass(-1.0), kBall, sphere().ddf,
      {.vectorMeaning = PathVectorMeaning::Auto, .pointMeaning = PathPointMeaning::Auto});
  const PathConvention& c = placed.convention;
  EXPECT_EQ(c.vectors, PathVectorMeaning::ApproachDirection);
  EXPECT_TRUE(c.vectorsDetected);
  EXPECT_EQ(c.sampled, 31);
  EXPECT_EQ(c.vectorsIn, 31);
  EXPECT_EQ(c.vectorsOut, 0);
  // A ball end's tip touches the surface: contact and tip cannot be told apart.
  EXPECT_EQ(c.points, ClPointKind::ToolReference);
  EXPECT_FALSE(c.pointsDetected);
  EXPECT_NEAR(c.medianPointDistanceMm, 0.0, 0.05);
  EXPECT_NE(c.reason.find("approach directions (detected"), std::string::npos) << c.reason;
  EXPECT_NE(c.reason.find("31 of 31"), std::string::npos) << c.reason;
  // Vectors out of the part: tool axes.
  const ImportedPath out =
      placeProgram(robotPass(1.0), kBall, sphere().ddf, {.vectorMeaning = PathVectorMeaning::Auto});
  EXPECT_EQ(out.convention.vectors, PathVectorMeaning::ToolAxis);
  EXPECT_EQ(out.convention.vectorsOut, 31);
  EXPECT_EQ(out.gougingPoses, 0);
}

TEST(ImportedPathConvention, ToolAxisReadingOfApproachVectorsIsWarnedAsGouging) {
  // The behaviour of the issue: approach vectors read as tip-to-holder axes put the ball
  // centre R inside the sphere, 2 R deep.
  const ImportedPath placed = placeProgram(robotPass(-1.0), kBall, sphere().ddf);
  EXPECT_EQ(placed.convention.vectors, PathVectorMeaning::ToolAxis);
  EXPECT_EQ(placed.gougingPoses, 31);
  EXPECT_NEAR(placed.maxGougeDepthMm, 2.0 * kBall.radiusMm, 0.05);
  EXPECT_TRUE(mentions(placed.warnings, "31 of 31 poses gouge the part"))
      << placed.warnings[0].text;
  EXPECT_TRUE(mentions(placed.warnings, "vectors read as tool axes"));
  EXPECT_TRUE(mentions(placed.warnings, "as approach directions do"));
  // The figures agree: every pose is off the part (6 mm > 2 mm) and that is the largest distance.
  EXPECT_EQ(placed.pointsOffPart, 31);
  EXPECT_NEAR(placed.maxAbsContactDistanceMm, 2.0 * kBall.radiusMm, 0.05);
  EXPECT_FALSE(placed.maxOnPartContactDistanceMm.has_value());
  EXPECT_TRUE(mentions(placed.warnings, "31 of 31 points lie farther than 2 mm"));
}

TEST(ImportedPathConvention, WheelContactsAndCentresAreToldApart) {
  // Contacts on the surface with approach vectors, though declared as reference points.
  const ImportedPath contacts = placeProgram(
      robotPass(-1.0), kRoll, sphere().ddf,
      {.vectorMeaning = PathVectorMeaning::Auto, .pointMeaning = PathPointMeaning::Auto});
  EXPECT_EQ(contacts.convention.vectors, PathVectorMeaning::ApproachDirection);
  EXPECT_EQ(contacts.convention.points, ClPointKind::Contact);
  EXPECT_TRUE(contacts.convention.pointsDetected);
  EXPECT_EQ(contacts.convention.pointsOnSurface, 31);
  EXPECT_DOUBLE_EQ(contacts.convention.referenceHeightMm, kRoll.radiusMm);
  // Wheel centres (one radius off) declared as contacts.
  const ImportedPath centres = placeProgram(
      robotPass(-1.0, kRoll.radiusMm, ClPointKind::Contact), kRoll, sphere().ddf,
      {.vectorMeaning = PathVectorMeaning::Auto, .pointMeaning = PathPointMeaning::Auto});
  EXPECT_EQ(centres.convention.points, ClPointKind::ToolReference);
  EXPECT_EQ(centres.convention.pointsAtReference, 31);
  for (const ImportedPath* placed : {&contacts, &centres}) {
    for (std::size_t i = 0; i < placed->path.poses.size(); ++i) {
      const auto& pose = placed->path.poses[i].pose;
      // Independent: the centre one radius above the contact, the axis in the tangent plane.
      const Vec3 u = direction(3.0 * i);
      EXPECT_LE((pose.translation() - (kSphereMm + kRoll.radiusMm) * u).norm(), 1e-6) << i;
      EXPECT_LT(std::abs((pose.linear() * Vec3::UnitX()).dot(u)), 1e-9) << i;
      EXPECT_NEAR(placed->contactDistancesMm[i], 0.0, 0.05) << i;
    }
    EXPECT_EQ(placed->gougingPoses, 0);
    EXPECT_TRUE(placed->warnings.empty()) << placed->warnings.front().text;
  }
  // The declared kind kept against the evidence: placed a radius too deep, and warned.
  const ImportedPath declared = placeProgram(robotPass(-1.0), kRoll, sphere().ddf,
                                             {.vectorMeaning = PathVectorMeaning::Auto});
  EXPECT_EQ(declared.convention.points, ClPointKind::ToolReference);
  EXPECT_TRUE(mentions(declared.warnings, "as contacts do")) << declared.warnings[0].text;
  EXPECT_EQ(declared.gougingPoses, 31);
  // Normals given as the vectors of a wheel program: a wheel's axis cannot point out of the
  // part, so auto reads them as surface normals.
  const ImportedPath normals = placeProgram(
      robotPass(1.0), kRoll, sphere().ddf,
      {.vectorMeaning = PathVectorMeaning::Auto, .pointMeaning = PathPointMeaning::Auto});
  EXPECT_EQ(normals.convention.vectors, PathVectorMeaning::SurfaceNormal);
  EXPECT_EQ(normals.gougingPoses, 0);
  EXPECT_NEAR(normals.maxAbsContactDistanceMm, 0.0, 0.05);
}

TEST(ImportedPathConvention, PathsFarFromThePartDecideNothing) {
  // In another frame (a robot base 1 m away): no evidence, the given meanings stay, and no
  // pose counts as gouging, though all are off the part.
  Eigen::Isometry3d away = Eigen::Isometry3d::Identity();
  away.translation() = Vec3(1000.0, 0.0, 0.0);
  const ImportedPath placed = placeProgram(robotPass(-1.0), kBall, sphere().ddf,
                                           {.transform = away,
                                            .vectorMeaning = PathVectorMeaning::Auto,
                                            .pointMeaning = PathPointMeaning::Auto});
  EXPECT_EQ(placed.convention.sampled, 0);
  EXPECT_EQ(placed.convention.leftOut, 31);
  EXPECT_EQ(placed.convention.vectors, PathVectorMeaning::ToolAxis);
  EXPECT_NE(placed.convention.reason.find("undecided: only 0 of 31"), std::string::npos)
      << placed.convention.reason;
  EXPECT_EQ(placed.pointsOffPart, 31);
  EXPECT_GT(placed.maxAbsContactDistanceMm, 900.0);
  EXPECT_FALSE(placed.maxOnPartContactDistanceMm.has_value());
}

TEST(ImportedPathConvention, NamesRoundTripAndBadParamsAreRefused) {
  for (const PathVectorMeaning m :
       {PathVectorMeaning::Auto, PathVectorMeaning::ToolAxis, PathVectorMeaning::ApproachDirection,
        PathVectorMeaning::SurfaceNormal})
    EXPECT_EQ(pathVectorMeaningFromName(pathVectorMeaningName(m)), m);
  for (const PathPointMeaning m : {PathPointMeaning::Declared, PathPointMeaning::Auto,
                                   PathPointMeaning::Contact, PathPointMeaning::ToolReference})
    EXPECT_EQ(pathPointMeaningFromName(pathPointMeaningName(m)), m);
  EXPECT_EQ(pathVectorMeaningName(PathVectorMeaning::ApproachDirection), "approach");
  EXPECT_EQ(pathPointMeaningName(PathPointMeaning::ToolReference), "tip");
  EXPECT_FALSE(pathVectorMeaningFromName("inwards").has_value());
  EXPECT_THROW(placeProgram(robotPass(-1.0), kBall, sphere().ddf, {.gougeWarnMm = 0.0}),
               InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
