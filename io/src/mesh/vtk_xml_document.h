// SPDX-License-Identifier: MIT
// ddfcam: a minimal XML element scanner for VTK XML files (no DTD, no namespaces).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ddfcam::io::detail {

/// @brief One element of a VTK XML file; content is the raw text between its tags.
struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;  ///< entity-decoded values
  std::size_t tagBegin = 0;      ///< offset of the '<' of the start tag
  std::size_t contentBegin = 0;  ///< offset into the text
  std::size_t contentEnd = 0;    ///< offset into the text (exclusive)
  int parent = -1;
  std::vector<int> children;

  /// @brief End of the text before the first child element (VTK puts InformationKey elements
  /// after the values of a DataArray).
  std::size_t textEnd(const std::vector<XmlElement>& all) const {
    return children.empty() ? contentEnd : all[children.front()].tagBegin;
  }
  /// @brief Value of attribute @p key, if present.
  std::optional<std::string> attribute(std::string_view key) const;
};

/// @brief Elements of a VTK XML file; element 0 is the root. Scanning stops at the '_' of an
/// AppendedData element, whose data start is kept.
struct XmlDocument {
  std::vector<XmlElement> elements;
  std::optional<std::size_t> appendedStart;  ///< offset of the byte after '_'
  int appendedElement = -1;                  ///< index of AppendedData, or -1

  /// @brief Children of @p parent named @p name.
  std::vector<int> children(int parent, std::string_view name) const;
  /// @brief The single child named @p name, if any.
  std::optional<int> child(int parent, std::string_view name) const;
};

/// @brief Scans @p text. @throws IoError "<source>: ..." for malformed XML.
XmlDocument parseXml(std::string_view text, const std::string& source);

}  // namespace ddfcam::io::detail
