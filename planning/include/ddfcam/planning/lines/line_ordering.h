// SPDX-License-Identifier: MIT
// ddfcam: traced lines made ready for tool placement: cleaned, ordered and oriented for cutting.
#pragma once

#include <ddfcam/ddf/displacement_field.h>
#include <ddfcam/planning/lines/streamline.h>
#include <ddfcam/planning/placement/path_linking.h>

#include <vector>

namespace ddfcam::planning {

/// @brief Removes repeated points (a trace that stalls at a boundary) and fold-backs onto the
/// point before (A B A) from @p line: both leave no feed direction for a tool's pose. Points
/// closer than 1e-6 mm count as repeated; seedIndex follows the seed point, or the point kept
/// in its place.
void dropRepeatedPoints(Streamline& line);

/// @brief @p line run backwards: points reversed, the two stop reasons swapped, seedIndex
/// mirrored.
Streamline reversedStreamline(Streamline line);

/// @brief Links @p lines with linkStreamlines() (@p params: order, feed sign, link limits) and
/// replaces them by the cut moves' lines in machining order, each reversed where
/// its cut runs against the trace; lines with fewer than two points drop out.
/// @return the linking report (moves index the lines as they were passed in).
/// @throws InvalidInput as linkStreamlines().
LinkedPaths orderLinesForCutting(const ddf::DisplacementField& part, std::vector<Streamline>& lines,
                                 const LinkingParams& params);

}  // namespace ddfcam::planning
