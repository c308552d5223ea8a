// SPDX-License-Identifier: MIT
// ddfcam: .ddf encoding and decoding (layout documented in ddf_file.h).
#include <ddfcam/io/mesh/ddf_file.h>

#include <ddfcam/error.h>
#include <ddfcam/io/common/checksum.h>

#include "../common/byte_codec.h"
#include "../common/file_access.h"
#include "ddf_layout.h"
#include "ddf_metadata.h"

#include <algorithm>
#include <functional>

namespace ddfcam::io {
namespace {

using detail::DdfHeader;

/// Accumulates encoded bytes, hands them to a sink in large chunks and keeps the CRC.
class DdfEncoder {
 public:
  explicit DdfEncoder(std::function<void(std::string_view)> sink) : sink_(std::move(sink)) {}
  std::string& buffer() { return buffer_; }
  void flushIfLarge() {
    if (buffer_.size() >= (1u << 20)) flush();
  }
  void finish() {
    flush();
    detail::putU32(buffer_, crc_.value());
    sink_(buffer_);
    buffer_.clear();
  }

 private:
  void flush() {
    crc_.update(std::as_bytes(std::span(buffer_.data(), buffer_.size())));
    sink_(buffer_);
    buffer_.clear();
  }

  std::function<void(std::string_view)> sink_;
  std::string buffer_;
  Crc32 crc_;
};

void putVec3(std::string& out, const ddf::Vec3& v) {
  for (int i = 0; i < 3; ++i) detail::putF64(out, v[i]);
}

void encode(const ddf::DisplacementField& field, const DdfMetadata* metadata, DdfEncoder& encoder) {
  std::string& out = encoder.buffer();
  DdfHeader header;
  header.version = metadata ? 2 : 1;
  header.vertexCount = static_cast<std::uint64_t>(field.vertexCount());
  header.faceCount = static_cast<std::uint64_t>(field.faceCount());
  header.m = static_cast<std::uint32_t>(field.resolution());
  detail::putDdfHeader(out, header);
  for (int v = 0; v < field.vertexCount(); ++v, encoder.flushIfLarge())
    putVec3(out, field.position(v));
  for (int v = 0; v < field.vertexCount(); ++v, encoder.flushIfLarge())
    putVec3(out, field.vector(v));
  for (int f = 0; f < field.faceCount(); ++f, encoder.flushIfLarge())
    for (const int v : field.faceVertices(f)) detail::putU32(out, static_cast<std::uint32_t>(v));
  for (int f = 0; f < field.faceCount(); ++f, encoder.flushIfLarge())
    for (const float h : field.heights(f)) detail::putF32(out, h);
  if (metadata) detail::putDdfMetadata(out, *metadata);
  encoder.finish();
}

/// Sequential reader of the body of a .ddf whose envelope (size, checksum) was checked, so
/// reads need no bounds checks; content errors name the file and the item.
struct BodyDecoder {
  const char* p;
  const std::string& sourceName;

