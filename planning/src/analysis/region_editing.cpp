// SPDX-License-Identifier: MIT
// ddfcam: manual region editing (sec. 8.1): assign, brush, merge, split, rename, remove.
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/region_editing.h>

#include "hsv_color.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace ddfcam::planning {
namespace {

void checkIndex(const std::vector<Region>& regions, int index, const char* what) {
  if (index < 0 || index >= static_cast<int>(regions.size()))
    throw InvalidInput(std::string(what) + ": region index " + std::to_string(index) +
                       " out of range (" + std::to_string(regions.size()) + " regions)");
}

std::vector<int> sortedUnique(std::vector<int> faces) {
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

// Candidate i of distinctRegionColor(): a golden-ratio hue walk, alternating between vivid,
// pale and dark variants so that crowded hue circles still leave clearly different colours.
std::array<float, 3> candidateColor(int i) {
  static constexpr double kSaturation[3] = {0.65, 0.35, 0.75};
  static constexpr double kValue[3] = {0.92, 0.97, 0.6};
  return detail::hsvColor(0.13 + 0.6180339887498949 * i, kSaturation[i % 3], kValue[i % 3]);
}

// Components of @p faces over shared support edges, each ascending, ordered by lowest face.
std::vector<std::vector<int>> connectedParts(const ddf::DisplacementField& ddf,
                                             const std::vector<int>& faces) {
  const auto& mesh = ddf.support();
  std::vector<int> part(ddf.faceCount(), -2);  // -2: not in the set, -1: unvisited
  for (int f : faces) {
    if (f < 0 || f >= ddf.faceCount())
      throw InvalidInput("split region: face " + std::to_string(f) + " is not a face of the part");
    part[f] = -1;
  }
  std::vector<std::vector<int>> out;
  std::vector<int> stack;
  for (int seed : faces) {  // ascending, so parts come out ordered by their lowest face
    if (part[seed] != -1) continue;
    const int id = static_cast<int>(out.size());
    out.emplace_back();
    part[seed] = id;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const int f = stack.back();
      stack.pop_back();
      out.back().push_back(f);
      for (auto nb : mesh.ff_range(mesh.face_handle(f))) {
        if (part[nb.idx()] != -1) continue;
        part[nb.idx()] = id;
        stack.push_back(nb.idx());
      }
    }
    std::sort(out.back().begin(), out.back().end());
  }
  return out;
}

}  // namespace

std::vector<int> faceRegionIndex(const std::vector<Region>& regions, int faceCount) {
  std::vector<int> index(static_cast<std::size_t>(std::max(faceCount, 0)), -1);
  for (std::size_t r = 0; r < regions.size(); ++r) {
    for (int f : regions[r].faces) {
      if (f < 0 || f >= faceCount)
        throw InvalidInput("region '" + regions[r].name + "': face " + std::to_string(f) +
                           " out of range (" + std::to_string(faceCount) + " faces)");
      if (index[f] >= 0 && index[f] != static_cast<int>(r))
        throw InvalidInput("face " + std::to_string(f) + " lies in regions '" +
                           regions[index[f]].name + "' and '" + regions[r].name + "'");
      index[f] = static_cast<int>(r);
    }
  }
  return index;
}

ScalarField regionIndexField(const ddf::DisplacementField& ddf,
                             const std::vector<Region>& regions) {
  const std::vector<int> index = faceRegionIndex(regions, ddf.faceCount());
  ScalarField field;
  field.name = "region";
  const std::size_t perFace = ddf.pointsPerFace();
  field.values.resize(perFace * index.size());
  for (std::size_t f = 0; f < index.size(); ++f) {
    const float value =
        index[f] < 0 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(index[f]);
    std::fill_n(field.values.begin() + static_cast<std::ptrdiff_t>(f * perFace), perFace, value);
  }
  return field;
}

std::array<float, 3> distinctRegionColor(const std::vector<Region>& regions) {
  std::array<float, 3> best = candidateColor(0);
  double bestDistance = -1.0;
  for (int i = 0; i < 96 && !regions.empty(); ++i) {
    const std::array<float, 3> c = candidateColor(i);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Region& r : regions) {
      double d = 0.0;
      for (int k = 0; k < 3; ++k) d += (c[k] - r.color[k]) * (c[k] - r.color[k]);
      nearest = std::min(nearest, d);
    }
    if (nearest > bestDistance + 1e-9) {
      bestDistance = nearest;
      best = c;
    }
  }
  return best;
}

