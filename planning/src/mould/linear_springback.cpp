// SPDX-License-Identifier: MIT
// ddfcam: a linear springback model S = P + (I - diag(alpha))(C - P) on DDF heights, for planning
// and tests of the compensation loop.
#include <ddfcam/ddf/crust_hash.h>
#include <ddfcam/ddf/depth_buffer.h>
#include <ddfcam/ddf/raster_mesh.h>
#include <ddfcam/error.h>
#include <ddfcam/planning/mould/springback_compensation.h>

#include <cmath>
#include <limits>
#include <string>

namespace ddfcam::planning {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

void checkAlpha(double alpha, const char* what) {
  if (!(alpha >= 0.0 && alpha < 1.0))
    throw InvalidInput(std::string(what) + " = " + std::to_string(alpha) + " is outside [0, 1)");
}

void checkModel(const LinearSpringbackModel& model, const ddf::DisplacementField& target,
                std::size_t mouldSize) {
  const std::size_t copies = target.allHeights().size();
  if (model.relaxedHeights.size() != copies || mouldSize != copies) {
    throw InvalidInput("linearSpringback: relaxed heights (" +
                       std::to_string(model.relaxedHeights.size()) + ") and mould heights (" +
                       std::to_string(mouldSize) + ") must both have the target's " +
                       std::to_string(copies) + " raster point copies");
  }
  if (model.axisAlpha) {
    checkAlpha(model.axisAlpha->x(), "linearSpringback: axisAlpha.x");
    checkAlpha(model.axisAlpha->y(), "linearSpringback: axisAlpha.y");
    checkAlpha(model.axisAlpha->z(), "linearSpringback: axisAlpha.z");
  } else {
    checkAlpha(model.alpha, "linearSpringback: alpha");
  }
}

std::vector<float> isotropicSpringback(double alpha, std::span<const float> relaxed,
                                       std::span<const float> mould) {
  std::vector<float> formed(mould.size());
  for (std::size_t l = 0; l < mould.size(); ++l) {
    const double p = relaxed[l];
    formed[l] = static_cast<float>(p + (1.0 - alpha) * (static_cast<double>(mould[l]) - p));
  }
  return formed;
}

// The formed points leave the stubbles, so they are connected along the raster lattice (both
// raster meshes share vertex order and triangles) and the surface is filled back onto the
// target's stubbles.
std::vector<float> anisotropicSpringback(const Eigen::Vector3d& alpha,
                                         const ddf::DisplacementField& target,
                                         std::span<const float> relaxed,
                                         std::span<const float> mould) {
  ddf::DisplacementField field = target;
  field.allHeights().assign(relaxed.begin(), relaxed.end());
  const ddf::TriangleMesh relaxedMesh = ddf::extractRasterMesh(field).mesh;
  field.allHeights().assign(mould.begin(), mould.end());
  ddf::TriangleMesh formedMesh = ddf::extractRasterMesh(field).mesh;
  const Eigen::Vector3d keep = Eigen::Vector3d::Ones() - alpha;
  for (std::size_t v = 0; v < formedMesh.vertices.size(); ++v) {
    const Eigen::Vector3d& p = relaxedMesh.vertices[v];
    formedMesh.vertices[v] = p + keep.cwiseProduct(formedMesh.vertices[v] - p);
  }
  // Triangles with a NaN corner (no relaxed or mould height) would poison the hash and fill.
  std::erase_if(formedMesh.triangles, [&](const std::array<int, 3>& t) {
    return !(formedMesh.vertices[t[0]].allFinite() && formedMesh.vertices[t[1]].allFinite() &&
             formedMesh.vertices[t[2]].allFinite());
  });
  std::fill(field.allHeights().begin(), field.allHeights().end(), kNaN);
  if (formedMesh.triangles.empty()) return field.allHeights();
  const ddf::CrustHash hash(field, ddf::crustHashParamsFor(field));
  const ddf::FillReport report = ddf::fillFromMesh(field, hash, formedMesh);
  std::vector<float> formed = field.allHeights();
  for (std::size_t l = 0; l < formed.size(); ++l)
    if (report.missingMask.size() == formed.size() && report.missingMask[l]) formed[l] = kNaN;
  return formed;
}

}  // namespace

std::vector<float> linearSpringback(const LinearSpringbackModel& model,
                                    const ddf::DisplacementField& target,
                                    std::span<const float> mouldHeights) {
  checkModel(model, target, mouldHeights.size());
  const std::span<const float> relaxed(model.relaxedHeights);
  if (!model.axisAlpha) return isotropicSpringback(model.alpha, relaxed, mouldHeights);
  return anisotropicSpringback(*model.axisAlpha, target, relaxed, mouldHeights);
}

LinearSpringbackModel calibrateSpringback(const ddf::DisplacementField& target,
                                          std::span<const float> firstFormedHeights, double alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw InvalidInput("calibrateSpringback: alpha = " + std::to_string(alpha) +
                       " is outside (0, 1)");
  }
  const std::vector<float>& t = target.allHeights();
  if (firstFormedHeights.size() != t.size()) {
    throw InvalidInput("calibrateSpringback: " + std::to_string(firstFormedHeights.size()) +
                       " formed heights given, the target DDF has " + std::to_string(t.size()) +
                       " raster point copies");
  }
  LinearSpringbackModel model;
  model.alpha = alpha;
  model.relaxedHeights.resize(t.size());
  // NaN where the first forming was not measured: the model then predicts no formed height there.
  for (std::size_t l = 0; l < t.size(); ++l) {
    const double tl = t[l];
    model.relaxedHeights[l] =
        static_cast<float>(tl + (static_cast<double>(firstFormedHeights[l]) - tl) / alpha);
  }
  return model;
}

}  // namespace ddfcam::planning
