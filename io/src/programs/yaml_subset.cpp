// SPDX-License-Identifier: MIT
// ddfcam: a strict parser for the block-YAML subset that robot tool-path files use.
#include "yaml_subset.h"

#include "yaml_flow_reader.h"
#include "yaml_line_reader.h"

#include <unordered_set>

namespace ddfcam::io::detail {
namespace {

/// Block structure by indentation; values written on one line go to YamlFlowReader.
class Parser {
 public:
  Parser(std::string_view text, const std::string& name, const YamlLimits& limits)
      : lines_(text, name), flow_(name, limits) {}

  YamlNode parseDocument() {
    if (!lines_.has()) return flow_.node(YamlKind::Null, 1);
    if (cur().indent != 0) lines_.fail(cur().number, "the document must start in column 1");
    YamlNode root = parseBlock(0, 0);
    if (lines_.has())
      lines_.fail(cur().number, "unexpected indentation or content after the document");
    return root;
  }

 private:
  YamlLine& cur() { return lines_.current(); }

  YamlNode parseBlock(int indent, int depth) {
    flow_.checkDepth(depth, cur().number);
    if (isYamlSequenceItem(cur().content)) return parseSequence(indent, depth);
    std::string key;
    std::string_view value;
    if (splitKey(cur().content, cur().number, key, value)) return parseMapping(indent, depth);
    const int line = cur().number;
    const std::string_view content = cur().content;
    lines_.advance();
    return flow_.parseInline(content, line, depth);
  }

  YamlNode parseSequence(int indent, int depth) {
    YamlNode seq = flow_.node(YamlKind::Sequence, cur().number);
    while (lines_.has() && cur().indent == indent && isYamlSequenceItem(cur().content)) {
      std::string_view rest = cur().content.substr(1);
      skipYamlBlanks(rest);
      if (rest.empty()) {
        const int line = cur().number;
        lines_.advance();
        if (lines_.has() && cur().indent > indent)
          seq.items.push_back(parseBlock(cur().indent, depth + 1));
        else
          seq.items.push_back(flow_.node(YamlKind::Null, line));
        continue;
      }
      // The item's content starts a node in the column where it is written.
      cur().indent = indent + static_cast<int>(rest.data() - cur().content.data());
      cur().content = rest;
      seq.items.push_back(parseBlock(cur().indent, depth + 1));
    }
    if (lines_.has() && cur().indent > indent) lines_.fail(cur().number, "unexpected indentation");
    return seq;
  }

  YamlNode parseMapping(int indent, int depth) {
    YamlNode map = flow_.node(YamlKind::Mapping, cur().number);
    std::unordered_set<std::string> keys;
    while (lines_.has() && cur().indent == indent) {
      const int line = cur().number;
      if (isYamlSequenceItem(cur().content))
        lines_.fail(line, "a sequence item where a mapping key was expected");
      std::string key;
      std::string_view rest;
      if (!splitKey(cur().content, line, key, rest)) lines_.fail(line, "expected 'key: value'");
      if (!keys.insert(key).second) lines_.fail(line, "duplicate key '" + key + "'");
      lines_.advance();
      YamlNode value;
      if (!rest.empty()) {
        value = flow_.parseInline(rest, line, depth + 1);
      } else if (lines_.has() && cur().indent > indent) {
        value = parseBlock(cur().indent, depth + 1);
      } else if (lines_.has() && cur().indent == indent && isYamlSequenceItem(cur().content)) {
        flow_.checkDepth(depth + 1, cur().number);
        value = parseSequence(indent, depth + 1);
      } else {
        value = flow_.node(YamlKind::Null, line);
      }
      map.entries.push_back({std::move(key), std::move(value)});
    }
    if (lines_.has() && cur().indent > indent)
      lines_.fail(cur().number, "unexpected indentation (multi-line scalars are not supported)");
    return map;
  }

  /// Splits "key: value" (value may be empty); false if @p content is not a mapping entry.
  bool splitKey(std::string_view content, int line, std::string& key, std::string_view& value) {
    std::string_view s = content;
    if (s[0] == '"' || s[0] == '\'') {
      key = flow_.parseQuoted(s, line);
      skipYamlBlanks(s);
      if (s.empty() || s[0] != ':' || (s.size() > 1 && !isYamlBlank(s[1]))) return false;
      value = s.substr(1);
    } else {
      if (s[0] == '[' || s[0] == '{' || s[0] == '?') return false;
      std::size_t colon = 0;
      for (colon = 0; colon < s.size(); ++colon)
        if (s[colon] == ':' && (colon + 1 == s.size() || isYamlBlank(s[colon + 1]))) break;
      if (colon == s.size()) return false;
      const std::string_view k = trimYamlRight(s.substr(0, colon));
      if (k.empty()) lines_.fail(line, "empty mapping key");
      flow_.checkScalarSize(k.size(), line);
      key = std::string(k);
      value = s.substr(colon + 1);
    }
    skipYamlBlanks(value);
    return true;
  }

  YamlLineReader lines_;
  YamlFlowReader flow_;
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
