// SPDX-License-Identifier: MIT
// Tests of the parametric tool meshes against closed-form shapes: watertightness, volume,
// distance of the facets to the true surface, extremes, and the checks of validateTool.
#include <ddfcam/error.h>
#include <ddfcam/planning/tools/revolved_mesh.h>
#include <ddfcam/planning/tools/tool.h>
#include <ddfcam/planning/tools/tool_profiles.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace ddfcam::planning {
namespace {

constexpr double kPi = std::numbers::pi;

/// Every directed edge once and its reverse once: closed, consistently oriented, manifold.
void expectWatertight(const ddf::TriangleMesh& mesh, const std::string& what) {
  std::map<std::pair<int, int>, int> edges;
  for (const auto& t : mesh.triangles) {
    EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) << what;
    for (int i = 0; i < 3; ++i) ++edges[{t[i], t[(i + 1) % 3]}];
  }
  int bad = 0;
  for (const auto& [e, n] : edges) {
    const auto back = edges.find({e.second, e.first});
    if (n != 1 || back == edges.end() || back->second != 1) ++bad;
  }
  EXPECT_EQ(bad, 0) << what << ": edges not shared by exactly two opposite triangles";
  EXPECT_FALSE(mesh.triangles.empty()) << what;
}

/// A piece of a meridian curve in the (axial, radial) half plane, written out here from the
/// shapes' definitions (independently of tool_profiles.cpp).
struct Piece {
  bool arc;
  double a0, r0, a1, r1;        // line ends, or for an arc: centre (a0, r0), radius a1, unused r1
  double from = 0.0, to = 0.0;  // arc angle range (from < to), rad
};

double distanceToPiece(const Piece& p, double a, double r) {
  if (!p.arc) {
    const double da = p.a1 - p.a0, dr = p.r1 - p.r0;
    if (da == 0.0 && dr == 0.0) return std::hypot(a - p.a0, r - p.r0);
    const double u =
        std::clamp(((a - p.a0) * da + (r - p.r0) * dr) / (da * da + dr * dr), 0.0, 1.0);
    return std::hypot(a - p.a0 - u * da, r - p.r0 - u * dr);
  }
  const double angle = std::atan2(r - p.r0, a - p.a0);
  if (angle >= p.from - 1e-12 && angle <= p.to + 1e-12)
    return std::abs(std::hypot(a - p.a0, r - p.r0) - p.a1);
  double best = INFINITY;
  for (const double t : {p.from, p.to})
    best = std::min(best, std::hypot(a - p.a0 - p.a1 * std::cos(t), r - p.r0 - p.a1 * std::sin(t)));
  return best;
}

Piece line(double a0, double r0, double a1, double r1) {
  return {false, a0, r0, a1, r1};
}
Piece arcPiece(double ca, double cr, double radius, double from, double to) {
  return {true, ca, cr, radius, 0.0, from, to};
}

/// The meridian of a wheel: side faces, rim fillets, flat or crowned mantle.
std::vector<Piece> wheelMeridian(double R, double w, double e, double C) {
  const double h = 0.5 * w;
  if (C == 0.0)
    return {line(-h, 0, -h, R - e), arcPiece(-h + e, R - e, e, kPi / 2, kPi),
            line(-h + e, R, h - e, R), arcPiece(h - e, R - e, e, 0, kPi / 2), line(h, 0, h, R - e)};
  // Fillet circle tangent to the side face and inside the crown circle (centre (0, R - C)).
  const double yc = R - C + std::sqrt((C - e) * (C - e) - (h - e) * (h - e));
  const double t = std::atan2(yc - (R - C), h - e);  // crown angle of the right tangent point
  return {line(-h, 0, -h, yc), arcPiece(-(h - e), yc, e, kPi - t, kPi),
          arcPiece(0, R - C, C, t, kPi - t), arcPiece(h - e, yc, e, 0, t), line(h, 0, h, yc)};
}

double meridianDistance(const std::vector<Piece>& pieces, double a, double r) {
  double best = INFINITY;
  for (const Piece& p : pieces) best = std::min(best, distanceToPiece(p, a, r));
  return best;
}

