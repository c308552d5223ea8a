// SPDX-License-Identifier: MIT
// ddfcam: the adaptive triangulation kept per support face and rebuilt only where heights
// changed: vertex slots shared through their place on the support, per-edge vertex lists for
// the T-vertex removal, normals summed from per-face parts.
#include <ddfcam/ddf/incremental_triangulation.h>
#include <ddfcam/error.h>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <unordered_map>
#include <utility>

#include "adaptive_assembly.h"
#include "adaptive_face.h"
#include "canonical_points.h"

namespace ddfcam::ddf {

using detail::FaceResult;

namespace {

// Mesh vertices inside one support edge: (canonical scaled position t, slot), sorted by t.
using EdgeList = std::vector<std::pair<std::int64_t, int>>;

struct EdgeListChain {
  const std::vector<EdgeList>* edges;
  void operator()(std::uint32_t edge, std::int64_t ta, std::int64_t tb,
                  std::vector<int>& out) const {
    const EdgeList& list = (*edges)[edge];
    const auto lo = std::min(ta, tb), hi = std::max(ta, tb);
    auto first = std::upper_bound(list.begin(), list.end(), std::pair{lo, INT32_MAX});
    const std::size_t begin = out.size();
    for (; first != list.end() && first->first < hi; ++first) out.push_back(first->second);
    if (ta > tb) std::reverse(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end());
  }
};

std::vector<int> sortedUnique(std::vector<int> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

}  // namespace

struct IncrementalTriangulation::State {
  const DisplacementField* ddf = nullptr;
  detail::PointOwners owners;
  std::vector<Vec3> boundary;
  detail::AdaptiveContext ctx;
  std::vector<FaceResult> results;
  std::vector<std::vector<std::array<int, 3>>> triangles;      // per face, slots
  // Per face, per triangle; computed on demand (faceTriangleParams), stale after a rebuild.
  mutable std::vector<std::vector<TriangleParams>> params;
  mutable std::vector<std::uint8_t> paramsStale;
  std::vector<std::vector<int>> centroidSlots;                 // per face
  std::vector<std::vector<std::pair<int, Vec3>>> normalParts;  // per face, sorted by slot
  std::vector<Vec3> vertices, normals;
  std::vector<std::uint64_t> slotKey;  // 0: inner or centroid slot
  std::vector<int> slotRefs, slotFace, freeSlots;
  std::unordered_map<std::uint64_t, int> keySlot;
  std::vector<EdgeList> edgeLists;
  std::vector<float> faceEps;  // the bound of every face, mm (ctx.faceEps points here)

  explicit State(const DisplacementField& field) : ddf(&field), owners(field) {}

