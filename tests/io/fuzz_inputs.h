// SPDX-License-Identifier: MIT
// ddfcam tests: deterministic mutations of path-file texts and the reader contract they check.
#pragma once

#include <ddfcam/planning/placement/cl_program.h>

#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace ddfcam::test {

/// @brief Text format of a reader; selects seeds and the tokens mutations insert.
enum class FuzzFormat { Csv, Apt, RosYaml, FanucLs };

/// @brief Tokens of @p format worth inserting (keywords, separators, hostile numbers).
std::vector<std::string> fuzzTokens(FuzzFormat format);

/// @brief Small valid texts of @p format, written by hand: the bases the mutations start from.
std::vector<std::string> builtinSeeds(FuzzFormat format);

/// @brief Applies 1..4 random edits to a text: byte flips, inserts, deletes, splices with another
/// text, numbers replaced by huge/NaN/empty ones, truncated or long lines, binary garbage, line-end
/// changes, deep nesting. Deterministic for a given seed.
class TextMutator {
 public:
  /// @param seed random seed; @param tokens format tokens (fuzzTokens()) to insert.
  TextMutator(std::uint64_t seed, std::vector<std::string> tokens);

  /// @brief A mutated copy of @p text; @p other is spliced in by some edits. Output is capped
  /// at about 256 KiB.
  std::string mutate(std::string_view text, std::string_view other);

 private:
  std::size_t below(std::size_t n);
  void mutateOnce(std::string& text, std::string_view other);
  void replaceNumber(std::string& text);
  void editLines(std::string& text);
  void insertLong(std::string& text);

  std::mt19937_64 rng_;
  std::vector<std::string> tokens_;
};

/// @brief Number of lines of @p text (a last line without a line end counts; "" has 0).
int lineCount(std::string_view text);

/// @brief Why a reader's error message @p message breaks the contract for input @p text, or
/// nothing: it must start with @p sourceName, and a "line N" in it must have 1 <= N <= lines + 1.
std::optional<std::string> messageViolation(std::string_view message, std::string_view text,
                                            std::string_view sourceName);

/// @brief The N of the first "line N" in @p message, if any.
std::optional<long long> lineNumberIn(std::string_view message);

/// @brief Why @p program read from @p text breaks the ClProgram contract, or nothing: finite
/// positions, unit axes and normals, finite non-negative feeds, non-negative path and point
/// indices, source lines within the text.
std::optional<std::string> programViolation(const planning::ClProgram& program,
                                            std::string_view text);

/// @brief Results that are not a ClProgram (older reader signatures) have no checked contract.
template <class Result>
std::optional<std::string> programViolation(const Result&, std::string_view) {
  return std::nullopt;
}

/// @brief @p text as a C string literal body, cut after @p maxBytes, for failure messages.
std::string escaped(std::string_view text, std::size_t maxBytes = 400);

}  // namespace ddfcam::test