/// Largest distance of the vertices (must be ~0) and of points spread over each facet (must
/// be within the tolerance) to the true surface.
void expectWithinTolerance(const ddf::TriangleMesh& mesh, const std::vector<Piece>& meridian,
                           bool axisX, double tolerance, const std::string& what) {
  auto meridianPoint = [&](const Eigen::Vector3d& p) {
    return axisX ? std::pair{p.x(), std::hypot(p.y(), p.z())}
                 : std::pair{p.z(), std::hypot(p.x(), p.y())};
  };
  double vertexWorst = 0.0, facetWorst = 0.0;
  for (const Eigen::Vector3d& v : mesh.vertices) {
    const auto [a, r] = meridianPoint(v);
    vertexWorst = std::max(vertexWorst, meridianDistance(meridian, a, r));
  }
  constexpr int n = 4;
  for (const auto& t : mesh.triangles)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Eigen::Vector3d p = (i * mesh.vertices[t[0]] + j * mesh.vertices[t[1]] +
                                   (n - i - j) * mesh.vertices[t[2]]) /
                                  n;
        const auto [a, r] = meridianPoint(p);
        facetWorst = std::max(facetWorst, meridianDistance(meridian, a, r));
      }
  EXPECT_LT(vertexWorst, 1e-9) << what;
  EXPECT_LE(facetWorst, tolerance) << what;
  EXPECT_GT(facetWorst, 0.05 * tolerance) << what << ": far finer than asked";
}

/// Inscribed in a convex solid: 0 < V - V_mesh <= (surface area) * tolerance; the area is
/// bounded by that of the enclosing cylinder.
void expectVolume(const ddf::TriangleMesh& mesh, double exact, double areaBound, double tol,
                  const std::string& what) {
  const double v = mesh.signedVolume();
  EXPECT_GT(v, 0.0) << what;
  EXPECT_LE(v, exact * (1 + 1e-12)) << what;
  EXPECT_GE(v, exact - areaBound * tol) << what;
}

double simpson(const std::function<double(double)>& f, double lo, double hi, int n = 20000) {
  const double step = (hi - lo) / n;
  double sum = f(lo) + f(hi);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4.0 : 2.0) * f(lo + i * step);
  return sum * step / 3.0;
}

Tool makeTool(ToolKind kind, double r, double w, double e = 0.0, double c = 0.0) {
  Tool t{.name = "t",
         .kind = kind,
         .radiusMm = r,
         .widthMm = w,
         .edgeRadiusMm = e,
         .crownRadiusMm = c,
         .chordToleranceMm = 0.01,
         .segments = 0};
  return t;
}

TEST(ToolLibrary, PlainRollIsTheInscribedPrismExactly) {
  Tool roll = makeTool(ToolKind::CylinderRoll, 5.0, 10.0);
  const ddf::TriangleMesh mesh = toolMesh(roll);
  const int s = static_cast<int>(mesh.triangles.size()) / 4;
  EXPECT_EQ(s % 4, 0);
  // Sagitta R (1 - cos(pi / s)) within half the tolerance, and s the smallest multiple of 4.
  EXPECT_LE(5.0 * (1 - std::cos(kPi / s)), 0.005);
  EXPECT_GT(5.0 * (1 - std::cos(kPi / (s - 4))), 0.005);
  expectWatertight(mesh, "roll");
  EXPECT_NEAR(mesh.signedVolume(), 0.5 * s * std::sin(2 * kPi / s) * 25.0 * 10.0, 1e-9);
  EXPECT_NEAR(mesh.bounds()[0].z(), -5.0, 1e-12);
  roll.segments = 40;
  EXPECT_EQ(toolMesh(roll).triangles.size(), 160u);
}

