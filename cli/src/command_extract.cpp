// SPDX-License-Identifier: MIT
// ddfcam-cli extract: the surface represented by a .ddf file as a triangle mesh file.
#include <ddfcam/ddf/adaptive_triangulation.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/mesh_io.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"

#include <cstdio>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Writes the surface represented by the field as a triangle mesh: the full raster mesh\n"
    "((m-1)^2 triangles per support face) or, with --eps, an adaptive triangulation whose\n"
    "distance to every raster surface point is at most E mm.";

Arguments options() {
  Arguments args("extract", "extract IN.ddf -o OUT.(stl|obj|ply|off) [--eps E]", kDescription);
  args.positional("IN.ddf", "input .ddf file");
  args.option("-o,--output", "FILE", "output mesh; the format follows the extension");
  args.option("--eps", "E", "adaptive triangulation with error bound E mm (> 0)")
      ->check(positiveNumber());
  return args;
}

std::string help() {
  return options().help();
}

int runExtract(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input .ddf file");
  const std::filesystem::path output = args.required("output");
  if (!io::meshFormatOf(output))
    throw UsageError("output " + output.string() + " must end in .stl, .obj, .ply or .off");
  const std::optional<double> eps = args.number("eps");
  const ddf::DisplacementField field = io::readDdf(args.positionals()[0]);
  ddf::TriangleMesh mesh;
  if (eps) {
    ddf::AdaptiveTriangulationParams params;
    params.epsMm = *eps;
    params.progress = consoleProgress("triangulating");
    mesh = ddf::triangulateAdaptive(field, params);
    endProgressLine();
  } else {
    mesh = ddf::extractRasterMesh(field).mesh;
  }
  io::writeMesh(mesh, output);
  const std::string kind = eps ? "adaptive, eps " + std::to_string(*eps) + " mm" : "raster mesh";
  std::printf("wrote %s: %zu vertices, %zu triangles (%s)\n", output.string().c_str(),
              mesh.vertices.size(), mesh.triangles.size(), kind.c_str());
  return 0;
}

}  // namespace

const Command kExtractCommand{"extract", "write the represented surface as a mesh file", &help,
                              &runExtract};

}  // namespace ddfcam::cli
