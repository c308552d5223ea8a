// SPDX-License-Identifier: MIT
#include <ddfcam/ddf/crust_hash.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

namespace ddfcam::ddf {
namespace {

constexpr int kMaxSplits = 32;  // caps the sub-volume count of one face at 32 x 32 x 32

// Points of the sub-triangle grid of level s: barycentric (a, b, s - a - b) / s.
Vec3 gridBary(int a, int b, int s) {
  return Vec3(a, b, s - a - b) / static_cast<double>(s);
}

// Calls fn(b0, b1, b2) with the barycentric corners of every sub-triangle of level s.
template <class Fn>
void forEachSubTriangle(int s, Fn&& fn) {
  for (int a = 0; a < s; ++a)
    for (int b = 0; a + b < s; ++b) {
      fn(gridBary(a, b, s), gridBary(a + 1, b, s), gridBary(a, b + 1, s));
      if (a + b + 2 <= s)
        fn(gridBary(a + 1, b, s), gridBary(a + 1, b + 1, s), gridBary(a, b + 1, s));
    }
}

}  // namespace

CrustHash::CrustHash(const DisplacementField& ddf, const CrustHashParams& params)
    : params_(params) {
  // Centre of the triangle extension space (sec. 5.1): mean x, y and z extent of the faces.
  Vec3 mean = Vec3::Zero();
  for (int f = 0; f < ddf.faceCount(); ++f) {
    Eigen::AlignedBox3d box;
    for (int v : ddf.faceVertices(f)) box.extend(ddf.position(v));
    mean += box.sizes();
  }
  if (ddf.faceCount() > 0) mean /= ddf.faceCount();
  const double largest = mean.maxCoeff();
  // A flat support has zero extent along its normal; such an axis borrows half the largest.
  for (int a = 0; a < 3; ++a) mean[a] = std::max(mean[a], 0.5 * largest);
  if (!(largest > 0.0)) mean = Vec3::Ones();
  cellSize_ = mean * params_.cellScale;
  invCell_ = cellSize_.cwiseInverse();
  rebuild(ddf);
}

CrustHash::CellKey CrustHash::key(const Eigen::Vector3i& c) const {
  // 21 bits per axis, two's complement folded into an unsigned field.
  constexpr std::uint64_t mask = (1u << 21) - 1;
  return (static_cast<std::uint64_t>(c.x()) & mask) |
         ((static_cast<std::uint64_t>(c.y()) & mask) << 21) |
         ((static_cast<std::uint64_t>(c.z()) & mask) << 42);
}

Eigen::Vector3i CrustHash::cellOf(const Vec3& p) const {
  const Vec3 s = p.cwiseProduct(invCell_);
  return {static_cast<int>(std::floor(s.x())), static_cast<int>(std::floor(s.y())),
          static_cast<int>(std::floor(s.z()))};
}

void CrustHash::collectCells(const Eigen::AlignedBox3d& box, std::vector<CellKey>& keys) const {
  const Eigen::Vector3i lo = cellOf(box.min()), hi = cellOf(box.max());
  for (int x = lo.x(); x <= hi.x(); ++x)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int z = lo.z(); z <= hi.z(); ++z) keys.push_back(key({x, y, z}));
}

Eigen::AlignedBox3d CrustHash::crustBox(const DisplacementField& ddf, int face) {
  Eigen::AlignedBox3d box;
  for (int v : ddf.faceVertices(face)) {
    box.extend(ddf.position(v) + ddf.vector(v));
    box.extend(ddf.position(v) - ddf.vector(v));
  }
  return box;
}

std::vector<CrustHash::CellKey> CrustHash::faceKeys(const DisplacementField& ddf, int face) const {
  // Sub-volumes (fig. 5.2): the box of the six corners of a sub-triangle slab bounds the slab,
  // because at fixed h the slab section is the affine image of the sub-triangle.
  const Eigen::AlignedBox3d whole = crustBox(ddf, face);
  const double target = params_.subVolumeFraction * cellSize_.minCoeff();
  const auto& fv = ddf.faceVertices(face);
  double edge = 0.0, thickness = 0.0;
  for (int e = 0; e < 3; ++e) {
    edge = std::max(edge, (ddf.position(fv[e]) - ddf.position(fv[(e + 1) % 3])).norm());
    thickness = std::max(thickness, 2.0 * ddf.vector(fv[e]).norm());
  }
  const int s = std::clamp(static_cast<int>(std::ceil(edge / target)), 1, kMaxSplits);
  const int layers = std::clamp(static_cast<int>(std::ceil(thickness / target)), 1, kMaxSplits);
  std::vector<CellKey> keys;
  if (s == 1 && layers == 1) {
    collectCells(whole, keys);
  } else {
    forEachSubTriangle(s, [&](const Vec3& b0, const Vec3& b1, const Vec3& b2) {
      for (int l = 0; l < layers; ++l) {
        const double h0 = -1.0 + 2.0 * l / layers, h1 = -1.0 + 2.0 * (l + 1) / layers;
        Eigen::AlignedBox3d box;
        for (const Vec3* b : {&b0, &b1, &b2}) {
          box.extend(ddf.pointAt(face, *b, h0));
          box.extend(ddf.pointAt(face, *b, h1));
        }
        collectCells(box, keys);
      }
    });
  }
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  keys.shrink_to_fit();  // the sub-volume pass collected many duplicates
  return keys;
}

