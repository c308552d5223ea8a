// SPDX-License-Identifier: MIT
// ddfcam: tangent frames, the surface patch index and tangential height grids.
#include <ddfcam/planning/placement/tangential_grid.h>

#include "tangential_raster.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/lines/streamline_path.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>

namespace ddfcam::planning {

TangentFrame tangentFrame(const ddf::Vec3& contact, const ddf::Vec3& normal,
                          const ddf::Vec3& hint) {
  const double len = normal.norm();
  if (!(len > 0.0) || !std::isfinite(len))
    throw InvalidInput("tangentFrame: the normal must be non-zero and finite");
  TangentFrame f;
  f.origin = contact;
  f.normal = normal / len;
  ddf::Vec3 u = hint - hint.dot(f.normal) * f.normal;
  if (!(u.norm() > 1e-6 * std::max(1.0, hint.norm()))) {
    // Any tangent: the unit axis least aligned with the normal.
    Eigen::Index axis = 0;
    f.normal.cwiseAbs().minCoeff(&axis);
    const ddf::Vec3 e = ddf::Vec3::Unit(axis);
    u = e - e.dot(f.normal) * f.normal;
  }
  f.axisU = u.normalized();
  f.axisV = f.normal.cross(f.axisU);
  return f;
}

SurfacePatchIndex::SurfacePatchIndex(const ddf::DisplacementField& goal) : ddf_(&goal) {
  const int faces = goal.faceCount();
  if (faces == 0) throw InvalidInput("SurfacePatchIndex: the field has no faces");
  hull_.resize(faces);
  tbb::parallel_for(0, faces, [&](int f) { computeHull(f); });
  std::vector<Eigen::AlignedBox3d> boxes(faces);
  bounds_.setEmpty();
  ddf::Vec3 extent = ddf::Vec3::Zero();
  for (int f = 0; f < faces; ++f) {
    for (const ddf::Vec3& p : hull_[f]) boxes[f].extend(p);
    bounds_.extend(boxes[f]);
    extent += boxes[f].sizes();
  }
  // Cells about a face across keep the per-cell lists short and a face in few cells.
  const double mean = std::max(extent.maxCoeff() / faces, 1e-9);
  const ddf::Vec3 size = bounds_.sizes().cwiseMax(mean);
  double cell = mean;
  while ((size / cell).array().ceil().prod() > 8.0 * faces + 64) cell *= 1.25;
  cell_ = ddf::Vec3::Constant(cell);
  for (int a = 0; a < 3; ++a) dims_[a] = std::max(1, static_cast<int>(std::ceil(size[a] / cell)));
  const auto cellRange = [&](const Eigen::AlignedBox3d& b, Eigen::Vector3i& lo,
                             Eigen::Vector3i& hi) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::clamp(static_cast<int>(std::floor((b.min()[a] - bounds_.min()[a]) / cell)), 0,
                         dims_[a] - 1);
      hi[a] = std::clamp(static_cast<int>(std::floor((b.max()[a] - bounds_.min()[a]) / cell)), 0,
                         dims_[a] - 1);
    }
  };
  const std::size_t cellCount = static_cast<std::size_t>(dims_.x()) * dims_.y() * dims_.z();
  cellStart_.assign(cellCount + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<int> fill;
    if (pass == 1) {
      for (std::size_t c = 0; c < cellCount; ++c) cellStart_[c + 1] += cellStart_[c];
      cellFaces_.resize(cellStart_[cellCount]);
      fill.assign(cellStart_.begin(), cellStart_.end() - 1);
    }
    for (int f = 0; f < faces; ++f) {
      Eigen::Vector3i lo, hi;
      cellRange(boxes[f], lo, hi);
      for (int z = lo.z(); z <= hi.z(); ++z)
        for (int y = lo.y(); y <= hi.y(); ++y)
          for (int x = lo.x(); x <= hi.x(); ++x) {
            const std::size_t c = x + static_cast<std::size_t>(dims_.x()) *
                                          (y + static_cast<std::size_t>(dims_.y()) * z);
            if (pass == 0)
              ++cellStart_[c + 1];
            else
              cellFaces_[fill[c]++] = f;
          }
    }
  }
}

void SurfacePatchIndex::computeHull(int f) {
  const auto heights = ddf_->heights(f);
  const auto [lo, hi] = std::minmax_element(heights.begin(), heights.end());
  const auto& fv = ddf_->faceVertices(f);
  for (int c = 0; c < 3; ++c) {
    hull_[f][c] = ddf_->position(fv[c]) + double(*lo) * ddf_->vector(fv[c]);
    hull_[f][c + 3] = ddf_->position(fv[c]) + double(*hi) * ddf_->vector(fv[c]);
  }
}

void SurfacePatchIndex::refresh(const std::vector<int>& faces) {
  for (int f : faces) computeHull(f);
}

