// SPDX-License-Identifier: MIT
// Tests of placeTool against the tool meshes and analytic placements of balls, tori, flat
// cutters and wheels.
#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tool_orientation.h>
#include <ddfcam/planning/placement/tool_placement.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kDeg = std::numbers::pi / 180.0;

/// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closestOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double distanceToMesh(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose, const Vec3& p) {
  const Vec3 q = pose.inverse() * p;
  double best = 1e300;
  for (const auto& t : mesh.triangles) {
    const Vec3 c =
        closestOnTriangle(q, mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    best = std::min(best, (c - q).norm());
  }
  return best;
}

std::vector<Tool> allKinds() {
  const auto make = [](std::string name, ToolKind kind, double r, double w, double e, double c) {
    Tool t;
    t.name = std::move(name);
    t.kind = kind;
    t.radiusMm = r;
    t.widthMm = w;
    t.edgeRadiusMm = e;
    t.crownRadiusMm = c;
    t.segments = 0;
    t.chordToleranceMm = 0.003;
    return t;
  };
  return {make("roll", ToolKind::CylinderRoll, 5, 10, 0, 0),
          make("crowned roll", ToolKind::CylinderRoll, 6, 8, 1, 12),
          make("belt wheel", ToolKind::BeltContactWheel, 8, 6, 0.5, 0),
          make("ball", ToolKind::Sphere, 3, 0, 0, 0),
          make("ball end", ToolKind::BallEnd, 3, 8, 0, 0),
          make("flat end", ToolKind::FlatEnd, 4, 8, 0, 0),
          make("torus", ToolKind::TorusCutter, 5, 8, 1.5, 0)};
}

struct RandomContact {
  Vec3 contact, normal, feed;
};

RandomContact randomContact(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return {Vec3(10 * u(rng), 10 * u(rng), 10 * u(rng)), Vec3(u(rng), u(rng), u(rng)).normalized(),
          Vec3(u(rng), u(rng), u(rng))};
}

TEST(ToolOrientation, EveryKindTouchesTheTangentPlaneAtTheContactFromTheToolSide) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-60.0, 60.0);
  for (const Tool& tool : allKinds()) {
    SCOPED_TRACE(tool.name);
    const ddf::TriangleMesh mesh = toolMesh(tool);
    for (int trial = 0; trial < 12; ++trial) {
      const RandomContact c = randomContact(rng);
      const PlacementParams params{angle(rng), angle(rng), 0.0};
      const Eigen::Isometry3d pose = placeTool(tool, c.contact, c.normal, c.feed, params);
      double lowest = 1e300;
      for (const Vec3& v : mesh.vertices)
        lowest = std::min(lowest, c.normal.dot(pose * v - c.contact));
      SCOPED_TRACE(tool.name + " lead " + std::to_string(params.leadDeg) + " tilt " +
                   std::to_string(params.tiltDeg));
      // Vertices lie on the true surface, facets within the chord tolerance of it.
      EXPECT_GE(lowest, -1e-9);
      EXPECT_LE(lowest, tool.chordToleranceMm + 1e-9);
      EXPECT_LE(distanceToMesh(mesh, pose, c.contact), tool.chordToleranceMm + 1e-9);
    }
  }
}

TEST(ToolOrientation, BallCentresSitOneRadiusAlongTheSphereNormal) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> angle(-70.0, 70.0);
  const double sphereRadius = 20.0;
  for (const ToolKind kind : {ToolKind::BallEnd, ToolKind::Sphere}) {
    const Tool tool{.name = "b", .kind = kind, .radiusMm = 2.5, .widthMm = 6.0};
    for (int trial = 0; trial < 20; ++trial) {
      const RandomContact c = randomContact(rng);
      const Vec3 contact = sphereRadius * c.normal;  // on a sphere at the origin, normal radial
      const Eigen::Isometry3d pose =
          placeTool(tool, contact, c.normal, c.feed, {angle(rng), angle(rng), 0.0});
      const Vec3 centre = kind == ToolKind::Sphere
                              ? pose.translation()
                              : Vec3(pose.translation() + 2.5 * pose.linear().col(2));
      EXPECT_LT((centre - (sphereRadius + 2.5) * c.normal).norm(), 1e-12);
    }
  }
}

