// SPDX-License-Identifier: MIT
// ddfcam-cli curvature: principal curvatures of a part as a coloured .vtp and a per-point CSV.
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/io/mesh/part_loader.h>
#include <ddfcam/io/results/vtp_writer.h>
#include <ddfcam/planning/analysis/curvature.h>
#include <ddfcam/planning/analysis/segmentation.h>

#include "arguments.h"
#include "commands.h"
#include "console.h"
#include "unit_options.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

namespace ddfcam::cli {
namespace {

constexpr const char* kDescription =
    "Computes the principal curvatures and directions at every raster point of PART (a .ddf\n"
    "file, or a mesh or CAD file converted on its own support at m = 10) from the DDF's\n"
    "parametric form (dissertation sec. 8.2). Signs are seen from the tool (+v side):\n"
    "positive where the surface bends away from the tool (convex), negative where it bends\n"
    "towards it.\n\n"
    "Writes the raster mesh as VTK XML PolyData with the point arrays k_max, k_min, mean,\n"
    "gaussian (1/mm, 1/mm^2), curvature_type (0 flat, 1 convex, 2 concave, 3 saddle),\n"
    "max_tool_radius (mm, 1e6 where unbounded), umbilic (1 where directions are meaningless)\n"
    "and the vectors dir_max, dir_min; and, with --csv, one row per distinct raster point.";

Arguments options() {
  Arguments args("curvature", "curvature PART [-o OUT.vtp] [--csv OUT.csv] [--step D]",
                 kDescription);
  args.positional("PART", "input part: .ddf, mesh or CAD file");
  args.option("-o,--output", "FILE", "output .vtp (default: PART with the extension .vtp)");
  args.option("--csv", "FILE",
              "also write per-point values as CSV (point_id, face, i, k, x, y, z,\n"
              "k_max, k_min, mean, gaussian, dir_max_x..z, dir_min_x..z, umbilic)");
  args.option("--step", "D", "difference step in raster steps (default: automatic from m)")
      ->check(integerIn(1, 1 << 20));
  addUnitsOption(args, "a mesh or CAD PART", "the unit a CAD file states, mm for meshes");
  return args;
}

std::string help() {
  return options().help();
}

using Clock = std::chrono::steady_clock;

double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/// Everything written per point, all in the layout of allHeights().
struct CurvatureResult {
  planning::CurvatureField curvature;
  std::vector<float> type;    ///< CurvatureType values
  std::vector<float> radius;  ///< max tool radius, mm
};

/// The raster mesh and, per vertex, the index of its canonical copy in allHeights() (-1: none).
struct SampledMesh {
  ddf::RasterMesh raster;
  std::vector<std::ptrdiff_t> copy;
  std::vector<std::array<int, 3>> fik;  ///< face, i, k of that copy (face -1: none)
};

SampledMesh sampleMesh(const ddf::DisplacementField& field) {
  SampledMesh s{ddf::extractRasterMesh(field), {}, {}};
  const ddf::SurfaceSamples samples = ddf::sampleRasterMesh(field, s.raster);
  const ddf::Raster& raster = field.raster();
  const int n = raster.steps();
  for (std::size_t v = 0; v < samples.face.size(); ++v) {
    const int f = samples.face[v];
    // Samples of a raster mesh sit exactly on lattice points, so rounding recovers (i, k).
    const int i = static_cast<int>(std::lround(samples.bary[v][0] * n));
    const int k = static_cast<int>(std::lround(samples.bary[v][2] * n));
    s.fik.push_back({f, i, k});
    s.copy.push_back(
        f < 0 ? -1 : static_cast<std::ptrdiff_t>(f * raster.pointCount() + raster.index(i, k)));
  }
  return s;
}

std::vector<float> gather(const std::vector<float>& values, const SampledMesh& s) {
  std::vector<float> out(s.copy.size(), std::numeric_limits<float>::quiet_NaN());
  for (std::size_t v = 0; v < out.size(); ++v)
    if (s.copy[v] >= 0) out[v] = values[s.copy[v]];
  return out;
}

std::vector<Eigen::Vector3d> gather(const std::vector<ddf::Vec3>& values, const SampledMesh& s) {
  std::vector<Eigen::Vector3d> out(s.copy.size(), Eigen::Vector3d::Constant(std::nan("")));
  for (std::size_t v = 0; v < out.size(); ++v)
    if (s.copy[v] >= 0) out[v] = values[s.copy[v]];
  return out;
}

io::VtpPointData pointData(const CurvatureResult& r, const SampledMesh& s) {
  const planning::CurvatureField& c = r.curvature;
  const std::vector<float> umbilic(c.umbilic.begin(), c.umbilic.end());
  io::VtpPointData data;
  data.scalars = {{"k_max", gather(c.kMax, s)},          {"k_min", gather(c.kMin, s)},
                  {"mean", gather(c.mean, s)},           {"gaussian", gather(c.gaussian, s)},
                  {"curvature_type", gather(r.type, s)}, {"max_tool_radius", gather(r.radius, s)},
                  {"umbilic", gather(umbilic, s)}};
  data.vectors = {{"dir_max", gather(c.dirMax, s)}, {"dir_min", gather(c.dirMin, s)}};
  return data;
}

template <class T>
void appendCsvNumber(std::string& out, T value) {
  out += ',';
  if (!std::isfinite(value)) {
    out += std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf");
    return;
  }
  char buffer[32];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void appendCsvRow(std::string& out, const CurvatureResult& r, const SampledMesh& s, std::size_t v) {
  const planning::CurvatureField& c = r.curvature;
  const std::size_t at = static_cast<std::size_t>(s.copy[v]);
  out += std::to_string(s.raster.vertexPoint[v]);
  for (const int value : s.fik[v]) out += ',' + std::to_string(value);
  for (int a = 0; a < 3; ++a) appendCsvNumber(out, s.raster.mesh.vertices[v][a]);
  for (const auto* values : {&c.kMax, &c.kMin, &c.mean, &c.gaussian})
    appendCsvNumber(out, (*values)[at]);
  for (const ddf::Vec3& d : {c.dirMax[at], c.dirMin[at]})
    for (int a = 0; a < 3; ++a) appendCsvNumber(out, static_cast<float>(d[a]));
  out += ',' + std::to_string(int{c.umbilic[at]}) + '\n';
}

/// Writes @p text to a temporary file beside @p path and renames it over @p path, so a failed
/// run never leaves a truncated CSV behind.
void writeTextAtomically(const std::string& text, const std::filesystem::path& path) {
  std::filesystem::path temp = path;
  temp += ".partial";
  std::ofstream file(temp, std::ios::binary | std::ios::trunc);
  file.write(text.data(), static_cast<std::streamsize>(text.size()));
  file.close();
  std::error_code ec;
  if (file) std::filesystem::rename(temp, path, ec);
  if (!file || ec) {
    std::filesystem::remove(temp, ec);
    throw IoError("cannot write " + path.string());
  }
}

/// Writes one CSV row per mesh vertex that has a copy, in raster point id order; returns rows.
std::size_t writeCsv(const CurvatureResult& r, const SampledMesh& s,
                     const std::filesystem::path& path) {
  std::vector<std::size_t> order(s.copy.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return s.raster.vertexPoint[a] < s.raster.vertexPoint[b];
  });
  std::string text =
      "point_id,face,i,k,x,y,z,k_max,k_min,mean,gaussian,dir_max_x,dir_max_y,dir_max_z,"
      "dir_min_x,dir_min_y,dir_min_z,umbilic\n";
  std::size_t rows = 0;
  for (const std::size_t v : order) {
    if (s.copy[v] < 0) continue;
    appendCsvRow(text, r, s, v);
    ++rows;
  }
  writeTextAtomically(text, path);
  return rows;
}

/// "[lo, hi]" over the finite values at the mesh vertices' copies.
std::string range(const std::vector<float>& values, const SampledMesh& s) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (const std::ptrdiff_t at : s.copy)
    if (at >= 0 && std::isfinite(values[at])) {
      lo = std::min(lo, values[at]);
      hi = std::max(hi, values[at]);
    }
  if (lo > hi) return "[none]";
  char text[64];
  std::snprintf(text, sizeof text, "[%.6g, %.6g]", lo, hi);
  return text;
}

void printSummary(const CurvatureResult& r, const SampledMesh& s) {
  std::array<std::size_t, 4> types{};
  std::size_t points = 0, umbilic = 0;
  for (const std::ptrdiff_t at : s.copy) {
    if (at < 0) continue;
    ++points;
    ++types[static_cast<std::size_t>(r.type[at])];
    umbilic += r.curvature.umbilic[at];
  }
  if (r.curvature.method == planning::CurvatureMethod::VertexQuadricFit)
    std::printf("  raster points: %zu, vertex quadric fits (the faces are flat)\n", points);
  else if (r.curvature.method == planning::CurvatureMethod::DesignMeshFit)
    std::printf("  raster points: %zu, vertex quadric fits of the mesh the part came from\n",
                points);
  else
    std::printf("  raster points: %zu, difference step d = %d\n", points, r.curvature.step);
  std::printf("  k_max %s 1/mm, k_min %s 1/mm\n", range(r.curvature.kMax, s).c_str(),
              range(r.curvature.kMin, s).c_str());
  std::printf("  types: ");
  for (std::uint8_t t = 0; t < 4; ++t)
    std::printf("%s%s %zu", t > 0 ? ", " : "",
                planning::curvatureTypeName(static_cast<planning::CurvatureType>(t)), types[t]);
  std::printf("; umbilic %zu\n", umbilic);
}

std::filesystem::path outputPath(const Arguments& args, const std::filesystem::path& input) {
  std::filesystem::path out = args.value("output").value_or(
      std::filesystem::path(input).replace_extension(".vtp").string());
  std::string ext = out.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (ext != ".vtp") throw UsageError("output " + out.string() + " must end in .vtp");
  return out;
}

int runCurvature(std::span<const std::string> words) {
  Arguments args = options();
  args.parse(words);
  args.expectPositionals(1, "an input part (.ddf or mesh)");
  const std::filesystem::path input = args.positionals()[0];
  const std::filesystem::path output = outputPath(args, input);
  const int step = args.integer("step", 0);
  const Clock::time_point start = Clock::now();
  io::LoadPartParams load;
  load.unit = unitOption(args);
  const planning::Project project = openPartInUnit(input, load, "loading");
  const ddf::DisplacementField& field = *project.part;
  planning::CurvatureParams params = planning::partCurvatureParams(project);
  params.step = step;
  const Clock::time_point computeStart = Clock::now();
  params.progress = consoleProgress("curvature");
  CurvatureResult r{planning::computeCurvature(field, params), {}, {}};
  endProgressLine();
  const double computeMs = millisecondsSince(computeStart);
  r.type = planning::curvatureTypeField(r.curvature).values;
  r.radius = planning::maxToolRadiusField(r.curvature).values;
  const SampledMesh s = sampleMesh(field);
  io::writeVtp(s.raster.mesh, pointData(r, s), output);
  const std::optional<std::string> csv = args.value("csv");
  const std::size_t csvRows = csv ? writeCsv(r, s, *csv) : 0;
  std::printf("curvature of %s: %d faces, m = %d\n", input.string().c_str(), field.faceCount(),
              field.raster().m);
  printSummary(r, s);
  std::printf("wrote %s: %zu points, %zu triangles\n", output.string().c_str(),
              s.raster.mesh.vertices.size(), s.raster.mesh.triangles.size());
  if (csv) std::printf("wrote %s: %zu rows\n", csv->c_str(), csvRows);
  std::printf("  time: curvature %.1f ms, total %.1f ms\n", computeMs, millisecondsSince(start));
  return 0;
}

}  // namespace

const Command kCurvatureCommand{"curvature",
                                "principal curvatures of a part as a coloured .vtp and a CSV",
                                &help, &runCurvature};

}  // namespace ddfcam::cli
