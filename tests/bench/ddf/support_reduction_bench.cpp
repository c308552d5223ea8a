// SPDX-License-Identifier: MIT
// ddfcam-bench: support reduction by constrained edge contraction (dissertation sec. 6.3,
// fig. 6.13/6.14 Bunny, fig. 6.19/6.21 B-spline patch) and the turbine blade, with the
// dissertation's figures printed next to ours and the deviation of the reduced DDF from the
// input measured both ways.
#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/mesh_conversion.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/ddf/support_reduction.h>
#include <ddfcam/ddf/validation.h>
#include <ddfcam/io/mesh/mesh_io.h>
#include <ddfcam/planning/surface/mesh_distance.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <memory>
#include <string>

namespace ddfcam::bench {
namespace {

using ddf::Vec3;

/// An input mesh and the support the conversion builds from it (welded, non-manifold faces
/// dropped) with its unit pseudo-normals: what reduceSupport receives in the conversion; and
/// those normals scaled to 2 % of the bounding-box diagonal, the start of the runs of the
/// dissertation's constraint set. Without unique projection nothing chooses the lengths, and
/// unit vectors on the bunny (0.25 units across) would make every crust hold the whole part;
/// the dissertation does not state its lengths.
struct Part {
  ddf::TriangleMesh input;
  ddf::SupportMesh support;
  std::vector<Vec3> normals;
  std::vector<Vec3> scaledNormals;
  int droppedFaces = 0;
};

std::unique_ptr<Part> prepare(ddf::TriangleMesh mesh) {
  auto part = std::make_unique<Part>();
  ddf::ConversionParams params;
  params.chooseLengths = false;
  const auto converted = ddf::convertMeshToDdf(mesh, params);
  part->input = std::move(mesh);
  part->support = converted.ddf.support();
  part->normals = converted.ddf.vectors();
  part->droppedFaces = converted.report.droppedFaces;
  const auto box = part->input.bounds();
  const double length = 0.02 * (box[1] - box[0]).norm();
  for (const Vec3& n : part->normals) part->scaledNormals.push_back(length * n.normalized());
  return part;
}

const Part* sharedPart(const std::string& file, double scale) {
  static std::map<std::string, std::unique_ptr<Part>> parts;
  auto& slot = parts[file];
  if (!slot) {
    const auto path = std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / file;
    if (!std::filesystem::exists(path)) return nullptr;
    ddf::TriangleMesh mesh = io::readMesh(path);
    for (Vec3& p : mesh.vertices) p *= scale;
    slot = prepare(std::move(mesh));
  }
  return slot.get();
}

// The 20,000-triangle B-spline patch (100 x 100 quads split in two) of fig. 6.17.
const Part* bsplinePart() {
  static const std::unique_ptr<Part> part = [] {
    ddf::FreeformPatchParams p;
    p.m = 2;
    const auto patch = ddf::freeformPatch(p);
    return prepare(ddf::extractSupportMesh(patch.ddf));
  }();
  return part.get();
}

/// Constraint sets: none (fig. 6.13, 6.21); all of sec. 6.2 with the conversion's defaults
/// (feature edges kept); and the set of the dissertation's runs of fig. 6.14 and 6.19
/// (candidates, coverage, containment; no unique projection, angle bound or feature edges);
/// and all of sec. 6.2 without the feature edges (a scan's noise makes many edges sharp).
enum Mode { kNone = 0, kAll = 1, kPaperSet = 2, kAllSmooth = 3 };

ddf::SupportReductionParams paramsFor(int m, int mode) {
  ddf::SupportReductionParams p;
  p.resolution = m;
  if (mode == kNone)
    p.requireInputCoverage = p.requireRayCoverage = p.requireContainment =
        p.requireUniqueProjection = p.requireAngleBound = false;
  if (mode != kAll) p.featureAngleDeg = 180.0;
  if (mode == kAllSmooth) return p;
  if (mode == kPaperSet) p.requireUniqueProjection = p.requireAngleBound = false;
  return p;
}

/// Largest distances input -> DDF surface (input vertices and centroids) and DDF raster
/// points -> input, with the heights filled from the input (the conversion's fill step).
struct Deviations {
  double inputToDdf = 0.0, ddfToInput = 0.0;
  std::size_t unfilled = 0;
  int issues = 0;  // validate() issues of the filled DDF (all three constraints)
  std::string firstIssue;
};
Deviations deviations(const Part& part, const ddf::SupportReductionResult& r, int m) {
  ddf::DisplacementField field(r.support, r.vectors, m);
  const auto fill = ddf::fillFromMesh(field, ddf::CrustHash(field), part.input);
  const ddf::TriangleMesh surface = ddf::extractRasterMesh(field).mesh;
  const planning::MeshDistance toInput(part.input), toDdf(surface);
  double ddfToInput = 0.0, inputToDdf = 0.0;
  for (const Vec3& q : surface.vertices)
    if (const auto c = toInput.closestPoint(q))
      ddfToInput = std::max(ddfToInput, std::abs(c->signedDistance));
  for (const auto& t : part.input.triangles) {
    const auto& v = part.input.vertices;
    for (const Vec3& q : {v[t[0]], Vec3((v[t[0]] + v[t[1]] + v[t[2]]) / 3.0)})
      if (const auto c = toDdf.closestPoint(q))
        inputToDdf = std::max(inputToDdf, std::abs(c->signedDistance));
  }
  const auto check = ddf::validate(field);
  return {inputToDdf, ddfToInput, fill.missing,
          static_cast<int>(check.issues.size()) + check.suppressedIssues,
          check.issues.empty() ? std::string() : check.issues.front().message};
}

std::map<std::string, double>& constrainedSeconds() {
  static std::map<std::string, double> seconds;
  return seconds;
}

void runReduction(benchmark::State& state, const Part* part, const std::string& key, int m,
                  int mode, double paperTriangles, double paperSeconds) {
  if (!part) {
    state.SkipWithError("shared mesh data not present");
    return;
  }
  ddf::SupportReductionResult result;
  for (auto _ : state) {
    const auto& vectors = mode == kPaperSet ? part->scaledNormals : part->normals;
    result = ddf::reduceSupport(part->support, vectors, {}, paramsFor(m, mode));
    benchmark::DoNotOptimize(result.support.n_faces());
  }
  const auto [inToDdf, ddfToIn, unfilled, issues, firstIssue] = deviations(*part, result, m);
  if (!firstIssue.empty()) state.SetLabel("first issue: " + firstIssue);
  const auto box = part->input.bounds();
  auto& c = state.counters;
  c["inputTriangles"] = static_cast<double>(part->input.triangles.size());
  c["droppedFaces"] = part->droppedFaces;
  c["supportTriangles"] = result.report.supportFaces;
  c["seconds"] = result.report.seconds;
  c["sweeps"] = result.report.sweeps;
  c["inToDdfMm"] = inToDdf;
  c["ddfToInMm"] = ddfToIn;
  c["unfilledPoints"] = static_cast<double>(unfilled);
  c["validateIssues"] = issues;
  c["diagMm"] = (box[1] - box[0]).norm();
  if (paperTriangles > 0) c["paperTriangles"] = paperTriangles;
  if (paperSeconds > 0) c["paperSeconds"] = paperSeconds;
  const auto& rep = result.report;
  c["refCover"] = rep.rejectedInputCoverage;
  c["refRays"] = rep.rejectedRayCoverage;
  c["refContain"] = rep.rejectedContainment;
  c["refUnique"] = rep.rejectedUniqueProjection;
  c["refAngle"] = rep.rejectedAngle;
  c["refCritical"] = rep.rejectedCritical;
  if (mode == kAll) {
    constrainedSeconds()[key] = rep.seconds;
  } else if (const auto it = constrainedSeconds().find(key);
             mode == kNone && it != constrainedSeconds().end()) {
    c["constrainedOverUnconstrained"] = it->second / std::max(rep.seconds, 1e-9);
  }
}

// Fig. 6.14: 16,301 -> 1,675 triangles in 150 s with candidates, coverage and containment;
// fig. 6.13: 503 triangles in 7 s without constraints.
void BM_Reduction_Bunny(benchmark::State& state) {
  const int mode = static_cast<int>(state.range(0));
  runReduction(state, sharedPart("bun_zipper_res2.ply", 1.0), "bunny", 10, mode,
               mode != kNone ? 1675 : 503, mode != kNone ? 150 : 7);
}
BENCHMARK(BM_Reduction_Bunny)
    ->Arg(kAll)
    ->Arg(kAllSmooth)
    ->Arg(kPaperSet)
    ->Arg(kNone)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// Fig. 6.19: m = 10..50 -> 1420, 662, 526, 478, 452 triangles in 3, 10, 25, 43, 82 min; fig.
// 6.21: 400 triangles in 10.4 s without constraints at m = 50.
void BM_Reduction_BSpline(benchmark::State& state) {
  const int m = static_cast<int>(state.range(0));
  const int mode = static_cast<int>(state.range(1));
  const bool constrained = mode != kNone;
  const std::map<int, std::pair<double, double>> paper = {
      {10, {1420, 180}}, {20, {662, 600}}, {30, {526, 1500}}, {40, {478, 2580}}, {50, {452, 4920}}};
  const auto it = paper.find(m);
  double tris = constrained && it != paper.end() ? it->second.first : 0;
  double secs = constrained && it != paper.end() ? it->second.second : 0;
  if (!constrained && m == 50) tris = 400, secs = 10.4;
  runReduction(state, bsplinePart(), "bspline" + std::to_string(m), m, mode, tris, secs);
}
BENCHMARK(BM_Reduction_BSpline)
    ->ArgsProduct({{10, 20, 30, 40, 50}, {kAll, kPaperSet}})
    ->Args({50, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The turbine blade (metres in the file, reduced in mm).
void BM_Reduction_Blade(benchmark::State& state) {
  runReduction(state, sharedPart("turbine-blade-jigsaw.stl", 1000.0), "blade", 10,
               static_cast<int>(state.range(0)), 0, 0);
}
BENCHMARK(BM_Reduction_Blade)->Arg(kAll)->Arg(kNone)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
}  // namespace ddfcam::bench
