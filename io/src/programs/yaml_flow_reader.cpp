// SPDX-License-Identifier: MIT
// ddfcam: YAML values written on one line (plain and quoted scalars, flow collections), and the
// limits every node of a document counts against.
#include "yaml_flow_reader.h"

#include "yaml_line_reader.h"

#include <ddfcam/error.h>

#include <charconv>
#include <cstdint>
#include <unordered_set>

namespace ddfcam::io::detail {
namespace {

void appendUtf8(std::string& out, std::uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

char simpleEscape(char c) {
  switch (c) {
    case '0':
      return '\0';
    case 'a':
      return '\a';
    case 'b':
      return '\b';
    case 't':
      return '\t';
    case 'n':
      return '\n';
    case 'v':
      return '\v';
    case 'f':
      return '\f';
    case 'r':
      return '\r';
    case 'e':
      return '\x1b';
    case ' ':
      return ' ';
    case '"':
      return '"';
    case '/':
      return '/';
    case '\\':
      return '\\';
    default:
      return 1;  // not a one-character escape
  }
}

}  // namespace

YamlFlowReader::YamlFlowReader(const std::string& sourceName, const YamlLimits& limits)
    : name_(sourceName), limits_(limits) {}

void YamlFlowReader::fail(int line, const std::string& what) const {
  throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
}

YamlNode YamlFlowReader::node(YamlKind kind, int line) {
  if (++nodes_ > limits_.maxNodes)
    fail(line, "more than " + std::to_string(limits_.maxNodes) + " YAML nodes");
  YamlNode n;
  n.kind = kind;
  n.line = line;
  return n;
}

void YamlFlowReader::checkDepth(int depth, int line) const {
  if (depth > limits_.maxDepth)
    fail(line, "nesting deeper than " + std::to_string(limits_.maxDepth) + " levels");
}

void YamlFlowReader::checkScalarSize(std::size_t size, int line) const {
  if (size > limits_.maxScalarBytes)
    fail(line, "scalar longer than " + std::to_string(limits_.maxScalarBytes) + " bytes");
}

YamlNode YamlFlowReader::parseInline(std::string_view text, int line, int depth) {
  std::string_view s = text;
  YamlNode value = parseFlow(s, line, depth, false);
  skipYamlBlanks(s);
  if (!s.empty()) fail(line, "unexpected text '" + std::string(s.substr(0, 20)) + "'");
  return value;
}

YamlNode YamlFlowReader::parseFlow(std::string_view& s, int line, int depth, bool inFlow) {
  checkDepth(depth, line);
  skipYamlBlanks(s);
  if (s.empty()) {
    if (inFlow) fail(line, "missing value in a flow collection");
    return node(YamlKind::Null, line);
  }
  const char c = s[0];
  if (c == '[') return parseFlowSequence(s, line, depth);
  if (c == '{') return parseFlowMapping(s, line, depth);
  if (c == '"' || c == '\'') {
    YamlNode scalar = node(YamlKind::Scalar, line);
    scalar.text = parseQuoted(s, line);
    scalar.quoted = true;
    return scalar;
  }
  if (std::string_view("&*!|>%@`?").find(c) != std::string_view::npos)
    fail(line, std::string("unsupported YAML feature starting with '") + c + "'");
  return parsePlain(s, line, inFlow);
}

YamlNode YamlFlowReader::parsePlain(std::string_view& s, int line, bool inFlow) {
  std::size_t end = 0;
  for (; end < s.size(); ++end) {
    const char c = s[end];
    const bool colonSep =
        c == ':' &&
        (end + 1 == s.size() || isYamlBlank(s[end + 1]) ||
         (inFlow && std::string_view(",]}").find(s[end + 1]) != std::string_view::npos));
    if (colonSep) {
      if (!inFlow) fail(line, "a mapping value is not allowed here");
      break;
    }
    if (inFlow && std::string_view(",[]{}").find(c) != std::string_view::npos) break;
  }
  const std::string_view text = trimYamlRight(s.substr(0, end));
  s.remove_prefix(end);
  if (text.empty()) fail(line, "missing value in a flow collection");
  checkScalarSize(text.size(), line);
  if (text == "~" || text == "null" || text == "Null" || text == "NULL")
    return node(YamlKind::Null, line);
  YamlNode scalar = node(YamlKind::Scalar, line);
  scalar.text = std::string(text);
  return scalar;
}

YamlNode YamlFlowReader::parseFlowSequence(std::string_view& s, int line, int depth) {
  YamlNode seq = node(YamlKind::Sequence, line);
  s.remove_prefix(1);
  for (;;) {
    skipYamlBlanks(s);
    if (s.empty()) fail(line, "flow sequence not closed on its line");
    if (s[0] == ']') break;
    seq.items.push_back(parseFlow(s, line, depth + 1, true));
    skipYamlBlanks(s);
    if (!s.empty() && s[0] == ',') {
      s.remove_prefix(1);
    } else if (s.empty()) {
      fail(line, "flow sequence not closed on its line");
    } else if (s[0] != ']') {
      fail(line, "expected ',' or ']' in a flow sequence");
    }
  }
  s.remove_prefix(1);
  return seq;
}

YamlNode YamlFlowReader::parseFlowMapping(std::string_view& s, int line, int depth) {
  YamlNode map = node(YamlKind::Mapping, line);
  std::unordered_set<std::string> keys;
  s.remove_prefix(1);
  for (;;) {
    skipYamlBlanks(s);
    if (s.empty()) fail(line, "flow mapping not closed on its line");
    if (s[0] == '}') break;
    YamlNode key = parseFlow(s, line, depth + 1, true);
    if (key.kind != YamlKind::Scalar) fail(line, "flow mapping keys must be scalars");
    skipYamlBlanks(s);
    if (s.empty() || s[0] != ':') fail(line, "expected ':' after a flow mapping key");
    s.remove_prefix(1);
    skipYamlBlanks(s);
    YamlNode value = (!s.empty() && (s[0] == ',' || s[0] == '}'))
                         ? node(YamlKind::Null, line)
                         : parseFlow(s, line, depth + 1, true);
    if (!keys.insert(key.text).second) fail(line, "duplicate key '" + key.text + "'");
    map.entries.push_back({std::move(key.text), std::move(value)});
    skipYamlBlanks(s);
    if (!s.empty() && s[0] == ',') {
      s.remove_prefix(1);
    } else if (s.empty()) {
      fail(line, "flow mapping not closed on its line");
    } else if (s[0] != '}') {
      fail(line, "expected ',' or '}' in a flow mapping");
    }
  }
  s.remove_prefix(1);
  return map;
}

std::string YamlFlowReader::parseQuoted(std::string_view& s, int line) {
  const char quote = s[0];
  std::string out;
  std::size_t i = 1;
  for (;; ++i) {
    if (i >= s.size())
      fail(line, "quoted scalar not closed on its line (multi-line scalars are not supported)");
    checkScalarSize(out.size(), line);
    const char c = s[i];
    if (quote == '\'' && c == '\'') {
      if (i + 1 < s.size() && s[i + 1] == '\'') {
        out += '\'';
        ++i;
        continue;
      }
      break;
    }
    if (quote == '"' && c == '"') break;
    if (quote == '"' && c == '\\') {
      i = decodeEscape(s, i, line, out);
      continue;
    }
    out += c;
  }
  s.remove_prefix(i + 1);
  return out;
}

/// Decodes the escape at s[i] == '\\'; returns the index of its last character.
std::size_t YamlFlowReader::decodeEscape(std::string_view s, std::size_t i, int line,
                                         std::string& out) {
  if (i + 1 >= s.size()) fail(line, "unfinished escape in a quoted scalar");
  const char e = s[i + 1];
  const char simple = simpleEscape(e);
  if (simple != 1) {
    out += simple;
    return i + 1;
  }
  const std::size_t digits = e == 'x' ? 2 : e == 'u' ? 4 : e == 'U' ? 8 : 0;
  if (digits == 0) fail(line, std::string("unknown escape '\\") + e + "'");
  if (i + 2 + digits > s.size()) fail(line, "unfinished escape in a quoted scalar");
  std::uint32_t cp = 0;
  const char* first = s.data() + i + 2;
  const auto [ptr, ec] = std::from_chars(first, first + digits, cp, 16);
  if (ec != std::errc() || ptr != first + digits || cp > 0x10FFFF)
    fail(line, "bad hexadecimal escape in a quoted scalar");
  appendUtf8(out, cp);
  return i + 1 + digits;
}

}  // namespace ddfcam::io::detail
