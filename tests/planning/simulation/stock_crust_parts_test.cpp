// SPDX-License-Identifier: MIT
// The stock crust on shared third-party parts (label data; skips without the shared data): the
// turbine blade and fandisk converted with a reduced support at the default resolution, the
// crust fitted to a 0.5 mm allowance (the blade must hold it; fandisk, whose sharp concave
// creases forbid it, must refuse it naming the place and the largest allowance that holds, and
// the rest runs with that one), the part raised by it, and a ball sweeping the design surface
// grinding the stock back down to the design and nowhere below it.
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_normal.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/workpiece.h>
#include <ddfcam/planning/tools/tool_shapes.h>

#include <gtest/gtest.h>
#include <OpenMesh/Core/IO/MeshIO.hh>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <numbers>
#include <optional>

#include "../../support/brute_force_distance.h"
#include "../../support/ddf_surface_distance.h"
#include "../../support/support_triangles.h"

namespace ddfcam::planning {
namespace {

using ddf::Vec3;

constexpr double kStockMm = 0.5;
constexpr double kBallRadiusMm = 0.3;
constexpr int kBallSegments = 24;

/// The shared mesh @p name scaled by @p scale to mm, or nullopt when the data is absent.
std::optional<ddf::TriangleMesh> sharedMesh(const std::string& name, double scale) {
  const auto path = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / name;
  if (!std::filesystem::exists(path)) return std::nullopt;
  ddf::SupportMesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, path.string())) return std::nullopt;
  return test::supportTriangles(mesh, scale);
}

