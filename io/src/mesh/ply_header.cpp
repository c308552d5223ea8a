// SPDX-License-Identifier: MIT
// ddfcam: PLY header parsing.
#include "ply_header.h"

#include <ddfcam/error.h>

#include "../common/text_parsing.h"

namespace ddfcam::io::detail {
namespace {

std::optional<ScalarType> scalarType(std::string_view n) {
  if (n == "char" || n == "int8") return ScalarType{1, false, true};
  if (n == "uchar" || n == "uint8") return ScalarType{1, false, false};
  if (n == "short" || n == "int16") return ScalarType{2, false, true};
  if (n == "ushort" || n == "uint16") return ScalarType{2, false, false};
  if (n == "int" || n == "int32") return ScalarType{4, false, true};
  if (n == "uint" || n == "uint32") return ScalarType{4, false, false};
  if (n == "float" || n == "float32") return ScalarType{4, true, true};
  if (n == "double" || n == "float64") return ScalarType{8, true, true};
  return std::nullopt;
}

ScalarType requireType(const LineCursor& cursor, std::string_view name) {
  const auto type = scalarType(name);
  if (!type) cursor.fail("unknown PLY property type '" + std::string(name.substr(0, 40)) + "'");
  return *type;
}

void readPropertyLine(const LineCursor& cursor, const std::vector<std::string_view>& tokens,
                      PlyHeader& header) {
  if (header.elements.empty()) cursor.fail("property before any element");
  PlyProperty property;
  if (tokens.size() == 5 && tokens[1] == "list") {
    property.countType = requireType(cursor, tokens[2]);
    if (property.countType->isFloat) cursor.fail("list count type must be an integer type");
    property.type = requireType(cursor, tokens[3]);
    property.name = tokens[4];
  } else if (tokens.size() == 3) {
    property.type = requireType(cursor, tokens[1]);
    property.name = tokens[2];
  } else {
    cursor.fail("malformed property line");
  }
  header.elements.back().properties.push_back(std::move(property));
}

void readHeaderLine(const LineCursor& cursor, const std::vector<std::string_view>& tokens,
                    PlyHeader& header, std::size_t dataBytes) {
  const std::string_view key = tokens.front();
  if (key == "format") {
    if (tokens.size() != 3 || tokens[2] != "1.0") cursor.fail("unsupported PLY format line");
    if (tokens[1] == "ascii")
      header.encoding = PlyEncoding::Ascii;
    else if (tokens[1] == "binary_little_endian")
      header.encoding = PlyEncoding::BinaryLittle;
    else if (tokens[1] == "binary_big_endian")
      header.encoding = PlyEncoding::BinaryBig;
    else
      cursor.fail("unknown PLY encoding '" + std::string(tokens[1].substr(0, 40)) + "'");
  } else if (key == "element") {
    if (tokens.size() != 3) cursor.fail("malformed element line");
    const std::int64_t count = cursor.toInt(tokens[2]);
    // Every element instance takes at least one byte, which bounds sane counts.
    if (count < 0 || count > static_cast<std::int64_t>(dataBytes))
      cursor.fail("implausible element count " + std::to_string(count));
    header.elements.push_back({std::string(tokens[1]), count, {}});
  } else if (key == "property") {
    readPropertyLine(cursor, tokens, header);
  } else if (key != "comment" && key != "obj_info") {
    cursor.fail("unexpected PLY header line '" + std::string(key.substr(0, 40)) + "'");
  }
}

}  // namespace

PlyHeader readPlyHeader(std::string_view bytes, const std::string& name) {
  LineCursor cursor(bytes, name);
  std::string_view line;
  if (!cursor.next(line) || line != "ply") cursor.failFile("not a PLY file (no 'ply' magic line)");
  if (!cursor.next(line) || line.substr(0, 7) != "format ")
    cursor.fail("PLY header must continue with a format line");
  PlyHeader header;
  std::vector<std::string_view> tokens;
  do {
    splitTokens(line, tokens);
    if (tokens.empty()) continue;
    if (tokens.front() == "end_header") {
      header.bodyOffset = bytes.size() - cursor.rest().size();
      header.bodyFirstLine = cursor.lineNumber() + 1;
      return header;
    }
    readHeaderLine(cursor, tokens, header, bytes.size());
  } while (cursor.next(line));
  cursor.failFile("PLY header has no end_header line");
}

}  // namespace ddfcam::io::detail