void SurfacePatchIndex::query(const Eigen::AlignedBox3d& box, std::vector<int>& out) const {
  out.clear();
  if (box.isEmpty()) return;
  Eigen::Vector3i lo, hi;
  for (int a = 0; a < 3; ++a) {
    const double l = (box.min()[a] - bounds_.min()[a]) / cell_[a];
    const double h = (box.max()[a] - bounds_.min()[a]) / cell_[a];
    if (h < 0.0 || l >= dims_[a]) return;
    lo[a] = std::max(0, static_cast<int>(std::floor(l)));
    hi[a] = std::min(dims_[a] - 1, static_cast<int>(std::floor(h)));
  }
  for (int z = lo.z(); z <= hi.z(); ++z)
    for (int y = lo.y(); y <= hi.y(); ++y)
      for (int x = lo.x(); x <= hi.x(); ++x) {
        const std::size_t c =
            x + static_cast<std::size_t>(dims_.x()) * (y + static_cast<std::size_t>(dims_.y()) * z);
        out.insert(out.end(), cellFaces_.begin() + cellStart_[c],
                   cellFaces_.begin() + cellStart_[c + 1]);
      }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

ddf::Vec3 SurfacePatchIndex::normalAt(const ddf::Vec3& contact) const {
  std::vector<int> faces;
  double reach = cell_.maxCoeff() * 0.5;
  for (int grow = 0; grow < 4 && faces.empty(); ++grow, reach *= 2.0)
    query(Eigen::AlignedBox3d(contact.array() - reach, contact.array() + reach), faces);
  std::optional<ddf::SurfaceLocation> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int f : faces) {
    const auto loc = ddf::locateOnFace(*ddf_, f, contact);
    if (!loc) continue;
    const double d = (loc->point - contact).norm();
    if (d < bestDistance) {
      bestDistance = d;
      best = loc;
    }
  }
  if (!best)
    throw InvalidInput("no goal surface near the contact point (" + std::to_string(contact.x()) +
                       ", " + std::to_string(contact.y()) + ", " + std::to_string(contact.z()) +
                       ")");
  return surfaceNormal(*ddf_, *best);
}

namespace detail {

GridBox footprintBox(const std::vector<Local>& pts, int gridSize, double marginMm) {
  double u0 = std::numeric_limits<double>::infinity(), u1 = -u0, v0 = u0, v1 = -u0, w1 = -u0;
  for (const Local& p : pts) {
    u0 = std::min(u0, p.u), u1 = std::max(u1, p.u);
    v0 = std::min(v0, p.v), v1 = std::max(v1, p.v);
    w1 = std::max(w1, p.w);
  }
  GridBox g;
  g.u0 = u0 - marginMm;
  g.v0 = v0 - marginMm;
  g.nu = g.nv = gridSize;
  g.du = std::max(u1 - u0 + 2.0 * marginMm, 1e-9) / gridSize;
  g.dv = std::max(v1 - v0 + 2.0 * marginMm, 1e-9) / gridSize;
  g.wTop = w1 + marginMm;
  return g;
}

void transformMesh(const ddf::TriangleMesh& mesh, const Eigen::Isometry3d& pose,
                   const TangentFrame& frame, std::vector<Local>& out) {
  Eigen::Matrix3d r;
  r.row(0) = frame.axisU.transpose();
  r.row(1) = frame.axisV.transpose();
  r.row(2) = frame.normal.transpose();
  const Eigen::Matrix3d m = r * pose.linear();
  const ddf::Vec3 t = r * (pose.translation() - frame.origin);
  out.resize(mesh.vertices.size());
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const ddf::Vec3 p = m * mesh.vertices[i] + t;
    out[i] = {p.x(), p.y(), p.z()};
  }
}

void rasterizeMin(const ddf::TriangleMesh& mesh, const std::vector<Local>& local, const GridBox& g,
                  std::vector<float>& h, double cutoff) {
  for (const auto& t : mesh.triangles) {
    if (std::min({local[t[0]].w, local[t[1]].w, local[t[2]].w}) > cutoff) continue;
    rasterizeTriangle(g, local[t[0]], local[t[1]], local[t[2]], [&](int cell, double w) {
      h[cell] = std::min(h[cell], static_cast<float>(w));
    });
  }
}

void faceLocalPoints(const ddf::DisplacementField& ddf, int f, const TangentFrame& frame,
                     std::vector<Local>& out) {
  const auto& fv = ddf.faceVertices(f);
  ddf::Vec3 p[3], v[3];
  for (int c = 0; c < 3; ++c) {
    const ddf::Vec3 l = frame.toLocal(ddf.position(fv[c]));
    const ddf::Vec3& vec = ddf.vector(fv[c]);
    p[c] = l;
    v[c] = {frame.axisU.dot(vec), frame.axisV.dot(vec), frame.normal.dot(vec)};
  }
  const ddf::Raster& r = ddf.raster();
  const int n = r.steps();
  const double inv = 1.0 / n;
  const auto heights = ddf.heights(f);
  out.resize(r.pointCount());
  std::size_t idx = 0;
  for (int k = 0; k <= n; ++k)
    for (int i = 0; i + k <= n; ++i, ++idx) {
      const double a = i * inv, c = k * inv, b = (n - i - k) * inv, h = heights[idx];
      const ddf::Vec3 q = a * (p[0] + h * v[0]) + b * (p[1] + h * v[1]) + c * (p[2] + h * v[2]);
      out[idx] = {q.x(), q.y(), q.z()};
    }
}

LocalBounds localHullBounds(const SurfacePatchIndex& index, int f, const TangentFrame& frame) {
  LocalBounds b{1e300, -1e300, 1e300, -1e300, 1e300, -1e300};
  for (const ddf::Vec3& p : index.hull(f)) {
    const ddf::Vec3 l = frame.toLocal(p);
    b.u0 = std::min(b.u0, l.x()), b.u1 = std::max(b.u1, l.x());
    b.v0 = std::min(b.v0, l.y()), b.v1 = std::max(b.v1, l.y());
    b.w0 = std::min(b.w0, l.z()), b.w1 = std::max(b.w1, l.z());
  }
  return b;
}

Eigen::AlignedBox3d partBox(const GridBox& g, const TangentFrame& frame, double wLow) {
  Eigen::AlignedBox3d box;
  for (int c = 0; c < 8; ++c) {
    const ddf::Vec3 l((c & 1) ? g.u0 + g.nu * g.du : g.u0, (c & 2) ? g.v0 + g.nv * g.dv : g.v0,
                      (c & 4) ? g.wTop : wLow);
    box.extend(frame.toPart(l));
  }
  return box;
}

}  // namespace detail

}  // namespace ddfcam::planning