std::vector<Region> assignFaces(const std::vector<Region>& regions, int target,
                                std::span<const int> faces, int faceCount,
                                const std::string& newRegionName) {
  const int count = static_cast<int>(regions.size());
  if (target < -1 || target > count)
    throw InvalidInput("assign faces: region index " + std::to_string(target) + " out of range (" +
                       std::to_string(count) + " regions)");
  faceRegionIndex(regions, faceCount);  // consistency check
  std::vector<char> moving(static_cast<std::size_t>(faceCount), 0);
  for (int f : faces) {
    if (f < 0 || f >= faceCount)
      throw InvalidInput("assign faces: face " + std::to_string(f) + " out of range (" +
                         std::to_string(faceCount) + " faces)");
    moving[f] = 1;
  }
  std::vector<Region> out = regions;
  if (target == count) {
    if (newRegionName.empty()) throw InvalidInput("assign faces: the new region has no name");
    Region fresh;
    fresh.name = newRegionName;
    fresh.color = distinctRegionColor(regions);
    out.push_back(std::move(fresh));
  }
  for (Region& r : out) std::erase_if(r.faces, [&](int f) { return moving[f] != 0; });
  if (target >= 0) {
    std::vector<int>& into = out[target].faces;
    into.insert(into.end(), faces.begin(), faces.end());
    into = sortedUnique(std::move(into));
  }
  return out;
}

std::vector<Region> mergeRegions(const std::vector<Region>& regions, std::vector<int> indices) {
  indices = sortedUnique(std::move(indices));
  if (indices.size() < 2) throw InvalidInput("merge regions: select at least two regions");
  for (int i : indices) checkIndex(regions, i, "merge regions");
  std::vector<Region> out = regions;
  std::vector<int>& into = out[indices.front()].faces;
  for (std::size_t k = 1; k < indices.size(); ++k) {
    const std::vector<int>& from = regions[indices[k]].faces;
    into.insert(into.end(), from.begin(), from.end());
  }
  into = sortedUnique(std::move(into));
  for (std::size_t k = indices.size() - 1; k >= 1; --k) out.erase(out.begin() + indices[k]);
  return out;
}

std::vector<Region> splitConnectedParts(const ddf::DisplacementField& ddf,
                                        const std::vector<Region>& regions, int index) {
  checkIndex(regions, index, "split region");
  const std::vector<std::vector<int>> parts = connectedParts(ddf, regions[index].faces);
  std::vector<Region> out = regions;
  if (parts.size() < 2) return out;
  out[index].faces = parts.front();
  for (std::size_t p = 1; p < parts.size(); ++p) {
    Region piece = regions[index];
    piece.name = regions[index].name + " (" + std::to_string(p + 1) + ")";
    piece.faces = parts[p];
    piece.color = distinctRegionColor(out);
    out.insert(out.begin() + index + static_cast<std::ptrdiff_t>(p), std::move(piece));
  }
  return out;
}

std::vector<Region> splitRegionFaces(const std::vector<Region>& regions, int index,
                                     std::span<const int> faces) {
  checkIndex(regions, index, "split region");
  const Region& source = regions[index];
  const std::vector<int> moving = sortedUnique({faces.begin(), faces.end()});
  if (moving.empty()) throw InvalidInput("split region '" + source.name + "': no faces given");
  for (int f : moving)
    if (!std::binary_search(source.faces.begin(), source.faces.end(), f))
      throw InvalidInput("split region '" + source.name + "': face " + std::to_string(f) +
                         " is not in the region");
  if (moving.size() == source.faces.size())
    throw InvalidInput("split region '" + source.name + "': cannot split off all faces");
  std::vector<Region> out = regions;
  std::vector<int> kept;
  std::set_difference(source.faces.begin(), source.faces.end(), moving.begin(), moving.end(),
                      std::back_inserter(kept));
  out[index].faces = std::move(kept);
  Region piece = source;
  piece.name = source.name + " (split)";
  piece.faces = moving;
  piece.color = distinctRegionColor(out);
  out.insert(out.begin() + index + 1, std::move(piece));
  return out;
}

std::vector<Region> renameRegion(const std::vector<Region>& regions, int index,
                                 const std::string& name) {
  checkIndex(regions, index, "rename region");
  if (name.empty())
    throw InvalidInput("rename region '" + regions[index].name + "': the new name is empty");
  std::vector<Region> out = regions;
  out[index].name = name;
  return out;
}

std::vector<Region> removeRegion(const std::vector<Region>& regions, int index) {
  checkIndex(regions, index, "remove region");
  std::vector<Region> out = regions;
  out.erase(out.begin() + index);
  return out;
}