TEST(ToolLibrary, CrownedRoundedWheelsMatchTheirMeridian) {
  for (const ToolKind kind : {ToolKind::CylinderRoll, ToolKind::BeltContactWheel}) {
    for (const auto& [e, C] : std::vector<std::pair<double, double>>{{1.0, 0.0},
                                                                     {0.0, 30.0},
                                                                     {1.5, 30.0},
                                                                     {5.0, 0.0},
                                                                     {0.0, 5.0},
                                                                     {1.0, 5.0},
                                                                     {5.0, 30.0}}) {
      const Tool t = makeTool(kind, 8.0, 10.0, e, C);
      const std::string what =
          std::string(toolKindName(kind)) + " e=" + std::to_string(e) + " C=" + std::to_string(C);
      const ddf::TriangleMesh mesh = toolMesh(t);
      expectWatertight(mesh, what);
      const std::vector<Piece> meridian = wheelMeridian(8.0, 10.0, e, C);
      expectWithinTolerance(mesh, meridian, true, t.chordToleranceMm, what);
      // Volume: pi r(x)^2 integrated, r(x) the outermost meridian radius at x.
      auto radius = [&](double x) {
        const double h = 5.0;
        if (C == 0.0) {
          const double d = std::max(0.0, std::abs(x) - (h - e));
          return 8.0 - e + std::sqrt(std::max(0.0, e * e - d * d));
        }
        const double yc = 8.0 - C + std::sqrt((C - e) * (C - e) - (h - e) * (h - e));
        const double xt = (h - e) * C / (C - e);  // crown / fillet tangent point
        if (std::abs(x) <= xt) return 8.0 - C + std::sqrt(C * C - x * x);
        const double d = std::abs(x) - (h - e);
        return yc + std::sqrt(std::max(0.0, e * e - d * d));
      };
      const double exact = simpson([&](double x) { return kPi * radius(x) * radius(x); }, -5, 5);
      expectVolume(mesh, exact, 2 * kPi * 8 * 10 + 2 * kPi * 64, t.chordToleranceMm, what);
      EXPECT_NEAR(mesh.bounds()[0].z(), -8.0, 1e-12) << what << ": lowest point";
      EXPECT_NEAR(mesh.bounds()[1].x(), 5.0, 1e-12) << what;
    }
  }
}

TEST(ToolLibrary, CuttersMatchTheirMeridianAndVolume) {
  struct Case {
    ToolKind kind;
    double corner, exact;
  };
  const double R = 3.0, w = 12.0, e = 1.0;
  const std::vector<Case> cases{
      {ToolKind::BallEnd, R, 2.0 / 3.0 * kPi * R * R * R + kPi * R * R * (w - R)},
      {ToolKind::FlatEnd, 0.0, kPi * R * R * w},
      // Pappus: inner cylinder, outer ring above the corner, corner quarter disc.
      {ToolKind::TorusCutter, e,
       kPi * (R - e) * (R - e) * w + kPi * (R * R - (R - e) * (R - e)) * (w - e) +
           2 * kPi * ((R - e) + 4 * e / (3 * kPi)) * kPi * e * e / 4}};
  for (const Case& c : cases) {
    const Tool t = makeTool(c.kind, R, w, c.kind == ToolKind::TorusCutter ? e : 0.0);
    const std::string what(toolKindName(c.kind));
    const ddf::TriangleMesh mesh = toolMesh(t);
    expectWatertight(mesh, what);
    std::vector<Piece> meridian{line(0, 0, 0, R - c.corner), line(c.corner, R, w, R),
                                line(w, 0, w, R)};
    if (c.corner > 0) meridian.push_back(arcPiece(c.corner, R - c.corner, c.corner, kPi / 2, kPi));
    expectWithinTolerance(mesh, meridian, false, t.chordToleranceMm, what);
    expectVolume(mesh, c.exact, 2 * kPi * R * w + 2 * kPi * R * R, t.chordToleranceMm, what);
    const auto [lo, hi] = mesh.bounds();
    EXPECT_NEAR(lo.z(), 0.0, 1e-12) << what << ": tip at the origin";
    EXPECT_NEAR(hi.z(), w, 1e-12) << what;
    bool tip = false;
    for (const Eigen::Vector3d& v : mesh.vertices) tip = tip || v.norm() < 1e-12;
    EXPECT_TRUE(tip) << what << ": a vertex at the tip";
  }
}

TEST(ToolLibrary, SphereFromToleranceAndFromSegments) {
  Tool ball = makeTool(ToolKind::Sphere, 2.0, 0.0);
  const ddf::TriangleMesh mesh = toolMesh(ball);
  expectWatertight(mesh, "sphere");
  expectWithinTolerance(mesh, {arcPiece(0, 0, 2.0, 0, kPi)}, false, 0.01, "sphere");
  expectVolume(mesh, 4.0 / 3.0 * kPi * 8.0, 4 * kPi * 4.0, 0.01, "sphere");
  EXPECT_TRUE(toolMeshes(ball).nonCutting.triangles.empty());
  ball.segments = 40;  // the UV sphere of format-2 projects: 20 rings
  EXPECT_EQ(toolMesh(ball).triangles.size(), 2u * 40u + 18u * 80u);
}