TEST(ToolOrientation, TorusTubeCentreIsTheCornerRadiusAlongTheNormal) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> angle(-60.0, 60.0);
  const Tool torus{.name = "t",
                   .kind = ToolKind::TorusCutter,
                   .radiusMm = 5.0,
                   .widthMm = 8.0,
                   .edgeRadiusMm = 1.5};
  for (int trial = 0; trial < 20; ++trial) {
    const RandomContact c = randomContact(rng);
    PlacementParams params{angle(rng), angle(rng), 0.0};
    if (trial == 0) params.leadDeg = 7.0, params.tiltDeg = 0.0;
    const Eigen::Isometry3d pose = placeTool(torus, c.contact, c.normal, c.feed, params);
    // contact + r n lies on the tube's centre circle: radius R - r about the axis, r above the tip.
    const Vec3 a = pose.linear().col(2);
    const Vec3 q = c.contact + 1.5 * c.normal - (pose.translation() + 1.5 * a);
    EXPECT_NEAR(q.dot(a), 0.0, 1e-12);
    EXPECT_NEAR((q - q.dot(a) * a).norm(), 3.5, 1e-12);
  }
}

TEST(ToolOrientation, FlatEndTouchesWithItsLeadingRimOrItsWholeBottom) {
  const Tool flat{.name = "f", .kind = ToolKind::FlatEnd, .radiusMm = 4.0, .widthMm = 8.0};
  const Vec3 n = Vec3(1, 2, 2) / 3.0, contact(1, -2, 3);
  const Vec3 t = Vec3(2, 1, -2) / 3.0;  // unit, perpendicular to n
  const Eigen::Isometry3d level = placeTool(flat, contact, n, t + 0.3 * n);
  EXPECT_LT((level.translation() - contact).norm(), 1e-12);
  EXPECT_LT((level.linear().col(2) - n).norm(), 1e-12);
  for (const double lead : {3.0, 15.0, 45.0, 80.0}) {
    const double l = lead * kDeg;
    const Eigen::Isometry3d pose = placeTool(flat, contact, n, t, {lead, 0.0, 0.0});
    EXPECT_LT((pose.linear().col(2) - (std::sin(l) * t + std::cos(l) * n)).norm(), 1e-12);
    // The rim point ahead of the tip touches: tip = contact - R (cos l t - sin l n).
    const Vec3 tip = contact - 4.0 * (std::cos(l) * t - std::sin(l) * n);
    EXPECT_LT((pose.translation() - tip).norm(), 1e-12) << lead;
  }
}

TEST(ToolOrientation, WheelOnACylinderAlongItsAxisRestsOnTheLineOfContact) {
  const double rho = 15.0;
  const Tool roll{.name = "roll", .radiusMm = 5.0, .widthMm = 10.0, .segments = 64};
  const ddf::TriangleMesh mesh = toolMesh(roll);
  for (const double phi : {0.0, 0.7, 2.5, -1.9}) {
    const Vec3 n(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 contact = rho * n + Vec3(0, 0, 4.0);
    const Eigen::Isometry3d pose = placeTool(roll, contact, n, Vec3::UnitZ());
    EXPECT_LT((pose.translation() - (rho + 5.0) * n - Vec3(0, 0, 4.0)).norm(), 1e-12);
    const Vec3 axis = pose.linear().col(0);
    EXPECT_NEAR(std::abs(axis.dot(Vec3(-n.y(), n.x(), 0.0))), 1.0, 1e-12);
    // The straight mantle runs along the tangent; the convex cylinder falls away from it.
    for (const Vec3& v : mesh.vertices) {
      const Vec3 p = pose * v;
      EXPECT_GE(std::hypot(p.x(), p.y()), rho - 1e-9);
    }
  }
}

TEST(ToolOrientation, LeadAndTiltMeasuredBackEqualTheInput) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> angle(-85.0, 85.0);
  for (const Tool& tool : allKinds()) {
    for (int trial = 0; trial < 10; ++trial) {
      const RandomContact c = randomContact(rng);
      const double lead = angle(rng), tilt = angle(rng);
      const Eigen::Isometry3d pose = placeTool(tool, c.contact, c.normal, c.feed, {lead, tilt, 0});
      const Vec3 t = (c.feed - c.feed.dot(c.normal) * c.normal).normalized();
      const Vec3 b = c.normal.cross(t);
      const Vec3 z = pose.linear().col(2);
      EXPECT_NEAR(std::asin(z.dot(t)) / kDeg, lead, 1e-9) << tool.name;
      EXPECT_NEAR(std::atan2(-z.dot(b), z.dot(c.normal)) / kDeg, tilt, 1e-9) << tool.name;
      const auto [l, s] = placementAnglesDeg(pose, c.normal, c.feed);
      EXPECT_NEAR(l, lead, 1e-9);
      EXPECT_NEAR(s, tilt, 1e-9);
      EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-12);
      if (tool.kind == ToolKind::CylinderRoll || tool.kind == ToolKind::BeltContactWheel) {
        const Vec3 axis = std::cos(tilt * kDeg) * b + std::sin(tilt * kDeg) * c.normal;
        EXPECT_LT((pose.linear().col(0) - axis).norm(), 1e-12);
      }
    }
  }
}

