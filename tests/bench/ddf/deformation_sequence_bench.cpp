// SPDX-License-Identifier: MIT
// ddfcam-bench: the deformation sequence (ch. 9, fig. 9.5) on the shared springback pair, with
// a brute-force per-stubble ray/mesh reference for the speed-up.
#include <ddfcam/ddf/deformation_sequence.h>
#include <ddfcam/ddf/pseudo_normals.h>

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <memory>
#include <vector>

namespace ddfcam::bench {
namespace {

using ddf::Vec3;

struct SpringbackPair {
  ddf::SupportMesh target;
  ddf::TriangleMesh formed;
};

// Loaded once; null when the shared data is absent.
const SpringbackPair* springbackPair() {
  static const std::unique_ptr<SpringbackPair> pair = [] {
    const auto dir =
        std::filesystem::path(DDFCAM_SHARED_DATA_DIR) / "meshes" / "springback-deepdrawn";
    auto out = std::make_unique<SpringbackPair>();
    ddf::SupportMesh formed;
    if (!OpenMesh::IO::read_mesh(out->target, (dir / "target_AF_bs.stl").string()) ||
        !OpenMesh::IO::read_mesh(formed, (dir / "mesh_ausgerichtet1.stl").string()))
      return std::unique_ptr<SpringbackPair>();
    for (const auto vh : formed.vertices())
      out->formed.vertices.push_back(ddf::toEigen(formed.point(vh)));
    for (const auto fh : formed.faces()) {
      std::array<int, 3> t{};
      int c = 0;
      for (const auto vh : formed.fv_range(fh)) t[c++] = vh.idx();
      out->formed.triangles.push_back(t);
    }
    return out;
  }();
  return pair.get();
}

// Reference: the nearest hit in [-1, 1] of one stubble against every triangle (Moller-Trumbore).
double bruteForceHeight(const ddf::TriangleMesh& mesh, const Vec3& g, const Vec3& v) {
  double best = std::numeric_limits<double>::quiet_NaN();
  for (const auto& t : mesh.triangles) {
    const Vec3 &a = mesh.vertices[t[0]], e1 = mesh.vertices[t[1]] - a, e2 = mesh.vertices[t[2]] - a;
    const Vec3 p = v.cross(e2);
    const double det = e1.dot(p);
    if (std::abs(det) < 1e-300) continue;
    const Vec3 s = g - a;
    const double u = s.dot(p) / det;
    const Vec3 q = s.cross(e1);
    const double w = v.dot(q) / det;
    if (u < 0 || w < 0 || u + w > 1) continue;
    const double h = e2.dot(q) / det;
    if (std::abs(h) <= 1.0 && !(std::abs(h) >= std::abs(best))) best = h;
  }
  return best;
}

// Seconds per stubble of the brute-force reference, measured once on the first faces.
double bruteForceSecondsPerStubble(const ddf::DeformationSequence& seq,
                                   const ddf::TriangleMesh& formed) {
  static double cached = 0.0;
  if (cached > 0.0) return cached;
  const ddf::DisplacementField& stage = seq.stages[0].ddf;
  const int n = stage.raster().steps();
  std::size_t count = 0;
  double sink = 0.0;
  const auto start = std::chrono::steady_clock::now();
  for (int f = 0; f < 20; ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++count) {
        const Vec3 bary = stage.rasterBary(i, k);
        const double h =
            bruteForceHeight(formed, stage.basePoint(f, bary), stage.vectorAt(f, bary));
        if (std::isfinite(h)) sink += h;
      }
  benchmark::DoNotOptimize(sink);
  cached = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / count;
  return cached;
}

// Arg: crustSafety x 10 (8 = default; 4 forces a split on this pair). Resolution m = 4.
void BM_DeformationSequenceSpringbackPair(benchmark::State& state) {
  const SpringbackPair* pair = springbackPair();
  if (pair == nullptr) {
    state.SkipWithError("shared springback pair not present");
    return;
  }
  const ddf::DisplacementField mould(pair->target, ddf::pseudoNormals(pair->target).normals, 4);
  ddf::DeformationSequenceParams params;
  params.crustSafety = state.range(0) / 10.0;
  ddf::DeformationSequence seq;
  for (auto _ : state) seq = ddf::buildDeformationSequence(mould, pair->formed, params);
  const double stubbles = 0.0 + seq.deformedPoints.size() * seq.stages.size();
  state.counters["faces"] = mould.faceCount();
  state.counters["stages"] = static_cast<double>(seq.stages.size());
  state.counters["crossing_faces"] = static_cast<double>(seq.crossingFaces.size());
  state.counters["unresolved_faces"] = static_cast<double>(seq.unresolvedFaces.size());
  state.counters["missing_points"] = static_cast<double>(seq.missingPoints);
  state.counters["stubbles_per_s"] =
      benchmark::Counter(stubbles * state.iterations(), benchmark::Counter::kIsRate);
  // Brute force would need bruteSeconds per stubble of every stage.
  state.counters["x_vs_bruteforce"] = benchmark::Counter(
      bruteForceSecondsPerStubble(seq, pair->formed) * stubbles * state.iterations(),
      benchmark::Counter::kIsRate);
}
BENCHMARK(BM_DeformationSequenceSpringbackPair)
    ->Arg(8)
    ->Arg(4)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(2);

}  // namespace
}  // namespace ddfcam::bench