void CrustHash::insertFace(const DisplacementField& ddf, int face) {
  faceCells_[face] = faceKeys(ddf, face);
  for (CellKey k : faceCells_[face]) cells_[k].push_back(face);
}

void CrustHash::removeFace(int face) {
  for (CellKey k : faceCells_[face]) {
    auto it = cells_.find(k);
    if (it == cells_.end()) continue;
    auto& list = it->second;
    list.erase(std::remove(list.begin(), list.end(), face), list.end());
    if (list.empty()) cells_.erase(it);
  }
  faceCells_[face].clear();
}

void CrustHash::rebuild(const DisplacementField& ddf) {
  cells_.clear();
  faceCells_.assign(ddf.faceCount(), {});
  cells_.reserve(static_cast<std::size_t>(ddf.faceCount()) * 4);
  // The cells of each face are found in parallel (most of the cost); the table is filled in
  // face order, so every cell lists its faces in ascending order as before.
  tbb::parallel_for(0, ddf.faceCount(), [&](int f) { faceCells_[f] = faceKeys(ddf, f); });
  for (int f = 0; f < ddf.faceCount(); ++f)
    for (CellKey k : faceCells_[f]) cells_[k].push_back(f);
  for (auto& [k, list] : cells_) list.shrink_to_fit();
}

void CrustHash::updateFaces(const DisplacementField& ddf, std::span<const int> faces) {
  if (faceCells_.size() != static_cast<std::size_t>(ddf.faceCount())) {
    rebuild(ddf);
    return;
  }
  for (int f : faces) removeFace(f);
  for (int f : faces) insertFace(ddf, f);
}

void CrustHash::gatherFaces(const std::vector<CellKey>& keys, std::vector<int>& out) const {
  out.clear();
  for (CellKey k : keys) {
    const auto it = cells_.find(k);
    if (it != cells_.end()) out.insert(out.end(), it->second.begin(), it->second.end());
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

void CrustHash::queryTriangle(const Vec3& a, const Vec3& b, const Vec3& c,
                              std::vector<int>& out) const {
  const double target = params_.subVolumeFraction * cellSize_.minCoeff();
  const double edge = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const int s = std::clamp(static_cast<int>(std::ceil(edge / target)), 1, kMaxSplits);
  std::vector<CellKey> keys;
  forEachSubTriangle(s, [&](const Vec3& b0, const Vec3& b1, const Vec3& b2) {
    Eigen::AlignedBox3d box;
    for (const Vec3* w : {&b0, &b1, &b2}) box.extend((*w)[0] * a + (*w)[1] * b + (*w)[2] * c);
    collectCells(box, keys);
  });
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  gatherFaces(keys, out);
}

void CrustHash::queryBox(const Eigen::AlignedBox3d& box, std::vector<int>& out) const {
  std::vector<CellKey> keys;
  collectCells(box, keys);
  gatherFaces(keys, out);
}

void CrustHash::queryCrust(int face, std::vector<int>& out) const {
  gatherFaces(faceCells_[face], out);
  out.erase(std::remove(out.begin(), out.end(), face), out.end());
}

std::size_t CrustHash::memoryBytes() const {
  std::size_t bytes = cells_.bucket_count() * sizeof(void*);
  for (const auto& [k, list] : cells_)
    bytes += sizeof(k) + sizeof(list) + 2 * sizeof(void*) + list.capacity() * sizeof(int);
  for (const auto& keys : faceCells_) bytes += sizeof(keys) + keys.capacity() * sizeof(CellKey);
  return bytes;
}

CrustHashParams crustHashParamsFor(const DisplacementField& ddf) {
  double edges = 0.0, vectors = 0.0;
  for (int f = 0; f < ddf.faceCount(); ++f) {
    const auto& fv = ddf.faceVertices(f);
    edges += (ddf.position(fv[1]) - ddf.position(fv[0])).norm();
  }
  for (int v = 0; v < ddf.vertexCount(); ++v) vectors += ddf.vector(v).norm();
  CrustHashParams params;
  if (edges > 0.0 && ddf.vertexCount() > 0) {
    const double ratio = (vectors / ddf.vertexCount()) / (edges / ddf.faceCount());
    params.cellScale = std::clamp(ratio, 1.0, 8.0);
  }
  return params;
}

}  // namespace ddfcam::ddf