  int allocate(const Vec3& position, std::uint64_t key, int face);
  void release(int slot);
  void registerFace(int f);
  void unregisterFace(int f);
  void refreshBoundary(const std::vector<int>& faces);
  void subdivide(const std::vector<int>& faces);
  void reassemble(const std::vector<int>& faces);
  void facesOfSlot(int slot, std::vector<int>& out) const;
  void refreshNormals(const std::vector<int>& slots);
  TriangulationUpdate rebuild(std::vector<int> subdivided, bool heightsChanged);
  std::vector<int> starOf(std::span<const int> faces) const;
  std::vector<int> edgeNeighbours(const std::vector<int>& faces) const;
};

int IncrementalTriangulation::State::allocate(const Vec3& position, std::uint64_t key, int face) {
  int slot;
  if (!freeSlots.empty()) {
    slot = freeSlots.back();
    freeSlots.pop_back();
  } else {
    slot = static_cast<int>(vertices.size());
    vertices.emplace_back(), normals.emplace_back(), slotKey.push_back(0);
    slotRefs.push_back(0), slotFace.push_back(-1);
  }
  vertices[slot] = position;
  normals[slot] = Vec3::Zero();
  slotKey[slot] = key;
  slotRefs[slot] = 1;
  slotFace[slot] = face;
  return slot;
}

void IncrementalTriangulation::State::release(int slot) {
  if (--slotRefs[slot] > 0) return;
  const std::uint64_t key = slotKey[slot];
  if (key != 0) {
    keySlot.erase(key);
    if (!detail::isSupportVertexKey(key)) {
      EdgeList& list = edgeLists[key >> 32];
      const auto t = static_cast<std::int64_t>(key & 0xffffffffu);
      list.erase(std::lower_bound(list.begin(), list.end(), std::pair{t, INT32_MIN}));
    }
  }
  normals[slot] = Vec3::Zero();
  slotKey[slot] = 0;
  freeSlots.push_back(slot);
}

void IncrementalTriangulation::State::registerFace(int f) {
  FaceResult& r = results[f];
  r.vertexIndex.assign(r.vertices.size(), -1);
  for (std::size_t v = 0; v < r.vertices.size(); ++v) {
    const std::uint64_t key = detail::borderKey(*ddf, ctx.scale, f, r.vertices[v]);
    if (key == 0) {
      r.vertexIndex[v] = allocate(r.vertices[v].position, 0, f);
      continue;
    }
    const auto [it, inserted] = keySlot.try_emplace(key, -1);
    if (!inserted) {
      ++slotRefs[it->second];
      vertices[it->second] = r.vertices[v].position;  // bitwise the same from either face
      r.vertexIndex[v] = it->second;
      continue;
    }
    it->second = r.vertexIndex[v] = allocate(r.vertices[v].position, key, -1);
    if (!detail::isSupportVertexKey(key)) {
      EdgeList& list = edgeLists[key >> 32];
      const std::pair entry{static_cast<std::int64_t>(key & 0xffffffffu), it->second};
      list.insert(std::lower_bound(list.begin(), list.end(), entry), entry);
    }
  }
}

void IncrementalTriangulation::State::unregisterFace(int f) {
  for (int slot : results[f].vertexIndex) release(slot);
  results[f].vertexIndex.clear();
}

void IncrementalTriangulation::State::refreshBoundary(const std::vector<int>& faces) {
  const RasterTopology& topo = ddf->topology();
  const int n = ddf->raster().steps();
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t at) {
    const int f = faces[at];
    // Each point is written by its owner only, as canonicalBoundaryPoints does.
    auto visit = [&](int i, int k) {
      const PointId id = topo.id(f, i, k);
      if (owners.owner(id, f) == f) boundary[id] = ddf->surfacePoint(f, i, k);
    };
    for (int i = 0; i <= n; ++i) visit(i, 0);
    for (int k = 1; k <= n; ++k) visit(0, k);
    for (int k = 1; k < n; ++k) visit(n - k, k);
  });
}

void IncrementalTriangulation::State::subdivide(const std::vector<int>& faces) {
  tbb::enumerable_thread_specific<detail::FaceSubdivider> workers(
      [&] { return detail::FaceSubdivider(ctx); });
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t at) {
    std::vector<int> keep = std::move(results[faces[at]].vertexIndex);
    workers.local().run(faces[at], results[faces[at]]);
    results[faces[at]].vertexIndex = std::move(keep);  // the old slots, released next
  });
  for (int f : faces) unregisterFace(f);
  for (int f : faces) registerFace(f);
}

void IncrementalTriangulation::State::reassemble(const std::vector<int>& faces) {
  const detail::TVertexRemoval removal(*ddf, ctx.scale, EdgeListChain{&edgeLists});
  tbb::enumerable_thread_specific<std::vector<int>> polygons;
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t at) {
    removal.retriangulate(faces[at], results[faces[at]], vertices, polygons.local());
  });
  for (int f : faces) {
    for (int slot : centroidSlots[f]) release(slot);
    centroidSlots[f].clear();
    FaceResult& r = results[f];
    for (const Vec3& c : r.centroids) centroidSlots[f].push_back(allocate(c, 0, f));
    triangles[f] = r.triangles;
    for (auto& t : triangles[f])
      for (int& v : t)
        if (v < 0) v = centroidSlots[f][-v - 1];
  }
  tbb::parallel_for(std::size_t{0}, faces.size(), [&](std::size_t at) {
    const int f = faces[at];
    paramsStale[f] = 1;  // computed when asked for: only a textured display needs them
    std::vector<std::pair<int, Vec3>> parts;
    for (const auto& t : triangles[f]) {
      const Vec3 n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
      for (int v : t) parts.emplace_back(v, n);
    }
    // Summed per slot in triangle order: the same order whatever the update history.
    std::stable_sort(parts.begin(), parts.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<std::pair<int, Vec3>>& out = normalParts[f];
    out.clear();
    for (const auto& [v, n] : parts)
      if (!out.empty() && out.back().first == v) out.back().second += n;
      else out.emplace_back(v, n);
  });
}

