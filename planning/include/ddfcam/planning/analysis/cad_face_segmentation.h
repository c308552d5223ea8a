// SPDX-License-Identifier: MIT
// ddfcam: segmentation of a part converted from a CAD model into its CAD faces.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/analysis/segmentation.h>
#include <ddfcam/planning/model/project.h>

#include <string>
#include <vector>

namespace ddfcam::planning {

/// @brief The defaults of segmentByCadFace(): SegmentationParams with minFaces = 1, since a CAD
/// face is a natural region even when it covers a single support face (a narrow fillet).
SegmentationParams cadFaceSegmentationParams();

/// @brief Regions from the CAD faces the support faces came from: segmentFaces() with each
/// support face labelled by its CAD face, so every connected piece of a CAD face becomes one
/// region named "<CAD face name> <n>" (e.g. "face 12 (B-spline) 3"). Support faces without a
/// CAD face (index -1) form regions named "no CAD face". With minFaces or minAreaMm2 raised,
/// small faces merge into the neighbour they share the longest boundary with, as in
/// segmentFaces().
/// @param cadFaceOfSupportFace per support face, its CAD face index in
/// [0, cadFaceNames.size()) or -1 (Project::cadFaceOfSupportFace, LoadPartReport's).
/// @param cadFaceNames display names of the CAD faces (Project::cadFaceNames).
/// @throws InvalidInput if cadFaceOfSupportFace does not have one entry per support face or
/// holds an index out of range, or as segmentFaces(). @throws Cancelled through params.progress.
std::vector<Region> segmentByCadFace(
    const ddf::DisplacementField& ddf, const std::vector<int>& cadFaceOfSupportFace,
    const std::vector<std::string>& cadFaceNames,
    const SegmentationParams& params = cadFaceSegmentationParams());

}  // namespace ddfcam::planning
