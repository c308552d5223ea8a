// SPDX-License-Identifier: MIT
// ddfcam: the optional "line" chunk of a .ddfproj: the raw lines and linking a path was planned
// with.
#pragma once

#include <ddfcam/planning/model/tool_path.h>

#include "project_chunks.h"

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

inline constexpr std::string_view kTagPathLines = "line";

/// @brief Whether @p path has anything for a "line" chunk (raw lines or a linked idle length);
/// other paths are saved as before.
bool hasPathLines(const planning::ToolPath& path);

/// @brief Appends the "line" payload (layout in project_file.h) of path @p index to @p out.
void putPathLines(std::string& out, int index, const planning::ToolPath& path);

/// @brief Reads a "line" payload into the path it names among @p paths (rawLines,
/// linkedIdleMm); bytes after the known members are consumed and ignored.
/// @throws IoError from @p in for a truncated payload, a path index out of range or a path
/// whose lines were read already.
void readPathLines(PayloadReader& in, std::vector<planning::ToolPath>& paths);

}  // namespace ddfcam::io::detail
