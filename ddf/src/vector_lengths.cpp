// SPDX-License-Identifier: MIT
// ddfcam: iterative choice of vector lengths with per-face crust heights and non-adjacent
// crust conflicts (sec. 4.4).
#include <ddfcam/ddf/crust.h>
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/vector_lengths.h>
#include <ddfcam/error.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <set>
#include <string>

namespace ddfcam::ddf {
namespace {

struct LengthState {
  std::vector<Vec3> dirs;       // unit directions per vertex
  std::vector<double> len;      // current length per vertex, mm
  std::vector<double> initial;  // length after the initial per-face step
  std::vector<char> validFace;  // face satisfies constraint 1
};

void checkParams(const VectorLengthParams& p) {
  if (!(p.safety > 0.0 && p.safety <= 1.0))
    throw InvalidInput("vector lengths: safety must be in (0, 1], got " + std::to_string(p.safety));
  if (!(p.conflictShrink > 0.0 && p.conflictShrink < 1.0))
    throw InvalidInput("vector lengths: conflictShrink must be in (0, 1), got " +
                       std::to_string(p.conflictShrink));
  if (p.maxIterations < 1 || !(p.maxLengthMm >= 0.0))
    throw InvalidInput("vector lengths: need maxIterations >= 1 and maxLengthMm >= 0");
}

std::vector<Vec3> unitDirections(const DisplacementField& ddf) {
  std::vector<Vec3> dirs(ddf.vertexCount());
  for (int v = 0; v < ddf.vertexCount(); ++v) {
    const double n = ddf.vector(v).norm();
    if (!(n > 0.0) || !std::isfinite(n))
      throw InvalidInput("vector lengths: the vector of vertex " + std::to_string(v) +
                         " is zero or not finite, so it has no direction");
    dirs[v] = ddf.vector(v) / n;
  }
  return dirs;
}

std::vector<Vec3> vectorsOf(const LengthState& st) {
  std::vector<Vec3> out(st.dirs.size());
  for (std::size_t v = 0; v < out.size(); ++v) out[v] = st.len[v] * st.dirs[v];
  return out;
}

/// Crust heights of face f with vectors len x dir.
CrustHeights heightsWith(const DisplacementField& ddf, int f, const LengthState& st) {
  const auto& fv = ddf.faceVertices(f);
  return crustHeights(ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]),
                      st.len[fv[0]] * st.dirs[fv[0]], st.len[fv[1]] * st.dirs[fv[1]],
                      st.len[fv[2]] * st.dirs[fv[2]]);
}

/// Per face with unit vectors: length safety x h0 (capped); per vertex the shortest.
void initialLengths(const DisplacementField& ddf, LengthState& st, double maxLen, double safety) {
  const int faces = ddf.faceCount();
  std::vector<double> faceLen(faces, maxLen);
  st.validFace.assign(faces, 1);
  st.len.assign(ddf.vertexCount(), 1.0);
  tbb::parallel_for(0, faces, [&](int f) {
    const double h0 = heightsWith(ddf, f, st).min();
    if (h0 <= 0.0) st.validFace[f] = 0;
    faceLen[f] = std::min(maxLen, safety * h0);
  });
  st.len.assign(ddf.vertexCount(), maxLen);
  for (int f = 0; f < faces; ++f)
    if (st.validFace[f])
      for (int v : ddf.faceVertices(f)) st.len[v] = std::min(st.len[v], faceLen[f]);
  st.initial = st.len;
}

/// Crust heights of face f with every length capped at @p cap.
double cappedH0(const DisplacementField& ddf, int f, const LengthState& st, double cap) {
  const auto& fv = ddf.faceVertices(f);
  std::array<Vec3, 3> v;
  for (int i = 0; i < 3; ++i) v[i] = std::min(st.len[fv[i]], cap) * st.dirs[fv[i]];
  return crustHeights(ddf.position(fv[0]), ddf.position(fv[1]), ddf.position(fv[2]), v[0], v[1],
                      v[2])
      .min();
}

