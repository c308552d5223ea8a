// SPDX-License-Identifier: MIT
// ddfcam: .ddfproj header and chunk framing, envelope checks and truncation diagnosis.
#include "project_layout.h"

#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>
#include <ddfcam/io/project/project_file.h>

#include "../common/byte_codec.h"
#include "../mesh/ddf_layout.h"

#include <span>

namespace ddfcam::io::detail {
namespace {

[[noreturn]] void fail(const std::string& name, const std::string& what) {
  throw IoError(name + ": " + what);
}

void putLeAt(std::string& out, std::size_t offset, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out[offset + i] = static_cast<char>((value >> (8 * i)) & 0xFFu);
}

/// A tag as it may be shown in a message: printable ASCII kept, anything else escaped.
std::string printableTag(std::string_view tag) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (const char c : tag) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      out += "\\x";
      out += kHex[u >> 4];
      out += kHex[u & 15u];
    }
  }
  return out;
}

std::string chunkLabel(std::size_t index, std::string_view tag) {
  std::string label = "chunk " + std::to_string(index + 1);
  if (!tag.empty()) label += " ('" + printableTag(tag) + "')";
  return label;
}

/// Magic and version; they are checked first because a newer version may change the rest.
void checkIdentity(std::string_view bytes, const std::string& name) {
  if (bytes.empty()) fail(name, "file is empty, not a ddfcam project file");
  const std::string_view head = bytes.substr(0, kProjectMagic.size());
  if (head != kProjectMagic.substr(0, head.size())) {
    if (head == kDdfMagic)
      fail(name, "not a ddfcam project file: it is a .ddf field file (open it as a part)");
    fail(name, "not a ddfcam project file (wrong magic)");
  }
  if (bytes.size() < 12)
    fail(name, "truncated project file: " + std::to_string(bytes.size()) +
                   " bytes, it ends in the header");
  const std::uint32_t version = getU32(bytes.data() + 8);
  if (version > kProjectFormatVersion)
    fail(name, "written by a newer ddfcam (format version " + std::to_string(version) +
                   ", this build reads up to " + std::to_string(kProjectFormatVersion) + ")");
  if (version == 0) fail(name, "damaged project file: invalid format version 0");
  if (bytes.size() < kProjectHeaderBytes)
    fail(name, "truncated project file: " + std::to_string(bytes.size()) +
                   " bytes, it ends in the header");
}

/// Where a walk over the chunk framing of the available bytes stops.
struct FramingWalk {
  bool complete = false;  ///< all chunks present and exactly the checksum after them
  std::string where;      ///< otherwise: where the data ends, for the message
};

FramingWalk walkFraming(std::string_view bytes, std::uint32_t chunkCount) {
  std::size_t at = kProjectHeaderBytes;
  std::string previous = "the header";
  for (std::size_t index = 0; index < chunkCount; ++index) {
    const std::size_t left = bytes.size() - at;
    if (left == 0) return {false, "it ends after " + previous};
    if (left < kChunkHeaderBytes) {
      const std::string_view tag = left >= 4 ? bytes.substr(at, 4) : std::string_view{};
      return {false, "it ends in the header of " + chunkLabel(index, tag)};
    }
    const std::string_view tag = bytes.substr(at, 4);
    const std::uint64_t length = getU64(bytes.data() + at + 4);
    if (length > left - kChunkHeaderBytes)
      return {false, "it ends in " + chunkLabel(index, tag) + " after " +
                         std::to_string(left - kChunkHeaderBytes) + " of its " +
                         std::to_string(length) + " payload bytes"};
    at += kChunkHeaderBytes + length;
    previous = chunkLabel(index, tag);
  }
  const std::size_t left = bytes.size() - at;
  if (left == kProjectChecksumBytes) return {true, ""};
  if (left < kProjectChecksumBytes)
    return {false, left == 0 ? "it ends before the checksum" : "it ends in the checksum"};
  return {false, "trailing data after the checksum"};
}