std::vector<Region> setRegionPlan(const std::vector<Region>& regions, int index,
                                  const RegionPlan& plan) {
  checkIndex(regions, index, "set region plan");
  std::vector<Region> out = regions;
  out[index].plan = plan;
  return out;
}

std::vector<FaceFrame> faceFrames(const ddf::DisplacementField& ddf) {
  const int n = ddf.raster().steps();
  std::vector<FaceFrame> frames(ddf.faceCount());
  for (int f = 0; f < ddf.faceCount(); ++f) {
    ddf::Vec3 sum = ddf::Vec3::Zero();
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) sum += ddf.surfacePoint(f, i, k);
    frames[f].centroid = sum / static_cast<double>(ddf.pointsPerFace());
    const ddf::Vec3 a = ddf.surfacePoint(f, n, 0), b = ddf.surfacePoint(f, 0, 0),
                    c = ddf.surfacePoint(f, 0, n);  // corners (n,0,0), (0,n,0), (0,0,n)
    ddf::Vec3 normal = (b - a).cross(c - a);
    const auto& v = ddf.faceVertices(f);
    const ddf::Vec3 meanVector = ddf.vector(v[0]) + ddf.vector(v[1]) + ddf.vector(v[2]);
    if (normal.dot(meanVector) < 0.0) normal = -normal;
    const double length = normal.norm();
    frames[f].normal = length > 0.0 ? ddf::Vec3(normal / length) : ddf::Vec3::Zero();
  }
  return frames;
}

bool pointInPolygon(const Eigen::Vector2d& point, std::span<const Eigen::Vector2d> polygon) {
  if (polygon.size() < 3) return false;
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d &a = polygon[i], &b = polygon[j];
    if ((a.y() > point.y()) != (b.y() > point.y()) &&
        point.x() < (b.x() - a.x()) * (point.y() - a.y()) / (b.y() - a.y()) + a.x())
      inside = !inside;
  }
  return inside;
}

// ---- SurfacePointGrid -------------------------------------------------------------------------

SurfacePointGrid::SurfacePointGrid(const ddf::DisplacementField& ddf, double cellSizeMm)
    : faceCount_(ddf.faceCount()) {
  if (faceCount_ == 0) throw InvalidInput("surface point grid: the DDF has no faces");
  const int n = ddf.raster().steps();
  points_.reserve(ddf.pointsPerFace() * faceCount_);
  pointFace_.reserve(points_.capacity());
  double edgeSum = 0.0;
  for (int f = 0; f < faceCount_; ++f) {
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        points_.push_back(ddf.surfacePoint(f, i, k));
        pointFace_.push_back(f);
      }
    const auto& v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e)
      edgeSum += (ddf.position(v[e]) - ddf.position(v[(e + 1) % 3])).norm();
  }
  double cellSize = cellSizeMm > 0.0 ? cellSizeMm : edgeSum / (3.0 * faceCount_);
  if (!(cellSize > 0.0) || !std::isfinite(cellSize)) cellSize = 1.0;
  ddf::Vec3 lo = points_.front(), hi = points_.front();
  for (const ddf::Vec3& p : points_) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  // Cells 2^21 apart share a grid key; coarsen the grid if the part spans more.
  while (((hi - lo) / cellSize).maxCoeff() >= double(1 << 20)) cellSize *= 2.0;
  grid_ = UniformGrid(cellSize);
  for (std::size_t p = 0; p < points_.size(); ++p) grid_.add(static_cast<int>(p), points_[p]);
}

std::vector<int> SurfacePointGrid::facesWithinDistance(const ddf::Vec3& point,
                                                       double radiusMm) const {
  if (!(radiusMm >= 0.0) || !std::isfinite(radiusMm))
    throw InvalidInput("brush radius " + std::to_string(radiusMm) + " mm: must be finite and >= 0");
  std::vector<char> hit(faceCount_, 0);
  const double r2 = radiusMm * radiusMm;
  grid_.forEachNear(point, radiusMm, [&](int p) {
    if ((points_[p] - point).squaredNorm() <= r2) hit[pointFace_[p]] = 1;
  });
  std::vector<int> out;
  for (int f = 0; f < faceCount_; ++f)
    if (hit[f]) out.push_back(f);
  return out;
}

std::vector<int> facesWithinDistance(const ddf::DisplacementField& ddf, const ddf::Vec3& point,
                                     double radiusMm) {
  return SurfacePointGrid(ddf).facesWithinDistance(point, radiusMm);
}

}  // namespace ddfcam::planning
