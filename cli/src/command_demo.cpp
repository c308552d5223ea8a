// SPDX-License-Identifier: MIT
// ddfcam-cli demo: the built-in demo part ground along a short path, written as .ddf and .stl.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/mesh_io.h>
#include <ddfcam/planning/demo_project.h>
#include <ddfcam/planning/path_simulation.h>
#include <ddfcam/progress.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "field_summary.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace ddfcam::cli {
namespace {

constexpr const char* kHelp =
    "usage: ddfcam-cli demo [--out DIR] [--depth D]\n\n"
    "Generates the built-in demo part (a 40 x 30 mm free-form patch with 0.2 mm stock), grinds\n"
    "three overlapping passes along y with the default cylindrical roll (radius 5 mm, width\n"
    "10 mm) held on the design surface (roll axis in the tangent plane, across the feed) by the\n"
    "DDF depth buffer, and writes DIR/demo.ddf and DIR/demo.stl (adaptive triangulation, eps\n"
    "0.005 mm).\n\n"
    "options:\n"
    "  --out DIR   output directory, created if needed (default ./ddfcam-demo)\n"
    "  --depth D   infeed below the design surface, mm (default 0.02)\n"
    "  -h, --help  show this help\n";

/// Error bound of the written STL, mm.
constexpr double kEpsMm = 0.005;

/// Grinds the demo passes (planning::demoPasses) with the default roll; returns the number of
/// lowered heights and the number of poses.
std::size_t grindPasses(ddf::GeneratedSurface& part, double depthMm, int& poses) {
  const planning::Tool roll;
  planning::DemoPassesParams passes;
  passes.depthMm = depthMm;
  const planning::ToolPath path = planning::demoPasses(*part.design, roll, passes);
  planning::PathSimulationParams params;
  params.progress = consoleProgress("grinding");
  const planning::PathSimulationReport report =
      planning::simulatePath(part.ddf, roll, path, params);
  endProgressLine();
  poses = report.poses;
  return report.pointsLowered;
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
  const planning::DemoPassesParams passes;
  std::printf(
      "ground %zu passes: %d roll poses at x = %.0f, %.0f, %.0f mm, y = %.1f..%.1f mm, %.3g mm "
      "below the design surface\n",
      passes.passXMm.size(), o.poses, passes.passXMm[0], passes.passXMm[1], passes.passXMm[2],
      passes.startYMm, passes.endYMm, depth);
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
  const double depth = args.positiveNumber("depth").value_or(0.02);
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw IoError("cannot create output directory " + dir.string() + ": " + ec.message());

  ddf::GeneratedSurface part = ddf::demoPart();
  DemoOutcome outcome;
  outcome.before = summarize(part.ddf);
  outcome.lowered = grindPasses(part, depth, outcome.poses);
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
