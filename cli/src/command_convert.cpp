// SPDX-License-Identifier: MIT
// ddfcam-cli convert: a mesh file converted into a .ddf file (the mesh becomes the support).
#include <ddfcam/ddf/conversion_report.h>
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

/// Exit code of a conversion whose result violates a DDF constraint.
constexpr int kInvalidResultExitCode = 3;

constexpr const char* kHelp =
    "usage: ddfcam-cli convert IN.(stl|obj|ply|off) -o OUT.ddf [options]\n\n"
    "Converts a triangle mesh into a Discrete Displacement Field whose support is the mesh\n"
    "itself, with pseudo-normal displacement vectors whose lengths keep the crusts free of\n"
    "foldovers (sec. 4.4) and heights filled from the mesh, and writes it as .ddf.\n"
    "It says what it repaired: welded vertices; unused vertices, degenerate, duplicate and\n"
    "non-manifold triangles dropped; holes and open borders; vector directions turned and\n"
    "lengths shortened. Then it checks the result against the three DDF constraints as\n"
    "'info' does. A result that violates one is an invalid DDF: the command names the\n"
    "constraints, where they fail and what to change, does not write OUT and exits with\n"
    "code 3, unless --allow-invalid is given (then OUT is written, the warnings stay).\n"
    "Coordinates are taken as mm.\n\n"
    "options:\n"
    "  -o, --output FILE          output .ddf file\n"
    "  --resolution M             raster resolution: points per support edge, 2..1024\n"
    "                             (default 10)\n"
    "  --weld-tolerance MM        weld vertices closer than this (default: 1e-9 x the\n"
    "                             bounding-box diagonal, at least 1e-6 mm)\n"
    "  --max-vector-length MM     longest displacement vector (default: the mean edge length)\n"
    "  --allow-invalid            write OUT even if it violates a DDF constraint (exit 0)\n"
    "  -h, --help                 show this help\n";

void printRepairs(const std::filesystem::path& input, const io::LoadPartReport& report) {
  std::printf("read %s: %d vertices, %d triangles\n", input.string().c_str(), report.meshVertices,
              report.meshTriangles);
  const ddf::ConversionReport& c = report.conversion;
  std::printf("  support: %d vertices, %d faces\n", c.supportVertices, c.supportFaces);
  for (const std::string& line : ddf::conversionRepairLines(c)) std::printf("  %s\n", line.c_str());
}

/// Prints the verdict; for an invalid result also the problems on stderr. Returns validity.
bool printVerdict(const std::filesystem::path& input, const ddf::ConversionReport& c) {
  if (c.valid()) {
    std::printf("  %s\n", ddf::conversionVerdict(c).c_str());
    return true;
  }
  endProgressLine();
  std::fflush(stdout);  // the facts above come first also when both streams are redirected
  std::fprintf(stderr, "warning: %s converts to an %s\n", input.string().c_str(),
               ddf::conversionVerdict(c).c_str());
  for (const std::string& line : ddf::conversionProblemLines(c))
    std::fprintf(stderr, "warning:   %s\n", line.c_str());
  return false;
}

io::LoadPartParams loadParams(const Arguments& args) {
  io::LoadPartParams params;
  params.conversion.resolution = args.integer("resolution", params.conversion.resolution, 2, 1024);
  if (const auto tol = args.positiveNumber("weld-tolerance"))
    params.conversion.weldToleranceMm = *tol;
  if (const auto length = args.positiveNumber("max-vector-length"))
    params.conversion.lengths.maxLengthMm = *length;
  params.progress = consoleProgress("converting");
  return params;
}

int runConvert(std::span<const std::string> words) {
  static const std::array<OptionSpec, 5> kSpecs = {
      OptionSpec{"output", 'o', true}, OptionSpec{"resolution", '\0', true},
      OptionSpec{"weld-tolerance", '\0', true}, OptionSpec{"max-vector-length", '\0', true},
      OptionSpec{"allow-invalid", '\0', false}};
  const Arguments args(words, kSpecs, "convert");
  args.expectPositionals(1, "an input mesh file");
  const std::filesystem::path input = args.positionals()[0];
  const std::filesystem::path output = args.required("output");
  if (output.extension() != ".ddf")
    throw UsageError("output " + output.string() + " must end in .ddf");
  const io::LoadPartParams params = loadParams(args);
  io::LoadPartReport report;
  const ddf::DisplacementField field = io::loadPart(input, params, &report);
  endProgressLine();
  bool valid = true;
  if (report.converted) {
    printRepairs(input, report);
    valid = printVerdict(input, report.conversion);
  }
  if (!valid && !args.has("allow-invalid")) {
    std::fprintf(stderr,
                 "ddfcam-cli convert: %s not written; change the mesh or the options as said "
                 "above, or pass --allow-invalid to write it anyway (exit code %d)\n",
                 output.string().c_str(), kInvalidResultExitCode);
    return kInvalidResultExitCode;
  }
  io::writeDdf(field, output);
  std::printf("wrote %s%s: %d vertices, %d faces, m = %d, %zu raster points\n",
              output.string().c_str(), valid ? "" : " (INVALID, --allow-invalid)",
              field.vertexCount(), field.faceCount(), field.resolution(),
              field.topology().pointCount());
  return 0;
}

}  // namespace

const Command kConvertCommand{"convert", "convert a mesh file into a .ddf file", kHelp,
                              &runConvert};

}  // namespace ddfcam::cli