/// The largest common cap on the lengths of face f that gives h0 >= target. Capping at the
/// face's shortest length makes the lengths equal, where h0 scales exactly inversely with the
/// length, so a cap that works always exists at or below it; above it, geometric bisection.
double faceCap(const DisplacementField& ddf, int f, const LengthState& st, double target) {
  const auto& fv = ddf.faceVertices(f);
  double lo = std::min({st.len[fv[0]], st.len[fv[1]], st.len[fv[2]]});
  double hi = std::max({st.len[fv[0]], st.len[fv[1]], st.len[fv[2]]});
  const double atLo = cappedH0(ddf, f, st, lo);
  if (atLo < target) return lo * atLo / target;
  for (int it = 0; it < 40 && hi > lo * (1.0 + 1e-6); ++it) {
    const double mid = std::sqrt(lo * hi);
    (cappedH0(ddf, f, st, mid) >= target ? lo : hi) = mid;
  }
  return lo;
}

/// Shortens the vertices of every valid face with min h0 < 1 so that it reaches 1/safety:
/// uniformly by safety x h0 (sec. 4.4), or by capping its longest vectors. Marks the changed
/// vertices; returns true when no face needed it.
bool fixFaces(const DisplacementField& ddf, LengthState& st, const VectorLengthParams& params,
              std::vector<char>& changed) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> factor(ddf.faceCount(), 1.0), cap(ddf.faceCount(), inf);
  tbb::parallel_for(0, ddf.faceCount(), [&](int f) {
    if (!st.validFace[f]) return;
    const double h0 = heightsWith(ddf, f, st).min();
    if (h0 >= 1.0) return;
    if (params.uniformShrink) {
      factor[f] = params.safety * h0;
    } else {
      cap[f] = faceCap(ddf, f, st, 1.0 / params.safety);
    }
  });
  bool ok = true;
  std::vector<double> next = st.len;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    if (factor[f] >= 1.0 && cap[f] == inf) continue;
    ok = false;
    for (int v : ddf.faceVertices(f)) {
      next[v] = std::min({next[v], st.len[v] * factor[f], cap[f]});
      changed[v] |= next[v] < st.len[v];
    }
  }
  st.len = std::move(next);
  return ok;
}

double minValidH0(const DisplacementField& ddf, const LengthState& st) {
  double m = std::numeric_limits<double>::infinity();
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (st.validFace[f]) m = std::min(m, heightsWith(ddf, f, st).min());
  return m;
}

/// Faces incident to any vertex flagged in @p changed.
std::vector<int> facesOfVertices(const DisplacementField& ddf, const std::vector<char>& changed) {
  std::vector<char> mark(ddf.faceCount(), 0);
  for (int v = 0; v < ddf.vertexCount(); ++v)
    if (changed[v])
      for (int f : ddf.topology().vertexFaces(v)) mark[f] = 1;
  std::vector<int> out;
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (mark[f]) out.push_back(f);
  return out;
}

/// The non-adjacent conflict rounds share this state across loop passes.
struct ConflictTracker {
  std::vector<int> vertexClasses;  // unwelded duplicates make faces adjacent too
  std::optional<CrustHash> hash;
  std::vector<char> dirtyVertices;
  std::set<std::array<int, 2>> seen;
};

/// One conflict round on faces changed since the last one; shrinks the vertices of every
/// conflicting pair. Returns the number of conflicts found.
std::size_t conflictRound(DisplacementField& ddf, LengthState& st, ConflictTracker& tr,
                          double shrink) {
  ddf.setVectors(vectorsOf(st));
  std::vector<int> dirty = facesOfVertices(ddf, tr.dirtyVertices);
  if (!tr.hash) {
    tr.hash.emplace(ddf);
  } else {
    tr.hash->updateFaces(ddf, dirty);
  }
  const auto conflicts = findCrustConflicts(ddf, *tr.hash, dirty, {}, tr.vertexClasses);
  tr.dirtyVertices.assign(ddf.vertexCount(), 0);
  for (const auto& pair : conflicts) {
    tr.seen.insert(pair);
    for (int f : pair)
      for (int v : ddf.faceVertices(f)) tr.dirtyVertices[v] = 1;
  }
  for (int v = 0; v < ddf.vertexCount(); ++v)
    if (tr.dirtyVertices[v]) st.len[v] *= shrink;
  return conflicts.size();
}

}  // namespace

