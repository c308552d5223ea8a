// SPDX-License-Identifier: MIT
// ddfcam: .ddfproj saving and loading (layout documented in project_file.h).
#include <ddfcam/io/project/project_file.h>

#include <ddfcam/error.h>
#include <ddfcam/io/mesh/ddf_file.h>

#include <ddfcam/log.h>

#include "../common/byte_codec.h"
#include "../common/file_access.h"
#include "mould_study_chunk.h"
#include "path_lines_chunk.h"
#include "project_chunks.h"
#include "project_layout.h"
#include "project_source_chunk.h"

#include <exception>

namespace ddfcam::io {
namespace {

using detail::ChunkView;
using detail::PayloadReader;

ddf::DisplacementField decodeEmbeddedDdf(std::string_view bytes, const PayloadReader& in,
                                         const std::string& what) {
  try {
    return decodeDdf(bytes, what);
  } catch (const Error&) {
    std::throw_with_nested(IoError(in.context() + ": " + what + " is not a valid .ddf encoding"));
  }
}

/// Fills a Project chunk by chunk; enforces the chunk order rules and skips (and reports) the
/// optional chunks it does not know.
class ProjectDecoder {
 public:
  ProjectDecoder(const std::string& sourceName, std::uint32_t formatVersion,
                 ProjectReadReport& report)
      : name_(sourceName), version_(formatVersion), report_(report) {
    report_ = ProjectReadReport{};
    report_.formatVersion = formatVersion;
  }

  void add(const ChunkView& chunk) {
    PayloadReader in(chunk.payload, name_ + ": " + chunk.label());
    if (chunk.index == 0 && chunk.tag != detail::kTagProject)
      in.fail("damaged project file: the first chunk must be 'PROJ'");
    if (chunk.tag == detail::kTagProject) {
      if (chunk.index != 0) in.fail("a second project header");
      detail::readProjectInfo(in, project_);
      sawProject_ = true;
    } else if (chunk.tag == detail::kTagPart) {
      if (project_.part) in.fail("a second part");
      project_.part = decodeEmbeddedDdf(in.rest(), in, "the embedded part");
    } else if (chunk.tag == detail::kTagDesign) {
      if (project_.designMesh) in.fail("a second design mesh");
      project_.designMesh = detail::readDesignMesh(in);
    } else if (chunk.tag == detail::kTagSource) {
      if (sawSource_) in.fail("a second part source");
      detail::readPartSource(in, project_);
      sawSource_ = true;
    } else if (chunk.tag == detail::kTagMould && version_ >= 4) {
      if (project_.mould) in.fail("a second mould study");
      project_.mould = detail::readMouldStudy(in);
    } else {
      addListItem(chunk.tag, in);
    }
    in.finish();
  }

  planning::Project finish() {
    if (!sawProject_) throw IoError(name_ + ": damaged project file: it holds no 'PROJ' chunk");
    try {
      detail::checkPartSource(project_);
      planning::validateProject(project_);
    } catch (const InvalidInput&) {
      std::throw_with_nested(IoError(name_ + ": the project in the file is invalid"));
    }
    return std::move(project_);
  }

 private:
  void addListItem(const std::string& tag, PayloadReader& in) {
    if (tag == detail::kTagField) {
      project_.fields.push_back(detail::readField(in));
    } else if (tag == detail::kTagRegion) {
      project_.regions.push_back(detail::readRegion(in, version_));
    } else if (tag == detail::kTagTool) {
      project_.tools.push_back(detail::readTool(in, version_));
    } else if (tag == detail::kTagPath) {
      project_.paths.push_back(detail::readPath(in));
    } else if (tag == detail::kTagPathLines) {
      detail::readPathLines(in, project_.paths);
    } else if (tag == detail::kTagState) {
      project_.states.push_back(detail::readState(in));
    } else if (tag == detail::kTagSurface) {
      planning::NamedSurface surface;
      surface.name = in.string("surface name");
      surface.ddf = decodeEmbeddedDdf(in.rest(), in, "surface '" + surface.name + "'");
      project_.surfaces.push_back(std::move(surface));
    } else if (tag == detail::kTagFieldDigest) {
      detail::readFieldDigest(in, project_.fields);
    } else if (detail::isOptionalChunkTag(tag)) {
      skip(in);
    } else {
      in.fail("unknown chunk type in format version " + std::to_string(version_) +
              " (damaged file, or written by an incompatible program)");
    }
  }