void IncrementalTriangulation::State::facesOfSlot(int slot, std::vector<int>& out) const {
  out.clear();
  const std::uint64_t key = slotKey[slot];
  if (key == 0) {
    out.push_back(slotFace[slot]);
  } else if (detail::isSupportVertexKey(key)) {
    const int v = static_cast<int>(key & 0xffffffffu);
    const auto& star = ddf->topology().vertexFaces(v);
    out.assign(star.begin(), star.end());
  } else {
    for (int f : ddf->topology().edgeFaces(static_cast<int>(key >> 32)))
      if (f >= 0) out.push_back(f);
  }
  std::sort(out.begin(), out.end());
}

void IncrementalTriangulation::State::refreshNormals(const std::vector<int>& slots) {
  tbb::enumerable_thread_specific<std::vector<int>> scratch;
  tbb::parallel_for(std::size_t{0}, slots.size(), [&](std::size_t at) {
    const int slot = slots[at];
    if (slotRefs[slot] <= 0) return;  // free
    std::vector<int>& faces = scratch.local();
    facesOfSlot(slot, faces);
    Vec3 sum = Vec3::Zero();
    for (int f : faces) {
      const auto& parts = normalParts[f];
      const auto it = std::lower_bound(parts.begin(), parts.end(), slot,
                                       [](const auto& p, int s) { return p.first < s; });
      if (it != parts.end() && it->first == slot) sum += it->second;
    }
    const double len = sum.norm();
    normals[slot] = len > 0.0 ? Vec3(sum / len) : Vec3::Zero();
  });
}

std::vector<int> IncrementalTriangulation::State::starOf(std::span<const int> faces) const {
  std::vector<int> out;
  for (int f : faces) {
    if (f < 0 || f >= ddf->faceCount())
      throw InvalidInput("IncrementalTriangulation::update: face " + std::to_string(f) +
                         " is not a support face (0.." + std::to_string(ddf->faceCount() - 1) +
                         ")");
    for (int v : ddf->faceVertices(f))
      for (int g : ddf->topology().vertexFaces(v)) out.push_back(g);
  }
  return sortedUnique(std::move(out));
}

std::vector<int> IncrementalTriangulation::State::edgeNeighbours(
    const std::vector<int>& faces) const {
  std::vector<int> out = faces;
  for (int f : faces)
    for (int side = 0; side < 3; ++side)
      for (int g : ddf->topology().edgeFaces(ddf->topology().faceEdge(f, side)))
        if (g >= 0) out.push_back(g);
  return sortedUnique(std::move(out));
}

IncrementalTriangulation::IncrementalTriangulation(const DisplacementField& ddf, double epsMm)
    : state_(std::make_unique<State>(ddf)) {
  if (!(epsMm > 0.0))
    throw InvalidInput("IncrementalTriangulation: error bound epsMm must be positive, got " +
                       std::to_string(epsMm));
  State& s = *state_;
  s.boundary = detail::canonicalBoundaryPoints(ddf, s.owners);
  s.ctx.ddf = &ddf;
  s.ctx.boundary = &s.boundary;
  s.ctx.eps = epsMm;
  // Until setFaceEps() the uniform bound (a double) decides, bit for bit as a fresh build.
  s.faceEps.assign(static_cast<std::size_t>(ddf.faceCount()), static_cast<float>(epsMm));
  s.ctx.collectChains = true;
  while (s.ctx.scale < ddf.raster().steps()) s.ctx.scale *= 2;
  const int faces = ddf.faceCount();
  s.results.resize(faces);
  s.triangles.resize(faces);
  s.params.resize(faces);
  s.paramsStale.assign(static_cast<std::size_t>(faces), 1);
  s.centroidSlots.resize(faces);
  s.normalParts.resize(faces);
  s.edgeLists.resize(ddf.support().n_edges());
  std::vector<int> all(faces);
  for (int f = 0; f < faces; ++f) all[f] = f;
  s.subdivide(all);
  s.reassemble(all);
  std::vector<int> slots(s.vertices.size());
  for (std::size_t i = 0; i < slots.size(); ++i) slots[i] = static_cast<int>(i);
  s.refreshNormals(slots);
}

