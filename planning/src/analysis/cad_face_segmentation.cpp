// SPDX-License-Identifier: MIT
// ddfcam: segmentation of a part converted from a CAD model into its CAD faces.
#include <ddfcam/planning/analysis/cad_face_segmentation.h>

#include <ddfcam/error.h>

namespace ddfcam::planning {

SegmentationParams cadFaceSegmentationParams() {
  SegmentationParams params;
  params.minFaces = 1;
  return params;
}

std::vector<Region> segmentByCadFace(const ddf::DisplacementField& ddf,
                                     const std::vector<int>& cadFaceOfSupportFace,
                                     const std::vector<std::string>& cadFaceNames,
                                     const SegmentationParams& params) {
  if (static_cast<int>(cadFaceOfSupportFace.size()) != ddf.faceCount())
    throw InvalidInput("segmentation by CAD face: " + std::to_string(cadFaceOfSupportFace.size()) +
                       " CAD face indices for " + std::to_string(ddf.faceCount()) +
                       " support faces");
  const int named = static_cast<int>(cadFaceNames.size());
  std::vector<std::string> names = cadFaceNames;
  names.push_back("no CAD face");
  std::vector<int> labels;
  labels.reserve(cadFaceOfSupportFace.size());
  for (std::size_t f = 0; f < cadFaceOfSupportFace.size(); ++f) {
    const int face = cadFaceOfSupportFace[f];
    if (face < -1 || face >= named)
      throw InvalidInput("segmentation by CAD face: support face " + std::to_string(f) +
                         " has CAD face " + std::to_string(face) + ", outside [0, " +
                         std::to_string(named) + ")");
    labels.push_back(face < 0 ? named : face);
  }
  return segmentFaces(ddf, labels, names, params);
}

}  // namespace ddfcam::planning
