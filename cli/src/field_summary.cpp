// SPDX-License-Identifier: MIT
// ddfcam-cli: key numbers of a DDF for info and demo output.
#include "field_summary.h"

#include "console.h"

#include <cmath>
#include <cstdio>
#include <limits>

namespace ddfcam::cli {
namespace {

void extend(std::array<ddf::Vec3, 2>& box, const ddf::Vec3& p, bool first) {
  box[0] = first ? p : ddf::Vec3(box[0].cwiseMin(p));
  box[1] = first ? p : ddf::Vec3(box[1].cwiseMax(p));
}

std::string vecText(const ddf::Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "(%.4f, %.4f, %.4f)", v.x(), v.y(), v.z());
  return text;
}

JsonReport jsonVec(const ddf::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

JsonReport jsonBox(const std::array<ddf::Vec3, 2>& box) {
  return {{"min", jsonVec(box[0])}, {"max", jsonVec(box[1])}};
}

}  // namespace

FieldSummary summarize(const ddf::DisplacementField& field) {
  FieldSummary s;
  s.vertices = field.vertexCount();
  s.faces = field.faceCount();
  s.resolution = field.resolution();
  s.pointsPerFace = field.pointsPerFace();
  s.storedHeights = field.allHeights().size();
  s.rasterPoints = field.topology().pointCount();
  s.memoryBytes = field.memoryBytes();
  s.heightMin = std::numeric_limits<double>::infinity();
  s.heightMax = -s.heightMin;
  for (const float h : field.allHeights()) {
    if (!std::isfinite(h)) {
      ++s.nonFiniteHeights;
      continue;
    }
    s.heightMin = std::min<double>(s.heightMin, h);
    s.heightMax = std::max<double>(s.heightMax, h);
    if (h <= -1.0f) ++s.heightsAtCrustBottom;
  }
  if (s.nonFiniteHeights == s.storedHeights) s.heightMin = s.heightMax = 0.0;
  for (int v = 0; v < s.vertices; ++v) extend(s.supportBounds, field.position(v), v == 0);
  const int n = field.raster().steps();
  bool first = true;
  for (int f = 0; f < s.faces; ++f)
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i) {
        const ddf::Vec3 q = field.surfacePoint(f, i, k);
        if (!q.allFinite()) continue;
        extend(s.surfaceBounds, q, first);
        first = false;
      }
  return s;
}

std::string summaryText(const FieldSummary& s) {
  char text[1024];
  std::snprintf(text, sizeof text,
                "  support: %d vertices, %d faces\n"
                "  raster: m = %d, %zu points per face, %zu stored heights, %zu distinct points\n"
                "  memory: %s\n"
                "  heights: [%.6g, %.6g] vector lengths, %zu at the crust bottom, %zu non-finite\n"
                "  support bounds: %s - %s mm\n"
                "  surface bounds: %s - %s mm\n",
                s.vertices, s.faces, s.resolution, s.pointsPerFace, s.storedHeights, s.rasterPoints,
                formatBytes(static_cast<double>(s.memoryBytes)).c_str(), s.heightMin, s.heightMax,
                s.heightsAtCrustBottom, s.nonFiniteHeights, vecText(s.supportBounds[0]).c_str(),
                vecText(s.supportBounds[1]).c_str(), vecText(s.surfaceBounds[0]).c_str(),
                vecText(s.surfaceBounds[1]).c_str());
  return text;
}

void writeSummary(JsonReport& json, const FieldSummary& s) {
  json["vertices"] = s.vertices;
  json["faces"] = s.faces;
  json["resolution"] = s.resolution;
  json["pointsPerFace"] = s.pointsPerFace;
  json["storedHeights"] = s.storedHeights;
  json["rasterPoints"] = s.rasterPoints;
  json["memoryBytes"] = s.memoryBytes;
  json["heightMin"] = s.heightMin;
  json["heightMax"] = s.heightMax;
  json["heightsAtCrustBottom"] = s.heightsAtCrustBottom;
  json["nonFiniteHeights"] = s.nonFiniteHeights;
  json["supportBounds"] = jsonBox(s.supportBounds);
  json["surfaceBounds"] = jsonBox(s.surfaceBounds);
}

}  // namespace ddfcam::cli
