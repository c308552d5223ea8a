// SPDX-License-Identifier: MIT
// ddfcam: the optional "prov" chunk of a .ddfproj: the unit and CAD faces the part came with.
#pragma once

#include <ddfcam/planning/model/project.h>

#include "project_chunks.h"

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

inline constexpr std::string_view kTagSource = "prov";

/// @brief Whether @p project has anything for the "prov" chunk (a unit other than mm, or CAD
/// faces); projects without it are saved as before.
bool hasPartSource(const planning::Project& project);

/// @brief Checks that cadFaceOfSupportFace of @p project is empty or has one entry per face of
/// its part, each in [-1, cadFaceNames.size()).
/// @throws InvalidInput naming the first mismatch.
void checkPartSource(const planning::Project& project);

/// @brief Appends the "prov" payload (layout in project_file.h) of @p project to @p out.
void putPartSource(std::string& out, const planning::Project& project);

/// @brief Reads a "prov" payload into @p project (sourceUnit, cadFaceNames,
/// cadFaceOfSupportFace); bytes after the known members are consumed and ignored.
/// @throws IoError from @p in for a truncated payload or an unknown unit code.
void readPartSource(PayloadReader& in, planning::Project& project);

}  // namespace ddfcam::io::detail
