// SPDX-License-Identifier: MIT
// ddfcam: the "prov" chunk of a .ddfproj (layout in project_file.h).
#include "project_source_chunk.h"

#include <ddfcam/error.h>

#include "../common/byte_codec.h"
#include "../mesh/ddf_metadata.h"

namespace ddfcam::io::detail {

bool hasPartSource(const planning::Project& project) {
  return project.sourceUnit != ddfcam::LengthUnit::Millimetre ||
         !project.cadFaceOfSupportFace.empty() || !project.cadFaceNames.empty();
}

void checkPartSource(const planning::Project& project) {
  const std::size_t faces = project.cadFaceOfSupportFace.size();
  if (faces == 0) return;
  const int partFaces = project.part ? project.part->faceCount() : 0;
  if (faces != static_cast<std::size_t>(partFaces))
    throw InvalidInput(std::to_string(faces) + " CAD face entries for a part of " +
                       std::to_string(partFaces) + " support faces");
  const auto names = static_cast<int>(project.cadFaceNames.size());
  for (std::size_t f = 0; f < faces; ++f)
    if (const int cad = project.cadFaceOfSupportFace[f]; cad < -1 || cad >= names)
      throw InvalidInput("support face " + std::to_string(f) + " names CAD face " +
                         std::to_string(cad) + " of " + std::to_string(names));
}

void putPartSource(std::string& out, const planning::Project& project) {
  putU32(out, lengthUnitCode(project.sourceUnit));
  putU64(out, project.cadFaceNames.size());
  for (const std::string& name : project.cadFaceNames) putString(out, name);
  putIntList(out, project.cadFaceOfSupportFace);
}

void readPartSource(PayloadReader& in, planning::Project& project) {
  const std::int32_t code = in.i32("source unit");
  const std::optional<ddfcam::LengthUnit> unit = lengthUnitOfCode(static_cast<std::uint32_t>(code));
  if (!unit) in.fail("unknown source unit code " + std::to_string(code));
  project.sourceUnit = *unit;
  const std::size_t names = in.count(4, "CAD face name");
  project.cadFaceNames.clear();
  for (std::size_t n = 0; n < names; ++n)
    project.cadFaceNames.push_back(in.string("CAD face name"));
  project.cadFaceOfSupportFace = readIntList(in, "CAD faces of the support faces");
  in.rest();  // members of later versions
}

}  // namespace ddfcam::io::detail