IncrementalTriangulation::~IncrementalTriangulation() = default;
IncrementalTriangulation::IncrementalTriangulation(IncrementalTriangulation&&) noexcept = default;
IncrementalTriangulation& IncrementalTriangulation::operator=(IncrementalTriangulation&&) noexcept =
    default;

TriangulationUpdate IncrementalTriangulation::State::rebuild(std::vector<int> subdivided,
                                                             bool heightsChanged) {
  const auto start = std::chrono::steady_clock::now();
  TriangulationUpdate out;
  out.subdividedFaces = std::move(subdivided);
  out.reassembledFaces = edgeNeighbours(out.subdividedFaces);
  std::vector<int> touched;
  for (int f : out.reassembledFaces)
    for (const auto& t : triangles[f]) touched.insert(touched.end(), t.begin(), t.end());
  if (heightsChanged) refreshBoundary(out.subdividedFaces);
  subdivide(out.subdividedFaces);
  reassemble(out.reassembledFaces);
  for (int f : out.reassembledFaces)
    for (const auto& t : triangles[f]) touched.insert(touched.end(), t.begin(), t.end());
  out.touchedSlots = sortedUnique(std::move(touched));
  refreshNormals(out.touchedSlots);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

TriangulationUpdate IncrementalTriangulation::update(std::span<const int> changedFaces) {
  return state_->rebuild(state_->starOf(changedFaces), true);
}

TriangulationUpdate IncrementalTriangulation::setFaceEps(std::span<const float> epsMm) {
  State& s = *state_;
  checkFaceEps(*s.ddf, epsMm);
  if (epsMm.empty()) throw InvalidInput("IncrementalTriangulation::setFaceEps: no bounds");
  std::vector<int> changed;
  for (std::size_t f = 0; f < epsMm.size(); ++f)
    if (static_cast<double>(epsMm[f]) != s.ctx.epsOf(static_cast<int>(f)))
      changed.push_back(static_cast<int>(f));
  std::copy(epsMm.begin(), epsMm.end(), s.faceEps.begin());
  s.ctx.faceEps = &s.faceEps;
  if (changed.empty()) return {};
  // A bound moves the decisions inside its face and on its edges: those faces and the faces
  // across the edges are subdivided again; the points they share do not move.
  return s.rebuild(s.edgeNeighbours(changed), false);
}

const std::vector<float>& IncrementalTriangulation::faceEps() const {
  return state_->faceEps;
}

double IncrementalTriangulation::epsMm() const {
  return state_->ctx.eps;
}

const std::vector<Vec3>& IncrementalTriangulation::vertices() const {
  return state_->vertices;
}

const std::vector<Vec3>& IncrementalTriangulation::normals() const {
  return state_->normals;
}

const std::vector<std::array<int, 3>>& IncrementalTriangulation::faceTriangles(int face) const {
  return state_->triangles.at(static_cast<std::size_t>(face));
}

const std::vector<TriangleParams>& IncrementalTriangulation::faceTriangleParams(int face) const {
  const State& s = *state_;
  const auto f = static_cast<std::size_t>(face);
  if (s.paramsStale.at(f)) {
    detail::cornerParams(*s.ddf, s.ctx.scale, face, s.results[f], s.slotKey, s.params[f]);
    s.paramsStale[f] = 0;
  }
  return s.params[f];
}

std::size_t IncrementalTriangulation::triangleCount() const {
  std::size_t n = 0;
  for (const auto& t : state_->triangles) n += t.size();
  return n;
}

AdaptiveTriangulation IncrementalTriangulation::snapshot() const {
  const State& s = *state_;
  AdaptiveTriangulation out;
  std::vector<int> index(s.vertices.size(), -1);
  for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f) {
    for (auto t : s.triangles[f]) {
      for (int& v : t) {
        if (index[v] < 0) {
          index[v] = static_cast<int>(out.mesh.vertices.size());
          out.mesh.vertices.push_back(s.vertices[v]);
        }
        v = index[v];
      }
      out.mesh.triangles.push_back(t);
      out.triangleFace.push_back(f);
    }
    out.leafTriangles += s.results[f].leaves.size() + s.results[f].finals.size();
    out.maxErrorMm = std::max(out.maxErrorMm, s.results[f].maxError);
  }
  return out;
}

}  // namespace ddfcam::ddf
