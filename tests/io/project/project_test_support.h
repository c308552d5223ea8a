// SPDX-License-Identifier: MIT
// Helpers for the .ddfproj tests: hand-built projects and a field-by-field bitwise comparison.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/planning/model/project.h>

#include <gtest/gtest.h>

#include "../io_test_support.h"

#include <Eigen/Geometry>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <vector>

namespace ddfcam::test {

/// A NaN with a payload, to check that the exact bit pattern survives.
inline float payloadNaN() {
  return std::bit_cast<float>(std::uint32_t{0x7fc12345u});
}

inline planning::PathPose makePose(double angleRad, const Eigen::Vector3d& axis,
                                   const Eigen::Vector3d& translation) {
  planning::PathPose pose;
  pose.pose = Eigen::Translation3d(translation) * Eigen::AngleAxisd(angleRad, axis.normalized());
  pose.contact = translation - Eigen::Vector3d(0.1, 1.0 / 3.0, std::sqrt(2.0));
  return pose;
}

/// A 2-face part (planePatch 1 x 1 cells, m = 3) and one item of every kind: design mesh,
/// tool, path (2 poses), field, region (with a plan holding one 2-point stroke), state,
/// surface (a 2-face m = 2 plane patch).
inline planning::Project makeSmallProject() {
  planning::Project project;
  project.partName = "small";
  ddf::PlanePatchParams params;
  params.cellsX = 1;
  params.cellsY = 1;
  params.m = 3;
  params.size = {2.0, 1.0};
  project.part = ddf::planePatch(params).ddf;
  const std::size_t values = project.part->allHeights().size();
  project.fields.push_back({"height", "mm", true, std::vector<float>(values, 0.5f), {}});
  project.tools.push_back(planning::Tool{});
  planning::ToolPath path;
  path.name = "p";
  path.poses = {makePose(0.3, {0, 1, 0}, {0.5, 0.5, 1.0}), makePose(0.1, {1, 0, 0}, {1, 0.5, 1})};
  path.passStarts = {0};
  project.paths.push_back(path);
  project.regions.push_back({"r", {1}, {1.0f, 0.0f, 0.5f}, {}});
  planning::RegionPlan& plan = project.regions[0].plan;
  plan.tool = 0;
  plan.flowSource = planning::FlowFieldSource::UserStrokes;
  plan.strokes = {{{0.25, 0.5, 0.0}, {1.5, 0.75, 0.0}}};
  plan.spacingMm = 0.5;
  project.states.push_back({"stock", std::vector<float>(values, 0.25f)});
  params.m = 2;
  project.surfaces.push_back({"s", ddf::planePatch(params).ddf});
  project.designMesh = ddf::TriangleMesh{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5}}, {{0, 1, 2}}};
  return project;
}

/// One valid tool of every kind, with names that need quoting and escaping and sizes that need
/// every bit of a double.
inline std::vector<planning::Tool> toolsOfEveryKind() {
  using planning::ToolKind;
  const double third = 1.0 / 3.0;
  return {{.name = "roll \"fine\" \\ 1",
           .kind = ToolKind::CylinderRoll,
           .radiusMm = 25.0 + third,
           .widthMm = 20.0,
           .edgeRadiusMm = 1e-7,
           .shankRadiusMm = 8.0,
           .shankLengthMm = 15.0,
           .holderRadiusMm = 18.0,
           .holderLengthMm = 3.0,
           .chordToleranceMm = 0.002,
           .segments = 0},
          {.name = "Kugel \u23006\nzwei\tZeilen",
           .kind = ToolKind::Sphere,
           .radiusMm = third,
           .widthMm = -0.0,
           .segments = 32},
          {.name = "",
           .kind = ToolKind::BeltContactWheel,
           .radiusMm = 50.0,
           .widthMm = 25.0,
           .edgeRadiusMm = 2.0,
           .crownRadiusMm = 200.0 + third,
           .shankRadiusMm = 10.0,
           .shankLengthMm = 20.0,
           .holderRadiusMm = 30.0,
           .holderLengthMm = 4.0,
           .chordToleranceMm = 1e-3 / 3.0,
           .segments = 0},
          {.name = "ball # not a comment",
           .kind = ToolKind::BallEnd,
           .radiusMm = 3.0,
           .widthMm = 12.0,
           .shankRadiusMm = 3.0,
           .shankLengthMm = 30.0,
           .holderRadiusMm = 12.0,
           .holderLengthMm = 40.0,
           .segments = 64},
          {.name = "flat",
           .kind = ToolKind::FlatEnd,
           .radiusMm = 5.0,
           .widthMm = 22.0,
           .shankLengthMm = 1e-300,
           .chordToleranceMm = 0.01,
           .segments = 3},
          {.name = "torus",
           .kind = ToolKind::TorusCutter,
           .radiusMm = 6.0,
           .widthMm = 18.0,
           .edgeRadiusMm = 2.0 - 1e-15,
           .holderRadiusMm = 16.0,
           .holderLengthMm = 45.0,
           .segments = 4096}};
}

