// SPDX-License-Identifier: MIT
// ddfcam: the metadata section of a .ddf file: source unit, CAD faces of the support and the
// design mesh.
#include "ddf_metadata.h"

#include <ddfcam/error.h>

#include "../common/byte_codec.h"

#include <array>
#include <bit>
#include <limits>

namespace ddfcam::io::detail {
namespace {

// The stored codes; their order is part of the file format, independent of the enum's.
constexpr std::array<ddfcam::LengthUnit, 4> kUnitCodes = {
    ddfcam::LengthUnit::Millimetre, ddfcam::LengthUnit::Centimetre, ddfcam::LengthUnit::Metre,
    ddfcam::LengthUnit::Inch};

/// Bounds-checked reader of the section; every failure names the file and the member.
class SectionReader {
 public:
  SectionReader(std::string_view rest, const std::string& name) : rest_(rest), name_(name) {}
  std::uint64_t unsignedValue(int bytes, const char* what) {
    const std::uint64_t v = getUnsigned(take(static_cast<std::size_t>(bytes), what), bytes);
    return v;
  }
  std::string text(const char* what) {
    const std::uint64_t length = unsignedValue(4, what);
    return std::string(take(static_cast<std::size_t>(length), what), length);
  }
  bool atEnd() const { return rest_.empty(); }
  double real(const char* what) { return std::bit_cast<double>(unsignedValue(8, what)); }
  [[noreturn]] void fail(const std::string& what) const {
    throw IoError(name_ + ": metadata section: " + what);
  }

 private:
  const char* take(std::size_t bytes, const char* what) {
    if (rest_.size() < bytes) fail(std::string("truncated in ") + what);
    const char* at = rest_.data();
    rest_.remove_prefix(bytes);
    return at;
  }

  std::string_view rest_;
  const std::string& name_;
};

void putDesignMesh(std::string& section, const std::optional<ddf::TriangleMesh>& mesh) {
  putU64(section, mesh ? mesh->vertices.size() : 0);
  if (mesh)
    for (const ddf::Vec3& p : mesh->vertices)
      for (int c = 0; c < 3; ++c) putF64(section, p[c]);
  putU64(section, mesh ? mesh->triangles.size() : 0);
  if (mesh)
    for (const auto& t : mesh->triangles)
      for (const int v : t) putU32(section, static_cast<std::uint32_t>(v));
}

std::optional<ddf::TriangleMesh> readDesignMesh(SectionReader& in, std::size_t sectionBytes) {
  const std::uint64_t vertices = in.unsignedValue(8, "the design mesh's vertex count");
  if (vertices > sectionBytes / 24) in.fail("implausible design mesh vertex count");
  ddf::TriangleMesh mesh;
  mesh.vertices.resize(vertices);
  for (ddf::Vec3& p : mesh.vertices)
    for (int c = 0; c < 3; ++c) p[c] = in.real("the design mesh's vertices");
  const std::uint64_t triangles = in.unsignedValue(8, "the design mesh's triangle count");
  if (triangles > sectionBytes / 12) in.fail("implausible design mesh triangle count");
  mesh.triangles.resize(triangles);
  for (auto& t : mesh.triangles)
    for (int& v : t) {
      const std::uint64_t index = in.unsignedValue(4, "the design mesh's triangles");
      if (index >= vertices)
        in.fail("design mesh vertex " + std::to_string(index) + " of " + std::to_string(vertices));
      v = static_cast<int>(index);
    }
  if (vertices == 0 && triangles == 0) return std::nullopt;
  return mesh;
}

}  // namespace

std::uint32_t lengthUnitCode(ddfcam::LengthUnit unit) {
  for (std::size_t c = 0; c < kUnitCodes.size(); ++c)
    if (kUnitCodes[c] == unit) return static_cast<std::uint32_t>(c);
  throw InvalidInput("unknown length unit");
}

std::optional<ddfcam::LengthUnit> lengthUnitOfCode(std::uint32_t code) {
  if (code >= kUnitCodes.size()) return std::nullopt;
  return kUnitCodes[code];
}

void checkDdfMetadata(const DdfMetadata& metadata, int faceCount) {
  const std::size_t faces = metadata.cadFaceOfSupportFace.size();
  if (faces != 0 && faces != static_cast<std::size_t>(faceCount))
    throw InvalidInput("DDF metadata: " + std::to_string(faces) + " CAD face entries for " +
                       std::to_string(faceCount) + " support faces");
  const auto names = static_cast<long long>(metadata.cadFaceNames.size());
  for (std::size_t f = 0; f < faces; ++f) {
    const int cad = metadata.cadFaceOfSupportFace[f];
    if (cad < -1 || cad >= names)
      throw InvalidInput("DDF metadata: support face " + std::to_string(f) + " names CAD face " +
                         std::to_string(cad) + " of " + std::to_string(names));
  }
}

void putDdfMetadata(std::string& out, const DdfMetadata& metadata) {
  std::string section;
  putU32(section, lengthUnitCode(metadata.sourceUnit));
  putU32(section, static_cast<std::uint32_t>(metadata.cadFaceNames.size()));
  for (const std::string& name : metadata.cadFaceNames) {
    if (name.size() > std::numeric_limits<std::uint32_t>::max())
      throw InvalidInput("DDF metadata: CAD face name longer than 4 GiB");
    putU32(section, static_cast<std::uint32_t>(name.size()));
    section += name;
  }
  putU64(section, metadata.cadFaceOfSupportFace.size());
  for (const int cad : metadata.cadFaceOfSupportFace)
    putU32(section, static_cast<std::uint32_t>(cad));
  putDesignMesh(section, metadata.designMesh);
  if (section.size() > std::numeric_limits<std::uint32_t>::max())
    throw InvalidInput("DDF metadata: section longer than 4 GiB");
  putU32(out, static_cast<std::uint32_t>(section.size()));
  out += section;
}

DdfMetadata readDdfMetadata(std::string_view section, int faceCount,
                            const std::string& sourceName) {
  SectionReader in(section, sourceName);
  DdfMetadata metadata;
  metadata.stored = true;
  const std::uint64_t code = in.unsignedValue(4, "the source unit");
  const std::optional<ddfcam::LengthUnit> unit = lengthUnitOfCode(static_cast<std::uint32_t>(code));
  if (!unit) in.fail("unknown source unit code " + std::to_string(code));
  metadata.sourceUnit = *unit;
  const std::uint64_t names = in.unsignedValue(4, "the CAD face name count");
  if (names > section.size() / 4) in.fail("implausible CAD face name count");
  metadata.cadFaceNames.reserve(names);
  for (std::uint64_t n = 0; n < names; ++n) metadata.cadFaceNames.push_back(in.text("a name"));
  const std::uint64_t faces = in.unsignedValue(8, "the CAD face list length");
  if (faces != 0 && faces != static_cast<std::uint64_t>(faceCount))
    in.fail(std::to_string(faces) + " CAD face entries for " + std::to_string(faceCount) +
            " support faces");
  metadata.cadFaceOfSupportFace.resize(faces);
  for (int& cad : metadata.cadFaceOfSupportFace)
    cad = static_cast<std::int32_t>(static_cast<std::uint32_t>(in.unsignedValue(4, "CAD faces")));
  if (!in.atEnd()) metadata.designMesh = readDesignMesh(in, section.size());
  try {
    checkDdfMetadata(metadata, faceCount);
  } catch (const InvalidInput& e) {
    in.fail(e.what());
  }
  return metadata;
}

}  // namespace ddfcam::io::detail
