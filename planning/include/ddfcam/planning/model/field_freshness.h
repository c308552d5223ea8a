// SPDX-License-Identifier: MIT
// ddfcam: whether a scalar field still describes the part's heights (stale fields).
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/model/scalar_field.h>

#include <cstdint>
#include <span>

namespace ddfcam::planning {

/// @brief A 64-bit digest of heights laid out like DisplacementField::allHeights(): equal
/// heights (bit for bit, sizes included) give equal digests; any change of a height changes
/// it with overwhelming probability. About 1 ns per height.
std::uint64_t heightsDigest(std::span<const float> heights);

/// @brief Records in @p field that its values were computed from @p part's current heights,
/// so that a later change of the heights (a simulated pass, an undo of one) marks it stale.
void markComputedFrom(ScalarField& field, const ddf::DisplacementField& part);

/// @brief True if @p field was computed from heights other than @p partHeightsDigest
/// (heightsDigest of the part's current heights); false for a field without a digest.
bool isStale(const ScalarField& field, std::uint64_t partHeightsDigest);

/// @brief isStale() against @p part's current heights.
bool isStale(const ScalarField& field, const ddf::DisplacementField& part);

}  // namespace ddfcam::planning
