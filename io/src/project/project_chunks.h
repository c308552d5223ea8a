// SPDX-License-Identifier: MIT
// ddfcam: payloads of the .ddfproj chunks, one encoder and decoder per item kind.
#pragma once

#include <ddfcam/planning/model/project.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ddfcam::io::detail {

inline constexpr std::string_view kTagProject = "PROJ";
inline constexpr std::string_view kTagPart = "PART";
inline constexpr std::string_view kTagDesign = "DSGN";
inline constexpr std::string_view kTagField = "FELD";
inline constexpr std::string_view kTagRegion = "REGN";
inline constexpr std::string_view kTagTool = "TOOL";
inline constexpr std::string_view kTagPath = "PATH";
inline constexpr std::string_view kTagState = "STAT";
inline constexpr std::string_view kTagSurface = "SURF";
/// Optional: the heights digest of one field (planning::ScalarField::heightsDigest), after it.
inline constexpr std::string_view kTagFieldDigest = "hdig";

/// @brief Whether @p tag names an optional chunk: its first character is a lower-case ASCII
/// letter (see project_file.h). A reader skips optional chunks it does not know.
inline bool isOptionalChunkTag(std::string_view tag) {
  return !tag.empty() && tag.front() >= 'a' && tag.front() <= 'z';
}

/// @brief Bounds-checked sequential reader of one chunk payload. Every read checks the bytes
/// left first, and counts are checked against them before anything is allocated, so hostile
/// lengths fail with a message instead of a huge allocation.
class PayloadReader {
 public:
  /// @param context prefix of every message, e.g. "part.ddfproj: chunk 3 ('FELD')".
  PayloadReader(std::string_view payload, std::string context)
      : rest_(payload), context_(std::move(context)) {}

  /// @brief The next little-endian value; @p what names it in messages.
  /// @throws IoError (as every reader below) if the payload ends first.
  std::uint8_t u8(const char* what);
  std::int32_t i32(const char* what);
  std::uint64_t u64(const char* what);
  float f32(const char* what);
  double f64(const char* what);
  /// @brief u32 byte count followed by the bytes.
  std::string string(const char* what);
  /// @brief A u64 element count whose elements of @p elementBytes each must fit in the rest.
  std::size_t count(std::size_t elementBytes, const char* what);
  /// @brief Number of bytes not read yet.
  std::size_t left() const { return rest_.size(); }
  /// @brief Everything not read yet (consumes it).
  std::string_view rest();
  /// @brief Requires the payload to be consumed completely.
  void finish() const;
  /// @throws IoError "<context>: <what>".
  [[noreturn]] void fail(const std::string& what) const;
  const std::string& context() const { return context_; }

 private:
  const char* take(std::size_t bytes, const char* what);

  std::string_view rest_;
  std::string context_;
};

/// @brief Payload encoders: each appends one chunk payload (layout in project_file.h) to @p out.
void putProjectInfo(std::string& out, const planning::Project& project);
void putDesignMesh(std::string& out, const ddf::TriangleMesh& mesh);
void putField(std::string& out, const planning::ScalarField& field);
/// @brief i32 index of the field in the project, u64 digest.
void putFieldDigest(std::string& out, int fieldIndex, std::uint64_t digest);
void putRegion(std::string& out, const planning::Region& region);
void putTool(std::string& out, const planning::Tool& tool);
void putPath(std::string& out, const planning::ToolPath& path);
void putState(std::string& out, const planning::SimulationState& state);
/// @brief u32 byte count + bytes.
/// @throws InvalidInput for a string longer than 4 GiB.
void putString(std::string& out, std::string_view text);
/// @brief Three f64 (x, y, z), mm.
void putVec3(std::string& out, const Eigen::Vector3d& v);
/// @brief Count + that many i32 / f32 values (the list layout of project_file.h).
void putIntList(std::string& out, const std::vector<int>& values);
void putFloatList(std::string& out, const std::vector<float>& values);

/// @brief Payload decoders, the inverses of the encoders; they check lengths but not the
/// project invariants (planning::validateProject does, once the whole project is read).
/// @throws IoError from @p in, naming the chunk and the item that does not parse.
void readProjectInfo(PayloadReader& in, planning::Project& project);
ddf::TriangleMesh readDesignMesh(PayloadReader& in);
planning::ScalarField readField(PayloadReader& in);
/// @brief Sets the digest of the field it names among @p fields (read before it).
void readFieldDigest(PayloadReader& in, std::vector<planning::ScalarField>& fields);
/// @param formatVersion version of the file: 1 (no plan, the default plan is used) or 2.
planning::Region readRegion(PayloadReader& in, std::uint32_t formatVersion);
/// @param formatVersion version of the file: before 3 a tool ends after its segments and the
/// fields added in version 3 keep the defaults of planning::Tool.
planning::Tool readTool(PayloadReader& in, std::uint32_t formatVersion);
planning::ToolPath readPath(PayloadReader& in);
planning::SimulationState readState(PayloadReader& in);
/// @brief Inverse of putVec3; @p what names the value in errors.
Eigen::Vector3d readVec3(PayloadReader& in, const char* what);
/// @brief Inverses of putIntList / putFloatList; @p what names the list in errors.
std::vector<int> readIntList(PayloadReader& in, const char* what);
std::vector<float> readFloatList(PayloadReader& in, const char* what);

}  // namespace ddfcam::io::detail
