// SPDX-License-Identifier: MIT
// ddfcam-cli demo: the built-in demo part ground along a short path, written as .ddf and .stl.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/mesh_io.h>
#include <ddfcam/planning/tool_shapes.h>
#include <ddfcam/progress.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "field_summary.h"

#include <array>
#include <chrono>
#include <cstdio>
#include <filesystem>

namespace ddfcam::cli {
namespace {

constexpr const char* kHelp =
    "usage: ddfcam-cli demo [--out DIR] [--depth D]\n\n"
    "Generates the built-in demo part (a 40 x 30 mm free-form patch with 0.2 mm stock), grinds\n"
    "one straight pass across it with the default cylindrical roll (radius 5 mm, width 10 mm,\n"
    "axis along x) by the DDF depth buffer, and writes DIR/demo.ddf and DIR/demo.stl (adaptive\n"
    "triangulation, eps 0.005 mm).\n\n"
    "options:\n"
    "  --out DIR   output directory, created if needed (default ./ddfcam-demo)\n"
    "  --depth D   infeed below the highest stock point under the roll, mm (default 0.25)\n"
    "  -h, --help  show this help\n";

/// The pass: roll centre x fixed, y from kStartY to kEndY in kStepMm steps.
constexpr double kPassX = 20.0, kStartY = 6.0, kEndY = 24.0, kStepMm = 0.5;
constexpr double kEpsMm = 0.005;

/// Every represented surface point of @p field (the stock before grinding), mm.
std::vector<ddf::Vec3> surfacePoints(const ddf::DisplacementField& field) {
  std::vector<ddf::Vec3> points;
  const int n = field.raster().steps();
  for (int f = 0; f < field.faceCount(); ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) points.push_back(field.surfacePoint(f, i, k));
  return points;
}

/// Highest stock z under the roll's footprint centred at (x, y), or 0 if nothing is below.
double footprintTop(const std::vector<ddf::Vec3>& stock, double x, double y,
                    const planning::CylinderToolParams& roll) {
  double top = -std::numeric_limits<double>::infinity();
  for (const ddf::Vec3& q : stock)
    if (std::abs(q.x() - x) <= 0.5 * roll.widthMm && std::abs(q.y() - y) <= roll.radiusMm)
      top = std::max(top, q.z());
  return std::isfinite(top) ? top : 0.0;
}

/// Grinds the pass; returns the number of lowered heights.
std::size_t grindPass(ddf::DisplacementField& field, double depthMm, int& poses) {
  const std::vector<ddf::Vec3> stock = surfacePoints(field);
  const planning::CylinderToolParams roll;
  const ddf::TriangleMesh tool = planning::makeCylinderTool(roll);
  const ddf::CrustHash hash(field);
  const auto progress = consoleProgress("grinding");
  const int steps = static_cast<int>(std::round((kEndY - kStartY) / kStepMm));
  std::size_t lowered = 0;
  for (int s = 0; s <= steps; ++s) {
    const double y = kStartY + s * kStepMm;
    const double z = footprintTop(stock, kPassX, y, roll) + roll.radiusMm - depthMm;
    const Eigen::Isometry3d pose(Eigen::Translation3d(kPassX, y, z));
    lowered += ddf::cutByMesh(field, hash, tool, pose).pointsLowered;
    reportProgress(progress, static_cast<double>(s + 1) / (steps + 1));
  }
  endProgressLine();
  poses = steps + 1;
  return lowered;
}

/// What one demo run did, for the summary.
struct DemoOutcome {
  FieldSummary before, after;
  int poses = 0;
  std::size_t lowered = 0;
  std::size_t stlTriangles = 0;
};

void printOutcome(const DemoOutcome& o, const std::filesystem::path& dir, double depth,
                  double seconds) {
  const auto ddfPath = dir / "demo.ddf", stlPath = dir / "demo.stl";
  std::printf("demo part: %d support faces, m = %d, %zu raster points\n", o.after.faces,
              o.after.resolution, o.after.rasterPoints);
  std::printf("ground one pass: %d roll poses at x = %.1f mm, y = %.1f..%.1f mm, infeed %.3g mm\n",
              o.poses, kPassX, kStartY, kEndY, depth);
  std::printf("  %zu heights lowered; height range [%.4f, %.4f] -> [%.4f, %.4f] vector lengths\n",
              o.lowered, o.before.heightMin, o.before.heightMax, o.after.heightMin,
              o.after.heightMax);
  const auto ddfBytes = static_cast<double>(std::filesystem::file_size(ddfPath));
  std::printf("wrote %s (%s)\n", ddfPath.string().c_str(), formatBytes(ddfBytes).c_str());
  std::printf("wrote %s (%zu triangles, adaptive eps %.3g mm)\n", stlPath.string().c_str(),
              o.stlTriangles, kEpsMm);
  std::printf("done in %.2f s\n", seconds);
}

int runDemo(std::span<const std::string> words) {
  static const std::array<OptionSpec, 2> kSpecs = {OptionSpec{"out", '\0', true},
                                                   OptionSpec{"depth", '\0', true}};
  const Arguments args(words, kSpecs, "demo");
  args.expectPositionals(0, "no positional arguments");
  const std::filesystem::path dir = args.value("out").value_or("ddfcam-demo");
  const double depth = args.positiveNumber("depth").value_or(0.25);
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output directory " + dir.string() + ": " + ec.message());

  ddf::GeneratedSurface part = ddf::demoPart();
  DemoOutcome outcome;
  outcome.before = summarize(part.ddf);
  outcome.lowered = grindPass(part.ddf, depth, outcome.poses);
  io::writeDdf(part.ddf, dir / "demo.ddf");
  ddf::AdaptiveTriangulationParams extract;
  extract.epsMm = kEpsMm;
  const ddf::TriangleMesh mesh = ddf::triangulateAdaptive(part.ddf, extract);
  io::writeMesh(mesh, dir / "demo.stl");
  outcome.stlTriangles = mesh.triangles.size();
  outcome.after = summarize(part.ddf);
  const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
  printOutcome(outcome, dir, depth, elapsed.count());
  return 0;
}

}  // namespace

const Command kDemoCommand{"demo", "grind the built-in demo part and write .ddf and .stl", kHelp,
                           &runDemo};

}  // namespace ddfcam::cli