TEST(ToolOrientation, DepthSinksAlongTheNormalAndTheOffsetIsReported) {
  std::mt19937 rng(21);
  for (const Tool& tool : allKinds()) {
    const RandomContact c = randomContact(rng);
    const PlacementParams touching{10.0, -20.0, 0.0};
    const PlacementParams sunk{10.0, -20.0, 0.4};
    const ToolPlacement a = placeToolDetailed(tool, c.contact, c.normal, c.feed, touching);
    const ToolPlacement b = placeToolDetailed(tool, c.contact, c.normal, c.feed, sunk);
    EXPECT_LT((b.pose.translation() - a.pose.translation() + 0.4 * c.normal).norm(), 1e-12);
    EXPECT_LT((b.referenceOffset - (b.pose.translation() - c.contact)).norm(), 1e-15);
    EXPECT_LT((a.pose * a.toolContact - c.contact).norm(), 1e-12);
    const PathPose pathPose{b.pose, c.contact};
    EXPECT_LT((referenceOffset(pathPose) - b.referenceOffset).norm(), 1e-15);
  }
}

TEST(ToolOrientation, PlainRollAgreesWithRollPoseAtContact) {
  std::mt19937 rng(2);
  const Tool roll;
  for (int trial = 0; trial < 10; ++trial) {
    const RandomContact c = randomContact(rng);
    const auto expected = rollPoseAtContact(c.contact, c.normal, c.feed, roll.radiusMm, 0.2);
    const auto pose = placeTool(roll, c.contact, c.normal, c.feed, {0.0, 0.0, 0.2});
    EXPECT_LT((pose.matrix() - expected.matrix()).norm(), 1e-12);
  }
}

TEST(ToolOrientation, AxisEndsAreTheSideCentresOrTipAndTop) {
  const auto [w0, w1] = toolAxisEnds(Tool{});
  EXPECT_LT((w0 - Vec3(-5, 0, 0)).norm(), 1e-12);
  EXPECT_LT((w1 - Vec3(5, 0, 0)).norm(), 1e-12);
  const auto [c0, c1] =
      toolAxisEnds(Tool{.name = "f", .kind = ToolKind::FlatEnd, .radiusMm = 3, .widthMm = 7});
  EXPECT_LT(c0.norm(), 1e-12);
  EXPECT_LT((c1 - Vec3(0, 0, 7)).norm(), 1e-12);
}

void expectRejected(const std::function<void()>& call, const std::string& word) {
  try {
    call();
    ADD_FAILURE() << "no exception, expected one naming " << word;
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find(word), std::string::npos) << e.what();
  }
}

TEST(ToolOrientation, RejectsBadInputNamingIt) {
  const Tool ball{.name = "ball", .kind = ToolKind::BallEnd, .radiusMm = 2, .widthMm = 5};
  expectRejected([&] { placeTool(ball, {0, 0, 0}, {0, 0, 0}, {1, 0, 0}); }, "normal");
  expectRejected([&] { placeTool(ball, {0, 0, 0}, {0, 0, 1}, {0, 0, -3}); }, "feed");
  expectRejected([&] { placeTool(ball, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {95, 0, 0}); }, "lead");
  expectRejected([&] { placeTool(ball, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, -90, 0}); }, "tilt");
  Tool bad = ball;
  bad.radiusMm = -1;
  expectRejected([&] { placeTool(bad, {0, 0, 0}, {0, 0, 1}, {1, 0, 0}); }, "radius");
}

}  // namespace
}  // namespace ddfcam::planning
