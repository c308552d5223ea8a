// SPDX-License-Identifier: MIT
// ddfcam: LiveToleranceMap.
#include <ddfcam/error.h>
#include <ddfcam/planning/simulation/live_tolerance_map.h>

#include <cmath>
#include <string>

namespace ddfcam::planning {

LiveToleranceMap::LiveToleranceMap(const ddf::DisplacementField& design,
                                   const ToleranceBand& band)
    : designHeights_(design.allHeights()),
      pointsPerFace_(design.pointsPerFace()),
      band_(band) {
  validateToleranceBand(band);
  const std::vector<ddf::Vec3> normals = rasterPointNormals(design);
  factors_.resize(designHeights_.size());
  const int n = design.raster().steps();
  for (int f = 0; f < design.faceCount(); ++f) {
    std::size_t l = static_cast<std::size_t>(f) * pointsPerFace_;
    for (int k = 0; k <= n; ++k)
      for (int i = 0; i + k <= n; ++i, ++l)
        factors_[l] = design.vectorAt(f, design.rasterBary(i, k)).dot(normals[l]);
  }
  classes_.assign(designHeights_.size(), kNoValue);
}

void LiveToleranceMap::checkPart(const ddf::DisplacementField& part) const {
  if (part.allHeights().size() != designHeights_.size())
    throw InvalidInput("LiveToleranceMap: the part has " +
                       std::to_string(part.allHeights().size()) + " heights, the design " +
                       std::to_string(designHeights_.size()));
}

void LiveToleranceMap::classifyFace(const ddf::DisplacementField& part, int face) {
  const std::vector<float>& heights = part.allHeights();
  const std::size_t begin = static_cast<std::size_t>(face) * pointsPerFace_;
  for (std::size_t l = begin; l < begin + pointsPerFace_; ++l) {
    const auto deviation = static_cast<float>(
        (static_cast<double>(heights[l]) - static_cast<double>(designHeights_[l])) * factors_[l]);
    classes_[l] = std::isnan(deviation) ? kNoValue
                                        : static_cast<std::uint8_t>(classify(deviation, band_));
  }
}

void LiveToleranceMap::updateAll(const ddf::DisplacementField& part) {
  checkPart(part);
  for (int f = 0; f < part.faceCount(); ++f) classifyFace(part, f);
}

void LiveToleranceMap::update(const ddf::DisplacementField& part, std::span<const int> faces) {
  checkPart(part);
  for (int f : faces) {
    if (f < 0 || f >= part.faceCount())
      throw InvalidInput("LiveToleranceMap::update: face " + std::to_string(f) +
                         " is not a support face");
    classifyFace(part, f);
  }
}

}  // namespace ddfcam::planning
