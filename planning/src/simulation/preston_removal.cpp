// SPDX-License-Identifier: MIT
// ddfcam: applyPrestonRemoval (Winkler contact pressure, Preston wear law) on a DDF workpiece.
#include <ddfcam/planning/simulation/preston_removal.h>

#include "../placement/tangential_raster.h"

#include <ddfcam/error.h>
#include <ddfcam/planning/placement/tangential_grid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>

namespace ddfcam::planning {

namespace {

using detail::GridBox;
using detail::Local;

void validate(const ddf::TriangleMesh& toolMesh, const ToolPath& path, const PrestonParams& p) {
  if (toolMesh.triangles.empty()) throw InvalidInput("Preston removal: the tool mesh is empty");
  const auto positive = [](double x, const char* name) {
    if (!(x > 0.0) || !std::isfinite(x))
      throw InvalidInput(std::string("Preston removal: ") + name + " must be positive");
  };
  positive(p.prestonCoefficientMm2PerN, "prestonCoefficientMm2PerN");
  positive(p.forceN, "forceN");
  positive(p.surfaceSpeedMmPerS, "surfaceSpeedMmPerS");
  positive(p.feedMmPerS, "feedMmPerS");
  positive(p.infeedMm, "infeedMm");
  if (p.gridSize < 2) throw InvalidInput("Preston removal: gridSize must be at least 2");
  if (!p.normals.empty() && p.normals.size() != path.poses.size())
    throw InvalidInput("Preston removal: " + std::to_string(p.normals.size()) + " normals for " +
                       std::to_string(path.poses.size()) + " poses");
}

/// Time each pose acts, s: half the distance to each neighbour in its pass over the feed.
std::vector<double> dwellTimes(const ToolPath& path, double feedMmPerS) {
  const int count = static_cast<int>(path.poses.size());
  std::vector<char> start(count + 1, 0);
  start[0] = start[count] = 1;
  for (int s : path.passStarts)
    if (s >= 0 && s <= count) start[s] = 1;
  std::vector<double> dt(count, 0.0);
  for (int i = 0; i + 1 < count; ++i) {
    if (start[i + 1]) continue;
    const double half =
        0.5 * (path.poses[i + 1].contact - path.poses[i].contact).norm() / feedMmPerS;
    dt[i] += half;
    dt[i + 1] += half;
  }
  return dt;
}

/// Tangential grid state of one pose: the tool and workpiece z-buffers on box g.
struct ContactGrid {
  GridBox g;
  std::vector<float> tool, work;
  double interferenceSum = 0.0;  // sum of max(0, h_W - h_T) over the cells, mm
};

/// Rasterizes the lowered tool and the workpiece faces @p faces on @p g.
void fillGrid(const SurfacePatchIndex& index, const ddf::TriangleMesh& toolMesh,
              const std::vector<Local>& tool, const TangentFrame& frame,
              const std::vector<int>& faces, std::vector<Local>& pts, ContactGrid& c) {
  c.tool.assign(c.g.cells(), detail::kInf);
  c.work.assign(c.g.cells(), -detail::kInf);
  double top = -std::numeric_limits<double>::infinity();
  for (int f : faces) {
    detail::faceLocalPoints(index.field(), f, frame, pts);
    detail::rasterizeFace(index.field(), pts, c.g, [&](int cell, double w) {
      if (w <= c.g.wTop) c.work[cell] = std::max(c.work[cell], float(w)), top = std::max(top, w);
    });
  }
  // Tool facets above the highest surface sample cannot interfere.
  detail::rasterizeMin(toolMesh, tool, c.g, c.tool, top);
  c.interferenceSum = 0.0;
  for (int i = 0; i < c.g.cells(); ++i)
    if (std::isfinite(c.tool[i]) && c.work[i] > c.tool[i])
      c.interferenceSum += c.work[i] - c.tool[i];
}

/// The gridSize^2 box over the interfering cells of @p coarse (one cell of border), or nothing.
std::optional<GridBox> contactBox(const ContactGrid& coarse, int gridSize) {
  const GridBox& g = coarse.g;
  int a0 = g.nu, a1 = -1, b0 = g.nv, b1 = -1;
  for (int b = 0; b < g.nv; ++b)
    for (int a = 0; a < g.nu; ++a) {
      const int i = a + b * g.nu;
      if (!(std::isfinite(coarse.tool[i]) && coarse.work[i] > coarse.tool[i])) continue;
      a0 = std::min(a0, a), a1 = std::max(a1, a), b0 = std::min(b0, b), b1 = std::max(b1, b);
    }
  if (a1 < 0) return std::nullopt;
  a0 = std::max(0, a0 - 1), b0 = std::max(0, b0 - 1);
  a1 = std::min(g.nu - 1, a1 + 1), b1 = std::min(g.nv - 1, b1 + 1);
  GridBox fine = g;
  fine.u0 = g.u0 + a0 * g.du, fine.v0 = g.v0 + b0 * g.dv;
  fine.du = (a1 - a0 + 1) * g.du / gridSize, fine.dv = (b1 - b0 + 1) * g.dv / gridSize;
  fine.nu = fine.nv = gridSize;
  return fine;
}

/// Bilinear interpolation of cell-centred @p depth (zero outside the grid): the hat functions
/// each integrate to one cell area, so the removed volume equals sum depth x cell area.
double bilinear(const GridBox& g, const std::vector<double>& depth, double u, double v) {
  const double x = (u - g.u0) / g.du - 0.5, y = (v - g.v0) / g.dv - 0.5;
  const int a = static_cast<int>(std::floor(x)), b = static_cast<int>(std::floor(y));
  const double fx = x - a, fy = y - b;
  double sum = 0.0;
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const int ca = a + dx, cb = b + dy;
      if (ca < 0 || cb < 0 || ca >= g.nu || cb >= g.nv) continue;
      sum += (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy) * depth[ca + cb * g.nu];
    }
  return sum;
}

/// Lowers the raster points of @p faces under the contact by the interpolated depth (mm along
/// the normal, divided by v . n). Returns the largest movement along a vector, mm.
double removeAtRasterPoints(ddf::DisplacementField& ddf, const std::vector<int>& faces,
                            const TangentFrame& frame, const ContactGrid& c,
                            const std::vector<double>& depth, double slackMm,
                            std::vector<Local>& pts) {
  const GridBox& g = c.g;
  double moved = 0.0;
  for (int f : faces) {
    detail::faceLocalPoints(ddf, f, frame, pts);
    auto heights = ddf.heights(f);
    const ddf::Raster& r = ddf.raster();
    for (int k = 0, idx = 0; k < r.m; ++k)
      for (int i = 0; i + k < r.m; ++i, ++idx) {
        const Local& p = pts[idx];
        const int a = static_cast<int>(std::floor((p.u - g.u0) / g.du));
        const int b = static_cast<int>(std::floor((p.v - g.v0) / g.dv));
        if (a < -1 || b < -1 || a > g.nu || b > g.nv) continue;
        // Only the sheet the tool presses on, not a far side of the part under the box.
        const float toolW = c.tool[std::clamp(a, 0, g.nu - 1) + std::clamp(b, 0, g.nv - 1) * g.nu];
        if (!(p.w >= double(toolW) - slackMm)) continue;
        const double d = bilinear(g, depth, p.u, p.v);
        if (!(d > 0.0)) continue;
        const ddf::Vec3 vec = ddf.vectorAt(f, ddf.rasterBary(i, k));
        const double vn = vec.dot(frame.normal);
        if (!(vn > 1e-12)) continue;
        heights[idx] = std::max(-1.0f, static_cast<float>(heights[idx] - d / vn));
        moved = std::max(moved, d / vn * vec.norm());
      }
  }
  return moved;
}

/// Winkler pressure p = c i with sum p dA = F, and the Preston depth K_p p v_s dt per cell;
/// fills the report entries of pose @p pose.
void pressureDepths(const ContactGrid& fine, const PrestonParams& params, double dt, int pose,
                    std::vector<double>& depth, PrestonReport& report) {
  const double cellArea = fine.g.du * fine.g.dv;
  const double stiffness = params.forceN / (fine.interferenceSum * cellArea);
  const double rate = params.prestonCoefficientMm2PerN * params.surfaceSpeedMmPerS * dt;
  depth.assign(fine.g.cells(), 0.0);
  int contactCells = 0;
  for (int i = 0; i < fine.g.cells(); ++i) {
    const double interference = std::isfinite(fine.tool[i]) ? fine.work[i] - fine.tool[i] : 0.0;
    if (!(interference > 0.0)) continue;
    ++contactCells;
    depth[i] = rate * stiffness * interference;
    report.maxPressure[pose] = std::max(report.maxPressure[pose], stiffness * interference);
    report.maxDepthMm[pose] = std::max(report.maxDepthMm[pose], depth[i]);
    report.removedVolumeMm3 += depth[i] * cellArea;
  }
  report.contactAreaMm2[pose] = contactCells * cellArea;
}

}  // namespace

