// SPDX-License-Identifier: MIT
// ddfcam: simulated scallops of parallel straight passes on a plane or a convex cylinder.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/inspection/error_map.h>
#include <ddfcam/planning/inspection/scallop_prediction.h>
#include <ddfcam/planning/placement/tool_placement.h>
#include <ddfcam/planning/simulation/path_simulation.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

// A generated part with the stock on it, its desired heights, the passes and the region between
// the first and last pass.
struct ScallopSetup {
  ddf::GeneratedSurface part;
  std::vector<float> desired;
  std::vector<int> region;
  double spacingMm = 0.0;        // actual spacing (rounded onto the support on a cylinder)
  double rasterSpacingMm = 0.0;  // across the feed
  double feedStepMm = 0.0;       // raster spacing along the feed
  // Contact, normal and feed of pass p at feed position s (mm).
  std::function<void(int, double, Vec3&, Vec3&, Vec3&)> frame;
  double passLengthMm = 0.0;
};

// Facets around a circle of radius r so that the chord error stays below tol, a multiple of 4
// (mesh vertices then lie on a wheel's lowest line and a ball's poles).
int segmentsFor(double radiusMm, double tolMm) {
  const double step = std::acos(std::max(-1.0, 1.0 - tolMm / radiusMm));
  const int n = static_cast<int>(std::ceil(2.0 * std::numbers::pi / step / 4.0)) * 4;
  return std::clamp(n, 16, 4096);
}

void raiseByStock(ddf::GeneratedSurface& part, double stockMm) {
  std::vector<float>& h = part.ddf.allHeights();
  const int n = part.ddf.raster().steps();
  for (int f = 0; f < part.ddf.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * part.ddf.pointsPerFace();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l) {
        const double length = part.ddf.vectorAt(f, part.ddf.rasterBary(i, k)).norm();
        h[l] = static_cast<float>(h[l] + stockMm / length);
      }
  }
}

// Faces whose three support vertices satisfy inside(position).
template <class Pred>
std::vector<int> facesWhere(const ddf::DisplacementField& ddf, Pred&& inside) {
  std::vector<int> out;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& v = ddf.faceVertices(f);
    if (inside(ddf.position(v[0])) && inside(ddf.position(v[1])) && inside(ddf.position(v[2])))
      out.push_back(f);
  }
  return out;
}

// Passes along +y on the plane z = 0, at x = w (p + 1); the raster lattice (step w / (2q))
// holds the contact lines and the cusps between them.
ScallopSetup planeSetup(const ScallopCase& c, const ScallopSimulationParams& params, int q) {
  const double w = c.spacingMm;
  ddf::PlanePatchParams plane;
  plane.cellsX = 2 * (params.passes + 1);
  plane.cellsY = std::max(1, static_cast<int>(std::ceil(params.passLengthMm / (0.5 * w))));
  plane.size = {0.5 * w * plane.cellsX, 0.5 * w * plane.cellsY};
  plane.m = q + 1;
  plane.planeZMm = 0.0;
  plane.vectorLengthMm = std::max(1.0, 3.0 * params.stockMm);
  ScallopSetup s;
  s.part = ddf::planePatch(plane);
  s.spacingMm = w;
  s.rasterSpacingMm = s.feedStepMm = 0.5 * w / q;
  s.passLengthMm = plane.size.y();
  const double xLast = w * params.passes;
  s.region = facesWhere(s.part.ddf, [&](const Vec3& p) {
    return p.x() >= w - 1e-9 * w && p.x() <= xLast + 1e-9 * w;
  });
  s.frame = [w](int pass, double y, Vec3& contact, Vec3& normal, Vec3& feed) {
    contact = Vec3(w * (pass + 1), y, 0.0);
    normal = Vec3::UnitZ();
    feed = Vec3::UnitY();
  };
  return s;
}