  [[noreturn]] void fail(const std::string& what) const { throw IoError(sourceName + ": " + what); }
  std::vector<ddf::Vec3> vec3List(std::uint64_t count, const char* what) {
    std::vector<ddf::Vec3> out(count);
    for (std::size_t v = 0; v < count; ++v, p += 24) {
      out[v] = {detail::getF64(p), detail::getF64(p + 8), detail::getF64(p + 16)};
      if (!out[v].allFinite())
        fail(std::string(what) + " of vertex " + std::to_string(v) + " is not finite");
    }
    return out;
  }
  std::vector<std::array<int, 3>> faces(const DdfHeader& header) {
    std::vector<std::array<int, 3>> out(header.faceCount);
    for (std::size_t f = 0; f < out.size(); ++f) {
      for (int c = 0; c < 3; ++c, p += 4) {
        const std::uint32_t v = detail::getU32(p);
        if (v >= header.vertexCount)
          fail("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) + " of " +
               std::to_string(header.vertexCount));
        out[f][c] = static_cast<int>(v);
      }
      if (out[f][0] == out[f][1] || out[f][1] == out[f][2] || out[f][2] == out[f][0])
        fail("face " + std::to_string(f) + " repeats a vertex");
    }
    return out;
  }
  void heights(std::vector<float>& out) {
    for (float& h : out) h = detail::getF32(p), p += 4;
  }
};

std::string encodeWith(const ddf::DisplacementField& field, const DdfMetadata* metadata) {
  std::string content;
  DdfEncoder encoder([&](std::string_view chunk) { content.append(chunk); });
  encode(field, metadata, encoder);
  return content;
}

void writeWith(const ddf::DisplacementField& field, const std::filesystem::path& path,
               const DdfMetadata* metadata) {
  detail::AtomicFileWriter writer(path);
  DdfEncoder encoder([&](std::string_view chunk) { writer.write(chunk); });
  encode(field, metadata, encoder);
  writer.commit();
}

}  // namespace

std::string encodeDdf(const ddf::DisplacementField& field) {
  return encodeWith(field, nullptr);
}

std::string encodeDdf(const ddf::DisplacementField& field, const DdfMetadata& metadata) {
  detail::checkDdfMetadata(metadata, field.faceCount());
  return encodeWith(field, &metadata);
}

void writeDdf(const ddf::DisplacementField& field, const std::filesystem::path& path) {
  writeWith(field, path, nullptr);
}

void writeDdf(const ddf::DisplacementField& field, const std::filesystem::path& path,
              const DdfMetadata& metadata) {
  detail::checkDdfMetadata(metadata, field.faceCount());
  writeWith(field, path, &metadata);
}

ddf::DisplacementField decodeDdf(std::string_view bytes, const std::string& sourceName,
                                 DdfMetadata* metadata) {
  const DdfHeader header = detail::checkDdfEnvelope(bytes, sourceName);
  BodyDecoder body{bytes.data() + detail::kDdfHeaderBytes, sourceName};
  std::vector<ddf::Vec3> positions = body.vec3List(header.vertexCount, "position");
  std::vector<ddf::Vec3> vectors = body.vec3List(header.vertexCount, "vector");
  const std::vector<std::array<int, 3>> faces = body.faces(header);
  // OpenMesh starts a new face's first halfedge at its last vertex, so (p2, p3, p1) in gives
  // the stored local order (p1, p2, p3) back; any other order is handled by reorderHeights.
  std::vector<std::array<int, 3>> rotated(faces.size());
  for (std::size_t f = 0; f < faces.size(); ++f)
    rotated[f] = {faces[f][1], faces[f][2], faces[f][0]};
  ddf::SupportMesh support;
  try {
    support = ddf::makeSupportMesh(positions, rotated);
  } catch (const InvalidInput&) {
    std::throw_with_nested(IoError(sourceName + ": the support mesh is invalid"));
  }
  ddf::DisplacementField field(std::move(support), std::move(vectors), static_cast<int>(header.m));
  std::vector<float> stored(field.pointsPerFace());
  for (int f = 0; f < field.faceCount(); ++f) {
    body.heights(stored);
    if (field.faceVertices(f) == faces[f]) {
      std::copy(stored.begin(), stored.end(), field.heights(f).begin());
    } else {
      detail::reorderHeights(faces[f], field.faceVertices(f), field.raster(), stored,
                             field.heights(f));
    }
  }
  // A damaged section is an error also for callers that do not ask for the metadata.
  DdfMetadata read;
  if (header.version >= 2)
    read = detail::readDdfMetadata(std::string_view(body.p + 4, header.metadataBytes),
                                   field.faceCount(), sourceName);
  if (metadata) *metadata = std::move(read);
  return field;
}

ddf::DisplacementField readDdf(const std::filesystem::path& path, DdfMetadata* metadata) {
  return decodeDdf(detail::readFileBytes(path), path.string(), metadata);
}

}  // namespace ddfcam::io
