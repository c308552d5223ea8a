// SPDX-License-Identifier: MIT
// ddfcam gui (private): the line fields the Streamlines panel traces, and the glue between
// the panel's choices and the planning calls.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/gui/panels/streamlines_panel.h>
#include <ddfcam/planning/curvature.h>
#include <ddfcam/planning/flow_field.h>
#include <ddfcam/planning/project.h>
#include <ddfcam/planning/streamline.h>
#include <ddfcam/progress.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace ddfcam::gui {

/// What the field depends on besides the part's heights.
struct FieldChoice {
  planning::FlowFieldSource source = planning::FlowFieldSource::MaxCurvatureDirection;
  ddf::Vec3 fixedDirection = ddf::Vec3::UnitX();  ///< for FixedDirection, part frame
  std::vector<std::vector<ddf::Vec3>> strokes;    ///< for UserStrokes, mm, part frame
  bool smoothing = false;                         ///< Ceres smoothing of the raw field
  double smoothnessWeight = 0.02;                 ///< lambda of FlowFieldParams
  std::vector<std::uint8_t> faceMask;             ///< faces of the region; empty: whole part

  bool operator==(const FieldChoice&) const = default;
};

/// The line fields the paths follow, for one state of the part's heights.
struct StreamlinesPanel::Fields {
  FieldChoice choice;
  std::shared_ptr<const planning::CurvatureField> curvature;
  planning::LineField field;       ///< the tool flow field (zero outside the region)
  planning::LineField transverse;  ///< field turned by 90 degrees in the tangent plane
  std::vector<planning::FieldSingularity> singularities;  ///< of field
};

/// Curvature (reused if @p curvature is given, else computed with @p curvatureParams, e.g.
/// planning::partCurvatureParams of the project), flow field, its perpendicular and its
/// singularities. Progress runs over [0, 1].
std::shared_ptr<StreamlinesPanel::Fields> computeStreamlineFields(
    const ddf::DisplacementField& part, const FieldChoice& choice,
    std::shared_ptr<const planning::CurvatureField> curvature,
    const planning::CurvatureParams& curvatureParams, const ProgressCallback& progress);

/// One entry per support face, 1 on the faces of @p region.
std::vector<std::uint8_t> regionFaceMask(const ddf::DisplacementField& part,
                                         const planning::Region& region);

/// @p lines each low-pass filtered on the surface by planning::smoothOnSurface with
/// @p halfWindow.
std::vector<planning::Streamline> smoothStreamlines(const ddf::DisplacementField& part,
                                                    const std::vector<planning::Streamline>& lines,
                                                    int halfWindow);

}  // namespace ddfcam::gui