// Passes along +z on a cylinder of radius 1/kappa, every second support vertex line apart (the
// spacing is rounded so that passes and cusps lie on vertex lines of the support).
ScallopSetup cylinderSetup(const ScallopCase& c, const ScallopSimulationParams& params, int q) {
  const double rho = 1.0 / c.crossFeedCurvaturePerMm;
  ddf::CylinderParams cyl;
  cyl.radiusMm = rho;
  cyl.segments =
      std::max(8, static_cast<int>(std::lround(4.0 * std::numbers::pi * rho / c.spacingMm)));
  const double dPhi = 2.0 * std::numbers::pi / cyl.segments;
  cyl.rings = std::max(1, static_cast<int>(std::ceil(params.passLengthMm / (0.5 * c.spacingMm))));
  cyl.lengthMm = 0.5 * c.spacingMm * cyl.rings;
  cyl.m = q + 1;
  cyl.crustFraction = std::clamp(4.0 * params.stockMm / rho, 0.02, 0.5);
  ScallopSetup s;
  s.part = ddf::cylinderPart(cyl);
  s.spacingMm = 2.0 * dPhi * rho;
  s.rasterSpacingMm = dPhi * rho / q;
  s.feedStepMm = cyl.lengthMm / cyl.rings / q;
  s.passLengthMm = cyl.lengthMm;
  const double lastAngle = 2.0 * dPhi * (params.passes - 1);
  s.region = facesWhere(s.part.ddf, [&](const Vec3& p) {
    const double angle = std::atan2(p.y(), p.x());
    return angle >= -1e-9 && angle <= lastAngle + 1e-9;
  });
  s.frame = [rho, dPhi](int pass, double z, Vec3& contact, Vec3& normal, Vec3& feed) {
    const double angle = 2.0 * dPhi * pass;
    normal = Vec3(std::cos(angle), std::sin(angle), 0.0);
    contact = rho * normal + Vec3(0.0, 0.0, z);
    feed = Vec3::UnitZ();
  };
  return s;
}

Tool caseTool(const ScallopCase& c, double tolMm) {
  Tool tool;
  tool.name = c.label;
  tool.radiusMm = c.radiusMm;
  tool.chordToleranceMm = tolMm;
  tool.segments = segmentsFor(c.radiusMm, tolMm);
  switch (c.model) {
    case ScallopToolModel::Ball:
      tool.kind = ToolKind::Sphere;
      break;
    case ScallopToolModel::FlatWheel:
      tool.kind = ToolKind::CylinderRoll;
      tool.widthMm = c.widthMm;
      break;
    case ScallopToolModel::TiltedFlatEnd:
      tool.kind = ToolKind::FlatEnd;
      tool.widthMm = c.radiusMm;
      break;
  }
  return tool;
}

// Tool frame -> part frame for a contact with unit normal n and unit feed f.
Eigen::Isometry3d casePose(const ScallopCase& c, const Vec3& contact, const Vec3& n,
                           const Vec3& f) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  switch (c.model) {
    case ScallopToolModel::Ball:
      pose.translation() = contact + c.radiusMm * n;
      return pose;
    case ScallopToolModel::FlatWheel:
      return rollPoseAtContact(contact, n, f, c.radiusMm, 0.0);
    case ScallopToolModel::TiltedFlatEnd: {
      // Axis tilted by the lead angle towards the feed; the heel of the bottom rim (direction
      // d = cos(l) f - sin(l) n from the tip) touches the contact.
      const double cl = std::cos(c.leadAngleRad), sl = std::sin(c.leadAngleRad);
      const Vec3 axis = cl * n + sl * f;
      const Vec3 d = cl * f - sl * n;
      Eigen::Matrix3d r;
      r.col(0) = d;
      r.col(1) = axis.cross(d);
      r.col(2) = axis;
      pose.linear() = r;
      pose.translation() = contact - c.radiusMm * d;
      return pose;
    }
  }
  return pose;
}

void validateCase(const ScallopCase& c, const ScallopSimulationParams& params) {
  if (params.passes < 2)
    throw InvalidInput("simulateScallopCase: needs >= 2 passes, got " +
                       std::to_string(params.passes));
  if (!(params.rasterStepsPerSpacing >= 2.0) || !(params.passLengthMm > 0.0) ||
      !(params.chordToleranceMm > 0.0) || !(params.stockMm > 0.0)) {
    throw InvalidInput(
        "simulateScallopCase: raster steps >= 2, pass length, chord tolerance "
        "and stock > 0 required");
  }
  if (!(c.spacingMm > 0.0) || !std::isfinite(c.spacingMm))
    throw InvalidInput("simulateScallopCase: case '" + c.label + "' needs a spacing > 0");
  if (!(c.crossFeedCurvaturePerMm >= 0.0))
    throw InvalidInput("simulateScallopCase: case '" + c.label +
                       "': only planes and convex cylinders (kappa >= 0) are simulated");
}