void checkSize(std::string_view bytes, const std::string& name) {
  const std::uint64_t declared = getU64(bytes.data() + 16);
  if (declared == bytes.size()) return;
  const FramingWalk walk = walkFraming(bytes, getU32(bytes.data() + 12));
  const std::string sizes =
      std::to_string(bytes.size()) + " bytes where the header promises " + std::to_string(declared);
  if (declared > bytes.size() && !walk.complete)
    fail(name, "truncated project file: " + sizes + ", " + walk.where);
  fail(name, "damaged project file: " + sizes +
                 (walk.complete ? " (damaged header)" : " (trailing data or a damaged header)"));
}

void checkChecksum(std::string_view bytes, const std::string& name) {
  const std::size_t body = bytes.size() - kProjectChecksumBytes;
  const std::uint32_t stored = getU32(bytes.data() + body);
  if (stored != crc32(std::as_bytes(std::span(bytes.data(), body))))
    fail(name, "damaged project file (checksum mismatch)");
}

}  // namespace

ProjectEncoder::ProjectEncoder() {
  out_.append(kProjectMagic);
  putU32(out_, kProjectFormatVersion);
  putU32(out_, 0);  // chunk count, filled in by finish()
  putU64(out_, 0);  // file size, filled in by finish()
}

std::string& ProjectEncoder::beginChunk(std::string_view tag) {
  closeChunk();
  openChunk_ = out_.size();
  out_.append(tag.substr(0, 4));
  putU64(out_, 0);  // payload size, filled in by closeChunk()
  ++chunkCount_;
  return out_;
}

void ProjectEncoder::closeChunk() {
  if (openChunk_ == 0) return;
  putLeAt(out_, openChunk_ + 4, out_.size() - openChunk_ - kChunkHeaderBytes, 8);
  openChunk_ = 0;
}

std::string ProjectEncoder::finish() {
  closeChunk();
  putLeAt(out_, 12, chunkCount_, 4);
  putLeAt(out_, 16, out_.size() + kProjectChecksumBytes, 8);
  putU32(out_, crc32(std::as_bytes(std::span(out_.data(), out_.size()))));
  return std::move(out_);
}

std::string ChunkView::label() const {
  return chunkLabel(index, tag);
}

std::vector<ChunkView> splitProjectChunks(std::string_view bytes, const std::string& name) {
  checkIdentity(bytes, name);
  checkSize(bytes, name);
  checkChecksum(bytes, name);
  const std::uint32_t count = getU32(bytes.data() + 12);
  const std::size_t end = bytes.size() - kProjectChecksumBytes;
  std::vector<ChunkView> chunks;
  std::size_t at = kProjectHeaderBytes;
  // Past the checksum the framing can only disagree if it was written that way (or forged).
  while (at < end) {
    if (end - at < kChunkHeaderBytes)
      fail(name, "damaged project file: " + std::to_string(end - at) + " stray bytes where " +
                     chunkLabel(chunks.size(), "") + " should start");
    ChunkView chunk{std::string(bytes.substr(at, 4)), chunks.size(), {}};
    const std::uint64_t length = getU64(bytes.data() + at + 4);
    if (length > end - at - kChunkHeaderBytes)
      fail(name, "damaged project file: " + chunk.label() + " claims " + std::to_string(length) +
                     " payload bytes, only " + std::to_string(end - at - kChunkHeaderBytes) +
                     " remain");
    chunk.payload = bytes.substr(at + kChunkHeaderBytes, length);
    chunks.push_back(std::move(chunk));
    at += kChunkHeaderBytes + length;
  }
  if (chunks.size() != count)
    fail(name, "damaged project file: the header announces " + std::to_string(count) +
                   " chunks, the file holds " + std::to_string(chunks.size()));
  return chunks;
}

}  // namespace ddfcam::io::detail
