// SPDX-License-Identifier: MIT
// ddfcam-cli convert: a mesh file converted into a .ddf file (the mesh becomes the support).
#include <ddfcam/io/ddf_file.h>
#include <ddfcam/io/part_loader.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"

#include <array>
#include <cstdio>
#include <filesystem>

namespace ddfcam::cli {
namespace {

constexpr const char* kHelp =
    "usage: ddfcam-cli convert IN.(stl|obj|ply|off) -o OUT.ddf [--resolution M]\n\n"
    "Converts a triangle mesh into a Discrete Displacement Field whose support is the mesh\n"
    "itself (vertices welded, degenerate and non-manifold triangles dropped with a warning),\n"
    "with pseudo-normal displacement vectors and all heights 0, and writes it as .ddf.\n\n"
    "options:\n"
    "  -o, --output FILE    output .ddf file\n"
    "  --resolution M       raster resolution: points per support edge, 2..1024 (default 10)\n"
    "  -h, --help           show this help\n";

int runConvert(std::span<const std::string> words) {
  static const std::array<OptionSpec, 2> kSpecs = {OptionSpec{"output", 'o', true},
                                                   OptionSpec{"resolution", '\0', true}};
  const Arguments args(words, kSpecs, "convert");
  args.expectPositionals(1, "an input mesh file");
  const std::filesystem::path input = args.positionals()[0];
  const std::filesystem::path output = args.required("output");
  if (output.extension() != ".ddf")
    throw UsageError("output " + output.string() + " must end in .ddf");
  io::LoadPartParams params;
  params.conversion.resolution = args.integer("resolution", params.conversion.resolution, 2, 1024);
  params.progress = consoleProgress("converting");
  io::LoadPartReport report;
  const ddf::DisplacementField field = io::loadPart(input, params, &report);
  endProgressLine();
  io::writeDdf(field, output);
  if (report.converted) {
    std::printf("read %s: %d vertices, %d triangles\n", input.string().c_str(), report.meshVertices,
                report.meshTriangles);
    std::printf(
        "  dropped %d non-manifold and %d degenerate triangles, welded %d vertices, "
        "repaired %d directions, %d infeasible vertices\n",
        report.droppedFaces, report.degenerateFaces, report.weldedVertices, report.repairedVertices,
        report.infeasibleVertices);
  }
  std::printf("wrote %s: %d vertices, %d faces, m = %d, %zu raster points\n",
              output.string().c_str(), field.vertexCount(), field.faceCount(), field.resolution(),
              field.topology().pointCount());
  return 0;
}

}  // namespace

const Command kConvertCommand{"convert", "convert a mesh file into a .ddf file", kHelp,
                              &runConvert};

}  // namespace ddfcam::cli