// The row's theory columns for the spacing actually used.
ScallopRow theoryRow(const ScallopCase& c, const ScallopSetup& s) {
  ScallopCase actual = c;
  actual.spacingMm = s.spacingMm;
  ScallopRow row;
  row.tool = c.label;
  row.spacingMm = s.spacingMm;
  row.curvaturePerMm = c.crossFeedCurvaturePerMm;
  row.predictedMm = predictedScallopMm(actual);
  const double effective = c.model == ScallopToolModel::Ball ? c.radiusMm
                           : c.model == ScallopToolModel::FlatWheel
                               ? std::numeric_limits<double>::infinity()
                               : tiltedFlatEffectiveRadiusMm(c.radiusMm, c.leadAngleRad);
  row.approximateMm = approximateScallopMm(effective, s.spacingMm, c.crossFeedCurvaturePerMm);
  row.rasterSpacingMm = s.rasterSpacingMm;
  return row;
}

// The passes: poses on every raster line across the feed, so the feed-direction cusps between
// poses do not show at raster points; a tilted flat end cuts with a rim point behind its
// contact, so it gets finer steps (its feed cusps grow linearly with the step, ~ step tan(l))
// and runs on by the rim's trailing offset R cos(l) (1 - cos(psi)), sin(psi) = w / (2R).
ToolPath passes(const ScallopCase& c, const ScallopSetup& s, double predictedMm, int count) {
  double step = s.feedStepMm;
  double runOn = 0.0;
  if (c.model == ScallopToolModel::TiltedFlatEnd) {
    if (predictedMm > 0.0) {
      const double wanted = 0.02 * predictedMm / std::tan(c.leadAngleRad);
      step /= std::clamp(std::ceil(step / wanted), 1.0, 64.0);
    }
    const double sinPsi = std::min(1.0, 0.5 * s.spacingMm / c.radiusMm);
    runOn = c.radiusMm * std::cos(c.leadAngleRad) * (1.0 - std::sqrt(1.0 - sinPsi * sinPsi)) + step;
  }
  ToolPath path;
  path.name = c.label;
  const int posesPerPass = static_cast<int>(std::lround((s.passLengthMm + runOn) / step)) + 1;
  for (int p = 0; p < count; ++p) {
    path.passStarts.push_back(static_cast<int>(path.poses.size()));
    for (int i = 0; i < posesPerPass; ++i) {
      Vec3 contact, normal, feed;
      s.frame(p, i * step, contact, normal, feed);
      path.poses.push_back({casePose(c, contact, normal, feed), contact});
    }
  }
  return path;
}

}  // namespace

ScallopRow simulateScallopCase(const ScallopCase& c, const ScallopSimulationParams& params) {
  validateCase(c, params);
  const int q = std::max(1, static_cast<int>(std::lround(params.rasterStepsPerSpacing / 2.0)));
  ScallopSetup s =
      c.crossFeedCurvaturePerMm > 0.0 ? cylinderSetup(c, params, q) : planeSetup(c, params, q);
  ScallopRow row = theoryRow(c, s);
  s.desired = s.part.ddf.allHeights();
  raiseByStock(s.part, params.stockMm);
  PathSimulationParams simulation;
  simulation.progress = params.progress;
  simulatePath(s.part.ddf, caseTool(c, params.chordToleranceMm),
               passes(c, s, row.predictedMm, params.passes), simulation);
  const ScalarField deviation = deviationMap(s.part.ddf, s.desired);
  row.simulatedMm = measuredScallopMm(deviation, s.part.ddf, s.region);
  if (row.predictedMm != 0.0) {
    row.relativeError = (row.simulatedMm - row.predictedMm) / row.predictedMm;
  } else {
    row.relativeError = row.simulatedMm == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  }
  return row;
}

std::vector<ScallopRow> scallopTable(std::span<const ScallopCase> cases,
                                     const ScallopSimulationParams& params) {
  std::vector<ScallopRow> rows;
  rows.reserve(cases.size());
  for (const ScallopCase& c : cases) rows.push_back(simulateScallopCase(c, params));
  return rows;
}

}  // namespace ddfcam::planning
