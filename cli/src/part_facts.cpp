// SPDX-License-Identifier: MIT
// ddfcam-cli info: raster spacing, crust reach, source unit and CAD faces of a part.
#include "part_facts.h"

#include <algorithm>
#include <cstdio>

namespace ddfcam::cli {

PartFacts partFacts(const ddf::DisplacementField& field) {
  PartFacts facts;
  for (int f = 0; f < field.faceCount(); ++f) {
    const auto v = field.faceVertices(f);
    for (int c = 0; c < 3; ++c)
      facts.longestEdgeMm = std::max(
          facts.longestEdgeMm, (field.position(v[c]) - field.position(v[(c + 1) % 3])).norm());
  }
  facts.rasterSpacingMm = facts.longestEdgeMm / (field.resolution() - 1);
  facts.reach = ddf::crustReach(field);
  return facts;
}

namespace {

std::string unitText(const PartFacts& facts) {
  if (!facts.sourceUnit) return "not recorded (mm assumed)";
  return std::string(unitSymbol(*facts.sourceUnit)) +
         (facts.unitFromFile ? " (stated by the file)" : "");
}

/// Support faces per CAD face, for the names list.
std::vector<int> facesPerCadFace(const PartFacts& facts) {
  std::vector<int> count(facts.cadFaceNames.size(), 0);
  for (const int cad : facts.cadFaceOfSupportFace)
    if (cad >= 0 && cad < static_cast<int>(count.size())) ++count[cad];
  return count;
}

}  // namespace

std::string partFactsText(const PartFacts& facts) {
  const ddf::CrustReach& r = facts.reach;
  char text[512];
  std::snprintf(text, sizeof text,
                "  raster spacing: %.4g mm (longest support edge %.4g mm / (m - 1))\n"
                "  crust reach above the surface: min %.4g mm, median %.4g mm\n"
                "  crust reach below the surface: min %.4g mm, median %.4g mm\n"
                "  source unit: %s\n",
                facts.rasterSpacingMm, facts.longestEdgeMm, r.minAboveMm, r.medianAboveMm,
                r.minBelowMm, r.medianBelowMm, unitText(facts).c_str());
  std::string out = text;
  if (facts.cadFaceNames.empty()) return out;
  out += "  CAD faces: " + std::to_string(facts.cadFaceNames.size()) + "\n";
  const std::vector<int> count = facesPerCadFace(facts);
  for (std::size_t c = 0; c < facts.cadFaceNames.size(); ++c)
    out += "    " + facts.cadFaceNames[c] + ": " + std::to_string(count[c]) + " support faces\n";
  return out;
}

void writePartFacts(JsonReport& json, const PartFacts& facts) {
  const ddf::CrustReach& r = facts.reach;
  json["rasterSpacingMm"] = facts.rasterSpacingMm;
  json["longestSupportEdgeMm"] = facts.longestEdgeMm;
  json["crustReach"] = {{"minAboveMm", r.minAboveMm},
                        {"medianAboveMm", r.medianAboveMm},
                        {"minBelowMm", r.minBelowMm},
                        {"medianBelowMm", r.medianBelowMm}};
  json["sourceUnit"] = facts.sourceUnit ? JsonReport(std::string(unitSymbol(*facts.sourceUnit)))
                                        : JsonReport(nullptr);
  json["cadFaces"] = facts.cadFaceNames.size();
  json["cadFaceNames"] = facts.cadFaceNames;
}

}  // namespace ddfcam::cli
