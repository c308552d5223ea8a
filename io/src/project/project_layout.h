// SPDX-License-Identifier: MIT
// ddfcam: the envelope of a .ddfproj file (header, chunk framing, checksum); see project_file.h.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

inline constexpr std::string_view kProjectMagic{"DDFPRJ\x1a\n", 8};
inline constexpr std::size_t kProjectHeaderBytes = 24;
inline constexpr std::size_t kChunkHeaderBytes = 12;
inline constexpr std::size_t kProjectChecksumBytes = 4;

/// @brief Builds a .ddfproj file: header, chunks appended one by one, then the checksum.
class ProjectEncoder {
 public:
  ProjectEncoder();
  /// @brief Starts a chunk with the 4-character @p tag; its payload is appended to the
  /// returned buffer until the next beginChunk() or finish().
  std::string& beginChunk(std::string_view tag);
  /// @brief Closes the open chunk, fills in the header's count and size, appends the CRC.
  /// @return the whole file content.
  std::string finish();

 private:
  void closeChunk();

  std::string out_;
  std::size_t openChunk_ = 0;  ///< offset of the open chunk's header; 0 if none is open
  std::uint32_t chunkCount_ = 0;
};

/// @brief One chunk of a checked file: its tag, its position among the chunks (0-based), and
/// a view of its payload inside the decoded bytes.
struct ChunkView {
  std::string tag;
  std::size_t index = 0;
  std::string_view payload;

  /// @brief "chunk 3 ('FELD')", for messages (1-based, as a person counts).
  std::string label() const;
};

/// @brief Checks magic, version, size and checksum of @p bytes and splits the body into its
/// chunks; after this, the chunk payloads are whole and undamaged (up to CRC-32 collisions).
/// @throws IoError "<sourceName>: <what is wrong>": empty, not a project file, newer version,
/// truncated (naming the chunk where the data ends), trailing data, checksum mismatch, or a
/// chunk framing that disagrees with the header.
std::vector<ChunkView> splitProjectChunks(std::string_view bytes, const std::string& sourceName);

}  // namespace ddfcam::io::detail
