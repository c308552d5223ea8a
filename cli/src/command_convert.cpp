// SPDX-License-Identifier: MIT
// ddfcam-cli convert: a mesh or CAD file converted into a .ddf file.
#include <ddfcam/ddf/conversion_report.h>
#include <ddfcam/io/mesh/ddf_file.h>
#include <ddfcam/io/mesh/part_loader.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "conversion_options.h"
#include "unit_options.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Converts a triangle mesh or a CAD model (STEP, IGES; tessellated finely enough for the\n"
    "tolerance) into a Discrete Displacement Field and writes it as .ddf. The support is the\n"
    "input reduced by constrained edge contraction (ch. 6; --support input keeps the input\n"
    "mesh; a reduced face never spans two CAD faces), the vectors pseudo-normals whose\n"
    "lengths keep the crusts free of foldovers (sec. 4.4), the heights filled from the\n"
    "input. Coordinates are read in --units (by default a CAD file's own unit, mm for\n"
    "meshes).\n"
    "It says what it repaired (welded vertices; unused, degenerate, duplicate and\n"
    "non-manifold triangles dropped; holes and open borders; vector directions turned and\n"
    "lengths shortened), how far the reduction went, m and the raster spacing, the distance\n"
    "between the DDF surface and the input both ways, and whether the crust holds --stock.\n"
    "Then it checks the result against the three DDF constraints as 'info' does. A result\n"
    "that violates one, or whose crust cannot hold the stock, is not written: the command\n"
    "says why and what to change and exits with code 3, unless --allow-invalid is given\n"
    "(then OUT is written, the warnings stay). OUT records the input's unit and CAD faces.";

Arguments options() {
  Arguments args("convert", "convert IN.(stl|obj|ply|off|step|stp|iges|igs) -o OUT.ddf [options]",
                 kDescription);
  args.positional("IN", "input mesh or CAD file");
  args.option("-o,--output", "FILE", "output .ddf file");
  addConversionOptions(args);
  args.flag("--allow-invalid", "write OUT even if it is invalid or misses the stock (exit 0)");
  return args;
}

std::string help() {
  return options().help();
}

int runConvert(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input mesh or CAD file");
  const std::filesystem::path input = args.positionals()[0];
  const std::filesystem::path output = args.required("output");
  if (output.extension() != ".ddf")
    throw UsageError("output " + output.string() + " must end in .ddf");
  io::LoadPartReport report;
  ddf::TriangleMesh inputMesh;
  const ddf::DisplacementField field =
      loadPartInUnit(input, conversionParams(args), "converting", &report, &inputMesh);
  bool usable = true;
  if (report.converted) {
    printConversion(input, report);
    usable = printVerdict(input, report);
  }
  if (!usable && !args.has("allow-invalid")) {
    std::fprintf(stderr,
                 "ddfcam-cli convert: %s not written; change the input or the options as said "
                 "above, or pass --allow-invalid to write it anyway (exit code %d)\n",
                 output.string().c_str(), kInvalidResultExitCode);
    return kInvalidResultExitCode;
  }
  io::DdfMetadata metadata;
  metadata.sourceUnit = report.unit;
  metadata.cadFaceOfSupportFace = report.cadFaceOfSupportFace;
  metadata.cadFaceNames = report.cadFaceNames;
  // The input stays with the field: the curvature of a reduced support comes from it.
  if (!inputMesh.triangles.empty()) metadata.designMesh = std::move(inputMesh);
  io::writeDdf(field, output, metadata);
  std::printf("wrote %s%s: %d vertices, %d faces, m = %d, %zu raster points\n",
              output.string().c_str(), usable ? "" : " (INVALID, --allow-invalid)",
              field.vertexCount(), field.faceCount(), field.resolution(),
              field.topology().pointCount());
  return 0;
}

}  // namespace

const Command kConvertCommand{"convert", "convert a mesh or CAD file into a .ddf file", &help,
                              &runConvert};

}  // namespace ddfcam::cli
