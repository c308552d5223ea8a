// SPDX-License-Identifier: MIT
// ddfcam: checking a converted DDF against the three constraints and repairing what the
// conversion can (constraint 2 by shared vectors, constraint 3 by shorter vectors).
#pragma once

#include <ddfcam/ddf/mesh_conversion.h>

#include <array>
#include <vector>

namespace ddfcam::ddf::detail {

/// @brief Number of boundary loops of @p mesh (holes and open borders).
int countBoundaryLoops(const SupportMesh& mesh);

/// @brief Number of undirected edges of @p triangles shared by more than two of them.
int countNonManifoldEdges(const std::vector<std::array<int, 3>>& triangles);

/// @brief params.lengths with the validation's coincidence tolerance where it has none, so the
/// length choice and the check agree on which faces are adjacent. No progress callback.
VectorLengthParams lengthParams(const ConversionParams& params);

/// @brief Validates result.ddf with params.validation and repairs what the conversion can:
/// coincident vertices with different vectors get one shared vector (the normalised sum of
/// their directions, the shortest of their lengths); faces below crust height 1 or pairs of
/// crossing crusts let the vector lengths be chosen again with at most half the previous
/// length limit (sec. 4.4), up to three times. Fills result.report.validation and the repair
/// counts; the heights are not touched (they are in units of the vector length, so the caller
/// fills them afterwards). @throws Cancelled through params.progress.
void validateAndRepair(ConversionResult& result, const ConversionParams& params);

}  // namespace ddfcam::ddf::detail
