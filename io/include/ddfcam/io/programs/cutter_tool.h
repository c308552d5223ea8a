// SPDX-License-Identifier: MIT
// ddfcam: the planning tool an APT cutter record describes (the inverse of aptCutter()).
#pragma once

#include <ddfcam/io/programs/cl_program.h>
#include <ddfcam/planning/tools/tool.h>

#include <string>

namespace ddfcam::io {

/// @brief The planning tool for an APT @p cutter (mm): a ball-end when the corner radius is
/// the radius (within 1e-6 of it), a flat-end when it is 0, else a torus cutter with that
/// corner radius; flute length h (2 d if h is 0). Frames as planning/tool.h (tip at the origin,
/// axis +z), so APT's CL point is the tool reference point.
/// @param name tool name; empty gives "imported cutter".
/// @throws InvalidInput if the cutter gives no usable tool (diameter <= 0, a negative corner
/// radius or one larger than the radius, or a tool planning::validateTool() refuses).
planning::Tool toolFromCutter(const ClCutter& cutter, const std::string& name);

}  // namespace ddfcam::io