/// Every kind of item, with unicode names, NaN values, signed zeros and odd doubles; one region
/// with a plan that differs from the default in every member, one with the default plan.
inline planning::Project makeRichProject() {
  planning::Project project;
  project.partName = "Teil \u00fc \u8a66\u9a13 \u2300 5";
  project.sourcePath = "parts/M\u00fchle/part.stl";
  ddf::PlanePatchParams params;
  params.cellsX = 3;
  params.cellsY = 2;
  params.m = 4;
  ddf::DisplacementField part = ddf::planePatch(params).ddf;
  std::vector<float>& h = part.allHeights();
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = 0.25f + 0.3f * std::sin(0.7f * i);
  h[0] = -0.0f;
  h[1] = std::numeric_limits<float>::denorm_min();
  h[2] = 1.0f;
  const std::size_t values = h.size();
  project.part = std::move(part);  // h dangles from here on

  planning::ScalarField signedField{"height \u0394", "mm", true, {}, {}};
  planning::ScalarField removed{"material removed", "mm\u00b3", false, {}, {}};
  for (std::size_t i = 0; i < values; ++i) {
    signedField.values.push_back(i % 7 == 3 ? std::numeric_limits<float>::quiet_NaN()
                                            : -0.01f * static_cast<float>(i));
    removed.values.push_back(i % 5 == 1 ? payloadNaN() : 1e-30f * static_cast<float>(i));
  }
  project.fields = {signedField, removed};
  project.regions.push_back({"Flanke S\u00fcd", {1, 3, 4}, {0.1f, 0.2f, 1.0f / 3.0f}, {}});
  planning::RegionPlan& plan = project.regions[0].plan;
  plan.tool = 1;
  plan.flowSource = planning::FlowFieldSource::FixedDirection;
  plan.fixedDirection = {-0.0, 1.0 / 3.0, 1e-300};
  plan.strokes = {{{0.1, 0.2, -0.0}, {1.0 / 7.0, 2.0, 3.0}, {4.0, 5.0, 6.0}}, {}, {{1e300, -2, 0}}};
  plan.smoothField = false;
  plan.smoothnessWeight = 0.0;
  plan.spacingMode = planning::SpacingMode::ScallopTolerance;
  plan.spacingMm = std::numeric_limits<double>::denorm_min();
  plan.scallopToleranceMm = 0.004;
  plan.feedSign = -1;
  plan.linking = planning::LinkingOrder::OneDirection;
  planning::Region defaults{"Boden", {0, 2}, {0.5f, 0.5f, 0.5f}, {}};
  project.regions.push_back(defaults);

  // Sizes added in format 3 with values that need every bit (1/3) or differ from the defaults.
  project.tools.push_back({.name = "Walze R5 W10",
                           .kind = planning::ToolKind::CylinderRoll,
                           .radiusMm = 5.0,
                           .widthMm = 10.0,
                           .edgeRadiusMm = 0.5,
                           .crownRadiusMm = 40.0,
                           .shankRadiusMm = 2.0,
                           .shankLengthMm = 1.0 / 3.0,
                           .holderRadiusMm = 4.0,
                           .holderLengthMm = 1.5,
                           .chordToleranceMm = 0.001,
                           .segments = 50});
  project.tools.push_back({.name = "Kugel \u23006",
                           .kind = planning::ToolKind::Sphere,
                           .radiusMm = 3.0,
                           .widthMm = 1.25,
                           .segments = 32});

  planning::ToolPath path;
  path.name = "Bahn 1 \u2192 Rand";
  path.tool = 1;
  path.feedMmPerMin = 1234.5678;
  for (int i = 0; i < 6; ++i)
    path.poses.push_back(makePose(0.37 * i, {1.0, 0.2 * i, 0.5}, {1.1 * i, -0.3 * i, 2.0 / 3.0}));
  path.passStarts = {0, 2, 5};
  project.paths.push_back(path);
  planning::ToolPath empty;
  empty.name = "";
  project.paths.push_back(empty);

  planning::SimulationState stock{"stock", project.part->allHeights()};
  planning::SimulationState after{"after roll pass 1", stock.heights};
  for (float& value : after.heights) value = std::nextafter(value, -1.0f);
  project.states = {stock, after};

  ddf::SphereParams sphere;
  sphere.subdivisions = 0;
  sphere.m = 3;
  ddf::DisplacementField mould = ddf::spherePart(sphere).ddf;
  mould.allHeights()[5] = -0.75f;
  project.surfaces.push_back({"Formfl\u00e4che", std::move(mould)});

  ddf::TriangleMesh design;
  design.vertices = {{0, 0, 0.1}, {1.0 / 3.0, 0, 0.2}, {1, 1, -0.0}, {0, 1, 1e-300}};
  design.triangles = {{0, 1, 2}, {0, 2, 3}};
  project.designMesh = design;
  return project;
}

/// Replaces the trailing CRC so that a deliberately edited body passes the checksum.
inline std::string resealed(std::string bytes) {
  const std::size_t body = bytes.size() - 4;
  const std::uint32_t crc = io::crc32(std::as_bytes(std::span(bytes.data(), body)));
  for (int i = 0; i < 4; ++i) bytes[body + i] = static_cast<char>((crc >> (8 * i)) & 0xFF);
  return bytes;
}

inline void putLeAt(std::string& bytes, std::size_t offset, std::uint64_t value, int count) {
  for (int i = 0; i < count; ++i) bytes[offset + i] = static_cast<char>((value >> (8 * i)) & 0xFF);
}

/// Sets the header's file size to the actual size and reseals the CRC.
inline std::string resized(std::string bytes) {
  putLeAt(bytes, 16, bytes.size(), 8);
  return resealed(std::move(bytes));
}

}  // namespace ddfcam::test