void printReach(const char* part, const char* when, const ddf::CrustReach& r) {
  std::cout << part << " crust reach " << when << ": above min " << r.minAboveMm << " median "
            << r.medianAboveMm << ", below min " << r.minBelowMm << " median " << r.medianBelowMm
            << " mm\n";
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// A ball contact: raster point (f, i, k) of the design and the ball centre touching it there.
struct Contact {
  int f, i, k;
  Vec3 centre;
};

/// Contacts on every @p stride-th face whose ball touches the design only there: the centre
/// lies kBallRadiusMm along the raster normal and no triangle of @p surface (the design's
/// lattice surface) comes closer to it.
std::vector<Contact> ballContacts(const ddf::DisplacementField& design,
                                  const ddf::TriangleMesh& surface, int stride) {
  std::vector<Contact> out;
  const int n = design.raster().steps();
  const test::TriangleRuns nearest(surface);
  for (int f = 0; f < design.faceCount(); f += stride) {
    const int i = n / 3, k = n / 3;
    const Vec3 q = design.surfacePoint(f, i, k);
    const Vec3 centre = q + kBallRadiusMm * ddf::rasterNormal(design, f, i, k);
    if (nearest.distance(centre) >= kBallRadiusMm * (1.0 - 1e-3))
      out.push_back({f, i, k, centre});
  }
  return out;
}

/// After the ball passes: nowhere below the design (the true ball keeps 1e-3 of its radius off
/// every raster point, the faceted one more), and at every contact within the facets' sag of
/// the design, the whole stock removed.
void expectGroundToDesign(const ddf::DisplacementField& design, const std::vector<float>& raised,
                          const ddf::DisplacementField& work, const std::vector<Contact>& contacts,
                          double allowanceMm) {
  const double belowTolMm = 2e-3 * kBallRadiusMm + 1e-5;
  const double sagMm =
      kBallRadiusMm * (1.0 - std::pow(std::cos(std::numbers::pi / kBallSegments), 2));
  double lowest = 0.0, worstContact = 0.0;
  for (int f = 0; f < design.faceCount(); ++f)
    for (int k = 0; k <= design.raster().steps(); ++k)
      for (int i = 0; i < design.raster().rowLength(k); ++i) {
        const double len = design.vectorAt(f, design.rasterBary(i, k)).norm();
        lowest = std::min(lowest, (work.height(f, i, k) - design.height(f, i, k)) * len);
      }
  for (const Contact& c : contacts) {
    const Vec3 v = design.vectorAt(c.f, design.rasterBary(c.i, c.k));
    const double len = v.norm();
    // What is left is measured along the normal, as the facets' sag is: along a stubble that
    // leans by an angle a it is 1 / cos a as long (a thin edge's stubbles lean by up to 70 deg).
    const double left = (work.height(c.f, c.i, c.k) - design.height(c.f, c.i, c.k)) *
                        v.dot(ddf::rasterNormal(design, c.f, c.i, c.k));
    worstContact = std::max(worstContact, left);
    const std::size_t at = c.f * design.pointsPerFace() + design.raster().index(c.i, c.k);
    EXPECT_GE((raised[at] - work.height(c.f, c.i, c.k)) * len, allowanceMm - 2.0 * sagMm);
  }
  std::cout << contacts.size() << " ball contacts: lowest height below the design " << -lowest
            << " mm, most left above it at a contact " << worstContact << " mm\n";
  EXPECT_GE(lowest, -belowTolMm);
  EXPECT_LE(worstContact, 2.0 * sagMm + 1e-4);
}

/// The largest concave turn, degrees, between the two triangles of an edge of @p mesh whose
/// midpoint lies within @p withinMm of @p point (brute force over all triangle pairs).
double sharpestConcaveTurnDeg(const ddf::TriangleMesh& mesh, const Vec3& point, double withinMm) {
  const auto& t = mesh.triangles;
  const auto normal = [&](std::size_t a) {
    const Vec3 &p0 = mesh.vertices[t[a][0]], &p1 = mesh.vertices[t[a][1]];
    return Vec3((p1 - p0).cross(mesh.vertices[t[a][2]] - p0).normalized());
  };
  std::vector<std::size_t> near;  // triangles with a vertex within reach of the point
  for (std::size_t a = 0; a < t.size(); ++a)
    for (int i : t[a])
      if ((mesh.vertices[i] - point).norm() <= withinMm) {
        near.push_back(a);
        break;
      }
  double sharpest = 0.0;
  for (std::size_t a : near)
    for (std::size_t b : near) {
      std::vector<int> shared;
      for (int i : t[a])
        if (std::find(t[b].begin(), t[b].end(), i) != t[b].end()) shared.push_back(i);
      if (shared.size() != 2) continue;
      const Vec3 mid = 0.5 * (mesh.vertices[shared[0]] + mesh.vertices[shared[1]]);
      if ((mid - point).norm() > withinMm) continue;
      int apex = -1;  // the vertex of b off the shared edge: in front of a where concave
      for (int i : t[b])
        if (i != shared[0] && i != shared[1]) apex = i;
      if ((mesh.vertices[apex] - mid).dot(normal(a)) <= 0.0) continue;
      const double c = std::clamp(normal(a).dot(normal(b)), -1.0, 1.0);
      sharpest = std::max(sharpest, std::acos(c) * 180.0 / std::numbers::pi);
    }
  return sharpest;
}

/// Converts @p input with a reduced support, fits the crust to kStockMm, raises the part by it
/// and grinds it back with a ball sweeping the design surface. Without @p concaveLimit the fit
/// must hold the allowance; with it the part has a sharp concave crease (radius far below the
/// allowance), and the fit must refuse the allowance naming a concave radius below it at a
/// place where the input does turn concavely.
void grindStockBackToDesign(const char* part, const ddf::TriangleMesh& input,
                            bool concaveLimit = false) {
  ddf::ConversionParams params;
  params.support = ddf::SupportChoice::Reduced;
  auto start = std::chrono::steady_clock::now();
  ddf::DisplacementField design = ddf::convertMeshToDdf(input, params).ddf;
  std::cout << part << ": " << design.faceCount() << " support faces, m = " << design.resolution()
            << ", converted in " << secondsSince(start) << " s\n";
  const ddf::CrustReach before = ddf::crustReach(design);
  const double outBefore = test::largestDistance(test::rasterSurfacePoints(design, 97), input);
  const double inBefore =
      test::largestDistance(test::triangleSamples(input, 89), test::latticeSurface(design));
  printReach(part, "before the fit", before);
  start = std::chrono::steady_clock::now();
  ddf::StockCrustParams stock;
  stock.stockMm = kStockMm;
  const ddf::StockFit fit = ddf::fitCrustToStock(design, input, stock);
  std::cout << part << ": fitted in " << secondsSince(start) << " s; "
            << (fit.holds ? "holds" : fit.limit->message) << "\n";
  printReach(part, "after the fit", fit.reach);
  // The blade holds the allowance (its thin trailing edges need the fold repair of the chosen
  // directions). Where it does not hold (fandisk has sharp right-angled concave creases), the
  // refusal must name the place and an allowance that does hold, and the grind below runs with
  // (just under) that one.
  ASSERT_TRUE(fit.holds || fit.limit.has_value());
  if (!concaveLimit) {
    EXPECT_TRUE(fit.holds) << fit.limit->message;
    EXPECT_GE(fit.reach.minAboveMm, kStockMm);
  }
  if (!fit.holds) {
    EXPECT_NE(fit.limit->message.find("does not fit at"), std::string::npos) << fit.limit->message;
    EXPECT_GT(fit.limit->largestAllowanceMm, 0.0);
    EXPECT_LT(fit.limit->largestAllowanceMm, kStockMm);
  }
  if (concaveLimit) {
    ASSERT_FALSE(fit.holds);
    EXPECT_LT(fit.limit->concaveRadiusMm, kStockMm) << fit.limit->message;
    EXPECT_NE(fit.limit->message.find("concave there with radius"), std::string::npos)
        << fit.limit->message;
    const double turnDeg =
        sharpestConcaveTurnDeg(input, fit.limit->point, kStockMm * (1.0 + stock.marginFraction));
    std::cout << part << ": sharpest concave turn near the limit " << turnDeg << " degrees\n";
    EXPECT_GT(turnDeg, 60.0);
  }
  const double allowanceMm = fit.holds ? kStockMm : 0.999 * fit.limit->largestAllowanceMm;
  EXPECT_GE(fit.reach.minAboveMm, before.minAboveMm * (1.0 - 1e-6));
  EXPECT_GE(fit.reach.minBelowMm, before.minBelowMm * (1.0 - 1e-3));
  const ddf::ValidationReport valid = ddf::validate(design);
  EXPECT_TRUE(valid.ok()) << (valid.issues.empty() ? "" : valid.issues.front().message);
  // The represented surface is unchanged by the fit: its distances to the input (both ways,
  // brute force on samples) are what they were after the conversion, up to 1 micron.
  const double out = test::largestDistance(test::rasterSurfacePoints(design, 97), input);
  const double in =
      test::largestDistance(test::triangleSamples(input, 89), test::latticeSurface(design));
  std::cout << part << ": surface to input " << out << " mm (before the fit " << outBefore
            << "), input to surface " << in << " mm (before " << inBefore << ")\n";
  EXPECT_LE(out, outBefore + 1e-3);
  EXPECT_LE(in, inBefore + 1e-3);

  ddf::DisplacementField work = workpieceWithAllowance(design, allowanceMm);
  const std::vector<float> raised = work.allHeights();
  const std::vector<Contact> contacts = ballContacts(design, test::latticeSurface(design), 7);
  ASSERT_GT(contacts.size(), 100u);
  const ddf::TriangleMesh ball = makeSphereTool(kBallRadiusMm, kBallSegments / 2, kBallSegments);
  const ddf::CrustHash hash(work, ddf::crustHashParamsFor(work));
  for (const Contact& c : contacts)
    ddf::cutByMesh(work, hash, ball, Eigen::Isometry3d(Eigen::Translation3d(c.centre)));
  expectGroundToDesign(design, raised, work, contacts, allowanceMm);
}

TEST(StockCrustParts, TurbineBladeFitsTheStockAndGrindsBackToTheDesign) {
  const auto blade = sharedMesh("turbine-blade-jigsaw.stl", 1000.0);  // metres
  if (!blade) GTEST_SKIP() << "shared mesh data not present";
  grindStockBackToDesign("turbine blade", *blade);
}

TEST(StockCrustParts, FandiskRefusesTheStockAtASharpConcaveCreaseAndGrindsBack) {
  const auto fandisk = sharedMesh("fandisk.obj", 1.0);
  if (!fandisk) GTEST_SKIP() << "shared mesh data not present";
  grindStockBackToDesign("fandisk", *fandisk, true);
}

}  // namespace
}  // namespace ddfcam::planning
