// SPDX-License-Identifier: MIT
// ddfcam: the G-code writer's positions and number text (private to io).
#pragma once

#include <ddfcam/io/programs/gcode_writer.h>

#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// Concatenation of @p parts (avoids GCC 12's -Wrestrict false positive on "lit" + string).
std::string cat(std::initializer_list<std::string_view> parts);
/// Fixed-point text of @p v, locale-independent, "-0.000" written as "0.000".
/// @throws InvalidInput if the number is too large to write.
std::string fixed(double v, int decimals);
/// "(x, y, z)" with 6 decimals.
std::string vecText(const ddf::Vec3& v);
/// Comment text safe for RS274: no parentheses, printable ASCII, bounded length.
std::string commentText(std::string_view text);
/// @throws InvalidInput for options encodeGCode() cannot write with, naming the option.
void validateGCodeParams(const GCodeWriteParams& params);
/// The tool change starting at point @p i of @p program, if any.
const planning::ClToolChange* changeAt(const planning::ClProgram& program, std::size_t i);
/// Positions of every point as written, in program order (mm, degrees): machine X Y Z from the
/// kinematics, or with tcpPositions the tip in the part frame; points without an axis keep the
/// axis in force. @throws InvalidInput as encodeGCode(), naming the point.
std::vector<planning::MachinePose> machinePoses(const planning::ClProgram& program,
                                                const planning::Tool& tool,
                                                const GCodeWriteParams& params);

}  // namespace ddfcam::io::detail