double meanEdgeLength(const DisplacementField& ddf) {
  const auto& mesh = ddf.support();
  double sum = 0.0;
  for (const auto eh : mesh.edges()) sum += mesh.calc_edge_length(eh);
  return mesh.n_edges() > 0 ? sum / static_cast<double>(mesh.n_edges()) : 0.0;
}

namespace {

/// Per-face passes until every valid face has h0 >= 1 (at most maxIterations passes).
bool settleFaces(const DisplacementField& ddf, LengthState& st, const VectorLengthParams& params,
                 ConflictTracker& tracker, VectorLengthReport& report) {
  for (int pass = 0; pass < params.maxIterations; ++pass) {
    ++report.iterations;
    std::vector<char> changed(ddf.vertexCount(), 0);
    const bool ok = fixFaces(ddf, st, params, changed);
    for (int v = 0; v < ddf.vertexCount(); ++v) tracker.dirtyVertices[v] |= changed[v];
    if (ok) return true;
  }
  return false;
}

/// Fills the summary fields of @p report from the final state.
void summarize(DisplacementField& ddf, const LengthState& st, bool conflictsClear,
               ConflictTracker& tracker, VectorLengthReport& report) {
  ddf.setVectors(vectorsOf(st));
  if (!conflictsClear) {
    const auto remaining = findAllCrustConflicts(ddf, CrustHash(ddf), {}, tracker.vertexClasses);
    report.remainingConflicts = static_cast<int>(remaining.size());
    for (const auto& pair : remaining) tracker.seen.erase(pair);
  }
  report.nonAdjacentConflictsResolved = static_cast<int>(tracker.seen.size());
  report.minH0 = minValidH0(ddf, st);
  for (int f = 0; f < ddf.faceCount(); ++f)
    if (!st.validFace[f]) report.constraint1Faces.push_back(f);
  for (int v = 0; v < ddf.vertexCount(); ++v)
    report.shortenedVertices += st.len[v] < st.initial[v] * (1.0 - 1e-12);
}

VectorLengthReport chooseLengthsInPlace(DisplacementField& ddf, const VectorLengthParams& params) {
  VectorLengthReport report;
  LengthState st;
  st.dirs = unitDirections(ddf);
  double maxLen = params.maxLengthMm > 0.0 ? params.maxLengthMm : meanEdgeLength(ddf);
  if (!(maxLen > 0.0)) maxLen = 1.0;  // no edges: any length is fine
  initialLengths(ddf, st, maxLen, params.safety);
  ConflictTracker tracker;
  tracker.dirtyVertices.assign(ddf.vertexCount(), 1);
  if (params.checkNonAdjacent)
    tracker.vertexClasses = coincidentVertexClasses(ddf, params.coincidentToleranceMm);
  bool facesOk = settleFaces(ddf, st, params, tracker, report);
  bool conflictsClear = !params.checkNonAdjacent;
  while (facesOk && !conflictsClear && report.conflictRounds < params.maxIterations) {
    reportProgress(params.progress, double(report.conflictRounds) / params.maxIterations);
    ++report.conflictRounds;
    conflictsClear = conflictRound(ddf, st, tracker, params.conflictShrink) == 0;
    if (!conflictsClear) facesOk = settleFaces(ddf, st, params, tracker, report);
  }
  const double minH0 = facesOk ? 1.0 : minValidH0(ddf, st);
  if (minH0 < 1.0) {  // uniform scaling restores h0 >= 1/safety on every face at once
    for (double& l : st.len) l *= params.safety * minH0;
    report.usedFallback = true;
  }
  summarize(ddf, st, conflictsClear, tracker, report);
  return report;
}

}  // namespace

VectorLengthReport chooseVectorLengths(DisplacementField& ddf, const VectorLengthParams& params) {
  checkParams(params);
  const std::vector<Vec3> original = ddf.vectors();
  try {
    VectorLengthReport report = chooseLengthsInPlace(ddf, params);
    reportProgress(params.progress, 1.0);
    return report;
  } catch (...) {
    ddf.setVectors(original);  // a cancelled (or failed) choice leaves the field as it was
    throw;
  }
}

}  // namespace ddfcam::ddf
