// SPDX-License-Identifier: MIT
// ddfcam: a strict parser for the block-YAML subset that robot tool-path files use.
#include "yaml_subset.h"

#include <ddfcam/error.h>

#include <charconv>
#include <cstdint>
#include <unordered_set>

namespace ddfcam::io::detail {
namespace {

bool isBlank(char c) {
  return c == ' ' || c == '\t';
}

std::string_view trimRight(std::string_view s) {
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

void skipBlanks(std::string_view& s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
}

bool isSeqItem(std::string_view content) {
  return content == "-" || (content.size() >= 2 && content[0] == '-' && isBlank(content[1]));
}

/// Content of a line without a trailing "#" comment; quotes protect "#".
std::string_view stripYamlComment(std::string_view s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const bool tokenStart =
        i == 0 || isBlank(s[i - 1]) || s[i - 1] == '[' || s[i - 1] == '{' || s[i - 1] == ',';
    if (quote == '"') {
      if (c == '\\')
        ++i;
      else if (c == '"')
        quote = 0;
    } else if (quote == '\'') {
      if (c == '\'' && i + 1 < s.size() && s[i + 1] == '\'')
        ++i;
      else if (c == '\'')
        quote = 0;
    } else if ((c == '"' || c == '\'') && tokenStart) {
      quote = c;
    } else if (c == '#' && (i == 0 || isBlank(s[i - 1]))) {
      return s.substr(0, i);
    }
  }
  return s;
}

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

struct Line {
  int number = 0;
  int indent = 0;
  std::string_view content;  // without indentation, comment and trailing blanks
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& name, const YamlLimits& limits)
      : text_(text), name_(name), limits_(limits) {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
    advance();
  }

  YamlNode parseDocument() {
    if (!has_) return node(YamlKind::Null, 1);
    if (cur_.indent != 0) fail(cur_.number, "the document must start in column 1");
    YamlNode root = parseBlock(0, 0);
    if (has_) fail(cur_.number, "unexpected indentation or content after the document");
    return root;
  }

 private:
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw IoError(name_ + ": line " + std::to_string(line) + ": " + what);
  }

  YamlNode node(YamlKind kind, int line) {
    if (++nodes_ > limits_.maxNodes)
      fail(line, "more than " + std::to_string(limits_.maxNodes) + " YAML nodes");
    YamlNode n;
    n.kind = kind;
    n.line = line;
    return n;
  }

  void checkDepth(int depth, int line) const {
    if (depth > limits_.maxDepth)
      fail(line, "nesting deeper than " + std::to_string(limits_.maxDepth) + " levels");
  }

  /// Loads the next line with content into cur_; has_ = false at the end.
  void advance() {
    has_ = false;
    while (pos_ < text_.size()) {
      const std::size_t end = text_.find('\n', pos_);
      const std::size_t stop = end == std::string_view::npos ? text_.size() : end;
      std::string_view line = text_.substr(pos_, stop - pos_);
      pos_ = end == std::string_view::npos ? text_.size() : end + 1;
      ++lineNo_;
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      for (const char c : line)
        if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
          fail(lineNo_, "control character (binary data?)");
      std::size_t lead = 0;
      while (lead < line.size() && isBlank(line[lead])) ++lead;
      const std::string_view content = trimRight(stripYamlComment(line.substr(lead)));
      if (content.empty()) continue;
      if (ended_) fail(lineNo_, "content after the document end marker '...'");
      if (line.substr(0, lead).find('\t') != std::string_view::npos)
        fail(lineNo_, "tab in indentation (YAML indents with spaces)");
      if (lead == 0 && content == "...") {
        ended_ = true;
        continue;
      }
      if (lead == 0 && content[0] == '%') fail(lineNo_, "YAML directives are not supported");
      if (lead == 0 && content.substr(0, 3) == "---") {
        if (seenContent_ || content != "---") fail(lineNo_, "several documents are not supported");
        seenContent_ = true;
        continue;
      }
      seenContent_ = true;
      cur_ = {lineNo_, static_cast<int>(lead), content};
      has_ = true;
      return;
    }
  }

