// SPDX-License-Identifier: MIT
// ddfcam-cli: key numbers of a DDF (sizes, height range, bounds) for info and demo output.
#pragma once

#include <ddfcam/ddf/displacement_field.h>

#include "json_output.h"

#include <array>
#include <cstddef>
#include <string>

namespace ddfcam::cli {

/// @brief Sizes, height statistics and bounds of a DisplacementField.
struct FieldSummary {
  int vertices = 0;                      ///< support vertices
  int faces = 0;                         ///< support faces
  int resolution = 0;                    ///< raster resolution m
  std::size_t pointsPerFace = 0;         ///< m (m + 1) / 2
  std::size_t storedHeights = 0;         ///< faces x pointsPerFace (shared points stored per face)
  std::size_t rasterPoints = 0;          ///< distinct raster points (shared points once)
  std::size_t memoryBytes = 0;           ///< DisplacementField::memoryBytes()
  double heightMin = 0.0;                ///< smallest finite height, vector lengths
  double heightMax = 0.0;                ///< largest finite height, vector lengths
  std::size_t nonFiniteHeights = 0;      ///< NaN or infinite heights
  std::size_t heightsAtCrustBottom = 0;  ///< heights <= -1 (clamped cuts)
  std::array<ddf::Vec3, 2> supportBounds{ddf::Vec3::Zero(), ddf::Vec3::Zero()};  ///< mm
  std::array<ddf::Vec3, 2> surfaceBounds{ddf::Vec3::Zero(), ddf::Vec3::Zero()};  ///< of q, mm
};

/// @brief Computes the summary of @p field (visits every raster point once per copy).
FieldSummary summarize(const ddf::DisplacementField& field);

/// @brief Human-readable multi-line text of @p s, each line "  label: value".
std::string summaryText(const FieldSummary& s);

/// @brief Sets the members of @p s in the JSON object @p json, in the order declared above
/// (each bounds box as {"min": [x, y, z], "max": [x, y, z]}).
void writeSummary(JsonReport& json, const FieldSummary& s);

}  // namespace ddfcam::cli
