// SPDX-License-Identifier: MIT
// ddfcam-cli: conversion options and the printed conversion summary.
#include "conversion_options.h"

#include <ddfcam/ddf/conversion_report.h>

#include "console.h"
#include "unit_options.h"

#include <cstdio>
#include <string>

namespace ddfcam::cli {

void addConversionOptions(Arguments& args) {
  addUnitsOption(args, "the input's coordinates",
                 "the unit a STEP/IGES file states, mm for meshes;\na part under 1 or over "
                 "10,000 units across draws a warning");
  args.option("--support", "reduced|input",
              "support of the DDF: the input reduced by edge contraction\nunder the constraints "
              "of ch. 6, or the input mesh")
      ->check(oneOf({"reduced", "input"}))
      ->default_str("reduced");
  args.option("--resolution", "M",
              "raster resolution: points per support edge, 2..1024\n(the first try of "
              "--tolerance)")
      ->check(integerIn(2, 1024))
      ->default_str(std::to_string(ddf::ConversionParams{}.resolution));
  args.option("--tolerance", "MM",
              "choose m so that the DDF surface lies within MM of the input,\nmeasured both ways "
              "on sample points")
      ->check(positiveNumber());
  args.option("--raster-spacing", "MM",
              "choose the smallest m whose raster spacing on the longest\nsupport edge is at most "
              "MM (not with --tolerance)")
      ->check(positiveNumber());
  args.option("--stock", "MM",
              "fit the crust to hold a stock allowance of MM above the\nsurface; if it cannot, "
              "say where and the largest allowance")
      ->check(positiveNumber());
  args.option("--weld-tolerance", "MM",
              "weld vertices closer than this (default: 1e-9 x the\nbounding-box diagonal, at "
              "least 1e-6 mm)")
      ->check(positiveNumber());
  args.option("--max-vector-length", "MM",
              "longest displacement vector (default: the mean edge length)")
      ->check(positiveNumber());
}

io::LoadPartParams conversionParams(const Arguments& args) {
  io::LoadPartParams params;
  ddf::ConversionParams& c = params.conversion;
  params.unit = unitOption(args);
  c.resolution = args.integer("resolution", c.resolution);
  c.support =
      args.value("support") == "input" ? ddf::SupportChoice::Input : ddf::SupportChoice::Reduced;
  if (args.has("tolerance") && args.has("raster-spacing"))
    throw UsageError(
        "--tolerance and --raster-spacing exclude each other (a tolerance chooses "
        "the spacing)");
  c.toleranceMm = args.number("tolerance").value_or(0.0);
  c.rasterSpacingMm = args.number("raster-spacing").value_or(0.0);
  c.stockMm = args.number("stock").value_or(0.0);
  if (const auto tol = args.number("weld-tolerance")) c.weldToleranceMm = *tol;
  if (const auto length = args.number("max-vector-length")) c.lengths.maxLengthMm = *length;
  return params;
}

namespace {

void printCadFaces(const io::LoadPartReport& report) {
  if (report.cadFaceNames.empty()) return;
  std::printf("  CAD faces: %zu\n", report.cadFaceNames.size());
  for (const std::string& line : report.cadHealing) std::printf("  healing: %s\n", line.c_str());
}

}  // namespace

void printConversion(const std::filesystem::path& input, const io::LoadPartReport& report) {
  std::printf("read %s: %d vertices, %d triangles\n", input.string().c_str(), report.meshVertices,
              report.meshTriangles);
  const auto& [lo, hi] = report.boundsMm;
  std::printf(
      "  unit: %s%s, %.6g units across; bounds [%.6g, %.6g, %.6g] to [%.6g, %.6g, %.6g] mm\n",
      std::string(unitSymbol(report.unit)).c_str(),
      report.unitFromFile ? " (stated by the file)" : "", report.fileDiagonal, lo.x(), lo.y(),
      lo.z(), hi.x(), hi.y(), hi.z());
  printCadFaces(report);
  const ddf::ConversionReport& c = report.conversion;
  std::printf("  support: %d vertices, %d faces\n", c.supportVertices, c.supportFaces);
  for (const std::string& line : ddf::conversionRepairLines(c)) std::printf("  %s\n", line.c_str());
  for (const std::string& line : ddf::conversionSummaryLines(c))
    std::printf("  %s\n", line.c_str());
}

bool printVerdict(const std::filesystem::path& input, const io::LoadPartReport& report) {
  const ddf::ConversionReport& c = report.conversion;
  const bool stockHeld = !report.stock || report.stock->holds;
  if (c.valid()) std::printf("  %s\n", ddf::conversionVerdict(c).c_str());
  if (c.valid() && stockHeld) return true;
  endProgressLine();
  std::fflush(stdout);  // the facts above come first also when both streams are redirected
  if (!c.valid()) {
    std::fprintf(stderr, "warning: %s converts to an %s\n", input.string().c_str(),
                 ddf::conversionVerdict(c).c_str());
    for (const std::string& line : ddf::conversionProblemLines(c))
      std::fprintf(stderr, "warning:   %s\n", line.c_str());
  }
  if (!stockHeld) {
    const ddf::StockFit& s = *report.stock;
    std::fprintf(stderr, "warning: the crust of %s cannot hold the stock of %.4g mm: %s\n",
                 input.string().c_str(), s.requestedMm,
                 s.limit ? s.limit->message.c_str() : "no limit named");
    std::fprintf(stderr, "warning:   largest allowance it holds: %.4g mm\n",
                 s.limit ? s.limit->largestAllowanceMm : s.reach.minAboveMm);
  }
  return false;
}

}  // namespace ddfcam::cli
