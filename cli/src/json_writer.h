// SPDX-License-Identifier: MIT
// ddfcam-cli: a small streaming JSON writer for reports (objects, arrays, numbers, strings).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::cli {

/// @brief Writes one JSON document into a string, indented by two spaces per level. Keys and
/// values are written in call order; commas and line breaks are placed automatically. Numbers
/// use the shortest text that reads back to the same double ('.' whatever the locale);
/// non-finite numbers become null (JSON has no NaN or infinity).
class JsonWriter {
 public:
  /// @brief Opens an object ('{'), as a value or at the top level.
  JsonWriter& beginObject();
  /// @brief Closes the innermost object. @throws std::logic_error if it is not an object.
  JsonWriter& endObject();
  /// @brief Opens an array ('[').
  JsonWriter& beginArray();
  /// @brief Closes the innermost array. @throws std::logic_error if it is not an array.
  JsonWriter& endArray();
  /// @brief The key of the next value inside an object.
  /// @throws std::logic_error outside an object or when a key is still waiting for its value.
  JsonWriter& key(std::string_view name);
  /// @brief A number (null if not finite).
  JsonWriter& value(double number);
  /// @brief An integer.
  JsonWriter& value(std::int64_t number);
  JsonWriter& value(int number) { return value(static_cast<std::int64_t>(number)); }
  JsonWriter& value(std::size_t number) { return value(static_cast<std::int64_t>(number)); }
  /// @brief A string, escaped (quote, backslash, control characters as \uXXXX); UTF-8 bytes
  /// pass unchanged.
  JsonWriter& value(std::string_view text);
  JsonWriter& value(const char* text) { return value(std::string_view(text)); }
  /// @brief true or false.
  JsonWriter& value(bool flag);
  /// @brief null.
  JsonWriter& null();

  /// @brief The document followed by a line end.
  /// @throws std::logic_error if an object or array is still open.
  std::string str() const;

 private:
  void beforeValue();
  void newline();

  std::string out_;
  struct Level {
    bool array = false;
    bool empty = true;
  };
  std::vector<Level> stack_;
  bool keyPending_ = false;
};

/// @brief @p text as a quoted, escaped JSON string.
std::string jsonString(std::string_view text);

}  // namespace ddfcam::cli
