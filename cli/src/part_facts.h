// SPDX-License-Identifier: MIT
// ddfcam-cli info: the facts of a part beyond its sizes: raster spacing, crust reach, source
// unit and CAD faces, as text and JSON.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/ddf/stock_crust.h>
#include <ddfcam/length_unit.h>

#include "json_output.h"

#include <optional>
#include <string>
#include <vector>

namespace ddfcam::cli {

/// @brief What info reports of a part besides FieldSummary.
struct PartFacts {
  double longestEdgeMm = 0.0;    ///< longest support edge, mm
  double rasterSpacingMm = 0.0;  ///< longestEdgeMm / (m - 1), mm
  ddf::CrustReach reach;         ///< ddf::crustReach of the part
  /// Unit the part's source file was read in; std::nullopt when not recorded (old .ddf file).
  std::optional<ddfcam::LengthUnit> sourceUnit;
  bool unitFromFile = false;              ///< the unit is the one a CAD file states
  std::vector<int> cadFaceOfSupportFace;  ///< per support face its CAD face (CAD input)
  std::vector<std::string> cadFaceNames;  ///< display names of the CAD faces
};

/// @brief Longest support edge, raster spacing and crust reach of @p field (the rest is left
/// for the caller to fill).
PartFacts partFacts(const ddf::DisplacementField& field);

/// @brief Lines "  label: value" of @p facts (spacing, reach, unit, CAD faces and names).
std::string partFactsText(const PartFacts& facts);

/// @brief Sets the members of @p facts in the JSON object @p json: rasterSpacingMm,
/// longestSupportEdgeMm, crustReach {minAboveMm, medianAboveMm, minBelowMm, medianBelowMm},
/// sourceUnit (null when not recorded), cadFaces and cadFaceNames.
void writePartFacts(JsonReport& json, const PartFacts& facts);

}  // namespace ddfcam::cli