  // A later ddfcam added data this build does not know and marked it safe to ignore.
  void skip(PayloadReader& in) {
    in.rest();
    report_.skippedChunks.push_back(in.context());
    log(LogLevel::Warning, in.context() + ": optional chunk of a newer ddfcam skipped (" +
                               "its content is not loaded and is lost on saving)");
  }

  const std::string& name_;
  std::uint32_t version_;
  ProjectReadReport& report_;
  planning::Project project_;
  bool sawProject_ = false;
  bool sawSource_ = false;
};

}  // namespace

std::string encodeProject(const planning::Project& project) {
  planning::validateProject(project);
  detail::checkPartSource(project);
  detail::ProjectEncoder encoder;
  detail::putProjectInfo(encoder.beginChunk(detail::kTagProject), project);
  if (project.part) encoder.beginChunk(detail::kTagPart).append(encodeDdf(*project.part));
  if (detail::hasPartSource(project))
    detail::putPartSource(encoder.beginChunk(detail::kTagSource), project);
  if (project.designMesh)
    detail::putDesignMesh(encoder.beginChunk(detail::kTagDesign), *project.designMesh);
  for (const planning::Tool& tool : project.tools)
    detail::putTool(encoder.beginChunk(detail::kTagTool), tool);
  for (const planning::ToolPath& path : project.paths)
    detail::putPath(encoder.beginChunk(detail::kTagPath), path);
  for (std::size_t i = 0; i < project.paths.size(); ++i)
    if (detail::hasPathLines(project.paths[i]))
      detail::putPathLines(encoder.beginChunk(detail::kTagPathLines), static_cast<int>(i),
                           project.paths[i]);
  for (const planning::ScalarField& field : project.fields)
    detail::putField(encoder.beginChunk(detail::kTagField), field);
  for (std::size_t i = 0; i < project.fields.size(); ++i)
    if (const auto& digest = project.fields[i].heightsDigest)
      detail::putFieldDigest(encoder.beginChunk(detail::kTagFieldDigest), static_cast<int>(i),
                             *digest);
  for (const planning::Region& region : project.regions)
    detail::putRegion(encoder.beginChunk(detail::kTagRegion), region);
  for (const planning::SimulationState& state : project.states)
    detail::putState(encoder.beginChunk(detail::kTagState), state);
  for (const planning::NamedSurface& surface : project.surfaces) {
    std::string& out = encoder.beginChunk(detail::kTagSurface);
    detail::putString(out, surface.name);
    out.append(encodeDdf(surface.ddf));
  }
  if (project.mould) detail::putMouldStudy(encoder.beginChunk(detail::kTagMould), *project.mould);
  return encoder.finish();
}

planning::Project decodeProject(std::string_view bytes, const std::string& sourceName,
                                ProjectReadReport* report) {
  const std::vector<ChunkView> chunks = detail::splitProjectChunks(bytes, sourceName);
  ProjectReadReport local;
  // splitProjectChunks has checked the header, so the version is there and supported.
  ProjectDecoder decoder(sourceName, detail::getU32(bytes.data() + 8), report ? *report : local);
  for (const ChunkView& chunk : chunks) decoder.add(chunk);
  return decoder.finish();
}

void writeProject(const planning::Project& project, const std::filesystem::path& path) {
  const std::string bytes = encodeProject(project);
  detail::writeFileAtomically(path, bytes);
}

planning::Project readProject(const std::filesystem::path& path, ProjectReadReport* report) {
  return decodeProject(detail::readFileBytes(path), path.string(), report);
}

}  // namespace ddfcam::io