  YamlNode parseBlock(int indent, int depth) {
    checkDepth(depth, cur_.number);
    if (isSeqItem(cur_.content)) return parseSequence(indent, depth);
    std::string key;
    std::string_view value;
    if (splitKey(cur_.content, cur_.number, key, value)) return parseMapping(indent, depth);
    const int line = cur_.number;
    const std::string_view content = cur_.content;
    advance();
    return parseInline(content, line, depth);
  }

  YamlNode parseSequence(int indent, int depth) {
    YamlNode seq = node(YamlKind::Sequence, cur_.number);
    while (has_ && cur_.indent == indent && isSeqItem(cur_.content)) {
      std::string_view rest = cur_.content.substr(1);
      skipBlanks(rest);
      if (rest.empty()) {
        const int line = cur_.number;
        advance();
        if (has_ && cur_.indent > indent)
          seq.items.push_back(parseBlock(cur_.indent, depth + 1));
        else
          seq.items.push_back(node(YamlKind::Null, line));
        continue;
      }
      // The item's content starts a node in the column where it is written.
      cur_.indent = indent + static_cast<int>(rest.data() - cur_.content.data());
      cur_.content = rest;
      seq.items.push_back(parseBlock(cur_.indent, depth + 1));
    }
    if (has_ && cur_.indent > indent) fail(cur_.number, "unexpected indentation");
    return seq;
  }

  YamlNode parseMapping(int indent, int depth) {
    YamlNode map = node(YamlKind::Mapping, cur_.number);
    std::unordered_set<std::string> keys;
    while (has_ && cur_.indent == indent) {
      const int line = cur_.number;
      if (isSeqItem(cur_.content)) fail(line, "a sequence item where a mapping key was expected");
      std::string key;
      std::string_view rest;
      if (!splitKey(cur_.content, line, key, rest)) fail(line, "expected 'key: value'");
      if (!keys.insert(key).second) fail(line, "duplicate key '" + key + "'");
      advance();
      YamlNode value;
      if (!rest.empty()) {
        value = parseInline(rest, line, depth + 1);
      } else if (has_ && cur_.indent > indent) {
        value = parseBlock(cur_.indent, depth + 1);
      } else if (has_ && cur_.indent == indent && isSeqItem(cur_.content)) {
        checkDepth(depth + 1, cur_.number);
        value = parseSequence(indent, depth + 1);
      } else {
        value = node(YamlKind::Null, line);
      }
      map.entries.push_back({std::move(key), std::move(value)});
    }
    if (has_ && cur_.indent > indent)
      fail(cur_.number, "unexpected indentation (multi-line scalars are not supported)");
    return map;
  }

  /// Splits "key: value" (value may be empty); false if @p content is not a mapping entry.
  bool splitKey(std::string_view content, int line, std::string& key, std::string_view& value) {
    std::string_view s = content;
    if (s[0] == '"' || s[0] == '\'') {
      key = parseQuoted(s, line);
      skipBlanks(s);
      if (s.empty() || s[0] != ':' || (s.size() > 1 && !isBlank(s[1]))) return false;
      value = s.substr(1);
    } else {
      if (s[0] == '[' || s[0] == '{' || s[0] == '?') return false;
      std::size_t colon = 0;
      for (colon = 0; colon < s.size(); ++colon)
        if (s[colon] == ':' && (colon + 1 == s.size() || isBlank(s[colon + 1]))) break;
      if (colon == s.size()) return false;
      const std::string_view k = trimRight(s.substr(0, colon));
      if (k.empty()) fail(line, "empty mapping key");
      checkScalarSize(k.size(), line);
      key = std::string(k);
      value = s.substr(colon + 1);
    }
    skipBlanks(value);
    return true;
  }

  YamlNode parseInline(std::string_view text, int line, int depth) {
    std::string_view s = text;
    YamlNode value = parseFlow(s, line, depth, false);
    skipBlanks(s);
    if (!s.empty()) fail(line, "unexpected text '" + std::string(s.substr(0, 20)) + "'");
    return value;
  }