TEST(ToolLibrary, NonCuttingPartsAreClosedStepsBesideTheCuttingPart) {
  Tool wheel = makeTool(ToolKind::CylinderRoll, 25.0, 20.0, 1.0);
  wheel.segments = 64;
  wheel.shankRadiusMm = 8.0;
  wheel.shankLengthMm = 15.0;
  wheel.holderRadiusMm = 18.0;
  wheel.holderLengthMm = 3.0;
  const ToolMeshes w = toolMeshes(wheel);
  expectWatertight(w.nonCutting, "arbor and flanges");
  const double polygon = 0.5 * 64 * std::sin(2 * kPi / 64);  // inscribed 64-gon / r^2
  // Per side: flange 3 mm of r 18, then arbor 12 mm of r 8.
  EXPECT_NEAR(w.nonCutting.signedVolume(), 2 * polygon * (18 * 18 * 3.0 + 8 * 8 * 12.0), 1e-6);
  for (const Eigen::Vector3d& v : w.nonCutting.vertices) EXPECT_GE(std::abs(v.x()), 10.0 - 1e-12);
  EXPECT_NEAR(w.nonCutting.bounds()[1].x(), 25.0, 1e-12);
  EXPECT_EQ(w.cutting.triangles, toolMesh(wheel).triangles);

  Tool cutter = makeTool(ToolKind::TorusCutter, 6.0, 18.0, 2.0);
  cutter.segments = 48;
  cutter.shankRadiusMm = 6.0;
  cutter.shankLengthMm = 35.0;
  cutter.holderRadiusMm = 16.0;
  cutter.holderLengthMm = 45.0;
  const ToolMeshes c = toolMeshes(cutter);
  expectWatertight(c.nonCutting, "shank and holder");
  const double poly48 = 0.5 * 48 * std::sin(2 * kPi / 48);
  EXPECT_NEAR(c.nonCutting.signedVolume(), poly48 * (36.0 * 35.0 + 256.0 * 45.0), 1e-6);
  const auto [lo, hi] = c.nonCutting.bounds();
  EXPECT_NEAR(lo.z(), 18.0, 1e-12);
  EXPECT_NEAR(hi.z(), 18.0 + 35.0 + 45.0, 1e-12);
  EXPECT_LE(c.cutting.bounds()[1].z(), 18.0 + 1e-12);
  // Holder only (no shank): it starts on the cutting part.
  cutter.shankRadiusMm = 0.0;
  EXPECT_NEAR(toolMeshes(cutter).nonCutting.bounds()[0].z(), 18.0 + 35.0, 1e-12);
  cutter.holderRadiusMm = 0.0;
  EXPECT_TRUE(toolMeshes(cutter).nonCutting.vertices.empty());
}

TEST(ToolLibrary, ProfileRadiusAtFollowsTheShape) {
  const ToolProfile p = toolProfile(makeTool(ToolKind::BallEnd, 3.0, 12.0));
  EXPECT_NEAR(p.radiusAt(0.0), 0.0, 1e-12);
  EXPECT_NEAR(p.radiusAt(1.0), std::sqrt(9.0 - 4.0), 1e-12);
  EXPECT_NEAR(p.radiusAt(7.0), 3.0, 1e-12);
  EXPECT_EQ(p.radiusAt(13.0), 0.0);
  EXPECT_EQ(p.axialRange(), std::make_pair(0.0, 12.0));
  const ToolProfile crowned = toolProfile(makeTool(ToolKind::CylinderRoll, 8.0, 10.0, 0.0, 30.0));
  EXPECT_NEAR(crowned.radiusAt(3.0), 8.0 - 30.0 + std::sqrt(900.0 - 9.0), 1e-12);
  EXPECT_NEAR(crowned.maxRadius(), 8.0, 1e-12);
}

void expectRejected(const Tool& tool, const std::string& field) {
  try {
    validateTool(tool);
    ADD_FAILURE() << "accepted, expected a complaint about " << field;
  } catch (const InvalidInput& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("'" + tool.name + "'"), std::string::npos) << message;
    EXPECT_NE(message.find(field), std::string::npos) << message;
  }
}

