// SPDX-License-Identifier: MIT
// ddfcam gui: the Streamlines panel's fields and line glue.
#include "streamlines_fields.h"

#include <ddfcam/ddf/surface_sampling.h>
#include <ddfcam/planning/line_field.h>
#include <ddfcam/planning/streamline_path.h>

#include <algorithm>
#include <limits>

namespace ddfcam::gui {

namespace {

void maskField(const ddf::DisplacementField& part, const std::vector<std::uint8_t>& faceMask,
               planning::LineField& field) {
  if (faceMask.empty()) return;
  const std::size_t perFace = part.raster().pointCount();
  for (int f = 0; f < part.faceCount(); ++f)
    if (!faceMask[f])
      for (std::size_t p = 0; p < perFace; ++p) field[f * perFace + p] = ddf::Vec3::Zero();
}

}  // namespace

std::shared_ptr<StreamlinesPanel::Fields> computeStreamlineFields(
    const ddf::DisplacementField& part, const FieldChoice& choice,
    std::shared_ptr<const planning::CurvatureField> curvature,
    const planning::CurvatureParams& curvatureParams, const ProgressCallback& progress) {
  auto fields = std::make_shared<StreamlinesPanel::Fields>();
  fields->choice = choice;
  if (!curvature) {
    planning::CurvatureParams params = curvatureParams;
    params.progress = [&](double f) { return !progress || progress(0.2 * f); };
    curvature =
        std::make_shared<const planning::CurvatureField>(planning::computeCurvature(part, params));
  }
  fields->curvature = curvature;
  planning::FlowFieldParams params;
  params.source = choice.source;
  params.fixedDirection = choice.fixedDirection;
  params.smoothing = choice.smoothing;
  params.smoothnessWeight = choice.smoothnessWeight;
  params.faceMask = choice.faceMask;
  params.strokes = choice.strokes;
  params.progress = [&](double f) { return !progress || progress(0.2 + 0.7 * f); };
  fields->field = planning::flowField(part, *curvature, params);
  // flowField also sets the region's boundary points at their copies on outside faces; those
  // faces must stay undefined so that lines stop at the region edge and no glyph is drawn.
  maskField(part, choice.faceMask, fields->field);
  reportProgress(progress, 0.9);
  fields->transverse = planning::transverseField(part, fields->field);
  fields->singularities = planning::findSingularities(part, fields->field);
  reportProgress(progress, 1.0);
  return fields;
}

std::vector<std::uint8_t> regionFaceMask(const ddf::DisplacementField& part,
                                         const planning::Region& region) {
  std::vector<std::uint8_t> mask(part.faceCount(), 0);
  for (const int f : region.faces)
    if (f >= 0 && f < part.faceCount()) mask[f] = 1;
  return mask;
}

std::vector<planning::Streamline> smoothStreamlines(const ddf::DisplacementField& part,
                                                    const std::vector<planning::Streamline>& lines,
                                                    int halfWindow) {
  return planning::smoothOnSurface(part, lines, halfWindow);
}

}  // namespace ddfcam::gui