  YamlNode parseFlow(std::string_view& s, int line, int depth, bool inFlow) {
    checkDepth(depth, line);
    skipBlanks(s);
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

  YamlNode parsePlain(std::string_view& s, int line, bool inFlow) {
    std::size_t end = 0;
    for (; end < s.size(); ++end) {
      const char c = s[end];
      const bool colonSep =
          c == ':' &&
          (end + 1 == s.size() || isBlank(s[end + 1]) ||
           (inFlow && std::string_view(",]}").find(s[end + 1]) != std::string_view::npos));
      if (colonSep) {
        if (!inFlow) fail(line, "a mapping value is not allowed here");
        break;
      }
      if (inFlow && std::string_view(",[]{}").find(c) != std::string_view::npos) break;
    }
    const std::string_view text = trimRight(s.substr(0, end));
    s.remove_prefix(end);
    if (text.empty()) fail(line, "missing value in a flow collection");
    checkScalarSize(text.size(), line);
    if (text == "~" || text == "null" || text == "Null" || text == "NULL")
      return node(YamlKind::Null, line);
    YamlNode scalar = node(YamlKind::Scalar, line);
    scalar.text = std::string(text);
    return scalar;
  }

  YamlNode parseFlowSequence(std::string_view& s, int line, int depth) {
    YamlNode seq = node(YamlKind::Sequence, line);
    s.remove_prefix(1);
    for (;;) {
      skipBlanks(s);
      if (s.empty()) fail(line, "flow sequence not closed on its line");
      if (s[0] == ']') break;
      seq.items.push_back(parseFlow(s, line, depth + 1, true));
      skipBlanks(s);
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

  YamlNode parseFlowMapping(std::string_view& s, int line, int depth) {
    YamlNode map = node(YamlKind::Mapping, line);
    std::unordered_set<std::string> keys;
    s.remove_prefix(1);
    for (;;) {
      skipBlanks(s);
      if (s.empty()) fail(line, "flow mapping not closed on its line");
      if (s[0] == '}') break;
      YamlNode key = parseFlow(s, line, depth + 1, true);
      if (key.kind != YamlKind::Scalar) fail(line, "flow mapping keys must be scalars");
      skipBlanks(s);
      if (s.empty() || s[0] != ':') fail(line, "expected ':' after a flow mapping key");
      s.remove_prefix(1);
      skipBlanks(s);
      YamlNode value = (!s.empty() && (s[0] == ',' || s[0] == '}'))
                           ? node(YamlKind::Null, line)
                           : parseFlow(s, line, depth + 1, true);
      if (!keys.insert(key.text).second) fail(line, "duplicate key '" + key.text + "'");
      map.entries.push_back({std::move(key.text), std::move(value)});
      skipBlanks(s);
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

  std::string parseQuoted(std::string_view& s, int line) {
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
  std::size_t decodeEscape(std::string_view s, std::size_t i, int line, std::string& out) {
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

  void checkScalarSize(std::size_t size, int line) const {
    if (size > limits_.maxScalarBytes)
      fail(line, "scalar longer than " + std::to_string(limits_.maxScalarBytes) + " bytes");
  }

  std::string_view text_;
  const std::string& name_;
  YamlLimits limits_;
  std::size_t pos_ = 0;
  int lineNo_ = 0;
  Line cur_;
  bool has_ = false;
  bool ended_ = false;
  bool seenContent_ = false;
  std::size_t nodes_ = 0;
};

}  // namespace

const YamlNode* YamlNode::find(std::string_view key) const {
  for (const auto& [k, v] : entries)
    if (k == key) return &v;
  return nullptr;
}

YamlNode parseYamlSubset(std::string_view text, const std::string& sourceName,
                         const YamlLimits& limits) {
  Parser parser(text, sourceName, limits);
  return parser.parseDocument();
}

}  // namespace ddfcam::io::detail