TEST(ToolLibrary, ValidateToolNamesTheBadField) {
  const Tool roll = makeTool(ToolKind::CylinderRoll, 8.0, 10.0);
  auto with = [](Tool t, auto change) {
    change(t);
    return t;
  };
  expectRejected(with(roll, [](Tool& t) { t.radiusMm = 0.0; }), "radius");
  expectRejected(with(roll, [](Tool& t) { t.widthMm = NAN; }), "width");
  expectRejected(with(roll, [](Tool& t) { t.edgeRadiusMm = 5.5; }), "edge radius");
  expectRejected(with(roll, [](Tool& t) { t.edgeRadiusMm = -1.0; }), "edge radius");
  expectRejected(with(roll, [](Tool& t) { t.crownRadiusMm = 4.0; }), "crown radius");
  expectRejected(with(roll, [](Tool& t) { t.crownRadiusMm = 6.0, t.radiusMm = 0.5; }), "crown");
  expectRejected(with(roll, [](Tool& t) { t.edgeRadiusMm = 5.0, t.radiusMm = 4.0; }), "edge");
  expectRejected(with(roll, [](Tool& t) { t.shankRadiusMm = -1.0; }), "shank radius");
  expectRejected(with(roll, [](Tool& t) { t.shankLengthMm = -1.0; }), "shank length");
  expectRejected(with(roll, [](Tool& t) { t.holderRadiusMm = 8.0; }), "holder");
  expectRejected(with(roll, [](Tool& t) { t.holderLengthMm = -2.0; }), "holder length");
  expectRejected(with(roll, [](Tool& t) { t.chordToleranceMm = 0.0; }), "chord tolerance");
  expectRejected(with(roll, [](Tool& t) { t.chordToleranceMm = 1e-9; }), "chord tolerance");
  expectRejected(with(roll, [](Tool& t) { t.segments = 2; }), "segments");
  expectRejected(with(roll, [](Tool& t) { t.kind = static_cast<ToolKind>(9); }), "kind");
  const Tool ball = makeTool(ToolKind::BallEnd, 3.0, 12.0);
  expectRejected(with(ball, [](Tool& t) { t.widthMm = 2.0; }), "width");
  const Tool torus = makeTool(ToolKind::TorusCutter, 3.0, 12.0, 1.0);
  expectRejected(with(torus, [](Tool& t) { t.edgeRadiusMm = 0.0; }), "corner");
  expectRejected(with(torus, [](Tool& t) { t.edgeRadiusMm = 3.0; }), "corner");
  expectRejected(with(torus, [](Tool& t) { t.widthMm = 0.5; }), "width");
  expectRejected(with(makeTool(ToolKind::Sphere, 3.0, 0.0), [](Tool& t) { t.segments = 3; }),
                 "segments");
  // Fields a kind does not use do not matter.
  EXPECT_NO_THROW(validateTool(with(ball, [](Tool& t) { t.crownRadiusMm = 1.0; })));
  EXPECT_NO_THROW(validateTool(makeTool(ToolKind::Sphere, 3.0, -1.0)));
}

TEST(ToolLibrary, KindNamesRoundTrip) {
  for (int k = 0; k < 6; ++k) {
    const auto kind = static_cast<ToolKind>(k);
    EXPECT_EQ(toolKindFromName(toolKindName(kind)), kind);
  }
  EXPECT_FALSE(toolKindFromName("drill"));
  EXPECT_EQ(toolKindName(static_cast<ToolKind>(42)), "unknown");
}

TEST(RevolvedMesh, RejectsProfilesOffTheAxis) {
  const std::vector<ProfilePoint> open{{0, 1}, {1, 1}, {1, 0}};
  EXPECT_THROW(revolveProfile(open, RevolveAxis::Z, 8), InvalidInput);
  const std::vector<ProfilePoint> pinched{{0, 0}, {1, 1}, {2, 0}, {3, 1}, {4, 0}};
  EXPECT_THROW(revolveProfile(pinched, RevolveAxis::Z, 8), InvalidInput);
  const std::vector<ProfilePoint> cone{{0, 0}, {0, 1}, {2, 0}};
  const ddf::TriangleMesh mesh = revolveProfile(cone, RevolveAxis::Z, 16);
  expectWatertight(mesh, "cone");
  // Either direction gives the same outward solid.
  const std::vector<ProfilePoint> reversed{{2, 0}, {0, 1}, {0, 0}};
  EXPECT_NEAR(revolveProfile(reversed, RevolveAxis::Z, 16).signedVolume(), mesh.signedVolume(),
              1e-12);
  EXPECT_NEAR(mesh.signedVolume(), 2.0 / 3.0 * 0.5 * 16 * std::sin(2 * kPi / 16), 1e-12);
  EXPECT_THROW(revolveProfile(cone, RevolveAxis::Z, 2), InvalidInput);
}

}  // namespace
}  // namespace ddfcam::planning
