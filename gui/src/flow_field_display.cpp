// SPDX-License-Identifier: MIT
// ddfcam gui: FlowFieldDisplay.
#include <ddfcam/gui/flow_field_display.h>

#include <ddfcam/gui/part_scene.h>

#include <vtkPolyData.h>

namespace ddfcam::gui {

namespace {

planning::LineField principal(const std::vector<ddf::Vec3>& directions,
                              const std::vector<std::uint8_t>& umbilic) {
  planning::LineField out = directions;
  for (std::size_t p = 0; p < out.size() && p < umbilic.size(); ++p)
    if (umbilic[p]) out[p] = ddf::Vec3::Zero();  // directions are meaningless there
  return out;
}

}  // namespace

FlowFieldDisplay::FlowFieldDisplay(PartScene& scene) : scene_(scene) {}

std::string FlowFieldDisplay::overlayName(GlyphField which) {
  switch (which) {
    case GlyphField::Flow:
      return "flow field glyphs";
    case GlyphField::MaxDirection:
      return "k_max glyphs";
    case GlyphField::MinDirection:
      return "k_min glyphs";
  }
  return {};
}

std::array<double, 3> FlowFieldDisplay::colour(GlyphField which) {
  switch (which) {
    case GlyphField::Flow:
      return {0.1, 0.8, 0.3};
    case GlyphField::MaxDirection:
      return {0.9, 0.15, 0.15};
    case GlyphField::MinDirection:
      return {0.15, 0.4, 1.0};
  }
  return {1.0, 1.0, 1.0};
}

std::array<double, 3> FlowFieldDisplay::singularityColour(bool positive) {
  return positive ? std::array<double, 3>{1.0, 0.85, 0.0} : std::array<double, 3>{0.9, 0.1, 0.9};
}

void FlowFieldDisplay::show(const ddf::DisplacementField& part, const planning::LineField& flow,
                            const planning::CurvatureField& curvature,
                            std::vector<planning::FieldSingularity> singularities,
                            const LineGlyphParams& params) {
  glyphs_[0] = lineGlyphs(part, flow, params);
  glyphs_[1] = lineGlyphs(part, principal(curvature.dirMax, curvature.umbilic), params);
  glyphs_[2] = lineGlyphs(part, principal(curvature.dirMin, curvature.umbilic), params);
  singularities_ = std::move(singularities);
  for (int g = 0; g < kGlyphFieldCount; ++g) {
    OverlayStyle style;
    style.rgb = colour(static_cast<GlyphField>(g));
    style.lineWidth = 1.5;
    scene_.setOverlay(overlayName(static_cast<GlyphField>(g)), toLineGlyphPolyData(glyphs_[g]),
                      style);
  }
  std::vector<Eigen::Vector3d> positive, negative;
  for (const planning::FieldSingularity& s : singularities_)
    (s.index > 0 ? positive : negative).push_back(s.point);
  for (const bool sign : {true, false}) {
    OverlayStyle style;
    style.rgb = singularityColour(sign);
    style.pointSize = 11.0;
    style.onTop = true;  // a marker inside a concave pocket should still be seen
    scene_.setOverlay(sign ? kPositiveSingularities : kNegativeSingularities,
                      toPointPolyData(sign ? positive : negative), style);
  }
  shown_ = true;
  applyVisibility();
}

void FlowFieldDisplay::clear() {
  for (int g = 0; g < kGlyphFieldCount; ++g) {
    scene_.removeOverlay(overlayName(static_cast<GlyphField>(g)));
    glyphs_[g] = {};
  }
  scene_.removeOverlay(kPositiveSingularities);
  scene_.removeOverlay(kNegativeSingularities);
  singularities_.clear();
  shown_ = false;
}

void FlowFieldDisplay::setVisible(GlyphField which, bool visible) {
  visible_[static_cast<int>(which)] = visible;
  applyVisibility();
}

void FlowFieldDisplay::setSingularitiesVisible(bool visible) {
  singularitiesVisible_ = visible;
  applyVisibility();
}

void FlowFieldDisplay::applyVisibility() {
  if (!shown_) return;
  for (int g = 0; g < kGlyphFieldCount; ++g)
    scene_.setOverlayVisible(overlayName(static_cast<GlyphField>(g)), visible_[g]);
  scene_.setOverlayVisible(kPositiveSingularities, singularitiesVisible_);
  scene_.setOverlayVisible(kNegativeSingularities, singularitiesVisible_);
}

}  // namespace ddfcam::gui