PrestonReport applyPrestonRemoval(ddf::DisplacementField& workpiece,
                                  const ddf::TriangleMesh& toolMesh, const ToolPath& path,
                                  const PrestonParams& params) {
  validate(toolMesh, path, params);
  const int count = static_cast<int>(path.poses.size());
  PrestonReport report;
  report.contactAreaMm2.assign(count, 0.0);
  report.maxPressure.assign(count, 0.0);
  report.maxDepthMm.assign(count, 0.0);
  if (count == 0) return report;
  SurfacePatchIndex index(workpiece);
  const std::vector<double> dt = dwellTimes(path, params.feedMmPerS);
  std::vector<Local> tool, pts;
  std::vector<int> faces, touched;
  std::vector<double> depth;
  double pad = 0.0;  // how far removal has moved raster points since the index was built
  for (int p = 0; p < count; ++p) {
    if (p % 16 == 0) reportProgress(params.progress, double(p) / count);
    const PathPose& pp = path.poses[p];
    const ddf::Vec3 n = params.normals.empty() ? index.normalAt(pp.contact) : params.normals[p];
    const TangentFrame frame = tangentFrame(pp.contact, n, pp.pose.linear().col(0));
    Eigen::Isometry3d lowered = pp.pose;
    lowered.pretranslate(-params.infeedMm * frame.normal);
    detail::transformMesh(toolMesh, lowered, frame, tool);
    ContactGrid coarse;
    coarse.g = detail::footprintBox(tool, params.gridSize, 0.0);
    double wMin = coarse.g.wTop;
    for (const Local& l : tool) wMin = std::min(wMin, l.w);
    const double slack = params.infeedMm + coarse.g.du + coarse.g.dv;
    Eigen::AlignedBox3d box = detail::partBox(coarse.g, frame, wMin - slack);
    box.min().array() -= pad, box.max().array() += pad;
    index.query(box, faces);
    fillGrid(index, toolMesh, tool, frame, faces, pts, coarse);
    const auto fineBox = contactBox(coarse, params.gridSize);
    if (!fineBox || dt[p] <= 0.0) {
      report.posesWithoutContact += fineBox ? 0 : 1;
      continue;
    }
    ContactGrid fine;
    fine.g = *fineBox;
    fillGrid(index, toolMesh, tool, frame, faces, pts, fine);
    if (!(fine.interferenceSum > 0.0)) fine = coarse;  // contact thinner than a fine cell
    pressureDepths(fine, params, dt[p], p, depth, report);
    pad += removeAtRasterPoints(workpiece, faces, frame, fine, depth, slack, pts);
    index.refresh(faces);
    touched.insert(touched.end(), faces.begin(), faces.end());
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  workpiece.synchronizeShared(ddf::SharedPolicy::Minimum, touched);
  reportProgress(params.progress, 1.0);
  return report;
}

}  // namespace ddfcam::planning
