// SPDX-License-Identifier: MIT
// ddfcam: per-face height differences between two states of a DDF (bounded-memory undo).
#include <ddfcam/error.h>
#include <ddfcam/planning/model/height_delta.h>

#include <algorithm>
#include <cstring>
#include <string>

namespace ddfcam::planning {
namespace {

bool sameFace(const float* a, const float* b, std::size_t count) {
  // Bitwise, so NaN payloads and the sign of zero count as changes too: revert must restore
  // exactly the bits that were there.
  return std::memcmp(a, b, count * sizeof(float)) == 0;
}

}  // namespace

HeightDelta HeightDelta::between(std::span<const float> before, std::span<const float> after,
                                 std::size_t pointsPerFace) {
  if (pointsPerFace == 0) throw InvalidInput("height delta: pointsPerFace must be positive");
  if (before.size() != after.size())
    throw InvalidInput("height delta: states differ in size (" + std::to_string(before.size()) +
                       " and " + std::to_string(after.size()) + " values)");
  if (before.size() % pointsPerFace != 0)
    throw InvalidInput("height delta: " + std::to_string(before.size()) +
                       " values are not a multiple of " + std::to_string(pointsPerFace) +
                       " points per face");
  HeightDelta delta;
  delta.pointsPerFace_ = pointsPerFace;
  delta.totalValues_ = before.size();
  const std::size_t faces = before.size() / pointsPerFace;
  for (std::size_t f = 0; f < faces; ++f) {
    const std::size_t offset = f * pointsPerFace;
    if (!sameFace(before.data() + offset, after.data() + offset, pointsPerFace))
      delta.faces_.push_back(static_cast<int>(f));
  }
  delta.faces_.shrink_to_fit();
  delta.before_.reserve(delta.faces_.size() * pointsPerFace);
  delta.after_.reserve(delta.faces_.size() * pointsPerFace);
  for (int f : delta.faces_) {
    const std::size_t offset = static_cast<std::size_t>(f) * pointsPerFace;
    delta.before_.insert(delta.before_.end(), before.begin() + offset,
                         before.begin() + offset + pointsPerFace);
    delta.after_.insert(delta.after_.end(), after.begin() + offset,
                        after.begin() + offset + pointsPerFace);
  }
  return delta;
}

void HeightDelta::apply(ddf::DisplacementField& ddf) const {
  write(ddf, after_);
}

void HeightDelta::revert(ddf::DisplacementField& ddf) const {
  write(ddf, before_);
}

std::size_t HeightDelta::memoryBytes() const {
  return sizeof(*this) + faces_.capacity() * sizeof(int) +
         (before_.capacity() + after_.capacity()) * sizeof(float);
}

void HeightDelta::write(ddf::DisplacementField& ddf, const std::vector<float>& source) const {
  // A default-constructed delta was made for no field and changes nothing.
  if (pointsPerFace_ == 0) return;
  if (ddf.pointsPerFace() != pointsPerFace_ || ddf.allHeights().size() != totalValues_)
    throw InvalidInput("height delta made for " + std::to_string(totalValues_) + " heights (" +
                       std::to_string(pointsPerFace_) + " per face) applied to a field of " +
                       std::to_string(ddf.allHeights().size()) + " heights (" +
                       std::to_string(ddf.pointsPerFace()) + " per face)");
  for (std::size_t i = 0; i < faces_.size(); ++i) {
    const auto first = source.begin() + static_cast<std::ptrdiff_t>(i * pointsPerFace_);
    std::copy(first, first + static_cast<std::ptrdiff_t>(pointsPerFace_),
              ddf.heights(faces_[i]).begin());
  }
}

}  // namespace ddfcam::planning
