// SPDX-License-Identifier: MIT
// ddfcam-cli: key numbers of a DDF for info and demo output.
#include "field_summary.h"

#include "console.h"

#include <charconv>
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

std::string jsonVec(const ddf::Vec3& v) {
  std::string out = "[";  // built piecewise: "lit" + string trips GCC 12's -Wrestrict
  out += jsonNumber(v.x());
  out += ", ";
  out += jsonNumber(v.y());
  out += ", ";
  out += jsonNumber(v.z());
  return out + "]";
}

std::string jsonBox(const std::array<ddf::Vec3, 2>& box) {
  return "{\"min\": " + jsonVec(box[0]) + ", \"max\": " + jsonVec(box[1]) + "}";
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

std::string summaryJsonMembers(const FieldSummary& s) {
  std::string out;
  const auto member = [&](const char* key, const std::string& value) {
    if (!out.empty()) out += ",\n";
    out += "  \"" + std::string(key) + "\": " + value;
  };
  member("vertices", std::to_string(s.vertices));
  member("faces", std::to_string(s.faces));
  member("resolution", std::to_string(s.resolution));
  member("pointsPerFace", std::to_string(s.pointsPerFace));
  member("storedHeights", std::to_string(s.storedHeights));
  member("rasterPoints", std::to_string(s.rasterPoints));
  member("memoryBytes", std::to_string(s.memoryBytes));
  member("heightMin", jsonNumber(s.heightMin));
  member("heightMax", jsonNumber(s.heightMax));
  member("heightsAtCrustBottom", std::to_string(s.heightsAtCrustBottom));
  member("nonFiniteHeights", std::to_string(s.nonFiniteHeights));
  member("supportBounds", jsonBox(s.supportBounds));
  member("surfaceBounds", jsonBox(s.surfaceBounds));
  return out;
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}

}  // namespace ddfcam::cli
