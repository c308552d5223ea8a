// SPDX-License-Identifier: MIT
// ddfcam: decoding VTK XML DataArray elements (ascii, base64 binary, appended; zlib).
#include "vtk_xml_arrays.h"

#include <ddfcam/error.h>
#include <ddfcam/io/mesh/vtk_xml_mesh.h>

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace ddfcam::io::detail {
namespace {

enum class Scalar { F32, F64, I8, U8, I16, U16, I32, U32, I64, U64 };

struct ScalarType {
  std::string_view name;
  Scalar kind;
  int size;
};

constexpr std::array<ScalarType, 10> kTypes = {{{"Float32", Scalar::F32, 4},
                                                {"Float64", Scalar::F64, 8},
                                                {"Int8", Scalar::I8, 1},
                                                {"UInt8", Scalar::U8, 1},
                                                {"Int16", Scalar::I16, 2},
                                                {"UInt16", Scalar::U16, 2},
                                                {"Int32", Scalar::I32, 4},
                                                {"UInt32", Scalar::U32, 4},
                                                {"Int64", Scalar::I64, 8},
                                                {"UInt64", Scalar::U64, 8}}};

template <typename T>
T load(const unsigned char* p, bool bigEndian) {
  std::array<unsigned char, sizeof(T)> b;
  std::memcpy(b.data(), p, sizeof(T));
  if (bigEndian) std::reverse(b.begin(), b.end());  // the machine is little endian (x86/ARM)
  T v;
  std::memcpy(&v, b.data(), sizeof(T));
  return v;
}

double loadScalar(const unsigned char* p, Scalar kind, bool bigEndian) {
  switch (kind) {
    case Scalar::F32:
      return load<float>(p, bigEndian);
    case Scalar::F64:
      return load<double>(p, bigEndian);
    case Scalar::I8:
      return load<std::int8_t>(p, bigEndian);
    case Scalar::U8:
      return load<std::uint8_t>(p, bigEndian);
    case Scalar::I16:
      return load<std::int16_t>(p, bigEndian);
    case Scalar::U16:
      return load<std::uint16_t>(p, bigEndian);
    case Scalar::I32:
      return load<std::int32_t>(p, bigEndian);
    case Scalar::U32:
      return load<std::uint32_t>(p, bigEndian);
    case Scalar::I64:
      return static_cast<double>(load<std::int64_t>(p, bigEndian));
    case Scalar::U64:
      return static_cast<double>(load<std::uint64_t>(p, bigEndian));
  }
  return 0.0;
}

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// Bytes of a data stream: raw bytes, or base64 decoded quad by quad. VTK encodes a compressed
// array's header and its data as separate base64 streams (padding in the middle), so each quad
// is decoded on its own and leftover bytes of a quad are kept for the next read.
class ByteSource {
 public:
  ByteSource(std::string_view text, std::size_t pos, bool base64, std::string what)
      : text_(text), pos_(pos), base64_(base64), what_(std::move(what)) {}

  void read(std::size_t n, std::string& out) {
    out.clear();
    if (!base64_) {
      if (pos_ > text_.size() || n > text_.size() - pos_) fail("data run past the end of the file");
      out.assign(text_.substr(pos_, n));
      pos_ += n;
      return;
    }
    while (out.size() < n) {
      if (pending_.empty()) decodeQuad();
      const std::size_t take = std::min(n - out.size(), pending_.size());
      out.append(pending_, 0, take);
      pending_.erase(0, take);
    }
  }

  [[noreturn]] void fail(const std::string& what) const { throw IoError(what_ + ": " + what); }

 private:
  void decodeQuad() {
    std::array<int, 4> v{};
    int count = 0, pad = 0;
    while (count < 4) {
      if (pos_ >= text_.size()) fail("base64 data ends early");
      const char c = text_[pos_++];
      if (std::isspace(static_cast<unsigned char>(c))) continue;
      if (c == '=') {
        ++pad;
        v[count++] = 0;
        continue;
      }
      const int value = base64Value(c);
      if (value < 0 || pad > 0) fail("invalid base64 character");
      v[count++] = value;
    }
    if (pad > 2) fail("invalid base64 padding");
    const std::uint32_t word = (v[0] << 18) | (v[1] << 12) | (v[2] << 6) | v[3];
    const char bytes[3] = {static_cast<char>(word >> 16), static_cast<char>(word >> 8),
                           static_cast<char>(word)};
    pending_.assign(bytes, 3 - pad);
  }

  std::string_view text_;
  std::size_t pos_;
  bool base64_;
  std::string what_;
  std::string pending_;
};

std::uint64_t readHeaderWord(ByteSource& src, const VtkArrayContext& ctx, std::string& buf) {
  src.read(ctx.headerBytes, buf);
  const auto* p = reinterpret_cast<const unsigned char*>(buf.data());
  return ctx.headerBytes == 8 ? load<std::uint64_t>(p, ctx.bigEndian)
                              : load<std::uint32_t>(p, ctx.bigEndian);
}

std::string readCompressed(ByteSource& src, const VtkArrayContext& ctx, std::size_t bytes) {
  std::string buf;
  const std::uint64_t blocks = readHeaderWord(src, ctx, buf);
  const std::uint64_t blockSize = readHeaderWord(src, ctx, buf);
  const std::uint64_t lastSize = readHeaderWord(src, ctx, buf);
  if (blocks == 0) {
    if (bytes != 0) src.fail("compression header has no blocks");
    return {};
  }
  if (blockSize == 0 || lastSize > blockSize) src.fail("bad compression header");
  if (blocks > bytes / blockSize + 1) src.fail("compression header claims too many blocks");
  const std::uint64_t total = (blocks - 1) * blockSize + (lastSize ? lastSize : blockSize);
  if (total != bytes)
    src.fail("holds " + std::to_string(total) + " bytes, expected " + std::to_string(bytes));
  std::vector<std::uint64_t> sizes(blocks);
  for (auto& s : sizes) s = readHeaderWord(src, ctx, buf);
  std::string out(bytes, '\0');
  std::size_t at = 0;
  for (std::uint64_t b = 0; b < blocks; ++b) {
    if (sizes[b] > ctx.text.size()) src.fail("compressed block larger than the file");
    src.read(sizes[b], buf);
    uLongf length = (b + 1 == blocks && lastSize) ? lastSize : blockSize;
    const uLongf expected = length;
    const int rc = uncompress(reinterpret_cast<Bytef*>(out.data() + at), &length,
                              reinterpret_cast<const Bytef*>(buf.data()), buf.size());
    if (rc != Z_OK || length != expected)
      src.fail("zlib block " + std::to_string(b) + " does not inflate");
    at += length;
  }
  return out;
}

std::string readBinary(ByteSource& src, const VtkArrayContext& ctx, std::size_t bytes) {
  if (ctx.compressed) return readCompressed(src, ctx, bytes);
  std::string buf;
  const std::uint64_t declared = readHeaderWord(src, ctx, buf);
  if (declared != bytes)
    src.fail("holds " + std::to_string(declared) + " bytes, expected " + std::to_string(bytes));
  std::string out;
  src.read(bytes, out);
  return out;
}

std::vector<double> parseAscii(std::string_view text, std::size_t count, const std::string& what) {
  std::vector<double> values;
  values.reserve(count);
  const char* p = text.data();
  const char* end = p + text.size();
  while (true) {
    while (p < end && std::isspace(static_cast<unsigned char>(*p))) ++p;
    if (p == end) break;
    if (values.size() == count) throw IoError(what + ": more values than expected");
    double v = 0.0;
    const auto [next, ec] = std::from_chars(p, end, v);
    if (ec != std::errc() || next == p)
      throw IoError(what + ": bad number '" + std::string(p, std::min<std::size_t>(end - p, 20)) +
                    "'");
    values.push_back(v);
    p = next;
  }
  if (values.size() != count)
    throw IoError(what + ": " + std::to_string(values.size()) + " values, expected " +
                  std::to_string(count));
  return values;
}

}  // namespace

VtkArrayInfo vtkArrayInfo(const VtkArrayContext& ctx, int element) {
  const XmlElement& e = ctx.doc->elements[element];
  VtkArrayInfo info;
  info.name = e.attribute("Name").value_or("");
  if (const auto c = e.attribute("NumberOfComponents")) {
    int n = 0;
    const auto [end, ec] = std::from_chars(c->data(), c->data() + c->size(), n);
    if (ec != std::errc() || end != c->data() + c->size() || n < 1 || n > 1000)
      throw IoError(ctx.source + ": DataArray '" + info.name + "': bad NumberOfComponents '" + *c +
                    "'");
    info.components = n;
  }
  return info;
}

std::vector<double> decodeVtkArray(const VtkArrayContext& ctx, int element, std::size_t tuples,
                                   const std::string& what) {
  const XmlElement& e = ctx.doc->elements[element];
  const std::string where = ctx.source + ": " + what;
  const VtkArrayInfo info = vtkArrayInfo(ctx, element);
  if (tuples > kMaxVtkXmlItems) throw IoError(where + ": too many tuples");
  const std::size_t count = tuples * static_cast<std::size_t>(info.components);
  const std::string typeName = e.attribute("type").value_or("");
  const auto type = std::find_if(kTypes.begin(), kTypes.end(),
                                 [&](const ScalarType& t) { return t.name == typeName; });
  if (type == kTypes.end()) throw IoError(where + ": unsupported type '" + typeName + "'");
  const std::string format = e.attribute("format").value_or("ascii");
  const std::size_t textEnd = e.textEnd(ctx.doc->elements);
  if (format == "ascii") {
    if (count > textEnd - e.contentBegin + 1) throw IoError(where + ": fewer values than expected");
    return parseAscii(ctx.text.substr(e.contentBegin, textEnd - e.contentBegin), count, where);
  }
  // Refuse sizes the file cannot hold before allocating (zlib inflates at most ~1032:1).
  const std::size_t bytesNeeded = count * type->size;
  const std::size_t limit = ctx.compressed ? ctx.text.size() * 1100 + 4096 : ctx.text.size();
  if (bytesNeeded > limit) throw IoError(where + ": array larger than the file can hold");
  std::string bytes;
  if (format == "binary") {
    ByteSource src(ctx.text.substr(0, textEnd), e.contentBegin, true, where);
    bytes = readBinary(src, ctx, count * type->size);
  } else if (format == "appended") {
    if (!ctx.doc->appendedStart) throw IoError(where + ": no AppendedData element");
    const std::string offsetText = e.attribute("offset").value_or("");
    std::size_t offset = 0;
    const auto [end, ec] =
        std::from_chars(offsetText.data(), offsetText.data() + offsetText.size(), offset);
    if (ec != std::errc() || end != offsetText.data() + offsetText.size() ||
        offset > ctx.text.size() - *ctx.doc->appendedStart)
      throw IoError(where + ": bad appended offset '" + offsetText + "'");
    ByteSource src(ctx.text, *ctx.doc->appendedStart + offset, ctx.appendedBase64, where);
    bytes = readBinary(src, ctx, count * type->size);
  } else {
    throw IoError(where + ": unsupported format '" + format + "'");
  }
  std::vector<double> values(count);
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
  for (std::size_t i = 0; i < count; ++i)
    values[i] = loadScalar(p + i * type->size, type->kind, ctx.bigEndian);
  return values;
}

}  // namespace ddfcam::io::detail
