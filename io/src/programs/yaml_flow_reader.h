// SPDX-License-Identifier: MIT
// ddfcam: YAML values written on one line (plain and quoted scalars, flow collections), and the
// limits every node of a document counts against.
#pragma once

#include "yaml_subset.h"

#include <string>
#include <string_view>

namespace ddfcam::io::detail {

/// @brief Reads the one-line values of a document and makes its nodes, counting them against
/// the document's limits. Errors name the source and the line.
class YamlFlowReader {
 public:
  /// @param sourceName used in messages (not owned); @param limits of the document.
  YamlFlowReader(const std::string& sourceName, const YamlLimits& limits);

  /// @brief A new node of @p kind on @p line. @throws IoError beyond limits.maxNodes.
  YamlNode node(YamlKind kind, int line);
  /// @throws IoError if @p depth exceeds limits.maxDepth.
  void checkDepth(int depth, int line) const;
  /// @throws IoError if a scalar of @p size bytes exceeds limits.maxScalarBytes.
  void checkScalarSize(std::size_t size, int line) const;
  /// @brief Throws IoError "<source>: line N: <what>".
  [[noreturn]] void fail(int line, const std::string& what) const;

  /// @brief The whole of @p text (a value after "key:" or "- ") as one node at @p depth.
  YamlNode parseInline(std::string_view text, int line, int depth);
  /// @brief The quoted scalar at the front of @p s (s[0] is the quote); advances @p s past it.
  std::string parseQuoted(std::string_view& s, int line);

 private:
  YamlNode parseFlow(std::string_view& s, int line, int depth, bool inFlow);
  YamlNode parsePlain(std::string_view& s, int line, bool inFlow);
  YamlNode parseFlowSequence(std::string_view& s, int line, int depth);
  YamlNode parseFlowMapping(std::string_view& s, int line, int depth);
  std::size_t decodeEscape(std::string_view s, std::size_t i, int line, std::string& out);

  const std::string& name_;
  YamlLimits limits_;
  std::size_t nodes_ = 0;
};

}  // namespace ddfcam::io::detail
