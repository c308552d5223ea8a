// SPDX-License-Identifier: MIT
// ddfcam-cli: helpers shared by the compare and compensate commands.
#include "mould_options.h"

#include <ddfcam/error.h>
#include <ddfcam/io/mesh/mesh_units.h>
#include <ddfcam/io/mesh/surface_file.h>

#include "arguments.h"
#include "unit_options.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

namespace ddfcam::cli {

void addMouldOptions(Arguments& args, const MouldOptionTexts& texts) {
  addUnitsOption(args, texts.surfaces, "mm; " + texts.written);
  args.option("--resolution", "M", "raster resolution of " + texts.ddf)
      ->check(integerIn(2, 64))
      ->default_str(std::to_string(kMouldResolution));
  args.option("--reach", "MM", texts.reach)->check(positiveNumber());
  args.option("--json", "FILE", texts.json);
}

std::vector<double> parseNumberList(const std::string& text, std::size_t count,
                                    const std::string& option) {
  std::vector<double> values;
  const char* at = text.data();
  const char* end = text.data() + text.size();
  while (at <= end && values.size() < count) {
    double value = 0.0;
    const auto result = std::from_chars(at, end, value);
    if (result.ec != std::errc{} || !std::isfinite(value)) break;
    values.push_back(value);
    at = result.ptr;
    if (at == end || *at != ',') break;
    ++at;
  }
  if (values.size() != count || at != end)
    throw UsageError("--" + option + ": expected " + std::to_string(count) +
                     " comma-separated numbers, got '" + text + "'");
  return values;
}

planning::LoadedSurface loadSurface(const std::filesystem::path& path, const std::string& role,
                                    const std::optional<ddfcam::LengthUnit>& unit) {
  planning::LoadedSurface surface = io::readSurfaceFile(path);
  warnIfOtherUnit(path, io::boundingBoxDiagonal(surface.mesh), unit);
  surface.mesh =
      io::scaledToMm(std::move(surface.mesh), unit.value_or(ddfcam::LengthUnit::Millimetre));
  std::fprintf(stderr, "%s: %s, %zu vertices, %zu triangles, %zu fields\n", role.c_str(),
               path.string().c_str(), surface.mesh.vertices.size(), surface.mesh.triangles.size(),
               surface.fields.size());
  return surface;
}

void writeTextFile(const std::string& text, const std::filesystem::path& file,
                   const std::string& command) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  out.close();
  if (!out) throw IoError(command + ": cannot write " + file.string());
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ddfcam::cli
