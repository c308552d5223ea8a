// SPDX-License-Identifier: MIT
// ddfcam: manual region editing (sec. 8.1): assign, brush, merge, split, rename, remove.
#include <ddfcam/error.h>
#include <ddfcam/planning/analysis/region_editing.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

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

std::array<float, 3> hsvColor(double hue01, double s, double v) {
  const double hue = std::fmod(hue01, 1.0) * 6.0;
  const double c = s * v;
  const double x = c * (1.0 - std::abs(std::fmod(hue, 2.0) - 1.0));
  const double r[6] = {c, x, 0, 0, x, c}, g[6] = {x, c, c, x, 0, 0}, b[6] = {0, 0, x, c, c, x};
  const int sector = std::min(5, static_cast<int>(hue));
  const double m = v - c;
  return {static_cast<float>(r[sector] + m), static_cast<float>(g[sector] + m),
          static_cast<float>(b[sector] + m)};
}

// Candidate i of distinctRegionColor(): a golden-ratio hue walk, alternating between vivid,
// pale and dark variants so that crowded hue circles still leave clearly different colours.
std::array<float, 3> candidateColor(int i) {
  static constexpr double kSaturation[3] = {0.65, 0.35, 0.75};
  static constexpr double kValue[3] = {0.92, 0.97, 0.6};
  return hsvColor(0.13 + 0.6180339887498949 * i, kSaturation[i % 3], kValue[i % 3]);
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
  std::vector<ddf::Vec3> points;
  std::vector<int> faces;
  points.reserve(ddf.pointsPerFace() * faceCount_);
  double edgeSum = 0.0;
  for (int f = 0; f < faceCount_; ++f) {
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i <= n - k; ++i) {
        points.push_back(ddf.surfacePoint(f, i, k));
        faces.push_back(f);
      }
    const auto& v = ddf.faceVertices(f);
    for (int e = 0; e < 3; ++e)
      edgeSum += (ddf.position(v[e]) - ddf.position(v[(e + 1) % 3])).norm();
  }
  cellSize_ = cellSizeMm > 0.0 ? cellSizeMm : edgeSum / (3.0 * faceCount_);
  if (!(cellSize_ > 0.0) || !std::isfinite(cellSize_)) cellSize_ = 1.0;
  ddf::Vec3 lo = points.front(), hi = points.front();
  for (const ddf::Vec3& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  origin_ = lo;
  // Cell coordinates are packed into 21 bits each; coarsen the grid if the part needs more.
  while (((hi - lo) / cellSize_).maxCoeff() >= double(1 << 20)) cellSize_ *= 2.0;
  for (int a = 0; a < 3; ++a) dims_[a] = static_cast<int>((hi[a] - lo[a]) / cellSize_) + 1;
  std::vector<std::pair<std::int64_t, int>> order(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    const auto c = cellOf(points[p]);
    order[p] = {key(c[0], c[1], c[2]), static_cast<int>(p)};
  }
  std::sort(order.begin(), order.end());
  points_.reserve(points.size());
  pointFace_.reserve(points.size());
  for (std::size_t p = 0; p < order.size(); ++p) {
    points_.push_back(points[order[p].second]);
    pointFace_.push_back(faces[order[p].second]);
    auto [it, fresh] = cells_.try_emplace(order[p].first, static_cast<int>(p), static_cast<int>(p));
    it->second.second = static_cast<int>(p) + 1;
  }
}

std::int64_t SurfacePointGrid::key(int x, int y, int z) const {
  return (static_cast<std::int64_t>(x) << 42) | (static_cast<std::int64_t>(y) << 21) | z;
}

std::array<int, 3> SurfacePointGrid::cellOf(const ddf::Vec3& p) const {
  std::array<int, 3> c{};
  for (int a = 0; a < 3; ++a)
    c[a] =
        std::clamp(static_cast<int>(std::floor((p[a] - origin_[a]) / cellSize_)), 0, dims_[a] - 1);
  return c;
}

std::vector<int> SurfacePointGrid::facesWithinDistance(const ddf::Vec3& point,
                                                       double radiusMm) const {
  if (!(radiusMm >= 0.0) || !std::isfinite(radiusMm))
    throw InvalidInput("brush radius " + std::to_string(radiusMm) + " mm: must be finite and >= 0");
  std::vector<char> hit(faceCount_, 0);
  const double r2 = radiusMm * radiusMm;
  const auto visit = [&](const std::pair<int, int>& range) {
    for (int p = range.first; p < range.second; ++p)
      if ((points_[p] - point).squaredNorm() <= r2) hit[pointFace_[p]] = 1;
  };
  const ddf::Vec3 reach = ddf::Vec3::Constant(radiusMm);
  const ddf::Vec3 lo = (point - reach - origin_) / cellSize_,
                  hi = (point + reach - origin_) / cellSize_;
  bool outside = false;
  std::array<int, 3> a{}, b{};
  double boxCells = 1.0;
  for (int k = 0; k < 3; ++k) {
    if (hi[k] < 0.0 || lo[k] >= dims_[k]) outside = true;
    a[k] = std::clamp(static_cast<int>(std::floor(lo[k])), 0, dims_[k] - 1);
    b[k] = std::clamp(static_cast<int>(std::floor(hi[k])), 0, dims_[k] - 1);
    boxCells *= b[k] - a[k] + 1;
  }
  if (outside) return {};
  if (boxCells > static_cast<double>(cells_.size())) {
    for (const auto& [cellKey, range] : cells_) visit(range);  // a huge brush: every cell
  } else {
    for (int x = a[0]; x <= b[0]; ++x)
      for (int y = a[1]; y <= b[1]; ++y)
        for (int z = a[2]; z <= b[2]; ++z)
          if (const auto it = cells_.find(key(x, y, z)); it != cells_.end()) visit(it->second);
  }
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
