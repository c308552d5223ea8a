// SPDX-License-Identifier: MIT
// ddfcam: parts and parameters shared by the flow field tests.
#pragma once

#include <ddfcam/ddf/analytic_generators.h>
#include <ddfcam/planning/flow/flow_field.h>

#include <numbers>
#include <vector>

namespace ddfcam::planning::flow_field_test {

inline constexpr double kDeg = 180.0 / std::numbers::pi;

inline ddf::GeneratedSurface torus(int m) {
  return ddf::torusPart(
      {.majorRadiusMm = 3.0, .minorRadiusMm = 1.0, .segmentsU = 24, .segmentsV = 12, .m = m});
}

inline FlowFieldParams rawParams(FlowFieldSource source = FlowFieldSource::MaxCurvatureDirection) {
  FlowFieldParams p;
  p.source = source;
  p.smoothing = false;
  return p;
}

inline double indexSum(const std::vector<FieldSingularity>& s) {
  double sum = 0.0;
  for (const FieldSingularity& x : s) sum += x.index;
  return sum;
}

}  // namespace ddfcam::planning::flow_field_test
