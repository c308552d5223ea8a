// SPDX-License-Identifier: MIT
// ddfcam: payload of the .ddfproj "MOLD" chunk (planning::MouldStudy, format version 4).
#pragma once

#include <ddfcam/planning/mould/mould_study.h>

#include "project_chunks.h"

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

inline constexpr std::string_view kTagMould = "MOLD";

/// @brief Appends the "MOLD" payload of @p study (layout in project_file.h) to @p out.
/// @throws InvalidInput for a string or embedded .ddf encoding longer than 4 GiB.
void putMouldStudy(std::string& out, const planning::MouldStudy& study);

/// @brief The inverse of putMouldStudy; checks lengths, not planning::validateMouldStudy.
/// @throws IoError from @p in naming the chunk and the item that does not parse (an embedded
/// .ddf that does not decode is nested).
planning::MouldStudy readMouldStudy(PayloadReader& in);

}  // namespace ddfcam::io::detail
