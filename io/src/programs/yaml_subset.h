// SPDX-License-Identifier: MIT
// ddfcam: a strict parser for the block-YAML subset that robot tool-path files use.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::io::detail {

/// @brief Kind of a parsed YAML node.
enum class YamlKind { Null, Scalar, Sequence, Mapping };

struct YamlEntry;

/// @brief One node of a parsed document. Scalars keep their text (quotes removed, escapes
/// decoded); plain "~", "null" and empty values are Null.
struct YamlNode {
  YamlKind kind = YamlKind::Null;  ///< what the node is
  int line = 0;                    ///< 1-based line where the node starts
  bool quoted = false;             ///< scalar was written in quotes
  std::string text;                ///< scalar text
  std::vector<YamlNode> items;     ///< sequence items, in order
  std::vector<YamlEntry> entries;  ///< mapping entries, in file order

  /// @brief The value of @p key in a mapping; nullptr if absent (or not a mapping).
  const YamlNode* find(std::string_view key) const;
};

/// @brief One "key: value" entry of a mapping.
struct YamlEntry {
  std::string key;  ///< the key's text
  YamlNode value;   ///< its value
};

/// @brief Limits that keep hostile input from exhausting the stack or memory.
struct YamlLimits {
  int maxDepth = 64;                  ///< deepest nesting of collections (default 64)
  std::size_t maxNodes = 2'000'000;   ///< most nodes in a document (default 2 M, ~200 k poses)
  std::size_t maxScalarBytes = 4096;  ///< longest scalar or key (default 4 KiB)
};

/// @brief Parses one YAML document of the subset: block mappings and sequences by
/// indentation (spaces only), "- " items that may start a mapping on the same line, plain,
/// single- and double-quoted scalars, flow sequences "[a, b]" and flow mappings "{k: v}" on
/// one line, "#" comments, and a leading "---". Anchors, aliases, tags, block scalars
/// ("|", ">"), multi-line scalars, multi-line flow collections and several documents are
/// rejected. Duplicate keys are rejected.
/// @param sourceName file name used in messages.
/// @return the root node (Null for an empty document).
/// @throws IoError "<sourceName>: line N: <what>" for anything outside the subset, and when
/// a limit of @p limits is exceeded.
YamlNode parseYamlSubset(std::string_view text, const std::string& sourceName,
                         const YamlLimits& limits = {});

}  // namespace ddfcam::io::detail
